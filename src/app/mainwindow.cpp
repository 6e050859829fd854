#include "mainwindow.h"

#include <qcustomplot.h>
#include <Eigen/Core>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QWhatsThis>
#include <cmath>
#include <utility>

#include "common/angles.h"
#include "dialogs/contour_dialogs.h"
#include "dialogs/shortcuts_dialog.h"
#include "dialogs/user_guide.h"
#include "document/commands.h"
#include "document/contour_edits.h"
#include "engine/compute_engine.h"
#include "engine/synthesis_runner.h"
#include "files/autosave.h"
#include "files/project_files.h"
#include "fillet/fillet.h"
#include "io/project_json.h"
#include "messages/diagnostic_text.h"
#include "models/delegates.h"
#include "models/segment_table_model.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/control_points_panel.h"
#include "views/follower_panel.h"
#include "views/joints_panel.h"
#include "views/kinematics_plots.h"
#include "views/machining_panel.h"
#include "views/motion_design_panel.h"
#include "views/motion_panel.h"
#include "views/path_study_panel.h"
#include "views/plot_data.h"
#include "views/plot_redraw.h"
#include "views/state_readout.h"
#include "widgets/column_fit.h"
#include "widgets/icons.h"
#include "widgets/quantity_format.h"

namespace cam {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_ui(std::make_unique<Ui::MainWindow>()),
      m_document(new ProjectDocument(this)),
      m_model(new SegmentTableModel(m_document, this)),
      m_engine(new ComputeEngine(this)) {
    m_ui->setupUi(this);
    setAcceptDrops(true);

    m_contour = new ContourView(m_document, this);
    m_plots = new KinematicsPlots(this);
    m_plots->setObjectName("kinematicsPlots");
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setObjectName("mainSplitter");
    splitter->addWidget(m_contour);
    splitter->addWidget(m_plots);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({400, 600});  // 2 : 3 from the start, not from the size hints
    setCentralWidget(splitter);

    m_files = new ProjectFiles(m_document, this, m_ui->menuRecent, m_ui->menuExamples);
    m_autosave = new Autosave(m_document, {}, this);
    connect(m_autosave, &Autosave::written, this, [this](const QString&, const QString& problem) {
        if (!problem.isEmpty()) {
            statusBar()->showMessage(tr("The recovery copy could not be written: %1").arg(problem),
                                     8000);
        }
    });
    connect(m_files, &ProjectFiles::message, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    setUpDocks();
    setUpActions();
    setUpExports();
    setUpPlay();
    setUpDesign();
    setUpIcons();

    m_validationLabel = new QLabel(this);
    m_validationLabel->setObjectName("validationLabel");
    m_computeLabel = new QLabel(this);
    m_computeLabel->setObjectName("computeLabel");
    // Permanent widgets: transient messages ("Saved …") appear beside them, never over them.
    statusBar()->addPermanentWidget(m_validationLabel);
    statusBar()->addPermanentWidget(m_computeLabel);
    m_busyTimer = new QTimer(this);
    m_busyTimer->setSingleShot(true);
    m_busyTimer->setInterval(400);
    connect(m_busyTimer, &QTimer::timeout, this, [this] {
        const ComputeResultPtr& latest = m_engine->latestResult();
        if (latest && latest->generation == m_engine->latestGeneration()) return;
        m_computeLabel->setStyleSheet({});
        m_computeLabel->setText(tr("computing…"));
    });

    connect(m_document, &ProjectDocument::changed, this, [this] {
        requestCompute();
        updateStatus();
    });
    connect(m_document, &ProjectDocument::modifiedChanged, this, &MainWindow::updateTitle);
    // A project that names its follower opens with the follower shown.
    connect(m_document, &ProjectDocument::contourReset, this, [this] {
        if (m_document->project().follower) m_followerDock->show();
        // Once the layout has settled: a short contour leaves the plots the rows it needs not.
        QTimer::singleShot(0, this, &MainWindow::fitSegmentsDock);
    });
    // A project with a design opens with it shown.
    connect(m_document, &ProjectDocument::filePathChanged, this, [this] {
        if (!m_document->project().design) return;
        m_designDock->show();
        // In front of the follower's tab, once the follower dock has been shown too, and wide
        // enough for the segment table.
        QTimer::singleShot(0, this, [this] {
            m_designDock->raise();
            if (m_designDock->width() < 400 && !m_designDock->isFloating()) {
                resizeDocks({m_designDock}, {400}, Qt::Horizontal);
            }
        });
    });
    connect(m_document, &ProjectDocument::filePathChanged, this, &MainWindow::updateTitle);
    // The views' containers are made in the worker, next to the computation.
    m_engine->setPlotDataPreparer(std::make_shared<QcpPlotDataPreparer>());
    connect(m_engine, &ComputeEngine::resultReady, this, &MainWindow::showResult);
    connect(m_engine, &ComputeEngine::timingReady, m_machining, &MachiningPanel::setOutcome);
    connect(m_contour, &ContourView::cursorAngleChanged, this, [this](double phi) {
        const auto& r = m_shown;
        if (!r) return;
        setCursorTime(phi / r->omega);  // the instant the ray points there (reduced below)
    });
    connect(m_plots, &KinematicsPlots::cursorMoved, this, &MainWindow::setCursorAtPlotX);

    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    m_ui->machiningDock->hide();  // until the user opens it (the saved layout may show it)
    m_ui->pathStudyDock->hide();
    m_followerDock->hide();  // until opened, or a project with a follower is loaded
    m_designDock->hide();    // until opened, or a project with a design is loaded
    // The right-hand docks are tabs of one group (tabified while hidden: tabified while shown,
    // two made the hidden window grow to the height of both). Stacked, Machining, Path Study
    // and Follower together asked for more height than the screen has, and the window grew
    // past its bottom edge. Opening one brings its tab to the front.
    tabifyDockWidget(m_followerDock, m_designDock);
    tabifyDockWidget(m_designDock, m_ui->machiningDock);
    tabifyDockWidget(m_ui->machiningDock, m_ui->pathStudyDock);
    for (QDockWidget* dock :
         {m_followerDock, m_designDock, m_ui->machiningDock, m_ui->pathStudyDock}) {
        connect(dock->toggleViewAction(), &QAction::toggled, dock, [dock](bool on) {
            if (on) QTimer::singleShot(0, dock, [dock] { dock->raise(); });
        });
    }
    restoreState(settings.value("window/state").toByteArray());
    m_ui->actionAxisTime->setChecked(settings.value("view/timeAxis", false).toBool());
    m_document->reset(ContourEdits::newProject(), {});
}

MainWindow::~MainWindow() = default;

void MainWindow::setUpPlay() {
    m_playAction = new QAction(tr("Play"), this);
    m_playAction->setObjectName("actionPlay");
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_playAction->setToolTip(tr("Turn the cam with the follower riding it (F5)"));
    m_playSpeed = new QComboBox(this);
    m_playSpeed->setObjectName("playSpeedComboBox");
    m_playSpeed->setToolTip(tr("Play at this fraction of the cam's real speed"));
    for (double factor : {0.01, 0.05, 0.1, 0.25, 0.5, 1.0}) {
        m_playSpeed->addItem(formatQuantity(DisplayQuantity::Ratio, factor) + QStringLiteral("×"),
                             factor);
    }
    QSettings settings;
    const int index = m_playSpeed->findData(settings.value("view/playSpeed", 0.05).toDouble());
    m_playSpeed->setCurrentIndex(index >= 0 ? index : 1);
    connect(m_playSpeed, &QComboBox::currentIndexChanged, this,
            [this] { QSettings().setValue("view/playSpeed", playSpeedFactor()); });
    m_ui->mainToolBar->addSeparator();
    m_ui->mainToolBar->addAction(m_playAction);
    m_ui->mainToolBar->addWidget(m_playSpeed);
    m_ui->menuView->addSeparator();
    m_ui->menuView->addAction(m_playAction);
    m_playTimer = new QTimer(this);
    m_playTimer->setInterval(16);  // about 60 frames a second
    connect(m_playTimer, &QTimer::timeout, this, [this] {
        const double elapsed = static_cast<double>(m_playClock.nsecsElapsed()) / 1e9;
        m_playClock.restart();
        // The cursor's time runs at the chosen fraction of real time; a frame only moves the
        // markers (one state and one follower position at the cursor).
        setCursorTime(m_cursorT + elapsed * playSpeedFactor());
    });
    connect(m_playAction, &QAction::toggled, this, [this](bool on) {
        m_playAction->setText(on ? tr("Pause") : tr("Play"));
        if (on) {
            m_playClock.start();
            m_playTimer->start();
        } else {
            m_playTimer->stop();
        }
    });
}

void MainWindow::setUpDesign() {
    m_designDock = new QDockWidget(tr("Motion Design"), this);
    m_designDock->setObjectName("motionDesignDock");
    m_design = new MotionDesignPanel(m_document, m_designDock);
    m_design->setObjectName("motionDesignPanel");
    // The dock scrolls rather than making the window taller than a small screen.
    auto* scroll = new QScrollArea(m_designDock);
    scroll->setObjectName("motionDesignScrollArea");
    scroll->setWidget(m_design);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    m_designDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_designDock);
    QAction* toggle = m_designDock->toggleViewAction();
    toggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    toggle->setToolTip(tr("Design the contour from the follower's motion (Ctrl+D)"));
    m_ui->mainToolBar->addAction(toggle);
    m_ui->menuView->addAction(toggle);

    m_synthesizeAction = new QAction(tr("S&ynthesize Contour"), this);
    m_synthesizeAction->setObjectName("actionSynthesize");
    m_synthesizeAction->setShortcut(QKeySequence(Qt::Key_F6));
    m_synthesizeAction->setToolTip(
        tr("Replace the contour by tangent arcs fitted to the design's exact profile within "
           "its tolerance (F6; one undo step)"));
    m_ui->menuEdit->addSeparator();
    m_ui->menuEdit->addAction(m_synthesizeAction);
    m_design->setSynthesizeAction(m_synthesizeAction);
    const auto enable = [this] {
        m_synthesizeAction->setEnabled(m_document->project().design.has_value() &&
                                       !m_synthesis->isRunning());
    };
    m_synthesis = new SynthesisRunner(this);
    connect(m_document, &ProjectDocument::designChanged, this, enable);
    connect(m_synthesizeAction, &QAction::triggered, this, [this] {
        m_synthesisInteractive = true;
        synthesize();
    });
    connect(m_synthesis, &SynthesisRunner::finished, this, &MainWindow::finishSynthesis);
    connect(m_synthesis, &SynthesisRunner::finished, this, enable);
    enable();
    setUpWhatsThis();
}

bool MainWindow::synthesize() {
    const auto& design = m_document->project().design;
    if (!design || m_synthesis->isRunning()) return false;
    m_synthesisClock.start();
    m_synthesis->start(m_document->project(), design->tolerance);
    m_synthesizeAction->setEnabled(false);
    statusBar()->showMessage(tr("Synthesizing the contour…"));
    // Most designs take milliseconds; a fine tolerance or a swinging arm may take longer, and
    // then a busy dialog offers Cancel.
    m_synthesisProgress = new QProgressDialog(tr("Synthesizing the contour from the design…"),
                                              tr("Cancel"), 0, 0, this);
    m_synthesisProgress->setObjectName("synthesisProgress");
    m_synthesisProgress->setWindowTitle(tr("Synthesize"));
    m_synthesisProgress->setWindowModality(Qt::WindowModal);
    m_synthesisProgress->setMinimumDuration(300);
    m_synthesisProgress->setAutoClose(false);
    m_synthesisProgress->setAutoReset(false);
    connect(m_synthesisProgress, &QProgressDialog::canceled, this, &MainWindow::cancelSynthesis);
    m_synthesisProgress->setValue(0);
    return true;
}

void MainWindow::cancelSynthesis() { m_synthesis->cancel(); }

void MainWindow::finishSynthesis(const std::shared_ptr<const Result<Synthesis>>& result,
                                 bool cancelled) {
    const bool interactive = std::exchange(m_synthesisInteractive, false);
    if (m_synthesisProgress) {
        m_synthesisProgress->disconnect(this);
        m_synthesisProgress->reset();
        m_synthesisProgress->deleteLater();
        m_synthesisProgress = nullptr;
    }
    QString problem;
    const Project& from = m_synthesis->startedFrom();
    const Project& now = m_document->project();
    if (cancelled) {
        problem = tr("Synthesis cancelled: the contour is unchanged.");
    } else if (from.design != now.design || from.follower != now.follower ||
               from.motion != now.motion) {
        // Made for a design that is no longer the project's: never applied.
        problem =
            tr("The design, follower or speed changed while synthesizing: press "
               "Synthesize again.");
    } else if (!result->ok()) {
        problem = tr("The contour cannot be made from this design:\n%1")
                      .arg(diagnosticsText(result->errors()));
    }
    if (!problem.isEmpty()) {
        statusBar()->showMessage(problem.section('\n', 0, 0), 8000);
        if (interactive && !cancelled) QMessageBox::warning(this, tr("Synthesize"), problem);
        emit synthesisFinished(problem);
        return;
    }
    const Synthesis& made = result->value();
    const bool swinging = now.follower && now.follower->motion == FollowerMotion::Oscillating;
    m_design->setReport(made.report, swinging);
    if (made.contour == now.contour) {
        // The same arcs again: nothing to undo.
        statusBar()->showMessage(tr("Synthesized: the contour already is this design's."), 6000);
        emit synthesisFinished({});
        return;
    }
    m_document->undoStack()->push(
        new SynthesizeContour(m_document, made.contour, from.design->tolerance));
    statusBar()->showMessage(
        tr("Synthesized %n segment(s) within %1 in %2", nullptr,
           static_cast<int>(made.report.segments))
            .arg(formatQuantity(DisplayQuantity::LengthError, made.report.maxDeviationMm),
                 formatQuantity(DisplayQuantity::Duration,
                                static_cast<double>(m_synthesisClock.nsecsElapsed()) / 1e6)),
        8000);
    emit synthesisFinished({});
}

double MainWindow::playSpeedFactor() const { return m_playSpeed->currentData().toDouble(); }

void MainWindow::setUpDocks() {
    QTableView* table = m_ui->segmentTable;
    table->setModel(m_model);
    auto* numbers = new NumberDelegate(table);
    auto* choices = new ChoiceDelegate(table);
    for (int c = 0; c < SegmentTableModel::ColumnCount; ++c) {
        const bool choice = c == SegmentTableModel::Type || c == SegmentTableModel::Branch;
        table->setItemDelegateForColumn(
            c, choice ? static_cast<QAbstractItemDelegate*>(choices) : numbers);
    }
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    keepColumnsFitting(table);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::AnyKeyPressed);
    // A spline's control points by value, tabbed with the table and the joints.
    m_controlPointsDock = new QDockWidget(tr("Control Points"), this);
    m_controlPointsDock->setObjectName("controlPointsDock");
    m_controlPoints = new ControlPointsPanel(m_document, m_controlPointsDock);
    m_controlPoints->setObjectName("controlPointsPanel");
    m_controlPointsDock->setWidget(m_controlPoints);
    addDockWidget(Qt::BottomDockWidgetArea, m_controlPointsDock);
    connect(table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                m_contour->setSelectedSegment(current.row());
                m_controlPoints->setRow(current.row());
            });

    m_motion = new MotionPanel(m_document, m_ui->motionDock);
    m_ui->motionDock->setWidget(m_motion);
    m_readout = new StateReadout(m_ui->readoutDock);
    m_ui->readoutDock->setWidget(m_readout);
    splitDockWidget(m_ui->motionDock, m_ui->readoutDock, Qt::Vertical);
    m_joints = new JointsPanel(m_ui->jointsDock);
    m_ui->jointsDock->setWidget(m_joints);
    tabifyDockWidget(m_ui->segmentsDock, m_ui->jointsDock);
    tabifyDockWidget(m_ui->jointsDock, m_controlPointsDock);
    m_ui->segmentsDock->raise();
    connect(m_joints, &JointsPanel::jointPicked, this, [this](int, int right, double phi) {
        if (!m_shown) return;
        setCursorTime(phi / m_shown->omega);
        m_ui->segmentTable->selectRow(right);
    });
    m_pathStudy = new PathStudyPanel(m_ui->pathStudyDock);
    m_ui->pathStudyDock->setWidget(m_pathStudy);
    m_ui->pathStudyDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    m_machining = new MachiningPanel(m_document, m_ui->machiningDock);
    m_ui->machiningDock->setWidget(m_machining);
    QAction* machining = m_ui->machiningDock->toggleViewAction();
    machining->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    machining->setToolTip(tr("Machining limits and times (Ctrl+M)"));
    m_ui->mainToolBar->addSeparator();
    m_ui->mainToolBar->addAction(machining);
    connect(m_machining, &MachiningPanel::plotMethodChanged, this, &MainWindow::requestCompute);
    connect(m_ui->machiningDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && !m_engine->latestTiming()) requestCompute();
    });
    // The follower and its design checks, tabbed with the machining dock.
    m_followerDock = new QDockWidget(tr("Follower"), this);
    m_followerDock->setObjectName("followerDock");
    m_follower = new FollowerPanel(m_document, m_followerDock);
    m_follower->setObjectName("followerPanel");
    m_followerDock->setWidget(m_follower);
    addDockWidget(Qt::RightDockWidgetArea, m_followerDock);
    QAction* follower = m_followerDock->toggleViewAction();
    follower->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    follower->setToolTip(tr("The follower and its design checks (Ctrl+L)"));
    m_ui->mainToolBar->addAction(follower);
    connect(m_follower, &FollowerPanel::anglePicked, this, [this](double phi) {
        if (!m_shown) return;
        setCursorTime(phi / m_shown->omega);
        statusBar()->showMessage(
            tr("Cursor at %1").arg(formatQuantity(DisplayQuantity::Angle, radToDeg(phi))), 4000);
    });
    // The pressure-angle plot shares the kinematics plots' x axis: panning or zooming either
    // moves the other.
    QCustomPlot* pressure = m_follower->pressurePlot();
    QCustomPlot* velocity = m_plots->plot(0);
    connect(velocity->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), pressure,
            [pressure](const QCPRange& r) {
                if (pressure->xAxis->range() == r) return;
                pressure->xAxis->setRange(r);
                queueReplot(pressure);
            });
    connect(pressure->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), velocity,
            [velocity](const QCPRange& r) {
                if (velocity->xAxis->range() != r) velocity->xAxis->setRange(r);
            });
    connect(pressure, &QCustomPlot::mouseMove, this, [this, pressure](QMouseEvent* e) {
        setCursorAtPlotX(pressure->xAxis->pixelToCoord(e->position().x()));
    });
    resizeDocks({m_ui->motionDock, m_ui->readoutDock}, {140, 400}, Qt::Vertical);
    for (QDockWidget* dock :
         {m_ui->segmentsDock, m_ui->jointsDock, m_controlPointsDock, m_ui->motionDock,
          m_ui->readoutDock, m_ui->machiningDock, m_ui->pathStudyDock, m_followerDock}) {
        m_ui->menuView->addAction(dock->toggleViewAction());
    }
}

void MainWindow::setUpActions() {
    QUndoStack* stack = m_document->undoStack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setObjectName("actionUndo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setObjectName("actionRedo");
    redo->setShortcut(QKeySequence::Redo);
    QAction* first = m_ui->menuEdit->actions().value(0);
    m_ui->menuEdit->insertAction(first, undo);
    m_ui->menuEdit->insertAction(first, redo);
    m_ui->menuEdit->insertSeparator(first);

    connect(m_ui->actionNew, &QAction::triggered, this, [this] {
        if (m_files->maybeSave()) m_document->reset(ContourEdits::newProject(), {});
    });
    connect(m_ui->actionClose, &QAction::triggered, this, [this] {
        const QString name = m_document->displayName();
        if (!m_files->maybeSave()) return;
        m_document->reset(ContourEdits::newProject(), {});
        statusBar()->showMessage(tr("Closed %1").arg(name), 4000);
    });
    connect(m_ui->actionRenameProject, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(
            this, tr("Project Name"), tr("Name of the project:"), QLineEdit::Normal,
            QString::fromStdString(m_document->project().name), &ok);
        if (ok) renameProject(name);
    });
    connect(m_ui->actionOpen, &QAction::triggered, this, [this] { m_files->open(); });
    connect(m_ui->actionSave, &QAction::triggered, this, [this] { m_files->save(); });
    connect(m_ui->actionSaveAs, &QAction::triggered, this, [this] { m_files->saveAs(); });
    connect(m_ui->actionQuit, &QAction::triggered, this, &QWidget::close);
    connect(m_ui->actionInsertSegment, &QAction::triggered, this,
            [this] { report(ContourEdits::insertSegment(*m_document, selectedRow())); });
    connect(m_ui->actionDeleteSegment, &QAction::triggered, this,
            [this] { report(ContourEdits::deleteSegment(*m_document, selectedRow()), {}); });
    connect(m_ui->actionMoveUp, &QAction::triggered, this,
            [this] { report(ContourEdits::moveSegment(*m_document, selectedRow(), -1), {}); });
    connect(m_ui->actionMoveDown, &QAction::triggered, this,
            [this] { report(ContourEdits::moveSegment(*m_document, selectedRow(), 1), {}); });
    connect(m_ui->actionFitWindows, &QAction::triggered, this,
            [this] { report(ContourEdits::fitWindows(*m_document), tr("Fit Windows")); });
    auto* approximate = new QAction(tr("Approximate Arc by &Béziers…"), this);
    approximate->setObjectName("actionApproximateArc");
    approximate->setToolTip(
        tr("Replace the selected arc by cubic Bézier pieces within a radial "
           "error you give"));
    m_ui->menuEdit->addAction(approximate);
    auto* teachIn = new QAction(tr("New Contour Through &Points…"), this);
    teachIn->setObjectName("actionContourThroughPoints");
    teachIn->setToolTip(
        tr("A closed Bézier spline through teach-in points, with automatic "
           "handles"));
    m_ui->menuEdit->addAction(teachIn);
    connect(teachIn, &QAction::triggered, this, [this] {
        if (const auto input = ContourDialogs::askTeachIn(this)) {
            report(ContourEdits::contourThroughPoints(*m_document, input->points, input->rule,
                                                      input->bulge),
                   tr("New Contour Through Points"));
        }
    });
    auto* round = new QAction(tr("R&ound Corner…"), this);
    round->setObjectName("actionRoundCorner");
    round->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    round->setToolTip(
        tr("Replace the corner before the selected segment by a tangent switch "
           "arc"));
    m_ui->menuEdit->addAction(round);
    connect(round, &QAction::triggered, this, [this] {
        const int joint = selectedRow();
        if (joint < 0) {
            QMessageBox::information(this, tr("Round Corner"),
                                     tr("Select the segment after the corner to round."));
            return;
        }
        const auto range =
            filletRange(m_document->project().contour, static_cast<std::size_t>(joint));
        if (!range.ok()) {
            QMessageBox::warning(this, tr("Round Corner"), diagnosticsText(range.errors()));
            return;
        }
        if (const auto rho = ContourDialogs::askSwitchArcRadius(this, range.value().maxRadius)) {
            report(ContourEdits::roundCorner(*m_document, joint, *rho), tr("Round Corner"));
        }
    });
    auto* tangentLine = new QAction(tr("Tangent &Line to Next Arc"), this);
    tangentLine->setObjectName("actionTangentLine");
    tangentLine->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    tangentLine->setToolTip(
        tr("Join the selected arc to the next one by the line tangent to both; the windows "
           "follow from the tangent points"));
    m_ui->menuEdit->addAction(tangentLine);
    connect(tangentLine, &QAction::triggered, this, [this] {
        report(ContourEdits::tangentLineToNext(*m_document, selectedRow()), tr("Tangent Line"));
    });
    auto* tangentArc = new QAction(tr("Tangent &Arc Through Point"), this);
    tangentArc->setObjectName("actionTangentArc");
    tangentArc->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    tangentArc->setToolTip(
        tr("Continue the selected segment by a tangent arc through a point you click in the "
           "contour view (Esc cancels)"));
    m_ui->menuEdit->addAction(tangentArc);
    connect(tangentArc, &QAction::triggered, this, [this] {
        const int row = selectedRow();
        if (row < 0) {
            QMessageBox::information(this, tr("Tangent Arc"),
                                     tr("Select the segment the arc continues first."));
            return;
        }
        m_pickRow = row;
        m_contour->beginPointPick();
        statusBar()->showMessage(
            tr("Click the point the tangent arc passes through (Esc cancels)"));
    });
    connect(m_contour, &ContourView::pointPicked, this, [this](const QPointF& p) {
        const int row = std::exchange(m_pickRow, -1);
        if (row < 0) return;
        statusBar()->clearMessage();
        report(ContourEdits::tangentArcThrough(*m_document, row, {p.x(), p.y()}),
               tr("Tangent Arc"));
    });
    connect(m_contour, &ContourView::pickCancelled, this, [this] {
        m_pickRow = -1;
        statusBar()->showMessage(tr("Tangent arc cancelled"), 3000);
    });
    connect(approximate, &QAction::triggered, this, [this] {
        if (const auto error = ContourDialogs::askRadialError(this)) {
            report(ContourEdits::approximateArc(*m_document, selectedRow(), *error),
                   tr("Approximate Arc"));
        }
    });
    connect(m_ui->actionAxisTime, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/timeAxis", on);
        requestCompute();
    });
    // The lift plot r(φ) above the kinematics plots: shown unless the user hid it.
    auto* lift = new QAction(tr("&Radius Plot r(φ)"), this);
    lift->setObjectName("actionLiftPlot");
    lift->setCheckable(true);
    lift->setToolTip(tr("Show the contour's radius r over the turn above the velocity"));
    lift->setChecked(QSettings().value("view/liftPlot", true).toBool());
    m_plots->plot(KinematicsPlots::kLiftPlot)->setVisible(lift->isChecked());
    connect(lift, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/liftPlot", on);
        QCustomPlot* plot = m_plots->plot(KinematicsPlots::kLiftPlot);
        plot->setVisible(on);
        if (on) queueReplot(plot);
    });
    m_ui->menuView->insertAction(m_ui->actionResetZoom, lift);
    connect(m_ui->actionResetZoom, &QAction::triggered, this, [this] {
        m_contour->resetZoom();
        m_plots->resetZoom();
    });
    connect(m_ui->actionAbout, &QAction::triggered, this,
            [this] { QMessageBox::about(this, tr("About Camwright"), aboutText()); });
    auto* shortcuts = new QAction(tr("&Keyboard Shortcuts"), this);
    shortcuts->setObjectName("actionKeyboardShortcuts");
    shortcuts->setToolTip(tr("Every shortcut of the window"));
    m_ui->menuHelp->insertAction(m_ui->actionAbout, shortcuts);
    connect(shortcuts, &QAction::triggered, this, [this] {
        ShortcutsDialog dialog(this);
        dialog.exec();
    });
    auto* guide = new QAction(tr("User &Guide"), this);
    guide->setObjectName("actionUserGuide");
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setToolTip(
        tr("A short guide to Camwright, opened at the part you are working in: the table, "
           "construction, followers, exports, the command line"));
    m_ui->menuHelp->insertAction(shortcuts, guide);
    connect(guide, &QAction::triggered, this, [this] {
        QWidget* focus = QApplication::focusWidget();
        if (m_guide && m_guide->isAncestorOf(focus)) {  // F1 in the guide: it stays where it is
            m_guide->raise();
            return;
        }
        if (!m_guide) m_guide = new UserGuide(this);
        m_guide->showSection(UserGuide::sectionFor(focus));
    });
    QAction* whatsThis = QWhatsThis::createAction(this);
    whatsThis->setObjectName("actionWhatsThis");
    whatsThis->setText(tr("What's &This?"));
    whatsThis->setToolTip(tr("Click a dock or view to learn what it is for"));
    m_ui->menuHelp->insertAction(shortcuts, whatsThis);
    m_ui->menuHelp->insertSeparator(shortcuts);
    // Segment actions work on the table, so they do not steal Delete/Insert from other widgets.
    for (QAction* a : {m_ui->actionInsertSegment, m_ui->actionDeleteSegment, m_ui->actionMoveUp,
                       m_ui->actionMoveDown}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_ui->segmentTable->addAction(a);
    }
}

QString MainWindow::aboutText() const {
    const QString eigen = QStringLiteral("%1.%2.%3")
                              .arg(EIGEN_WORLD_VERSION)
                              .arg(EIGEN_MAJOR_VERSION)
                              .arg(EIGEN_MINOR_VERSION);
    return tr("<h3>Camwright %1</h3><p>Design and inspect cam contours: exact polar kinematics "
              "of the follower, design from motion laws, machining time, exports for CAD, CNC "
              "and servo drives.</p><p>License: GPL-3.0-or-later.</p>"
              "<p>Built with</p><ul><li>Qt %2 (LGPL-3.0)</li><li>QCustomPlot %3 (GPL-3.0)</li>"
              "<li>Eigen %4 (MPL-2.0)</li><li>JSON for Modern C++ (nlohmann-json) %5 (MIT)</li>"
              "</ul>")
        .arg(QCoreApplication::applicationVersion(), QString::fromLatin1(qVersion()),
             QStringLiteral(QCUSTOMPLOT_VERSION_STR), eigen,
             QString::fromStdString(jsonLibraryVersion()));
}

void MainWindow::setUpWhatsThis() {
    const std::pair<QWidget*, QString> texts[] = {
        {m_ui->segmentsDock,
         tr("<b>Segments</b>: the contour as a table, one row per arc, line or spline piece. "
            "Each owns a polar window [φ start, φ end) of the turn; together they cover one "
            "turn. Type into a cell and press Enter; Ins inserts, Del deletes. A red cell's "
            "tooltip names its problem. F1: the user guide's section on the table.")},
        {m_ui->jointsDock,
         tr("<b>Joints</b>: where neighbouring segments meet, with their continuity (position, "
            "tangent, curvature) and the jumps of velocity and acceleration. Click a joint to "
            "go to it.")},
        {m_controlPointsDock,
         tr("<b>Control Points</b>: the selected Bézier or Hermite row by value: every control "
            "point's x and y, and each end's handle as length and angle. Every edit is one "
            "undo step.")},
        {m_ui->motionDock,
         tr("<b>Motion</b>: how fast the cam turns (a period, rpm or rad/s) and how many "
            "samples per turn the plots and exports use.")},
        {m_ui->readoutDock,
         tr("<b>State at Cursor</b>: the follower's values at the cursor's instant: angle, "
            "segment, r and the polar components of velocity, acceleration and jerk.")},
        {m_ui->machiningDock,
         tr("<b>Machining</b>: the axes' limits and the tool, and the time it takes to machine "
            "the contour with its feed profile.")},
        {m_ui->pathStudyDock,
         tr("<b>Path Study</b>: how evenly the spline segments are parametrised, and their "
            "curvature.")},
        {m_followerDock,
         tr("<b>Follower</b>: knife, roller or flat face, translating or on a swinging arm, "
            "and its checks: pressure angle, curvature, undercut, reach.")},
        {m_designDock,
         tr("<b>Motion Design</b>: the follower's motion as motion laws over the turn; "
            "Synthesize Contour (F6) makes the cam from it.")},
        {m_contour,
         tr("<b>Contour</b>: the cam as seen from above. Drag a square or diamond handle to "
            "move a centre, a radius or a spline handle; dragged points snap to centres, joints "
            "and the grid (Shift keeps an axis, Alt places freely).")},
        {m_plots,
         tr("<b>Plots</b>: velocity, acceleration and jerk over the angle or the time; the "
            "dashed line is the cursor.")},
    };
    for (const auto& [widget, text] : texts) widget->setWhatsThis(text);
}

void MainWindow::setUpIcons() {
    // Toolbar icons smaller than Fusion's 24 px: the bar stays as low as the text-only one
    // was, and a 900×600 window still fits.
    m_ui->mainToolBar->setIconSize(QSize(18, 18));
    const auto set = [](QAction* action, const char* icon) { action->setIcon(actionIcon(icon)); };
    set(m_ui->actionNew, "document-new");
    set(m_ui->actionOpen, "document-open");
    set(m_ui->actionSave, "document-save");
    set(m_ui->actionSaveAs, "document-save-as");
    set(m_ui->actionClose, "document-close");
    set(m_ui->actionRenameProject, "edit-rename");
    set(m_ui->actionQuit, "application-exit");
    set(m_ui->actionInsertSegment, "list-add");
    set(m_ui->actionDeleteSegment, "list-remove");
    set(m_ui->actionMoveUp, "go-up");
    set(m_ui->actionMoveDown, "go-down");
    set(m_ui->actionFitWindows, "camwright-fit-windows");
    set(m_ui->actionAxisTime, "camwright-time-axis");
    set(m_ui->actionResetZoom, "zoom-fit-best");
    set(m_ui->actionAbout, "help-about");
    if (auto* guide = findChild<QAction*>("actionUserGuide")) set(guide, "help-contents");
    if (auto* whatsThis = findChild<QAction*>("actionWhatsThis")) set(whatsThis, "help-whatsthis");
    m_ui->menuRecent->setIcon(actionIcon("document-open-recent"));
    m_ui->menuExamples->setIcon(actionIcon("folder"));
    const std::pair<const char*, const char*> named[] = {
        {"actionUndo", "edit-undo"},
        {"actionRedo", "edit-redo"},
        {"actionExport", "document-export"},
        {"actionApproximateArc", "camwright-approximate-arc"},
        {"actionContourThroughPoints", "camwright-through-points"},
        {"actionRoundCorner", "camwright-round-corner"},
        {"actionTangentLine", "camwright-tangent-line"},
        {"actionTangentArc", "camwright-tangent-arc"},
        {"actionSynthesize", "camwright-synthesize"},
        {"actionKeyboardShortcuts", "preferences-desktop-keyboard"},
        {"actionPlay", "media-playback-start"},
        {"actionLiftPlot", "camwright-lift-plot"},
    };
    for (const auto& [object, icon] : named) {
        if (auto* action = findChild<QAction*>(object)) set(action, icon);
    }
    const std::pair<QDockWidget*, const char*> docks[] = {
        {m_ui->segmentsDock, "camwright-segments"},
        {m_ui->jointsDock, "camwright-joints"},
        {m_ui->motionDock, "camwright-motion"},
        {m_ui->readoutDock, "camwright-readout"},
        {m_ui->machiningDock, "camwright-machining"},
        {m_ui->pathStudyDock, "camwright-path-study"},
        {m_followerDock, "camwright-follower"},
        {m_designDock, "camwright-motion-design"},
        {m_controlPointsDock, "camwright-control-points"},
    };
    for (const auto& [dock, icon] : docks) set(dock->toggleViewAction(), icon);
    connect(m_playAction, &QAction::toggled, this, [this](bool on) {
        m_playAction->setIcon(actionIcon(on ? "media-playback-pause" : "media-playback-start"));
    });
    // Every action's tooltip names its shortcut, in the desktop's words ("Strg+S" in German).
    for (QAction* action : findChildren<QAction*>()) {
        if (action->shortcut().isEmpty()) continue;
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        QString tip = action->toolTip();
        // Qt's default tooltip is the text without its '&': give it a sentence of its own.
        if (tip.contains(QLatin1Char('(') + keys + QLatin1Char(')'))) continue;
        action->setToolTip(tr("%1 (%2)").arg(tip, keys));
    }
}

QString MainWindow::loadFile(const QString& path) { return m_files->load(path); }

bool MainWindow::offerRecovery() {
    // Claimed while the question is open: a second window starting meanwhile offers another.
    const std::vector<Autosave::Orphan> orphans = m_autosave->orphans();
    if (orphans.empty()) return false;
    const Autosave::Orphan& newest = orphans.front();
    const QString name = newest.original.isEmpty() ? tr("an untitled project")
                                                   : QDir::toNativeSeparators(newest.original);
    QMessageBox box(
        QMessageBox::Question, tr("Recover Unsaved Changes"),
        tr("Camwright did not close properly. Unsaved changes to %1, autosaved %2, "
           "can be restored.")
            .arg(name, QLocale().toString(newest.saved.toLocalTime(), QLocale::ShortFormat)),
        QMessageBox::NoButton, this);
    box.setObjectName("recoveryBox");
    QPushButton* restore = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
    QPushButton* discard = box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
    box.addButton(tr("Later"), QMessageBox::RejectRole);
    box.setDefaultButton(restore);
    box.setInformativeText(tr("Later keeps the copy and asks again at the next start."));
    box.exec();
    if (box.clickedButton() == discard) {
        Autosave::discard(newest);
        statusBar()->showMessage(tr("The recovery copy was discarded."), 6000);
        return false;
    }
    if (box.clickedButton() != restore) return false;
    return restoreRecovery(newest);
}

bool MainWindow::restoreRecovery(const Autosave::Orphan& orphan) {
    QString problem;
    const bool restored = m_autosave->adopt(orphan, &problem);
    if (!problem.isEmpty()) QMessageBox::warning(this, tr("Recover Unsaved Changes"), problem);
    if (restored) {
        statusBar()->showMessage(
            tr("Restored the unsaved changes of %1: save them to keep them.")
                .arg(orphan.original.isEmpty() ? tr("an untitled project")
                                               : QDir::toNativeSeparators(orphan.original)),
            10000);
    }
    return restored;
}

QString MainWindow::saveFile(const QString& path) { return m_files->save(path); }

void MainWindow::report(const EditOutcome& outcome, const QString& title) {
    if (!outcome.ok()) {
        if (!title.isEmpty()) QMessageBox::warning(this, title, outcome.problem);
        return;
    }
    if (!outcome.status.isEmpty()) statusBar()->showMessage(outcome.status, 6000);
    if (outcome.row >= 0) m_ui->segmentTable->selectRow(outcome.row);
}

void MainWindow::fitSegmentsDock() {
    QDockWidget* dock = m_ui->segmentsDock;
    QTableView* table = m_ui->segmentTable;
    if (dock->isFloating() || !dock->isVisible() ||
        dockWidgetArea(dock) != Qt::BottomDockWidgetArea) {
        return;
    }
    layout()->activate();  // the docks' heights as laid out now, not as first constructed
    // The height the layout gave the dock (or the user, after we last fitted it): the most it
    // is ever fitted to.
    if (m_segmentsDockFitted < 0 || dock->height() != m_segmentsDockFitted) {
        m_segmentsDockRoom = dock->height();
    }
    const int rowHeight = table->verticalHeader()->defaultSectionSize();
    const int rows = std::max(m_model->rowCount(), kMinSegmentRowsShown);
    // resizeDocks sets the dock area, and the dock gets that less its tab bar: ask, measure
    // what it got, ask once more for the difference.
    const int wanted = std::min(dock->height() + rows * rowHeight + 2 - table->viewport()->height(),
                                m_segmentsDockRoom);
    int asked = wanted;
    for (int pass = 0; pass < 2 && dock->height() != wanted; ++pass) {
        resizeDocks({dock}, {asked}, Qt::Vertical);
        layout()->activate();
        asked += wanted - dock->height();
    }
    m_segmentsDockFitted = dock->height();
}

void MainWindow::renameProject(const QString& name) {
    const std::string trimmed = name.trimmed().toStdString();
    if (trimmed == m_document->project().name) return;
    m_document->undoStack()->push(new SetProjectName(m_document, trimmed));
    statusBar()->showMessage(tr("Project renamed to “%1”").arg(name.trimmed()), 4000);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
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

void MainWindow::requestCompute() {
    // The machining times are computed only while their panel is open.
    const bool timing = !m_ui->machiningDock->isHidden();
    if (timing) m_machining->setPending();
    m_engine->request(m_document->project(),
                      m_ui->actionAxisTime->isChecked() ? PlotAxis::Time : PlotAxis::Angle, timing,
                      m_machining->plotMethod());
    m_busyTimer->start();
}

void MainWindow::showResult(const ComputeResultPtr& result) {
    if (m_shown && result->ok() && result->generation == m_shown->generation) {
        // The same result with the finer plot levels (see ComputeWorker): only the plots,
        // which draw them when zoomed in, take it; and the follower's design checks.
        const bool checks = m_shown->followerChecksPending && !result->followerChecksPending;
        m_shown = result;
        m_plots->setResult(result);
        if (checks) m_follower->showChecks(result);
        emit resultShown(result);
        return;
    }
    m_busyTimer->stop();
    m_handedGeneration = result->generation;
    // The views keep what they drew from the last computable result and mark it out of date.
    // The plots first: each view's redraw is queued, and they are drawn in this order.
    m_plots->setResult(result);
    m_follower->setResult(result);
    // The pressure-angle plot shows what the kinematics plots show (their zoom included).
    m_follower->pressurePlot()->xAxis->setRange(m_plots->plot(0)->xAxis->range());
    if (!result->ok()) {
        showBesidePlots(result);
        const QString first = diagnosticText(result->errors.front());
        // The problems themselves are in the validation label beside it.
        m_computeLabel->setText(result->failed() ? tr("not computed: %1").arg(first)
                                : m_document->awaitsSynthesis()
                                    ? tr("no contour yet")
                                    : tr("not computed: the project has problems"));
        m_computeLabel->setStyleSheet("color: #b00020;");
        if (result->failed()) statusBar()->showMessage(tr("Computation failed: %1").arg(first));
        m_readout->clear();  // no state of the project as it is
        // A design without a contour yet: the views drew nothing, and nothing of an earlier
        // project may be exported as this one's.
        if (result->awaitsContour()) m_shown.reset();
        emit resultShown(result);
        return;
    }
    m_shown = result;
    // The rest of the window (the contour view, the Joints tab, the readout, the status bar)
    // follows once the plots are drawn, so that painting it never delays them: it took 1.5 to
    // 2 ms of an edit's redraw. By then it takes the newest result of this request (a first
    // picture may have been refined meanwhile); a newer request's result, computable or not,
    // has its own turn, and this one is then never shown there.
    whenReplotsDone(this, [this, generation = result->generation, samples = result->sampleCount,
                           ms = result->computeMs] {
        if (m_handedGeneration != generation || !m_shown || m_shown->generation != generation) {
            return;
        }
        showBesidePlots(m_shown);
        m_computeLabel->setStyleSheet({});
        setCursorTime(m_cursorT);
        m_computeLabel->setText(
            tr("%1 samples computed in %2")
                .arg(formatQuantity(DisplayQuantity::Count, static_cast<double>(samples)),
                     formatQuantity(DisplayQuantity::Duration, ms)));
    });
    emit resultShown(result);
}

void MainWindow::showBesidePlots(const ComputeResultPtr& result) {
    m_contour->setResult(result);
    m_joints->setResult(result);
    m_pathStudy->setResult(result);
    m_design->setResult(result);
}

void MainWindow::setCursorAtPlotX(double x) {
    const auto& r = m_shown;
    if (!r) return;
    setCursorTime(r->axis == PlotAxis::Angle ? degToRad(x) / r->omega : x);
}

void MainWindow::setCursorTime(double t) {
    const auto& r = m_shown;
    const auto& latest = m_engine->latestResult();
    if (!r || !latest || !latest->ok()) {
        // Nothing computed for the project as it is: no state to read out.
        m_cursorT = t;
        m_readout->clear();
        return;
    }
    // Any instant, the mouse's or a joint's, is read within the turn: 0 <= t < T.
    t = std::fmod(t, r->period);
    if (t < 0.0) t += r->period;
    if (t >= r->period) t = 0.0;
    m_cursorT = t;
    // One state from the shared, immutable contour of the result: a few hundred nanoseconds.
    const KinematicState s = stateAt(*r->contour, r->omega, t);
    m_readout->setState(s);
    m_contour->setCursorAngle(s.phi);
    m_plots->setCursorX(r->axis == PlotAxis::Angle ? radToDeg(s.phi) : t);
    m_follower->setCursorX(r->axis == PlotAxis::Angle ? radToDeg(s.phi) : t);
    m_design->setCursorX(r->axis == PlotAxis::Angle ? radToDeg(s.phi) : t);
}

bool MainWindow::waitForCurrentResult(int timeoutMs) {
    const auto current = [this] {
        const auto& r = m_engine->latestResult();
        // A first picture is followed by its finer plot levels and the follower's checks.
        return r && r->generation == m_engine->latestGeneration() && r->complete();
    };
    // Shown: the plots have been replotted with it too (they replot one per pass of the event
    // loop, see queueReplot).
    const auto shown = [] {
        replotQueuedNow();
        return true;
    };
    if (current()) return shown();
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, [&loop] { loop.exit(1); });
    connect(m_engine, &ComputeEngine::resultReady, &loop, [&loop, current] {
        if (current()) loop.exit(0);
    });
    return loop.exec() == 0 && shown();
}

void MainWindow::updateStatus() {
    const Diagnostics& d = m_document->diagnostics();
    const int n = static_cast<int>(m_document->project().contour.size());
    if (d.empty() && m_document->awaitsSynthesis()) {
        m_validationLabel->setText(tr("Valid · no contour yet: Synthesize (F6) makes it"));
        m_validationLabel->setToolTip({});
        m_validationLabel->setStyleSheet({});
    } else if (d.empty()) {
        m_validationLabel->setText(n == 1 ? tr("Valid · 1 segment")
                                          : tr("Valid · %1 segments").arg(n));
        m_validationLabel->setToolTip({});
        m_validationLabel->setStyleSheet({});
    } else {
        const QString first = diagnosticText(d.front());
        const QString count = d.size() == 1 ? tr("1 problem: ") : tr("%1 problems: ").arg(d.size());
        m_validationLabel->setText(count + fontMetrics().elidedText(first, Qt::ElideRight, 600));
        m_validationLabel->setToolTip(diagnosticsText(d, 40));
        m_validationLabel->setStyleSheet("color: #b00020;");
    }
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — Camwright").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

int MainWindow::selectedRow() const {
    const QModelIndex current = m_ui->segmentTable->currentIndex();
    return current.isValid() ? current.row() : -1;
}

QString MainWindow::contourThroughPoints(const QString& pointsText, int rule, double bulge) {
    const EditOutcome outcome = ContourEdits::contourThroughPoints(
        *m_document, pointsText, static_cast<HandleRule>(rule), bulge);
    report(outcome, {});
    return outcome.problem;
}

QString MainWindow::roundCorner(int joint, double rho) {
    const EditOutcome outcome = ContourEdits::roundCorner(*m_document, joint, rho);
    report(outcome, {});
    return outcome.problem;
}

QString MainWindow::approximateArc(int row, double maxErrorMm) {
    const EditOutcome outcome = ContourEdits::approximateArc(*m_document, row, maxErrorMm);
    report(outcome, {});
    return outcome.problem;
}

}  // namespace cam
