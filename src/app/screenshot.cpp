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
#include "io/atomic_file.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"

namespace cam {

QImage renderScreenshot(MainWindow& window, const QSize& size) {
    window.resize(size);
    window.show();
    QCoreApplication::processEvents();
    if (!window.waitForCurrentResult(20000)) return {};
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
        if (!current()) loop.exec();
    }
    if (window.shownResult()) window.setCursorTime(window.shownResult()->period / 8.0);
    window.statusBar()->clearMessage();  // transient messages name paths: not part of the picture
    for (int p = 0; p < 3; ++p) window.plots()->plot(p)->replot(QCustomPlot::rpImmediateRefresh);
    window.contourView()->replot(QCustomPlot::rpImmediateRefresh);
    QCoreApplication::processEvents();
    return window.grab().toImage();
}

int writeScreenshot(MainWindow& window, const QString& file, const QString& sizeText) {
    int w = 1400, h = 860;
    if (!sizeText.isEmpty()) {
        const QStringList parts = sizeText.split('x');
        bool okW = false, okH = false;
        if (parts.size() == 2) {
            w = parts[0].toInt(&okW);
            h = parts[1].toInt(&okH);
        }
        if (!okW || !okH || w < 320 || h < 240 || w > 8000 || h > 8000) {
            std::fprintf(stderr,
                         "camwright: --size: expected WxH between 320x240 and 8000x8000 "
                         "(got \"%s\")\n",
                         qPrintable(sizeText));
            return 1;
        }
    }
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
    const Diagnostics problems = writeFileAtomically(QFile::encodeName(file).toStdString(),
                                                     std::string_view(png.constData(), png.size()));
    if (!problems.empty()) {
        std::fprintf(stderr, "camwright: %s: %s\n", qPrintable(file),
                     problems.front().message.c_str());
        return 2;
    }
    return 0;
}

}  // namespace cam
