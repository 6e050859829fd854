#include "screenshot.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QStatusBar>
#include <QTimer>
#include <cstdio>

#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "export/plot_picture.h"
#include "io/atomic_file.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/plot_redraw.h"

namespace cam {

namespace {

/// Waits until the window shows the newest result and, with the Machining dock open, its
/// times (at most 20 s each). False when the result did not arrive.
bool waitUntilShown(MainWindow& window) {
    QCoreApplication::processEvents();
    if (!window.waitForCurrentResult(20000)) return false;
    ComputeEngine* engine = window.engine();
    const auto* machining = window.findChild<QDockWidget*>("machiningDock");
    if (machining && !machining->isHidden() && window.document()->project().machining) {
        const auto current = [engine] {
            const auto& t = engine->latestTiming();
            return t && t->generation == engine->latestGeneration();
        };
        QEventLoop loop;
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        QObject::connect(engine, &ComputeEngine::timingReady, &loop, [&] {
            if (current()) loop.quit();
        });
        if (!current()) loop.exec();  // times that never come leave their panel pending
    }
    return true;
}

/// Parses WxH within [min, 8000]; false with the message printed.
bool parseSize(const QString& text, int minW, int minH, int& w, int& h) {
    const QStringList parts = text.split('x');
    bool okW = false, okH = false;
    if (parts.size() == 2) {
        w = parts[0].toInt(&okW);
        h = parts[1].toInt(&okH);
    }
    if (okW && okH && w >= minW && h >= minH && w <= kMaxPictureSide && h <= kMaxPictureSide)
        return true;
    std::fprintf(stderr, "camwright: --size: expected WxH between %dx%d and %dx%d (got \"%s\")\n",
                 minW, minH, kMaxPictureSide, kMaxPictureSide, qPrintable(text));
    return false;
}

/// Writes the bytes atomically; the exit code.
int writeBytes(const QString& file, const QByteArray& bytes) {
    const Diagnostics problems = writeFileAtomically(
        QFile::encodeName(file).toStdString(), std::string_view(bytes.constData(), bytes.size()));
    if (!problems.empty()) {
        std::fprintf(stderr, "camwright: %s: %s\n", qPrintable(file),
                     problems.front().message.c_str());
        return 2;
    }
    return 0;
}

}  // namespace

QImage renderScreenshot(MainWindow& window, const QSize& size) {
    window.resize(size);
    window.show();
    if (!waitUntilShown(window)) return {};
    if (window.shownResult()) window.setCursorTime(window.shownResult()->period / 8.0);
    window.statusBar()->clearMessage();  // transient messages name paths: not part of the picture
    // Twice: the stacked plots share one left margin, and each takes it from the others' last
    // layout (a slow build had the lift plot laid out before the others took theirs).
    for (int round = 0; round < 2; ++round) {
        for (int p = 0; p < KinematicsPlots::kPlotCount; ++p) {
            window.plots()->plot(p)->replot(QCustomPlot::rpImmediateRefresh);
        }
    }
    window.contourView()->replot(QCustomPlot::rpImmediateRefresh);
    QCoreApplication::processEvents();
    replotQueuedNow();  // the docks' plots: queued one per pass of the event loop
    return window.grab().toImage();
}

int writeScreenshot(MainWindow& window, const QString& file, const QString& sizeText) {
    int w = 1400, h = 860;
    if (!sizeText.isEmpty() && !parseSize(sizeText, 320, 240, w, h)) return 1;
    const QImage image = renderScreenshot(window, QSize(w, h));
    if (image.isNull()) {
        std::fprintf(stderr, "camwright: the computation did not finish within 20 s\n");
        return 3;
    }
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
        std::fprintf(stderr, "camwright: %s: cannot encode the PNG\n", qPrintable(file));
        return 2;
    }
    return writeBytes(file, png);
}

int writePlotPicture(MainWindow& window, const QString& plotName, const QString& formatName,
                     const QString& file, const QString& sizeText) {
    const std::optional<PlotKind> kind = plotKindNamed(plotName);
    if (!kind) {
        std::fprintf(stderr, "camwright: --export-plot: unknown plot '%s' (one of %s)\n",
                     qPrintable(plotName), qPrintable(plotKindNames()));
        return 1;
    }
    if (file.isEmpty()) {
        std::fprintf(stderr, "camwright: --export-plot: --out FILE is required\n");
        return 1;
    }
    const std::optional<PictureFormat> format =
        formatName.isEmpty() ? pictureFormatOfFile(file) : pictureFormatNamed(formatName);
    if (!format) {
        if (formatName.isEmpty()) {
            std::fprintf(stderr,
                         "camwright: %s: say --format png, pdf or svg (the file's suffix names "
                         "none of them)\n",
                         qPrintable(file));
        } else {
            std::fprintf(stderr,
                         "camwright: --format: unknown picture format '%s' (png, pdf, svg)\n",
                         qPrintable(formatName));
        }
        return 1;
    }
    QSize size = defaultPictureSize(*format);
    if (!sizeText.isEmpty()) {
        int w = 0, h = 0;
        if (!parseSize(sizeText, kMinPictureSide, kMinPictureSide, w, h)) return 1;
        size = QSize(w, h);
    }
    if (isMachiningPlot(*kind)) {
        if (!window.document()->project().machining) {
            std::fprintf(stderr,
                         "camwright: --export-plot %s: the project has no machining section\n",
                         qPrintable(plotName));
            return 3;
        }
        window.showMachiningPanel();
    }
    window.resize(1400, 860);
    window.show();
    if (!waitUntilShown(window)) {
        std::fprintf(stderr, "camwright: the computation did not finish within 20 s\n");
        return 3;
    }
    QString problem;
    const QByteArray bytes = window.plotPicture(*kind, *format, size, &problem);
    if (bytes.isEmpty()) {
        std::fprintf(stderr, "camwright: --export-plot %s: %s\n", qPrintable(plotName),
                     qPrintable(problem));
        return 3;
    }
    return writeBytes(file, bytes);
}

}  // namespace cam
