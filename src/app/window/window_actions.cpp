#include "window/window_actions.h"

#include <qcustomplot.h>
#include <Eigen/Core>
#include <QAction>
#include <QApplication>
#include <QCursor>
#include <QDockWidget>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>
#include <QWhatsThis>
#include <utility>

#include "dialogs/contour_dialogs.h"
#include "dialogs/round_corner_dialog.h"
#include "dialogs/shortcuts_dialog.h"
#include "dialogs/user_guide.h"
#include "document/commands.h"
#include "document/contour_edits.h"
#include "document/project_document.h"
#include "files/project_files.h"
#include "fillet/fillet.h"
#include "io/project_json.h"
#include "messages/diagnostic_text.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/plot_redraw.h"
#include "widgets/icons.h"
#include "window/dock_layout.h"

namespace cam {

WindowActions::WindowActions(QMainWindow* window, Ui::MainWindow& ui, ProjectDocument* document,
                             ProjectFiles* files, DockLayout& views)
    : QObject(window),
      m_window(window),
      m_ui(ui),
      m_document(document),
      m_files(files),
      m_views(views) {
    setUpActions();
}

void WindowActions::setUpActions() {
    QUndoStack* stack = m_document->undoStack();
    QAction* undo = stack->createUndoAction(m_window, tr("&Undo"));
    undo->setObjectName("actionUndo");
    undo->setShortcut(QKeySequence::Undo);
    // Their text names the next step ("Undo Change dynamics"); the shortcuts list names them.
    undo->setProperty(kShortcutTitle, tr("Undo"));
    QAction* redo = stack->createRedoAction(m_window, tr("&Redo"));
    redo->setObjectName("actionRedo");
    redo->setShortcut(QKeySequence::Redo);
    redo->setProperty(kShortcutTitle, tr("Redo"));
    QAction* first = m_ui.menuEdit->actions().value(0);
    m_ui.menuEdit->insertAction(first, undo);
    m_ui.menuEdit->insertAction(first, redo);
    m_ui.menuEdit->insertSeparator(first);

    connect(m_ui.actionNew, &QAction::triggered, this, [this] {
        if (m_files->maybeSave()) m_document->reset(ContourEdits::newProject(), {});
    });
    connect(m_ui.actionClose, &QAction::triggered, this, [this] {
        const QString name = m_document->displayName();
        if (!m_files->maybeSave()) return;
        m_document->reset(ContourEdits::newProject(), {});
        m_window->statusBar()->showMessage(tr("Closed %1").arg(name), 4000);
    });
    connect(m_ui.actionRenameProject, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(
            m_window, tr("Project Name"), tr("Name of the project:"), QLineEdit::Normal,
            QString::fromStdString(m_document->project().name), &ok);
        if (ok) renameProject(name);
    });
    connect(m_ui.actionOpen, &QAction::triggered, this, [this] { m_files->open(); });
    connect(m_ui.actionSave, &QAction::triggered, this, [this] { m_files->save(); });
    connect(m_ui.actionSaveAs, &QAction::triggered, this, [this] { m_files->saveAs(); });
    connect(m_ui.actionQuit, &QAction::triggered, m_window, &QWidget::close);
    connect(m_ui.actionInsertSegment, &QAction::triggered, this,
            [this] { report(ContourEdits::insertSegment(*m_document, selectedRow())); });
    connect(m_ui.actionDeleteSegment, &QAction::triggered, this,
            [this] { report(ContourEdits::deleteSegment(*m_document, selectedRow()), {}); });
    connect(m_ui.actionMoveUp, &QAction::triggered, this,
            [this] { report(ContourEdits::moveSegment(*m_document, selectedRow(), -1), {}); });
    connect(m_ui.actionMoveDown, &QAction::triggered, this,
            [this] { report(ContourEdits::moveSegment(*m_document, selectedRow(), 1), {}); });
    connect(m_ui.actionFitWindows, &QAction::triggered, this,
            [this] { report(ContourEdits::fitWindows(*m_document), tr("Fit Windows")); });
    auto* approximate = new QAction(tr("Approximate Arc by &Béziers…"), m_window);
    approximate->setObjectName("actionApproximateArc");
    approximate->setToolTip(
        tr("Replace the selected arc by cubic Bézier pieces within a radial "
           "error you give"));
    m_ui.menuEdit->addAction(approximate);
    auto* teachIn = new QAction(tr("New Contour Through &Points…"), m_window);
    teachIn->setObjectName("actionContourThroughPoints");
    teachIn->setToolTip(
        tr("A closed Bézier spline through teach-in points, with automatic "
           "handles"));
    m_ui.menuEdit->addAction(teachIn);
    connect(teachIn, &QAction::triggered, this, [this] {
        if (const auto input = ContourDialogs::askTeachIn(m_window)) {
            report(ContourEdits::contourThroughPoints(*m_document, input->points, input->rule,
                                                      input->bulge),
                   tr("New Contour Through Points"));
        }
    });
    auto* round = new QAction(tr("R&ound Corner…"), m_window);
    round->setObjectName("actionRoundCorner");
    round->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    round->setToolTip(
        tr("Replace the corner before the selected segment by a tangent switch "
           "arc"));
    m_ui.menuEdit->addAction(round);
    connect(round, &QAction::triggered, this, [this] {
        const int joint = selectedRow();
        if (joint < 0) {
            QMessageBox::information(m_window, tr("Round Corner"),
                                     tr("Select the segment after the corner to round."));
            return;
        }
        const auto range =
            filletRange(m_document->project().contour, static_cast<std::size_t>(joint));
        if (!range.ok()) {
            QMessageBox::warning(m_window, tr("Round Corner"), diagnosticsText(range.errors()));
            return;
        }
        RoundCornerDialog dialog(m_document->project(), static_cast<std::size_t>(joint),
                                 range.value(), m_window);
        if (dialog.exec() == QDialog::Accepted) {
            report(ContourEdits::roundCorner(*m_document, joint, dialog.radius()),
                   tr("Round Corner"));
        }
    });
    auto* tangentLine = new QAction(tr("Tangent &Line to Next Arc"), m_window);
    tangentLine->setObjectName("actionTangentLine");
    tangentLine->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    tangentLine->setToolTip(
        tr("Join the selected arc to the next one by the line tangent to both; the windows "
           "follow from the tangent points"));
    m_ui.menuEdit->addAction(tangentLine);
    connect(tangentLine, &QAction::triggered, this, [this] {
        report(ContourEdits::tangentLineToNext(*m_document, selectedRow()), tr("Tangent Line"));
    });
    auto* tangentArc = new QAction(tr("Tangent &Arc Through Point"), m_window);
    tangentArc->setObjectName("actionTangentArc");
    tangentArc->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    tangentArc->setToolTip(
        tr("Continue the selected segment by a tangent arc through a point you click in the "
           "contour view (Esc cancels)"));
    m_ui.menuEdit->addAction(tangentArc);
    connect(tangentArc, &QAction::triggered, this, [this] {
        const int row = selectedRow();
        if (row < 0) {
            QMessageBox::information(m_window, tr("Tangent Arc"),
                                     tr("Select the segment the arc continues first."));
            return;
        }
        m_pickRow = row;
        m_views.contour->beginPointPick();
        m_window->statusBar()->showMessage(
            tr("Click the point the tangent arc passes through (Esc cancels)"));
    });
    connect(m_views.contour, &ContourView::pointPicked, this, [this](const QPointF& p) {
        const int row = std::exchange(m_pickRow, -1);
        if (row < 0) return;
        m_window->statusBar()->clearMessage();
        report(ContourEdits::tangentArcThrough(*m_document, row, {p.x(), p.y()}),
               tr("Tangent Arc"));
    });
    connect(m_views.contour, &ContourView::pickCancelled, this, [this] {
        m_pickRow = -1;
        m_window->statusBar()->showMessage(tr("Tangent arc cancelled"), 3000);
    });
    connect(approximate, &QAction::triggered, this, [this] {
        if (const auto error = ContourDialogs::askRadialError(m_window)) {
            report(ContourEdits::approximateArc(*m_document, selectedRow(), *error),
                   tr("Approximate Arc"));
        }
    });
    connect(m_ui.actionAxisTime, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/timeAxis", on);
        emit viewChanged();
    });
    // The lift plot above the kinematics plots: shown unless the user hid it.
    auto* lift = new QAction(tr("&Lift Plot"), m_window);
    lift->setObjectName("actionLiftPlot");
    lift->setCheckable(true);
    lift->setToolTip(
        tr("Show the follower's lift (or, in the polar view, the contour's radius "
           "r) over the turn above the velocity"));
    lift->setChecked(QSettings().value("view/liftPlot", true).toBool());
    m_views.plots->plot(KinematicsPlots::kLiftPlot)->setVisible(lift->isChecked());
    connect(lift, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/liftPlot", on);
        QCustomPlot* plot = m_views.plots->plot(KinematicsPlots::kLiftPlot);
        plot->setVisible(on);
        if (on) queueReplot(plot);
    });
    m_ui.menuView->insertAction(m_ui.actionResetZoom, lift);
    // The follower's motion is what the plots show when the project names a follower; the
    // contour's polar kinematics along the ray are one choice away.
    auto* polar = new QAction(tr("&Polar Kinematics"), m_window);
    polar->setObjectName("actionPolarKinematics");
    polar->setCheckable(true);
    polar->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    polar->setToolTip(
        tr("Plot the contour's radius r and its polar velocity, acceleration and jerk along "
           "the ray instead of the follower's lift, velocity, acceleration and jerk "
           "(Ctrl+Shift+P)"));
    polar->setChecked(QSettings().value("view/polarKinematics", false).toBool());
    m_views.plots->setPolarChosen(polar->isChecked());
    connect(polar, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/polarKinematics", on);
        m_views.plots->setPolarChosen(on);
        m_window->statusBar()->showMessage(
            on ? tr("The plots show the contour's polar kinematics along the ray")
               : tr("The plots show the follower's motion (when the project names one)"),
            4000);
    });
    m_ui.menuView->insertAction(m_ui.actionResetZoom, polar);
    // The profile coloured by its contact stress (a project with dynamics): on demand.
    auto* stress = new QAction(tr("Colour by Contact &Stress"), m_window);
    stress->setObjectName("actionStressColours");
    stress->setCheckable(true);
    stress->setToolTip(
        tr("Colour the profile by the Hertz contact stress where the follower "
           "touches it (needs the Forces dock's contact width and materials)"));
    stress->setChecked(QSettings().value("view/stressColours", false).toBool());
    m_views.contour->setStressColouring(stress->isChecked());
    connect(stress, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/stressColours", on);
        m_views.contour->setStressColouring(on);
    });
    m_ui.menuView->insertAction(m_ui.actionResetZoom, stress);
    connect(m_ui.actionResetZoom, &QAction::triggered, this, [this] {
        m_views.contour->resetZoom();
        m_views.plots->resetZoom();
    });
    connect(m_ui.actionAbout, &QAction::triggered, this,
            [this] { QMessageBox::about(m_window, tr("About Camwright"), aboutText()); });
    auto* shortcuts = new QAction(tr("&Keyboard Shortcuts"), m_window);
    shortcuts->setObjectName("actionKeyboardShortcuts");
    shortcuts->setToolTip(tr("Every shortcut of the window"));
    m_ui.menuHelp->insertAction(m_ui.actionAbout, shortcuts);
    connect(shortcuts, &QAction::triggered, this, [this] {
        ShortcutsDialog dialog(m_window);
        dialog.exec();
    });
    auto* guide = new QAction(tr("User &Guide"), m_window);
    guide->setObjectName("actionUserGuide");
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setToolTip(
        tr("A short guide to Camwright, opened at the part you are working in: the table, "
           "construction, followers, exports, the command line"));
    m_ui.menuHelp->insertAction(shortcuts, guide);
    connect(guide, &QAction::triggered, this, [this] {
        // The part the mouse is over (the contour view, a dock), else the one with the focus:
        // F1 over the contour while the table has the focus is about the contour.
        QWidget* focus = QApplication::widgetAt(QCursor::pos());
        if (!focus || focus->window() != m_window) focus = QApplication::focusWidget();
        if (m_guide && m_guide->isAncestorOf(focus)) {  // F1 in the guide: it stays where it is
            m_guide->raise();
            return;
        }
        if (!m_guide) m_guide = new UserGuide(m_window);
        m_guide->showSection(UserGuide::sectionFor(focus));
    });
    QAction* whatsThis = QWhatsThis::createAction(m_window);
    whatsThis->setObjectName("actionWhatsThis");
    whatsThis->setText(tr("What's &This?"));
    whatsThis->setToolTip(tr("Click a dock or view to learn what it is for"));
    m_ui.menuHelp->insertAction(shortcuts, whatsThis);
    m_ui.menuHelp->insertSeparator(shortcuts);
    // Segment actions work on the table, so they do not steal Delete/Insert from other widgets.
    for (QAction* a : {m_ui.actionInsertSegment, m_ui.actionDeleteSegment, m_ui.actionMoveUp,
                       m_ui.actionMoveDown}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_ui.segmentTable->addAction(a);
    }
}

void WindowActions::setUpIcons() {
    // Toolbar icons smaller than Fusion's 24 px: the bar stays as low as the text-only one
    // was, and a 900×600 window still fits.
    m_ui.mainToolBar->setIconSize(QSize(18, 18));
    const auto set = [](QAction* action, const char* icon) { action->setIcon(actionIcon(icon)); };
    set(m_ui.actionNew, "document-new");
    set(m_ui.actionOpen, "document-open");
    set(m_ui.actionSave, "document-save");
    set(m_ui.actionSaveAs, "document-save-as");
    set(m_ui.actionClose, "document-close");
    set(m_ui.actionRenameProject, "edit-rename");
    set(m_ui.actionQuit, "application-exit");
    set(m_ui.actionInsertSegment, "list-add");
    set(m_ui.actionDeleteSegment, "list-remove");
    set(m_ui.actionMoveUp, "go-up");
    set(m_ui.actionMoveDown, "go-down");
    set(m_ui.actionFitWindows, "camwright-fit-windows");
    set(m_ui.actionAxisTime, "camwright-time-axis");
    set(m_ui.actionResetZoom, "zoom-fit-best");
    set(m_ui.actionAbout, "help-about");
    if (auto* guide = m_window->findChild<QAction*>("actionUserGuide")) set(guide, "help-contents");
    if (auto* whatsThis = m_window->findChild<QAction*>("actionWhatsThis"))
        set(whatsThis, "help-whatsthis");
    m_ui.menuRecent->setIcon(actionIcon("document-open-recent"));
    m_ui.menuExamples->setIcon(actionIcon("folder"));
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
        {"actionPolarKinematics", "camwright-polar-kinematics"},
        {"actionStressColours", "camwright-stress-colours"},
        {"actionCursorPreviousSample", "go-previous"},
        {"actionCursorNextSample", "go-next"},
        {"actionCursorPreviousJoint", "camwright-previous-joint"},
        {"actionCursorNextJoint", "camwright-next-joint"},
        {"actionCursorTurnStart", "go-first"},
        {"actionCursorTurnEnd", "go-last"},
    };
    for (const auto& [object, icon] : named) {
        if (auto* action = m_window->findChild<QAction*>(object)) set(action, icon);
    }
    const std::pair<QDockWidget*, const char*> docks[] = {
        {m_ui.segmentsDock, "camwright-segments"},
        {m_ui.jointsDock, "camwright-joints"},
        {m_ui.motionDock, "camwright-motion"},
        {m_ui.readoutDock, "camwright-readout"},
        {m_ui.machiningDock, "camwright-machining"},
        {m_ui.pathStudyDock, "camwright-path-study"},
        {m_views.followerDock, "camwright-follower"},
        {m_views.forcesDock, "camwright-forces"},
        {m_views.designDock, "camwright-motion-design"},
        {m_views.controlPointsDock, "camwright-control-points"},
    };
    for (const auto& [dock, icon] : docks) set(dock->toggleViewAction(), icon);
    // Every action's tooltip names its shortcut, in the desktop's words ("Strg+S" in German).
    for (QAction* action : m_window->findChildren<QAction*>()) {
        if (action->shortcut().isEmpty()) continue;
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        QString tip = action->toolTip();
        // Qt's default tooltip is the text without its '&': give it a sentence of its own.
        if (tip.contains(QLatin1Char('(') + keys + QLatin1Char(')'))) continue;
        action->setToolTip(tr("%1 (%2)").arg(tip, keys));
    }
}

QString WindowActions::aboutText() const {
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

void WindowActions::report(const EditOutcome& outcome, const QString& title) {
    if (!outcome.ok()) {
        if (!title.isEmpty()) QMessageBox::warning(m_window, title, outcome.problem);
        return;
    }
    if (!outcome.status.isEmpty()) m_window->statusBar()->showMessage(outcome.status, 6000);
    if (outcome.row >= 0) m_ui.segmentTable->selectRow(outcome.row);
    if (!outcome.details.isEmpty()) {
        // Not modal for the event loop: the window stays live, tests can read and close it.
        auto* box = new QMessageBox(QMessageBox::Information, title, outcome.status,
                                    QMessageBox::Ok, m_window);
        box->setObjectName("editDetailsBox");
        box->setInformativeText(outcome.details);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
}

void WindowActions::renameProject(const QString& name) {
    const std::string trimmed = name.trimmed().toStdString();
    if (trimmed == m_document->project().name) return;
    m_document->undoStack()->push(new SetProjectName(m_document, trimmed));
    m_window->statusBar()->showMessage(tr("Project renamed to “%1”").arg(name.trimmed()), 4000);
}

int WindowActions::selectedRow() const {
    const QModelIndex current = m_ui.segmentTable->currentIndex();
    return current.isValid() ? current.row() : -1;
}

}  // namespace cam
