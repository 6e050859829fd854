#include "mainwindow.h"

#include <QCloseEvent>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>

#include "common/angles.h"
#include "document/contour_edits.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "files/project_files.h"
#include "files/recovery_prompt.h"
#include "models/segment_table_model.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/follower_panel.h"
#include "views/forces_panel.h"
#include "views/joints_panel.h"
#include "views/kinematics_plots.h"
#include "views/machining_panel.h"
#include "views/motion_design_panel.h"
#include "views/path_study_panel.h"
#include "views/plot_data.h"
#include "views/state_readout.h"
#include "widgets/quantity_format.h"
#include "window/cursor_actions.h"
#include "window/cursor_model.h"
#include "window/dock_layout.h"
#include "window/export_controller.h"
#include "window/play_controller.h"
#include "window/result_hub.h"
#include "window/status_labels.h"
#include "window/synthesis_controller.h"
#include "window/window_actions.h"

namespace cam {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_ui(std::make_unique<Ui::MainWindow>()),
      m_document(new ProjectDocument(this)),
      m_model(new SegmentTableModel(m_document, this)),
      m_engine(new ComputeEngine(this)) {
    m_ui->setupUi(this);
    setAcceptDrops(true);
    const auto say = [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); };

    m_files = new ProjectFiles(m_document, this, m_ui->menuRecent, m_ui->menuExamples);
    connect(m_files, &ProjectFiles::message, this, say);
    m_autosave = new Autosave(m_document, {}, this);
    connect(m_autosave, &Autosave::written, this, [this](const QString&, const QString& problem) {
        if (!problem.isEmpty()) {
            statusBar()->showMessage(tr("The recovery copy could not be written: %1").arg(problem),
                                     8000);
        }
    });
    m_recovery = new RecoveryPrompt(m_autosave, this);
    connect(m_recovery, &RecoveryPrompt::message, this, say);

    // The views and docks, then the actions in the order of the menus and the tool bar.
    m_views = new DockLayout(this, *m_ui, m_document, m_model);
    m_results = new ResultHub(m_engine, this);
    m_cursor = new CursorModel(m_results, m_engine, this);
    m_labels = new StatusLabels(statusBar(), m_document, m_engine);
    m_actions = new WindowActions(this, *m_ui, m_document, m_files, *m_views);
    connect(m_actions, &WindowActions::viewChanged, this, &MainWindow::requestCompute);
    m_exports = new ExportController(this, *m_ui, m_document, m_engine, *m_views, m_results);
    connect(m_exports, &ExportController::finished, this, &MainWindow::exportFinished);
    m_play = new PlayController(m_cursor, this);
    m_ui->mainToolBar->addSeparator();
    m_ui->mainToolBar->addAction(m_play->action());
    m_ui->mainToolBar->addWidget(m_play->speedBox());
    m_ui->menuView->addSeparator();
    m_ui->menuView->addAction(m_play->action());
    m_ui->menuView->addAction(m_play->turnCamAction());
    connect(m_play, &PlayController::turningChanged, m_views->contour, &ContourView::setTurning);
    new CursorActions(m_cursor, centralWidget(), m_ui->menuView);
    m_ui->mainToolBar->addAction(m_views->designDock->toggleViewAction());
    m_ui->menuView->addAction(m_views->designDock->toggleViewAction());
    m_synthesis = new SynthesisController(m_document, m_views->design, this);
    m_ui->menuEdit->addSeparator();
    m_ui->menuEdit->addAction(m_synthesis->action());
    connect(m_synthesis, &SynthesisController::message, this, say);
    connect(m_synthesis, &SynthesisController::finished, this, &MainWindow::synthesisFinished);
    m_actions->setUpIcons();

    connect(m_document, &ProjectDocument::changed, this, [this] {
        requestCompute();
        m_labels->showValidation();
    });
    connect(m_document, &ProjectDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ProjectDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_views->machining, &MachiningPanel::plotMethodChanged, this,
            &MainWindow::requestCompute);
    connect(m_ui->machiningDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && !m_engine->latestTiming()) requestCompute();
    });
    // The views' containers are made in the worker, next to the computation.
    m_engine->setPlotDataPreparer(std::make_shared<QcpPlotDataPreparer>());
    connect(m_engine, &ComputeEngine::timingReady, m_views->machining, &MachiningPanel::setOutcome);
    wireResults();
    wireCursor();

    m_views->restore();
    m_ui->actionAxisTime->setChecked(QSettings().value("view/timeAxis", false).toBool());
    m_document->reset(ContourEdits::newProject(), {});
}

MainWindow::~MainWindow() = default;

void MainWindow::wireResults() {
    DockLayout& v = *m_views;
    // The plots first, and the follower's pressure angle, which shares their axis (and zoom).
    connect(m_results, &ResultHub::arrived, this, [this, &v](const ComputeResultPtr& result) {
        m_labels->arrived();
        v.plots->setResult(result);
        v.follower->setResult(result);
        v.forces->setResult(result);
        for (QCustomPlot* plot : v.turnPlots()) {
            plot->xAxis->setRange(v.plots->plot(0)->xAxis->range());
        }
        if (result->sampleCount > 0) {
            const auto n = static_cast<double>(result->sampleCount);
            v.readout->setSteps(result->period / n, 360.0 / n);
        }
    });
    connect(m_results, &ResultHub::refined, this,
            [&v](const ComputeResultPtr& result, bool checks) {
                v.plots->setResult(result);
                if (checks) v.follower->showChecks(result);
                // A conjugate pair's second plate is fitted with the checks: draw it now.
                if (checks && result->conjugate) v.contour->setResult(result);
            });
    // Then the views beside the plots: the contour, the Joints tab, the path study, the design.
    const auto beside = [&v](const ComputeResultPtr& result) {
        v.contour->setResult(result);
        v.joints->setResult(result);
        v.pathStudy->setResult(result);
        v.design->setResult(result);
    };
    connect(m_results, &ResultHub::uncomputed, this, [this, beside](const ComputeResultPtr& r) {
        beside(r);
        m_labels->showUncomputed(*r);
        m_views->readout->clear();  // no state of the project as it is
    });
    connect(m_results, &ResultHub::settled, this, [this, beside](const ComputeResultPtr& r) {
        beside(r);
        m_labels->showComputed(*r);
        m_cursor->refresh();
    });
    connect(m_results, &ResultHub::handed, this, &MainWindow::resultShown);
}

void MainWindow::wireCursor() {
    DockLayout& v = *m_views;
    connect(m_cursor, &CursorModel::cleared, v.readout, &StateReadout::clear);
    connect(m_cursor, &CursorModel::moved, this, [this, &v](const KinematicState& s, double x) {
        // The state the plots show: the follower's (one evaluation of the result's follower,
        // a few hundred nanoseconds), or the polar state along the ray.
        const ComputeResultPtr& r = m_results->shown();
        const auto spans = [](const std::array<PlotRange, 4>& ranges) {
            std::array<double, 4> out{};
            for (std::size_t i = 0; i < 4; ++i) {
                out[i] = std::max(std::abs(ranges[i].lower), std::abs(ranges[i].upper));
            }
            return out;
        };
        std::optional<FollowerState> follower;
        if (r && r->follower) follower = r->follower->at(s.phi, r->omega);
        if (follower && v.plots->showsFollower()) {
            v.readout->setFollowerState(s, *follower, r->follower->liftMotion(*follower),
                                        r->follower->oscillating(), spans(r->followerMotionRanges));
        } else {
            v.readout->setState(s, r ? spans(r->curves.yRanges) : std::array<double, 4>{});
        }
        // The forces there, from the same state.
        if (r && r->forces && follower) {
            const ForceModel& model = r->forces->model;
            v.readout->setForces(forceAt(model, forceMotion(*r->follower, *follower), r->omega),
                                 model.swinging);
        } else {
            v.readout->setForces(std::nullopt, false);
        }
        v.contour->setCursorAngle(s.phi);
        v.plots->setCursorX(x);
        v.follower->setCursorX(x);
        v.forces->setCursorX(x);
        v.design->setCursorX(x);
    });
    // Whoever points at an instant moves the cursor: the mouse, a typed time or angle, a key.
    connect(v.contour, &ContourView::cursorAngleChanged, m_cursor, &CursorModel::setAtAngle);
    connect(v.readout, &StateReadout::timeTyped, m_cursor, &CursorModel::setTime);
    connect(v.readout, &StateReadout::angleTyped, m_cursor,
            [this](double degrees) { m_cursor->setAtAngle(degToRad(degrees)); });
    connect(v.plots, &KinematicsPlots::cursorMoved, m_cursor, &CursorModel::setAtPlotX);
    connect(v.plots, &KinematicsPlots::followerShownChanged, m_cursor, &CursorModel::refresh);
    for (QCustomPlot* plot : v.turnPlots()) {
        connect(plot, &QCustomPlot::mouseMove, this, [this, plot](QMouseEvent* e) {
            m_cursor->setAtPlotX(plot->xAxis->pixelToCoord(e->position().x()));
        });
    }
    connect(v.joints, &JointsPanel::jointPicked, this, [this](int, int right, double phi) {
        if (!m_results->shown()) return;
        m_cursor->setAtAngle(phi);
        m_ui->segmentTable->selectRow(right);
    });
    const auto goTo = [this](double phi) {
        if (!m_results->shown()) return;
        m_cursor->setAtAngle(phi);
        statusBar()->showMessage(
            tr("Cursor at %1").arg(formatQuantity(DisplayQuantity::Angle, radToDeg(phi))), 4000);
    };
    connect(v.follower, &FollowerPanel::anglePicked, this, goTo);
    connect(v.forces, &ForcesPanel::anglePicked, this, goTo);
}

void MainWindow::requestCompute() {
    // The machining times are computed only while their panel is open.
    const bool timing = !m_ui->machiningDock->isHidden();
    if (timing) m_views->machining->setPending();
    m_engine->request(m_document->project(),
                      m_ui->actionAxisTime->isChecked() ? PlotAxis::Time : PlotAxis::Angle, timing,
                      m_views->machining->plotMethod());
    m_labels->computing();
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — Camwright").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    m_views->save();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().toLocalFile().endsWith(".json")) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    m_files->open(event->mimeData()->urls().front().toLocalFile());
}

// What the tests and the command line drive: each hands over to the part that does it.

QString MainWindow::loadFile(const QString& path) { return m_files->load(path); }
QString MainWindow::saveFile(const QString& path) { return m_files->save(path); }
void MainWindow::renameProject(const QString& name) { m_actions->renameProject(name); }
QString MainWindow::aboutText() const { return m_actions->aboutText(); }
bool MainWindow::offerRecovery() { return m_recovery->offer(); }
bool MainWindow::restoreRecovery(const Autosave::Orphan& orphan) {
    return m_recovery->restore(orphan);
}
bool MainWindow::synthesize() { return m_synthesis->start(); }
void MainWindow::cancelSynthesis() { m_synthesis->cancel(); }
void MainWindow::setCursorTime(double t) { m_cursor->setTime(t); }
void MainWindow::setCursorAtPlotX(double x) { m_cursor->setAtPlotX(x); }
bool MainWindow::waitForCurrentResult(int timeoutMs) {
    return m_results->waitForCurrent(timeoutMs);
}
const ComputeResultPtr& MainWindow::shownResult() const { return m_results->shown(); }
double MainWindow::cursorTime() const { return m_cursor->time(); }
QAction* MainWindow::playAction() const { return m_play->action(); }
double MainWindow::playSpeedFactor() const { return m_play->speedFactor(); }
QAction* MainWindow::synthesizeAction() const { return m_synthesis->action(); }
UserGuide* MainWindow::userGuide() const { return m_actions->userGuide(); }
KinematicsPlots* MainWindow::plots() const { return m_views->plots; }
ContourView* MainWindow::contourView() const { return m_views->contour; }
StateReadout* MainWindow::readout() const { return m_views->readout; }
FollowerPanel* MainWindow::followerPanel() const { return m_views->follower; }
ForcesPanel* MainWindow::forcesPanel() const { return m_views->forces; }
ControlPointsPanel* MainWindow::controlPointsPanel() const { return m_views->controlPoints; }
MachiningPanel* MainWindow::machiningPanel() const { return m_views->machining; }
JointsPanel* MainWindow::jointsPanel() const { return m_views->joints; }
PathStudyPanel* MainWindow::pathStudyPanel() const { return m_views->pathStudy; }
MotionDesignPanel* MainWindow::motionDesignPanel() const { return m_views->design; }

void MainWindow::showMachiningPanel() { m_ui->machiningDock->show(); }
QCustomPlot* MainWindow::plotWidget(PlotKind kind) const { return m_exports->plotWidget(kind); }
std::vector<PlotKind> MainWindow::drawablePlots() const { return m_exports->drawablePlots(); }
QByteArray MainWindow::plotPicture(PlotKind kind, PictureFormat format, QSize size,
                                   QString* problem) {
    return m_exports->plotPicture(kind, format, size, problem);
}
void MainWindow::exportFile(const ExportRequest& request) { m_exports->exportFile(request); }

QString MainWindow::contourThroughPoints(const QString& pointsText, int rule, double bulge) {
    const EditOutcome outcome = ContourEdits::contourThroughPoints(
        *m_document, pointsText, static_cast<HandleRule>(rule), bulge);
    m_actions->report(outcome);
    return outcome.problem;
}

QString MainWindow::roundCorner(int joint, double rho) {
    const EditOutcome outcome = ContourEdits::roundCorner(*m_document, joint, rho);
    m_actions->report(outcome);
    return outcome.problem;
}

QString MainWindow::approximateArc(int row, double maxErrorMm) {
    const EditOutcome outcome = ContourEdits::approximateArc(*m_document, row, maxErrorMm);
    m_actions->report(outcome);
    return outcome.problem;
}

}  // namespace cam
