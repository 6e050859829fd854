#include "window/dock_layout.h"

#include <qcustomplot.h>
#include <QDockWidget>
#include <QHeaderView>
#include <QLayout>
#include <QMainWindow>
#include <QResizeEvent>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QToolBar>

#include "document/project_document.h"
#include "models/delegates.h"
#include "models/segment_table_model.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/control_points_panel.h"
#include "views/follower_panel.h"
#include "views/forces_panel.h"
#include "views/joints_panel.h"
#include "views/kinematics_plots.h"
#include "views/machining_panel.h"
#include "views/motion_design_panel.h"
#include "views/motion_panel.h"
#include "views/path_study_panel.h"
#include "views/plot_redraw.h"
#include "views/state_readout.h"
#include "widgets/column_fit.h"
#include "widgets/read_only_cells.h"

namespace cam {
namespace {

/// Puts `panel` into `dock` through a scroll area named `name`: a panel taller than a small
/// screen scrolls rather than making the window taller.
void setScrollingWidget(QDockWidget* dock, QWidget* panel, const char* name) {
    auto* scroll = new QScrollArea(dock);
    scroll->setObjectName(name);
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    dock->setWidget(scroll);
}

}  // namespace

DockLayout::DockLayout(QMainWindow* window, Ui::MainWindow& ui, ProjectDocument* document,
                       SegmentTableModel* model)
    : QObject(window), m_window(window), m_ui(ui), m_document(document), m_model(model) {
    makeCentre();
    makeBottomDocks();
    makeRightDocks();
    linkFollowerAxes();
    setWhatsThis();
    showWhatTheProjectHas();
}

void DockLayout::makeCentre() {
    contour = new ContourView(m_document, m_window);
    plots = new KinematicsPlots(m_window);
    plots->setObjectName("kinematicsPlots");
    auto* splitter = new QSplitter(Qt::Horizontal, m_window);
    splitter->setObjectName("mainSplitter");
    splitter->addWidget(contour);
    splitter->addWidget(plots);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({400, 600});  // 2 : 3 from the start, not from the size hints
    m_window->setCentralWidget(splitter);
}

void DockLayout::makeBottomDocks() {
    QTableView* table = m_ui.segmentTable;
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
    sayWhyCellsAreReadOnly(table);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::AnyKeyPressed);
    // A spline's control points by value, tabbed with the table and the joints.
    controlPointsDock = new QDockWidget(tr("Control Points"), m_window);
    controlPointsDock->setObjectName("controlPointsDock");
    controlPoints = new ControlPointsPanel(m_document, controlPointsDock);
    controlPoints->setObjectName("controlPointsPanel");
    controlPointsDock->setWidget(controlPoints);
    m_window->addDockWidget(Qt::BottomDockWidgetArea, controlPointsDock);
    connect(table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                contour->setSelectedSegment(current.row());
                controlPoints->setRow(current.row());
            });
    motion = new MotionPanel(m_document, m_ui.motionDock);
    m_ui.motionDock->setWidget(motion);
    readout = new StateReadout(m_ui.readoutDock);
    m_ui.readoutDock->setWidget(readout);
    m_window->splitDockWidget(m_ui.motionDock, m_ui.readoutDock, Qt::Vertical);
    joints = new JointsPanel(m_ui.jointsDock);
    m_ui.jointsDock->setWidget(joints);
    m_window->tabifyDockWidget(m_ui.segmentsDock, m_ui.jointsDock);
    m_window->tabifyDockWidget(m_ui.jointsDock, controlPointsDock);
    m_ui.segmentsDock->raise();
    m_window->resizeDocks({m_ui.motionDock, m_ui.readoutDock}, {140, 400}, Qt::Vertical);
}

void DockLayout::makeRightDocks() {
    pathStudy = new PathStudyPanel(m_ui.pathStudyDock);
    m_ui.pathStudyDock->setWidget(pathStudy);
    m_ui.pathStudyDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    machining = new MachiningPanel(m_document, m_ui.machiningDock);
    m_ui.machiningDock->setWidget(machining);
    QAction* machiningToggle = m_ui.machiningDock->toggleViewAction();
    machiningToggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    machiningToggle->setToolTip(tr("Machining limits and times (Ctrl+M)"));
    m_ui.mainToolBar->addSeparator();
    m_ui.mainToolBar->addAction(machiningToggle);
    // The follower and its design checks, tabbed with the machining dock.
    followerDock = new QDockWidget(tr("Follower"), m_window);
    followerDock->setObjectName("followerDock");
    follower = new FollowerPanel(m_document, followerDock);
    follower->setObjectName("followerPanel");
    followerDock->setWidget(follower);
    m_window->addDockWidget(Qt::RightDockWidgetArea, followerDock);
    QAction* followerToggle = followerDock->toggleViewAction();
    followerToggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    followerToggle->setToolTip(tr("The follower and its design checks (Ctrl+L)"));
    m_ui.mainToolBar->addAction(followerToggle);
    // The forces of the project's dynamics, tabbed with the follower (it scrolls: its inputs
    // and three plots are taller than a small screen).
    forcesDock = new QDockWidget(tr("Forces"), m_window);
    forcesDock->setObjectName("forcesDock");
    forces = new ForcesPanel(m_document, forcesDock);
    forces->setObjectName("forcesPanel");
    setScrollingWidget(forcesDock, forces, "forcesScrollArea");
    m_window->addDockWidget(Qt::RightDockWidgetArea, forcesDock);
    QAction* forcesToggle = forcesDock->toggleViewAction();
    forcesToggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F));
    forcesToggle->setToolTip(
        tr("Forces: the spring, the jump speed, torque and contact stress (Ctrl+F)"));
    m_ui.mainToolBar->addAction(forcesToggle);
    for (QDockWidget* dock :
         {m_ui.segmentsDock, m_ui.jointsDock, controlPointsDock, m_ui.motionDock, m_ui.readoutDock,
          m_ui.machiningDock, m_ui.pathStudyDock, followerDock, forcesDock}) {
        m_ui.menuView->addAction(dock->toggleViewAction());
    }
    // The motion design, tabbed there too; it scrolls rather than making the window taller
    // than a small screen.
    designDock = new QDockWidget(tr("Motion Design"), m_window);
    designDock->setObjectName("motionDesignDock");
    design = new MotionDesignPanel(m_document, designDock);
    design->setObjectName("motionDesignPanel");
    setScrollingWidget(designDock, design, "motionDesignScrollArea");
    m_window->addDockWidget(Qt::RightDockWidgetArea, designDock);
    QAction* designToggle = designDock->toggleViewAction();
    designToggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    designToggle->setToolTip(tr("Design the contour from the follower's motion (Ctrl+D)"));
    // Into the tool bar and the View menu by the window, after Play.
}

std::vector<QCustomPlot*> DockLayout::turnPlots() const {
    std::vector<QCustomPlot*> all;
    for (QCustomPlot* plot : follower->turnPlots()) all.push_back(plot);
    for (QCustomPlot* plot : forces->turnPlots()) all.push_back(plot);
    return all;
}

void DockLayout::linkFollowerAxes() {
    // The follower's plots over the turn (pressure angle, curvature, forces) share the
    // kinematics plots' x axis: panning or zooming one moves the others.
    QCustomPlot* velocity = plots->plot(0);
    for (QCustomPlot* plot : turnPlots()) {
        connect(velocity->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), plot,
                [plot](const QCPRange& r) {
                    if (plot->xAxis->range() == r) return;
                    plot->xAxis->setRange(r);
                    queueReplot(plot);
                });
        connect(plot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), velocity,
                [velocity](const QCPRange& r) {
                    if (velocity->xAxis->range() != r) velocity->xAxis->setRange(r);
                });
    }
}

void DockLayout::showWhatTheProjectHas() {
    // Once the layout has settled: a short contour leaves the plots the rows it needs not.
    connect(m_document, &ProjectDocument::contourReset, this,
            [this] { QTimer::singleShot(0, this, &DockLayout::fitSegmentsDock); });
    // Only when another project arrives: a Save (which may give the file its first path)
    // switched the right-hand tabs and took the focus with them (issue 31).
    connect(m_document, &ProjectDocument::replaced, this, [this] {
        const Project& project = m_document->project();
        if (project.follower) followerDock->show();
        if (project.dynamics) forcesDock->show();
        if (project.design) designDock->show();
        if (!project.dynamics && !project.design) return;
        // A design's dock in front of the follower's and the forces' tabs, else the forces' in
        // front of the follower's; once the docks are shown, and the design's wide enough for
        // its segment table.
        QDockWidget* front = project.design ? designDock : forcesDock;
        QTimer::singleShot(0, front, [this, front] {
            front->raise();
            if (front == designDock && designDock->width() < 400 && !designDock->isFloating()) {
                m_window->resizeDocks({designDock}, {400}, Qt::Horizontal);
            }
        });
    });
}

void DockLayout::restore() {
    QSettings settings;
    m_window->restoreGeometry(settings.value("window/geometry").toByteArray());
    m_ui.machiningDock->hide();  // until the user opens it (the saved layout may show it)
    m_ui.pathStudyDock->hide();
    followerDock->hide();  // until opened, or a project with a follower is loaded
    forcesDock->hide();    // until opened, or a project with dynamics is loaded
    designDock->hide();    // until opened, or a project with a design is loaded
    // The right-hand docks are tabs of one group (tabified while hidden: tabified while shown,
    // two made the hidden window grow to the height of both). Stacked, Machining, Path Study
    // and Follower together asked for more height than the screen has, and the window grew
    // past its bottom edge. Opening one brings its tab to the front.
    m_window->tabifyDockWidget(followerDock, forcesDock);
    m_window->tabifyDockWidget(forcesDock, designDock);
    m_window->tabifyDockWidget(designDock, m_ui.machiningDock);
    m_window->tabifyDockWidget(m_ui.machiningDock, m_ui.pathStudyDock);
    for (QDockWidget* dock :
         {followerDock, forcesDock, designDock, m_ui.machiningDock, m_ui.pathStudyDock}) {
        connect(dock->toggleViewAction(), &QAction::toggled, dock, [dock](bool on) {
            if (on) QTimer::singleShot(0, dock, [dock] { dock->raise(); });
        });
    }
    m_window->restoreState(settings.value("window/state").toByteArray());
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly)) {
        dock->installEventFilter(this);
    }
}

void DockLayout::save() const {
    QSettings settings;
    settings.setValue("window/geometry", m_window->saveGeometry());
    settings.setValue("window/state", m_window->saveState());
}

namespace {

/// The dock in front in `area`: shown, docked there (a tab group shares its width).
QDockWidget* frontDockIn(QMainWindow* window, Qt::DockWidgetArea area) {
    for (QDockWidget* dock : window->findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly)) {
        if (dock->isVisible() && !dock->isFloating() && window->dockWidgetArea(dock) == area &&
            !dock->visibleRegion().isEmpty()) {
            return dock;
        }
    }
    return nullptr;
}

constexpr Qt::DockWidgetArea kSides[2] = {Qt::LeftDockWidgetArea, Qt::RightDockWidgetArea};

}  // namespace

bool DockLayout::eventFilter(QObject* watched, QEvent* event) {
    auto* dock = qobject_cast<QDockWidget*>(watched);
    if (!dock || event->type() != QEvent::Resize) return false;
    // The window's resizing reaches a dock in a later layout pass: a dock resized at another
    // window width than its last resize was resized by the window; one resized at the same
    // width, by a choice (a separator drag, a dock opened or widened for a project).
    int& last = m_windowWidthAt[dock];
    const bool byTheWindow = m_window->width() != last;
    last = m_window->width();
    const Qt::DockWidgetArea area = m_window->dockWidgetArea(dock);
    const int side = area == Qt::LeftDockWidgetArea ? 0 : area == Qt::RightDockWidgetArea ? 1 : -1;
    if (side < 0 || dock->isFloating() || !m_window->isVisible()) return false;
    const auto* resize = static_cast<QResizeEvent*>(event);
    if (!byTheWindow && !m_givingWidthsBack &&
        resize->size().width() != resize->oldSize().width()) {
        m_dockWidths[side] = dock->width();
    } else if (byTheWindow && dock->width() < m_dockWidths[side]) {
        QTimer::singleShot(0, this, &DockLayout::giveDocksTheirWidthsBack);
    }
    return false;
}

void DockLayout::giveDocksTheirWidthsBack() {
    QList<QDockWidget*> docks;
    QList<int> widths;
    for (int side = 0; side < 2; ++side) {
        QDockWidget* dock = frontDockIn(m_window, kSides[side]);
        if (dock && m_dockWidths[side] > dock->width()) {
            docks << dock;
            widths << m_dockWidths[side];
        }
    }
    if (docks.isEmpty()) return;
    // As much as the centre can give; the wish stays for the next growth.
    m_givingWidthsBack = true;
    m_window->resizeDocks(docks, widths, Qt::Horizontal);
    m_window->layout()->activate();
    QTimer::singleShot(0, this, [this] { m_givingWidthsBack = false; });
}

void DockLayout::fitSegmentsDock() {
    QDockWidget* dock = m_ui.segmentsDock;
    QTableView* table = m_ui.segmentTable;
    if (dock->isFloating() || !dock->isVisible() ||
        m_window->dockWidgetArea(dock) != Qt::BottomDockWidgetArea) {
        return;
    }
    m_window->layout()->activate();  // the docks' heights as laid out now, not as first made
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
        m_window->resizeDocks({dock}, {asked}, Qt::Vertical);
        m_window->layout()->activate();
        asked += wanted - dock->height();
    }
    m_segmentsDockFitted = dock->height();
}

void DockLayout::setWhatsThis() {
    const std::pair<QWidget*, QString> texts[] = {
        {m_ui.segmentsDock,
         tr("<b>Segments</b>: the contour as a table, one row per arc, line or spline piece. "
            "Each owns a polar window [φ start, φ end) of the turn; together they cover one "
            "turn. Type into a cell and press Enter; Ins inserts, Del deletes. A red cell's "
            "tooltip names its problem. F1: the user guide's section on the table.")},
        {m_ui.jointsDock,
         tr("<b>Joints</b>: where neighbouring segments meet, with their continuity (position, "
            "tangent, curvature) and the jumps of velocity and acceleration. Click a joint to "
            "go to it.")},
        {controlPointsDock,
         tr("<b>Control Points</b>: the selected Bézier or Hermite row by value: every control "
            "point's x and y, and each end's handle as length and angle. Every edit is one "
            "undo step.")},
        {m_ui.motionDock,
         tr("<b>Motion</b>: how fast the cam turns (a period, rpm or rad/s) and how many "
            "samples per turn the plots and exports use.")},
        {m_ui.readoutDock,
         tr("<b>State at Cursor</b>: the follower's values at the cursor's instant: angle, "
            "segment, r and the polar components of velocity, acceleration and jerk.")},
        {m_ui.machiningDock,
         tr("<b>Machining</b>: the axes' limits and the tool, and the time it takes to machine "
            "the contour with its feed profile.")},
        {m_ui.pathStudyDock,
         tr("<b>Path Study</b>: how evenly the spline segments are parametrised, and their "
            "curvature.")},
        {followerDock,
         tr("<b>Follower</b>: knife, roller or flat face, translating or on a swinging arm, "
            "and its checks: pressure angle, curvature, undercut, reach.")},
        {forcesDock,
         tr("<b>Forces</b>: the follower's mass, its spring, the load and the materials, and "
            "what they give over the turn: where the follower leaves the cam, the speed at which "
            "it would, the least preload, the torque on the camshaft and the contact stress "
            "against the allowable.")},
        {designDock, tr("<b>Motion Design</b>: the follower's motion as motion laws over the turn; "
                        "Synthesize Contour (F6) makes the cam from it.")},
        {contour,
         tr("<b>Contour</b>: the cam as seen from above. Drag a square or diamond handle to "
            "move a centre, a radius or a spline handle; dragged points snap to centres, joints "
            "and the grid (Shift keeps an axis, Alt places freely).")},
        {plots, tr("<b>Plots</b>: velocity, acceleration and jerk over the angle or the time; the "
                   "dashed line is the cursor.")},
    };
    for (const auto& [widget, text] : texts) widget->setWhatsThis(text);
}

}  // namespace cam
