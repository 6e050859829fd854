#include "window/export_controller.h"

#include <qcustomplot.h>
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QtConcurrent/QtConcurrentRun>

#include "document/project_document.h"
#include "engine/background_priority.h"
#include "engine/compute_engine.h"
#include "export/export_dialog.h"
#include "export/export_formats.h"
#include "io/atomic_file.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/follower_panel.h"
#include "views/kinematics_plots.h"
#include "views/machining_panel.h"
#include "window/dock_layout.h"
#include "window/result_hub.h"

namespace cam {

namespace {

/// What a worker hands back: the bytes written, or the problem.
struct ExportOutcome {
    qint64 bytes = 0;
    QString problem;
};

QString problemText(const Diagnostics& problems) { return diagnosticsText(problems, 6); }

ExportOutcome writeExport(const QString& path, std::string_view content) {
    const Diagnostics problems =
        writeFileAtomically(QFile::encodeName(path).toStdString(), content);
    if (!problems.empty()) return {0, problemText(problems)};
    return {static_cast<qint64>(content.size()), {}};
}

}  // namespace

ExportController::ExportController(QMainWindow* window, Ui::MainWindow& ui,
                                   ProjectDocument* document, const ComputeEngine* engine,
                                   DockLayout& views, const ResultHub* results)
    : QObject(window),
      m_window(window),
      m_ui(ui),
      m_document(document),
      m_engine(engine),
      m_views(views),
      m_results(results) {
    auto* exportAction = new QAction(tr("E&xport…"), m_window);
    exportAction->setObjectName("actionExport");
    exportAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportAction->setToolTip(
        tr("Write the profile as CSV, DXF, SVG, G-code or a servo cam table, or a plot as a "
           "picture (Ctrl+E)"));
    m_ui.menuFile->insertAction(m_ui.actionQuit, exportAction);
    m_ui.menuFile->insertSeparator(m_ui.actionQuit);
    connect(exportAction, &QAction::triggered, this, [this] {
        ExportDialog dialog(m_document->project(), exportBaseName(), drawablePlots(), m_window,
                            m_document->filePath());
        if (dialog.exec() == QDialog::Accepted) exportFile(dialog.request());
    });
    for (PlotKind kind : kPlotKinds) {
        QCustomPlot* plot = plotWidget(kind);
        if (!plot) continue;  // the motion sheet: the kinematics plots offer it
        const bool stacked = kind == PlotKind::Lift || kind == PlotKind::Velocity ||
                             kind == PlotKind::Acceleration || kind == PlotKind::Jerk;
        plot->setContextMenuPolicy(Qt::CustomContextMenu);
        connect(plot, &QWidget::customContextMenuRequested, this,
                [this, kind, plot, stacked](QPoint at) {
                    QMenu menu(m_window);
                    QAction* a = menu.addAction(tr("Export Plot…"));
                    a->setObjectName("actionExportPlot");
                    connect(a, &QAction::triggered, this, [this, kind] { askExportPlot(kind); });
                    if (stacked) {
                        QAction* sheet =
                            menu.addAction(tr("Export Lift, Velocity, Acceleration "
                                              "and Jerk on One Sheet…"));
                        sheet->setObjectName("actionExportMotionSheet");
                        connect(sheet, &QAction::triggered, this,
                                [this] { askExportPlot(PlotKind::Motion); });
                    }
                    menu.exec(plot->mapToGlobal(at));
                });
    }
}

QString ExportController::exportTitle() const {
    return QString::fromStdString(
        exportName(m_document->project().name, exportBaseName().toStdString()));
}

QString ExportController::exportBaseName() const {
    const QString path = m_document->filePath();
    if (path.isEmpty()) return "untitled";
    QString name = QFileInfo(path).fileName();
    for (const QString& suffix : {QStringLiteral(".cam.json"), QStringLiteral(".json")}) {
        if (name.endsWith(suffix)) {
            name.chop(suffix.size());
            break;
        }
    }
    return name;
}

QCustomPlot* ExportController::plotWidget(PlotKind kind) const {
    switch (kind) {
        case PlotKind::Contour:
            return m_views.contour;
        case PlotKind::Velocity:
            return m_views.plots->plot(0);
        case PlotKind::Acceleration:
            return m_views.plots->plot(1);
        case PlotKind::Jerk:
            return m_views.plots->plot(2);
        case PlotKind::Feed:
            return m_views.machining->feedPlot();
        case PlotKind::AxisAcceleration:
            return m_views.machining->accelerationPlot();
        case PlotKind::PressureAngle:
            return m_views.follower->pressurePlot();
        case PlotKind::Lift:
            return m_views.plots->plot(KinematicsPlots::kLiftPlot);
        case PlotKind::Motion:
            return nullptr;  // four plots: see plotPicture()
    }
    return nullptr;
}

std::vector<PlotKind> ExportController::drawablePlots() const {
    std::vector<PlotKind> kinds;
    if (!m_results->shown()) return kinds;
    const bool machining = !m_ui.machiningDock->isHidden() &&
                           m_document->project().machining.has_value() &&
                           m_engine->latestTiming() != nullptr;
    for (PlotKind kind : kPlotKinds) {
        if (kind == PlotKind::PressureAngle) {
            if (m_results->shown()->follower) kinds.push_back(kind);
        } else if (!isMachiningPlot(kind) || machining) {
            kinds.push_back(kind);
        }
    }
    return kinds;
}

QByteArray ExportController::plotPicture(PlotKind kind, PictureFormat format, QSize size,
                                         QString* problem) {
    const std::vector<PlotKind> drawable = drawablePlots();
    if (std::find(drawable.begin(), drawable.end(), kind) == drawable.end()) {
        if (problem) {
            *problem = !m_results->shown() ? tr("Nothing has been computed yet.")
                       : kind == PlotKind::PressureAngle
                           ? tr("The project has no follower that rides its cam: there is no "
                                "pressure-angle plot.")
                       : !m_document->project().machining
                           ? tr("The project has no machining section: there is no %1 plot.")
                                 .arg(plotKindTitle(kind))
                           : tr("The %1 plot is drawn only while the Machining panel is open "
                                "(Ctrl+M).")
                                 .arg(plotKindTitle(kind));
        }
        return {};
    }
    PictureText text;
    // The lift plot shows the radius r in the polar view.
    text.title = tr("%1 — %2").arg(
        exportTitle(), kind == PlotKind::Lift ? m_views.plots->liftTitle() : plotKindTitle(kind));
    // The stacked plots share the bottom one's x axis label.
    if (kind == PlotKind::Velocity || kind == PlotKind::Acceleration || kind == PlotKind::Lift ||
        kind == PlotKind::Motion) {
        text.xLabel = m_views.plots->plot(2)->xAxis->label();
    }
    if (kind == PlotKind::Motion) {
        // The lift above velocity, acceleration and jerk, as the window stacks them.
        KinematicsPlots& plots = *m_views.plots;
        if (size.isEmpty()) size = plots.size();
        QByteArray bytes = renderPlotSheet(
            {plots.plot(KinematicsPlots::kLiftPlot), plots.plot(0), plots.plot(1), plots.plot(2)},
            {2, 3, 3, 3}, format, size, text);
        if (bytes.isEmpty() && problem) *problem = tr("The picture could not be drawn.");
        return bytes;
    }
    QCustomPlot* plot = plotWidget(kind);
    if (size.isEmpty()) size = plot->size();
    std::function<void()> fit;
    if (kind == PlotKind::Contour) {
        // The drag handles of the selected segment are for editing, not for the picture.
        m_views.contour->setSelectedSegment(-1);
        fit = [this] { m_views.contour->fitToViewport(); };
    }
    QByteArray bytes = renderPlotPicture(*plot, format, size, text, fit);
    if (kind == PlotKind::Contour)
        m_views.contour->setSelectedSegment(m_ui.segmentTable->currentIndex().row());
    if (bytes.isEmpty() && problem) *problem = tr("The picture could not be drawn.");
    return bytes;
}

void ExportController::askExportPlot(PlotKind kind) {
    QSettings settings;
    const QString folder = settings.value("export/folder", QDir::homePath()).toString();
    const QString suffix = settings.value("export/plotSuffix", "png").toString();
    const QString proposed =
        QDir(folder).filePath(exportBaseName() + "-" + plotKindName(kind) + "." + suffix);
    const QString png = tr("PNG image (*.png)"), pdf = tr("PDF document (*.pdf)"),
                  svg = tr("SVG drawing (*.svg)");
    QString selected = suffix == "pdf" ? pdf : suffix == "svg" ? svg : png;
    QString path = QFileDialog::getSaveFileName(m_window, tr("Export Plot"), proposed,
                                                png + ";;" + pdf + ";;" + svg, &selected);
    if (path.isEmpty()) return;
    std::optional<PictureFormat> format = pictureFormatOfFile(path);
    if (!format) {  // no or another suffix: the filter chosen says which
        format = selected == pdf   ? PictureFormat::Pdf
                 : selected == svg ? PictureFormat::Svg
                                   : PictureFormat::Png;
        path += "." + pictureSuffix(*format);
    }
    settings.setValue("export/folder", QFileInfo(path).absolutePath());
    settings.setValue("export/plotSuffix", pictureSuffix(*format));
    ExportRequest request;
    request.format = ExportFormat::Picture;
    request.plot = kind;
    request.picture = *format;
    request.path = path;
    // What is on screen, but room enough for the title and the numbers of both axes.
    const QWidget* shown =
        kind == PlotKind::Motion ? static_cast<QWidget*>(m_views.plots) : plotWidget(kind);
    request.pictureSize =
        shown->size().expandedTo(kind == PlotKind::Motion ? QSize(800, 900) : QSize(640, 400));
    exportFile(request);
}

void ExportController::exportFile(const ExportRequest& request) {
    const QString what = request.format == ExportFormat::Picture
                             ? tr("%1 plot").arg(plotKindTitle(request.plot))
                             : exportFormatTitle(request.format);
    if (request.format == ExportFormat::Picture) {
        QString problem;
        const QSize size = request.pictureSize.isEmpty() ? defaultPictureSize(request.picture)
                                                         : request.pictureSize;
        const QByteArray bytes = plotPicture(request.plot, request.picture, size, &problem);
        if (bytes.isEmpty()) {
            finishExport(request.path, what, 0, problem);
            return;
        }
        const ExportOutcome outcome =
            writeExport(request.path, std::string_view(bytes.constData(), bytes.size()));
        finishExport(request.path, what, outcome.bytes, outcome.problem);
        return;
    }
    // A design's cam table from its law needs no contour: a plain electronic cam.
    const bool fromTheLaw =
        request.format == ExportFormat::CamTable &&
        request.camTableSource.value_or(CamTableSource::Law) == CamTableSource::Law;
    if (m_document->awaitsSynthesis() && !fromTheLaw) {
        finishExport(request.path, what, 0,
                     tr("The project has no contour yet: Synthesize (F6) makes it from the "
                        "design."));
        return;
    }
    if (hasErrors(m_document->diagnostics())) {
        finishExport(request.path, what, 0,
                     tr("The project has problems; correct them first:\n%1")
                         .arg(problemText(m_document->diagnostics())));
        return;
    }
    m_window->statusBar()->showMessage(
        tr("Exporting %1 to %2…").arg(what, QDir::toNativeSeparators(request.path)));
    // The worker gets a copy of the project: edits meanwhile do not reach it.
    auto* watcher = new QFutureWatcher<ExportOutcome>(this);
    connect(watcher, &QFutureWatcher<ExportOutcome>::finished, this,
            [this, watcher, request, what] {
                const ExportOutcome outcome = watcher->result();
                watcher->deleteLater();
                finishExport(request.path, what, outcome.bytes, outcome.problem);
            });
    watcher->setFuture(QtConcurrent::run([project = m_document->project(), request] {
        runInTheBackground();
        const Result<std::string> text = exportText(project, request);
        if (!text.ok()) return ExportOutcome{0, problemText(text.errors())};
        return writeExport(request.path, text.value());
    }));
}

void ExportController::finishExport(const QString& path, const QString& what, qint64 bytes,
                                    const QString& problem) {
    const QString shown = QDir::toNativeSeparators(path);
    if (problem.isEmpty()) {
        m_window->statusBar()->showMessage(
            tr("Exported %1 to %2 (%3)").arg(what, shown, QLocale().formattedDataSize(bytes)),
            10000);
    } else {
        m_window->statusBar()->showMessage(tr("Export failed: %1").arg(shown), 10000);
        // Not modal for the event loop: the window stays live, tests can read and close it.
        auto* box =
            new QMessageBox(QMessageBox::Warning, tr("Export"),
                            tr("%1 was not written.").arg(shown), QMessageBox::Ok, m_window);
        box->setObjectName("exportProblemBox");
        box->setInformativeText(problem);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
    emit finished(path, problem);
}

}  // namespace cam
