#include "mainwindow.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QSaveFile>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableView>
#include <QTimer>
#include <cmath>

#include "common/angles.h"
#include "contour/fit_windows.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "fillet/fillet.h"
#include "io/project_json.h"
#include "models/arc_table_model.h"
#include "models/delegates.h"
#include "spline/circle_approximation.h"
#include "spline/teach_in.h"
#include "ui_mainwindow.h"
#include "views/contour_view.h"
#include "views/joints_panel.h"
#include "views/kinematics_plots.h"
#include "views/machining_panel.h"
#include "views/motion_panel.h"
#include "views/path_study_panel.h"
#include "views/plot_data.h"
#include "views/state_readout.h"

namespace cam {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* kFileFilter = QT_TRANSLATE_NOOP("cam::MainWindow", "Camwright projects (*.cam.json)");

QString diagnosticsText(const Diagnostics& diagnostics, int limit = 12) {
    QStringList lines;
    for (const Diagnostic& d : diagnostics) {
        if (lines.size() == limit) {
            lines << MainWindow::tr("… and %1 more").arg(diagnostics.size() - limit);
            break;
        }
        lines << QString::fromStdString(d.text());
    }
    return lines.join('\n');
}

/// The example projects: next to the binary when installed, in the source tree when built.
QStringList exampleDirectories() {
    return {QDir(QCoreApplication::applicationDirPath()).filePath("../share/camwright/examples"),
            QStringLiteral(CAMWRIGHT_SOURCE_EXAMPLES)};
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_ui(std::make_unique<Ui::MainWindow>()),
      m_document(new ProjectDocument(this)),
      m_model(new ArcTableModel(m_document, this)),
      m_engine(new ComputeEngine(this)) {
    m_ui->setupUi(this);
    setAcceptDrops(true);

    m_contour = new ContourView(m_document, this);
    m_plots = new KinematicsPlots(this);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setObjectName("mainSplitter");
    splitter->addWidget(m_contour);
    splitter->addWidget(m_plots);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({400, 600});  // 2 : 3 from the start, not from the size hints
    setCentralWidget(splitter);

    setUpDocks();
    setUpActions();

    m_validationLabel = new QLabel(this);
    m_validationLabel->setObjectName("validationLabel");
    m_computeLabel = new QLabel(this);
    m_computeLabel->setObjectName("computeLabel");
    // Permanent widgets: transient messages ("Saved …") appear beside them, never over them.
    statusBar()->addPermanentWidget(m_validationLabel);
    statusBar()->addPermanentWidget(m_computeLabel);

    connect(m_document, &ProjectDocument::changed, this, [this] {
        requestCompute();
        updateStatus();
    });
    connect(m_document, &ProjectDocument::modifiedChanged, this, &MainWindow::updateTitle);
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
    connect(m_plots, &KinematicsPlots::cursorMoved, this, [this](double x) {
        const auto& r = m_shown;
        if (!r) return;
        setCursorTime(r->axis == PlotAxis::Angle ? degToRad(x) / r->omega : x);
    });

    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    m_ui->machiningDock->hide();  // until the user opens it (the saved layout may show it)
    m_ui->pathStudyDock->hide();
    restoreState(settings.value("window/state").toByteArray());
    m_ui->actionAxisTime->setChecked(settings.value("view/timeAxis", false).toBool());
    rebuildRecentMenu();
    rebuildExamplesMenu();

    newProject();
}

MainWindow::~MainWindow() = default;

void MainWindow::setUpDocks() {
    QTableView* table = m_ui->segmentTable;
    table->setModel(m_model);
    auto* numbers = new NumberDelegate(table);
    auto* choices = new ChoiceDelegate(table);
    for (int c = 0; c < ArcTableModel::ColumnCount; ++c) {
        const bool choice = c == ArcTableModel::Type || c == ArcTableModel::Branch;
        table->setItemDelegateForColumn(
            c, choice ? static_cast<QAbstractItemDelegate*>(choices) : numbers);
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::AnyKeyPressed);
    connect(table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) { m_contour->setSelectedSegment(current.row()); });

    m_motion = new MotionPanel(m_document, m_ui->motionDock);
    m_ui->motionDock->setWidget(m_motion);
    m_readout = new StateReadout(m_ui->readoutDock);
    m_ui->readoutDock->setWidget(m_readout);
    splitDockWidget(m_ui->motionDock, m_ui->readoutDock, Qt::Vertical);
    m_joints = new JointsPanel(m_ui->jointsDock);
    m_ui->jointsDock->setWidget(m_joints);
    tabifyDockWidget(m_ui->segmentsDock, m_ui->jointsDock);
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
    resizeDocks({m_ui->motionDock, m_ui->readoutDock}, {140, 400}, Qt::Vertical);
    for (QDockWidget* dock : {m_ui->segmentsDock, m_ui->jointsDock, m_ui->motionDock,
                              m_ui->readoutDock, m_ui->machiningDock, m_ui->pathStudyDock}) {
        m_ui->menuView->addAction(dock->toggleViewAction());
    }
}

void MainWindow::setUpActions() {
    QUndoStack* stack = m_document->undoStack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    QAction* first = m_ui->menuEdit->actions().value(0);
    m_ui->menuEdit->insertAction(first, undo);
    m_ui->menuEdit->insertAction(first, redo);
    m_ui->menuEdit->insertSeparator(first);

    connect(m_ui->actionNew, &QAction::triggered, this, [this] {
        if (maybeSave()) newProject();
    });
    connect(m_ui->actionOpen, &QAction::triggered, this, [this] { openInteractive(); });
    connect(m_ui->actionSave, &QAction::triggered, this, &MainWindow::save);
    connect(m_ui->actionSaveAs, &QAction::triggered, this, &MainWindow::saveAs);
    connect(m_ui->actionQuit, &QAction::triggered, this, &QWidget::close);
    connect(m_ui->actionInsertSegment, &QAction::triggered, this, &MainWindow::insertSegment);
    connect(m_ui->actionDeleteSegment, &QAction::triggered, this, &MainWindow::deleteSegment);
    connect(m_ui->actionMoveUp, &QAction::triggered, this, [this] { moveSegment(-1); });
    connect(m_ui->actionMoveDown, &QAction::triggered, this, [this] { moveSegment(1); });
    connect(m_ui->actionFitWindows, &QAction::triggered, this, &MainWindow::fitWindows);
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
        QDialog dialog(this);
        dialog.setWindowTitle(tr("New Contour Through Points"));
        auto* form = new QFormLayout(&dialog);
        auto* points = new QPlainTextEdit(&dialog);
        points->setPlaceholderText(
            tr("x, y per line, in mm, counter-clockwise around the "
               "rotation centre"));
        points->setPlainText("20, 0\n14, 15\n-3, 22\n-18, 9\n-16, -12\n5, -19");
        auto* rule = new QComboBox(&dialog);
        rule->addItems({tr("Chord"), tr("Circumcircle"), tr("Oval")});
        rule->setCurrentIndex(2);
        auto* bulge = new QDoubleSpinBox(&dialog);
        bulge->setRange(0.05, 5.0);
        bulge->setSingleStep(0.05);
        bulge->setValue(1.0);
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
        form->addRow(tr("Points"), points);
        form->addRow(tr("Handle rule"), rule);
        form->addRow(tr("Bulge factor"), bulge);
        form->addRow(buttons);
        connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
        connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
        if (dialog.exec() != QDialog::Accepted) return;
        const QString problem =
            contourThroughPoints(points->toPlainText(), rule->currentIndex(), bulge->value());
        if (!problem.isEmpty()) QMessageBox::warning(this, dialog.windowTitle(), problem);
    });
    auto* round = new QAction(tr("&Round Corner…"), this);
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
        bool ok = false;
        const double max = range.value().maxRadius;
        const double rho =
            QInputDialog::getDouble(this, tr("Round Corner"),
                                    tr("Radius of the switch arc [mm] (below %1 mm fits):")
                                        .arg(QLocale().toString(max, 'g', 6)),
                                    std::min(max / 2.0, 5.0), 1e-6, max, 6, &ok);
        if (!ok) return;
        const QString problem = roundCorner(joint, rho);
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Round Corner"), problem);
    });
    connect(approximate, &QAction::triggered, this, [this] {
        bool ok = false;
        const double error =
            QInputDialog::getDouble(this, tr("Approximate Arc by Béziers"),
                                    tr("Admissible radial error [mm]:"), 0.001, 1e-9, 10.0, 6, &ok);
        if (!ok) return;
        const QString problem = approximateArc(selectedRow(), error);
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Approximate Arc"), problem);
    });
    connect(m_ui->actionAxisTime, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/timeAxis", on);
        requestCompute();
    });
    connect(m_ui->actionResetZoom, &QAction::triggered, this, [this] {
        m_contour->resetZoom();
        m_plots->resetZoom();
    });
    connect(m_ui->actionAbout, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About Camwright"),
                           tr("<b>Camwright %1</b><p>Design and inspect cam contours: exact polar "
                              "kinematics of the follower.</p><p>GPL-3.0-or-later.</p>")
                               .arg(QCoreApplication::applicationVersion()));
    });
    // Segment actions work on the table, so they do not steal Delete/Insert from other widgets.
    for (QAction* a : {m_ui->actionInsertSegment, m_ui->actionDeleteSegment, m_ui->actionMoveUp,
                       m_ui->actionMoveDown}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_ui->segmentTable->addAction(a);
    }
}

void MainWindow::newProject() {
    Project p;
    p.name = tr("Untitled").toStdString();
    p.motion = {SpeedUnit::PeriodS, 1.0};
    // An eccentric circle in two windows: a valid contour to start editing from.
    for (double start : {0.0, 180.0}) {
        SegmentSpec s;
        s.center = {5.0, 0.0};
        s.radius = 30.0;
        s.phiStartDeg = start;
        s.phiEndDeg = start + 180.0;
        p.contour.push_back(s);
    }
    m_document->reset(std::move(p), {});
}

QString MainWindow::loadFile(const QString& path) {
    auto loaded = loadProjectFile(path.toStdString());
    if (!loaded.ok()) {
        return tr("%1 cannot be opened:\n%2")
            .arg(QDir::toNativeSeparators(path), diagnosticsText(loaded.errors()));
    }
    m_document->reset(std::move(loaded).value(), QFileInfo(path).absoluteFilePath());
    addRecentFile(QFileInfo(path).absoluteFilePath());
    statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)), 4000);
    return {};
}

void MainWindow::openInteractive(const QString& givenPath) {
    if (!maybeSave()) return;
    QString path = givenPath;
    if (path.isEmpty()) {
        path = QFileDialog::getOpenFileName(this, tr("Open Project"),
                                            QSettings().value("files/lastDir").toString(),
                                            tr(kFileFilter));
        if (path.isEmpty()) return;
    }
    QSettings().setValue("files/lastDir", QFileInfo(path).absolutePath());
    const QString problem = loadFile(path);
    if (!problem.isEmpty()) QMessageBox::warning(this, tr("Open Project"), problem);
}

QString MainWindow::saveFile(const QString& path) {
    if (!m_document->isValid()) {
        return tr("The project has problems; fix them before saving (a file with these problems "
                  "could not be opened again):\n%1")
            .arg(diagnosticsText(m_document->diagnostics()));
    }
    QSaveFile file(path);
    const std::string text = serializeProject(m_document->project());
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(text.data(), static_cast<qint64>(text.size())) !=
            static_cast<qint64>(text.size()) ||
        !file.commit()) {
        return tr("%1 could not be written: %2")
            .arg(QDir::toNativeSeparators(path), file.errorString());
    }
    m_document->markSaved(QFileInfo(path).absoluteFilePath());
    addRecentFile(QFileInfo(path).absoluteFilePath());
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 4000);
    return {};
}

bool MainWindow::save() {
    if (m_document->filePath().isEmpty()) return saveAs();
    const QString problem = saveFile(m_document->filePath());
    if (!problem.isEmpty()) QMessageBox::warning(this, tr("Save Project"), problem);
    return problem.isEmpty();
}

bool MainWindow::saveAs() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"),
                                                m_document->filePath().isEmpty()
                                                    ? QSettings().value("files/lastDir").toString()
                                                    : m_document->filePath(),
                                                tr(kFileFilter));
    if (path.isEmpty()) return false;
    if (!path.endsWith(".cam.json")) path += ".cam.json";
    QSettings().setValue("files/lastDir", QFileInfo(path).absolutePath());
    const QString problem = saveFile(path);
    if (!problem.isEmpty()) QMessageBox::warning(this, tr("Save Project"), problem);
    return problem.isEmpty();
}

bool MainWindow::maybeSave() {
    if (!m_document->isModified()) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved Changes"),
        tr("%1 has unsaved changes. Save them?").arg(m_document->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
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
    openInteractive(event->mimeData()->urls().front().toLocalFile());
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value("files/recent").toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue("files/recent", files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    QMenu* menu = m_ui->menuRecent;
    menu->clear();
    const QStringList files = QSettings().value("files/recent").toStringList();
    for (const QString& f : files) {
        menu->addAction(QDir::toNativeSeparators(f), this, [this, f] { openInteractive(f); });
    }
    menu->setEnabled(!files.isEmpty());
}

void MainWindow::rebuildExamplesMenu() {
    QMenu* menu = m_ui->menuExamples;
    menu->clear();
    for (const QString& dir : exampleDirectories()) {
        const auto entries = QDir(dir).entryInfoList({"*.cam.json"}, QDir::Files, QDir::Name);
        for (const QFileInfo& f : entries) {
            const QString path = f.absoluteFilePath();
            menu->addAction(f.fileName().chopped(9), this, [this, path] {
                if (!maybeSave()) return;
                auto loaded = loadProjectFile(path.toStdString());
                if (!loaded.ok()) {
                    QMessageBox::warning(this, tr("Open Example"),
                                         diagnosticsText(loaded.errors()));
                    return;
                }
                // An example opens as an untitled copy: Save asks where, never over the example.
                m_document->reset(std::move(loaded).value(), {});
            });
        }
        if (!entries.isEmpty()) break;
    }
    menu->setEnabled(!menu->isEmpty());
}

void MainWindow::requestCompute() {
    // The machining times are computed only while their panel is open.
    const bool timing = !m_ui->machiningDock->isHidden();
    if (timing) m_machining->setPending();
    m_engine->request(m_document->project(),
                      m_ui->actionAxisTime->isChecked() ? PlotAxis::Time : PlotAxis::Angle, timing,
                      m_machining->plotMethod());
}

void MainWindow::showResult(const ComputeResultPtr& result) {
    // The views keep what they drew from the last computable result and mark it out of date.
    m_contour->setResult(result);
    m_plots->setResult(result);
    m_joints->setResult(result);
    m_pathStudy->setResult(result);
    if (!result->ok()) {
        const QString first = QString::fromStdString(result->errors.front().text());
        // The problems themselves are in the validation label beside it.
        m_computeLabel->setText(result->failed ? tr("not computed: %1").arg(first)
                                               : tr("not computed: the project has problems"));
        m_computeLabel->setStyleSheet("color: #b00020;");
        if (result->failed) statusBar()->showMessage(tr("Computation failed: %1").arg(first));
        m_readout->clear();  // no state of the project as it is
        emit resultShown(result);
        return;
    }
    m_shown = result;
    m_computeLabel->setStyleSheet({});
    setCursorTime(m_cursorT);
    m_computeLabel->setText(
        tr("%1 samples computed in %2 ms")
            .arg(QLocale().toString(static_cast<qlonglong>(result->sampleCount)),
                 QLocale().toString(result->computeMs, 'f', 1)));
    emit resultShown(result);
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
}

bool MainWindow::waitForCurrentResult(int timeoutMs) {
    const auto current = [this] {
        const auto& r = m_engine->latestResult();
        return r && r->generation == m_engine->latestGeneration();
    };
    if (current()) return true;
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, [&loop] { loop.exit(1); });
    connect(m_engine, &ComputeEngine::resultReady, &loop, [&loop, current] {
        if (current()) loop.exit(0);
    });
    return loop.exec() == 0;
}

QImage MainWindow::renderScreenshot(const QSize& size) {
    resize(size);
    show();
    QCoreApplication::processEvents();
    if (!waitForCurrentResult(20000)) return {};
    if (!m_ui->machiningDock->isHidden() && m_document->project().machining) {
        const auto current = [this] {
            const auto& t = m_engine->latestTiming();
            return t && t->generation == m_engine->latestGeneration();
        };
        QEventLoop loop;
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        connect(m_engine, &ComputeEngine::timingReady, &loop, [&] {
            if (current()) loop.quit();
        });
        if (!current()) loop.exec();
    }
    if (m_shown) setCursorTime(m_shown->period / 8.0);
    statusBar()->clearMessage();  // transient messages name paths: not part of the picture
    for (int p = 0; p < 3; ++p) m_plots->plot(p)->replot(QCustomPlot::rpImmediateRefresh);
    m_contour->replot(QCustomPlot::rpImmediateRefresh);
    QCoreApplication::processEvents();
    return grab().toImage();
}

void MainWindow::updateStatus() {
    const Diagnostics& d = m_document->diagnostics();
    const int n = static_cast<int>(m_document->project().contour.size());
    if (d.empty()) {
        m_validationLabel->setText(n == 1 ? tr("Valid · 1 segment")
                                          : tr("Valid · %1 segments").arg(n));
        m_validationLabel->setToolTip({});
        m_validationLabel->setStyleSheet({});
    } else {
        const QString first = QString::fromStdString(d.front().text());
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

void MainWindow::insertSegment() {
    const auto& contour = m_document->project().contour;
    const int row = selectedRow() < 0 ? static_cast<int>(contour.size()) : selectedRow() + 1;
    SegmentSpec s;
    if (row > 0) {
        // Split the window of the segment above: the new one takes its second half.
        s = contour.at(static_cast<std::size_t>(row - 1));
        const double mid = (s.phiStartDeg + s.phiEndDeg) / 2.0;
        SegmentSpec above = s;
        above.phiEndDeg = mid;
        s.phiStartDeg = mid;
        m_document->undoStack()->beginMacro(tr("Insert segment"));
        m_document->undoStack()->push(
            new EditSegment(m_document, row - 1, above, SegmentField::Whole, tr("Split window")));
        m_document->undoStack()->push(new InsertSegment(m_document, row, s));
        m_document->undoStack()->endMacro();
    } else {
        s.center = {0.0, 0.0};
        s.radius = 20.0;
        s.phiStartDeg = 0.0;
        s.phiEndDeg = 360.0;
        m_document->undoStack()->push(new InsertSegment(m_document, row, s));
    }
    m_ui->segmentTable->selectRow(row);
}

void MainWindow::deleteSegment() {
    const int row = selectedRow();
    if (row < 0) return;
    m_document->undoStack()->push(new RemoveSegment(m_document, row));
}

void MainWindow::moveSegment(int delta) {
    const int row = selectedRow();
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= static_cast<int>(m_document->project().contour.size())) return;
    m_document->undoStack()->push(new MoveSegment(m_document, row, to));
    m_ui->segmentTable->selectRow(to);
}

QString MainWindow::contourThroughPoints(const QString& pointsText, int rule, double bulge) {
    std::vector<Eigen::Vector2d> knots;
    const QStringList lines = pointsText.split('\n', Qt::SkipEmptyParts);
    for (int i = 0; i < lines.size(); ++i) {
        const QStringList cells = lines[i].split(',');
        bool okX = false, okY = false;
        const double x = cells.value(0).trimmed().toDouble(&okX);
        const double y = cells.value(1).trimmed().toDouble(&okY);
        if (cells.size() != 2 || !okX || !okY || !std::isfinite(x) || !std::isfinite(y)) {
            return tr("line %1: expected \"x, y\" (got \"%2\")").arg(i + 1).arg(lines[i]);
        }
        knots.emplace_back(x, y);
    }
    const auto contour = cam::contourThroughPoints(knots, static_cast<HandleRule>(rule), bulge);
    if (!contour.ok()) return diagnosticsText(contour.errors());
    m_document->undoStack()->push(
        new ReplaceContour(m_document, contour.value(), tr("New contour through points")));
    return {};
}

QString MainWindow::roundCorner(int joint, double rho) {
    if (joint < 0) return tr("Select the segment after the corner to round.");
    const auto result =
        filletJoint(m_document->project().contour, static_cast<std::size_t>(joint), rho);
    if (!result.ok()) return diagnosticsText(result.errors());
    m_document->undoStack()->push(
        new ReplaceContour(m_document, result.value().contour, tr("Round corner")));
    statusBar()->showMessage(
        tr("Corner rounded with a %1 mm switch arc").arg(QLocale().toString(rho, 'g', 6)), 6000);
    return {};
}

QString MainWindow::approximateArc(int row, double maxErrorMm) {
    if (row < 0) return tr("Select the arc to approximate first.");
    ArcApproximation report;
    const auto replaced = approximateArcSegment(m_document->project().contour,
                                                static_cast<std::size_t>(row), maxErrorMm, &report);
    if (!replaced.ok()) return diagnosticsText(replaced.errors());
    m_document->undoStack()->push(
        new ReplaceContour(m_document, replaced.value(), tr("Approximate arc by Béziers")));
    statusBar()->showMessage(tr("%n Bézier piece(s): radial error %1 mm, end/middle speed ratio %2",
                                "", static_cast<int>(report.pieces.size()))
                                 .arg(QLocale().toString(report.radialErrorMm, 'g', 3),
                                      QLocale().toString(report.speedRatio, 'f', 4)),
                             8000);
    return {};
}

void MainWindow::fitWindows() {
    const auto fitted = cam::fitWindows(m_document->project().contour);
    if (!fitted.ok()) {
        QMessageBox::warning(this, tr("Fit Windows"), diagnosticsText(fitted.errors()));
        return;
    }
    if (fitted.value() == m_document->project().contour) {
        statusBar()->showMessage(tr("The windows already fit."), 3000);
        return;
    }
    m_document->undoStack()->push(
        new ReplaceContour(m_document, fitted.value(), tr("Fit windows")));
}

}  // namespace cam
