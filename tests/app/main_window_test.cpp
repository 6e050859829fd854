// The main window as a user drives it: open, edit, save, reopen, bad files, and how it looks.

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QTranslator>
#include <QUrl>
#include <csignal>
#include <filesystem>
#include <fstream>

#include "app_test_support.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "screenshot.h"
#include "views/contour_view.h"
#include "views/joints_panel.h"
#include "views/path_study_panel.h"
#include "views/state_readout.h"

#include <qcustomplot.h>
#include <QTest>

namespace cam {
namespace {

using test::kExampleFile;

TEST(MainWindow, OpeningABadFileLeavesTheOpenDocumentUntouched) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.tableModel()->setData(window.tableModel()->index(1, SegmentTableModel::CenterX), 18.2,
                                 Qt::EditRole);
    const Project before = window.document()->project();
    const QString pathBefore = window.document()->filePath();
    const int undoBefore = window.document()->undoStack()->count();
    // Files that are no Camwright project at all: wrong JSON, a newer format, a string where a
    // number belongs, no file.
    for (const char* bad :
         {"invalid/type-string-for-number.cam.json", "invalid/syntax-truncated.cam.json",
          "invalid/identity-version-newer.cam.json", "invalid/nope.cam.json"}) {
        const QString message = window.loadFile(QString::fromStdString(test::dataPath(bad)));
        EXPECT_FALSE(message.isEmpty()) << bad;
        EXPECT_EQ(window.document()->project(), before) << bad;
        EXPECT_EQ(window.document()->filePath(), pathBefore);
        EXPECT_EQ(window.document()->undoStack()->count(), undoBefore);
        EXPECT_TRUE(window.document()->isModified());
    }
    const QString message = window.loadFile(
        QString::fromStdString(test::dataPath("invalid/identity-version-newer.cam.json")));
    EXPECT_TRUE(message.contains("version: this file has format version 2"))
        << message.toStdString();
}

TEST(MainWindow, EditSaveReopen) {
    QTemporaryDir dir;
    const QString path = dir.filePath("edited.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    // Two edits that keep the contour valid: the notch piece becomes a line, the speed halves.
    ASSERT_TRUE(window.tableModel()->setData(window.tableModel()->index(0, SegmentTableModel::Type),
                                             1, Qt::EditRole));
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 75.0}));
    window.document()->undoStack()->undo();
    window.document()->undoStack()->redo();
    const Project edited = window.document()->project();
    const QString problem = window.saveFile(path);
    ASSERT_TRUE(problem.isEmpty()) << problem.toStdString();
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_EQ(window.document()->filePath(), QFileInfo(path).absoluteFilePath());

    MainWindow other;
    ASSERT_TRUE(other.loadFile(path).isEmpty());
    EXPECT_EQ(serializeProject(other.document()->project()), serializeProject(edited));
    EXPECT_EQ(other.document()->project().contour[0].type(), SegmentType::Line);
    EXPECT_EQ(other.document()->project().motion.unit, SpeedUnit::Rpm);
}

// Save goes through the core's one writer, as the CLI's --out does.
TEST(MainWindow, SaveKeepsTheModeTheOwnerAndTheSymlinkOfTheFile) {
    namespace fs = std::filesystem;
    const test::TempDir dir;
    fs::create_directory(dir.path() / "projects");
    const std::string real = dir.file("projects/cam.cam.json");
    test::writeFileWithMode(real, "old", 0640);
    const bool root = ::geteuid() == 0;
    if (root) {
        ASSERT_EQ(::chown(real.c_str(), 1234, 5678), 0);
    }
    fs::create_symlink("projects/cam.cam.json", dir.path() / "current.cam.json");
    const QString link = QString::fromStdString(dir.file("current.cam.json"));

    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    const QString problem = window.saveFile(link);
    ASSERT_TRUE(problem.isEmpty()) << problem.toStdString();
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_TRUE(fs::is_symlink(dir.path() / "current.cam.json"));
    EXPECT_EQ(test::readFile(real), serializeProject(window.document()->project()));
    EXPECT_EQ(test::fileMode(real), 0640);
    struct stat st {};
    ASSERT_EQ(::stat(real.c_str(), &st), 0);
    if (root) {
        EXPECT_EQ(st.st_uid, 1234u);
        EXPECT_EQ(st.st_gid, 5678u);
    }
    EXPECT_EQ(test::folderEntries(dir.path() / "projects"),
              std::vector<std::string>{"cam.cam.json"});
}

TEST(MainWindow, SavingOverSomethingThatIsNotAFileIsRefusedAndLeavesItAlone) {
    namespace fs = std::filesystem;
    const test::TempDir dir;
    const std::string pipe = dir.file("pipe.cam.json");
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 75.0}));
    const QString message = window.saveFile(QString::fromStdString(pipe));
    EXPECT_TRUE(message.contains("is a FIFO, not a regular file")) << message.toStdString();
    EXPECT_TRUE(fs::is_fifo(pipe));
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"pipe.cam.json"});
    EXPECT_TRUE(window.document()->isModified());
}

TEST(MainWindow, ASaveThatFailsMidwayKeepsTheOldFileAndTheDocumentModified) {
    const test::TempDir dir;
    const std::string path = dir.file("cam.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(window.saveFile(QString::fromStdString(path)).isEmpty());
    const std::string saved = test::readFile(path);
    ASSERT_GT(saved.size(), 1024u);
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 75.0}));
    ASSERT_TRUE(window.document()->isModified());

    // A file size limit below the project's size: write() fails with EFBIG part-way through.
    // Restored at once; nothing else in this process writes files meanwhile.
    const auto oldHandler = ::signal(SIGXFSZ, SIG_IGN);
    rlimit oldLimit{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &oldLimit), 0);
    rlimit small = oldLimit;
    small.rlim_cur = 512;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    const QString message = window.saveFile(QString::fromStdString(path));
    ::setrlimit(RLIMIT_FSIZE, &oldLimit);
    ::signal(SIGXFSZ, oldHandler);

    EXPECT_TRUE(message.contains(QString::fromStdString(path))) << message.toStdString();
    EXPECT_TRUE(message.contains("File too large")) << message.toStdString();
    EXPECT_EQ(test::readFile(path), saved);
    EXPECT_TRUE(window.document()->isModified());
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"cam.cam.json"});
}

TEST(MainWindow, AnUnfinishedDesignOpensWithItsProblemsMarkedAndSavesAgain) {
    // window-gap: sound JSON of format 1, every value of the right type, but a 1° gap between
    // the windows of segments 0 and 1. It opens; the gap is listed and marked; it saves.
    const QString gap = QString::fromStdString(test::dataPath("invalid/window-gap.cam.json"));
    MainWindow window;
    ASSERT_TRUE(window.loadFile(gap).isEmpty());
    EXPECT_EQ(window.document()->filePath(), QFileInfo(gap).absoluteFilePath());
    EXPECT_FALSE(window.document()->isValid());
    ASSERT_FALSE(window.document()->diagnostics().empty());
    EXPECT_EQ(window.document()->diagnostics().front().text(),
              "contour[0]/contour[1]: gap of 1° between phi_end 180 and phi_start 181");
    EXPECT_FALSE(window.tableModel()->problemsAt(0, SegmentTableModel::PhiEnd).isEmpty());
    EXPECT_FALSE(window.tableModel()->problemsAt(1, SegmentTableModel::PhiStart).isEmpty());
    EXPECT_TRUE(window.findChild<QLabel*>("validationLabel")->text().startsWith("1 problem"));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("with 1 problem"))
        << window.statusBar()->currentMessage().toStdString();

    QTemporaryDir dir;
    const QString path = dir.filePath("parked.cam.json");
    const QString problem = window.saveFile(path);
    ASSERT_TRUE(problem.isEmpty()) << problem.toStdString();
    EXPECT_FALSE(window.document()->isModified());
    const std::string saved = test::readFile(path.toStdString());
    EXPECT_EQ(saved, serializeProject(window.document()->project()));
    MainWindow again;
    ASSERT_TRUE(again.loadFile(path).isEmpty());
    EXPECT_EQ(again.document()->project(), window.document()->project());
    // The CLI's computing commands still refuse it, naming the problem.
    const auto state = test::run(CAMWRIGHT_CLI, {"state", path.toStdString(), "--t", "0.1"});
    EXPECT_EQ(state.exitCode, 2);
    EXPECT_NE(state.err.find("contour[0]/contour[1]: gap of 1°"), std::string::npos) << state.err;
    EXPECT_EQ(test::run(CAMWRIGHT_CLI, {"validate", path.toStdString()}).exitCode, 2);
}

TEST(MainWindow, ANumberAFileCannotHoldIsNotSavedAndNothingIsWritten) {
    QTemporaryDir dir;
    const QString path = dir.filePath("bad.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    // No editor lets a NaN in; the document's own undo command is the only way to get one there.
    SegmentSpec s = window.document()->project().contour[2];
    std::get<Arc>(s.shape).radius = std::numeric_limits<double>::quiet_NaN();
    window.document()->undoStack()->push(
        new EditSegment(window.document(), 2, s, EditedField::Radius, "NaN"));
    const QString message = window.saveFile(path);
    EXPECT_TRUE(message.contains("Segment 2, Radius [mm]: is not a finite number"))
        << message.toStdString();
    EXPECT_FALSE(QFile::exists(path));
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

TEST(MainWindow, FitWindowsActionRepairsDisturbedBoundariesInOneUndoStep) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    SegmentTableModel* model = window.tableModel();
    model->setData(model->index(1, SegmentTableModel::PhiEnd), 51.0, Qt::EditRole);
    model->setData(model->index(2, SegmentTableModel::PhiStart), 51.0, Qt::EditRole);
    EXPECT_FALSE(window.document()->isValid());  // the joint no longer meets
    auto* fit = window.findChild<QAction*>("actionFitWindows");
    ASSERT_NE(fit, nullptr);
    fit->trigger();
    EXPECT_TRUE(window.document()->isValid());
    EXPECT_NEAR(window.document()->project().contour[1].phiEndDeg, 50.30859, 1e-5);
    window.document()->undoStack()->undo();
    EXPECT_DOUBLE_EQ(window.document()->project().contour[1].phiEndDeg, 51.0);
}

TEST(MainWindow, EditsReachThePlotsAndTheReadout) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    window.setCursorTime(0.05);
    // Lengths have 7 significant digits (widgets/quantity_format.h): 26.218824198 mm.
    EXPECT_TRUE(window.readout()->text().contains("r 26.21882 mm"))
        << window.readout()->text().toStdString();
    // Slower turning: every velocity halves; the readout follows the new result.
    auto* stack = window.document()->undoStack();
    stack->push(new SetMotion(window.document(), {SpeedUnit::PeriodS, 0.8}));
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    window.setCursorTime(0.1);                                          // the same angle, 45°
    EXPECT_TRUE(window.readout()->text().contains("v_φ 205.922 mm/s"))  // 6 digits
        << window.readout()->text().toStdString();
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(Translations, GermanIsEmbeddedAndComplete) {
    QTranslator german;
    ASSERT_TRUE(
        german.load(QLocale(QLocale::German, QLocale::Germany), "camwright", "_", ":/i18n"));
    QCoreApplication::installTranslator(&german);
    {
        MainWindow window;
        const auto menus = window.menuBar()->actions();
        ASSERT_FALSE(menus.isEmpty());
        EXPECT_EQ(menus.front()->text(), "&Datei");
        EXPECT_EQ(window.tableModel()->headerData(SegmentTableModel::Radius, Qt::Horizontal,
                                                  Qt::DisplayRole),
                  "Radius [mm]");
        EXPECT_EQ(window.tableModel()->index(0, SegmentTableModel::Type).data().toString(),
                  "Bogen");
    }
    QCoreApplication::removeTranslator(&german);
    // Every string has a translation: the .ts file says so for each message.
    const QString ts = QString::fromStdString(test::readFile(
        std::string(CAMWRIGHT_SOURCE_DIR) + "/resources/translations/camwright_de.ts"));
    EXPECT_FALSE(ts.contains("type=\"unfinished\""));
    EXPECT_GT(ts.count("<message>"), 100);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// Drags in the contour view from `from` to `to` (mm) in `steps` mouse moves, as a user would.
/// Drags from `from` to `to` (mm) in `steps` moves, with Alt held: no snapping, so the handle
/// lands where the mouse is (Construction.* tests snapping).
void dragInView(ContourView* view, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                int steps) {
    auto pixel = [view](const Eigen::Vector2d& p) {
        return QPointF(view->xAxis->coordToPixel(p.x()), view->yAxis->coordToPixel(p.y()));
    };
    QTest::mousePress(view, Qt::LeftButton, Qt::AltModifier, pixel(from).toPoint());
    for (int i = 1; i <= steps; ++i) {
        const QPointF p = pixel(from + (to - from) * i / steps);
        QMouseEvent move(QEvent::MouseMove, p, view->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                         Qt::AltModifier);
        QCoreApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, Qt::AltModifier, pixel(to).toPoint());
}

TEST(ContourView, DraggingTheCentreHandleIsOneUndoStep) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    ContourView* view = window.contourView();
    view->setSelectedSegment(3);  // the lobe at the top, centre (0, 20.9)
    view->replot(QCustomPlot::rpImmediateRefresh);
    const SegmentSpec before = window.document()->project().contour[3];
    const Arc& arcBefore = test::arcOf(before);
    dragInView(view, arcBefore.center, arcBefore.center + Eigen::Vector2d(1.0, 0.0), 5);
    const Arc arcAfter = test::arcOf(window.document()->project().contour[3]);
    EXPECT_NEAR(arcAfter.center.x(), arcBefore.center.x() + 1.0, 0.1);  // within a pixel or so
    EXPECT_NEAR(arcAfter.center.y(), arcBefore.center.y(), 0.1);
    EXPECT_EQ(arcAfter.radius, arcBefore.radius);
    EXPECT_EQ(window.document()->undoStack()->count(), 1);  // five moves, one gesture
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().contour[3], before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MainWindow, EditingARadiusThatOpensTheJointsReadsOutNoStateUntilTheyClose) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    const auto before = window.engine()->latestResult();
    SegmentTableModel* model = window.tableModel();
    ASSERT_TRUE(model->setData(model->index(1, SegmentTableModel::Radius), 8.5, Qt::EditRole));
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    const auto after = window.engine()->latestResult();
    ASSERT_NE(after, before);
    ASSERT_TRUE(after->ok());  // the contour is built and drawn while the designer edits
    ASSERT_FALSE(after->valid());
    EXPECT_DOUBLE_EQ(test::arcOf(after->project->contour[1]).radius, 8.5);
    // The plots keep the last valid cam, greyed; the cursor reads out nothing, not the state of
    // a cam whose joints are open (issue 29).
    window.setCursorTime(after->period * 30.0 / 360.0);
    EXPECT_TRUE(window.readout()->text().startsWith("t —"))
        << window.readout()->text().toStdString();
    // The document still reports the opened joints, and undo brings back the valid cam, whose
    // lobe tip at 30° is 29 mm out.
    EXPECT_FALSE(window.document()->isValid());
    window.document()->undoStack()->undo();
    EXPECT_TRUE(window.document()->isValid());
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    window.setCursorTime(after->period * 30.0 / 360.0);
    EXPECT_TRUE(window.readout()->text().contains("r 29 mm"))
        << window.readout()->text().toStdString();
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(ScreenshotCommand, WorksWithNoDisplayAndNoPlatformSet) {
    // The pitfall: QApplication aborts without a display unless the app picks offscreen itself.
    QTemporaryDir dir;
    const QString png = dir.filePath("window.png");
    const QByteArray platform = qgetenv("QT_QPA_PLATFORM"), display = qgetenv("DISPLAY");
    qunsetenv("QT_QPA_PLATFORM");
    qunsetenv("DISPLAY");
    qunsetenv("WAYLAND_DISPLAY");
    const auto run = test::run(CAMWRIGHT_APP, {"--screenshot", png.toStdString(), "--size",
                                               "900x600", kExampleFile.toStdString()});
    const auto bad = test::run(
        CAMWRIGHT_APP,
        {"--screenshot", png.toStdString(), test::dataPath("invalid/syntax-truncated.cam.json")});
    qputenv("QT_QPA_PLATFORM", platform);
    if (!display.isEmpty()) qputenv("DISPLAY", display);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const QImage image(png);
    EXPECT_EQ(image.size(), QSize(900, 600));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("cannot be opened"), std::string::npos) << bad.err;
}

TEST(MainWindow, RemembersTheDockLayout) {
    {
        MainWindow window;
        window.show();
        window.findChild<QDockWidget*>("readoutDock")->hide();
        window.close();
    }
    MainWindow again;
    again.show();
    EXPECT_FALSE(again.findChild<QDockWidget*>("readoutDock")->isVisible());
    EXPECT_TRUE(again.findChild<QDockWidget*>("segmentsDock")->isVisible());
    again.findChild<QDockWidget*>("readoutDock")->show();
    again.close();
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// Answers the next modal message box with `button` as soon as it appears.
void answerNextMessageBox(QMessageBox::StandardButton button, QString* text = nullptr) {
    QTimer::singleShot(0, [=] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) {
            answerNextMessageBox(button, text);  // not open yet: try again on the next turn
            return;
        }
        if (text) *text = box->text();
        box->button(button)->click();
    });
}

TEST(MainWindow, UnsavedChangesPromptCancelKeepsAndDiscardDrops) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 100.0}));
    auto* newAction = window.findChild<QAction*>("actionNew");
    QString asked;
    answerNextMessageBox(QMessageBox::Cancel, &asked);
    newAction->trigger();
    EXPECT_TRUE(asked.contains("unsaved changes")) << asked.toStdString();
    EXPECT_EQ(window.document()->project().motion.unit, SpeedUnit::Rpm);  // nothing lost
    EXPECT_TRUE(window.document()->isModified());
    answerNextMessageBox(QMessageBox::Discard);
    newAction->trigger();
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_EQ(window.document()->project().contour.size(), 2u);  // the new-project circle
    EXPECT_TRUE(window.document()->filePath().isEmpty());
}

/// A copy of the example of this test's own: opening a file another window holds asks first
/// (FileWatch::isOpenElsewhere), and the app_tests processes ctest runs side by side open the
/// bundled example all the time — a modal question no test answers.
QString privateExample(const QTemporaryDir& dir) {
    const QString copy = dir.filePath("six-lobe-arc-cam.cam.json");
    QFile::copy(kExampleFile, copy);
    return copy;
}

TEST(MainWindow, DroppingAProjectOpensItAndRecentFilesRememberIt) {
    QTemporaryDir dir;
    const QString example = privateExample(dir);
    MainWindow window;
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(example)});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &drop);
    EXPECT_EQ(window.document()->project().contour.size(), 13u);
    EXPECT_EQ(window.document()->filePath(), QFileInfo(example).absoluteFilePath());
    auto* recent = window.findChild<QMenu*>("menuRecent");
    ASSERT_NE(recent, nullptr);
    ASSERT_FALSE(recent->actions().isEmpty());
    EXPECT_EQ(recent->actions().front()->text(),
              QDir::toNativeSeparators(QFileInfo(example).absoluteFilePath()));
    delete mime;
}

TEST(MainWindow, CloseAsksAboutUnsavedChangesAndLeavesANewProject) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 100.0}));
    auto* close = window.findChild<QAction*>("actionClose");
    ASSERT_NE(close, nullptr);
    EXPECT_EQ(close->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_W));
    QString asked;
    answerNextMessageBox(QMessageBox::Cancel, &asked);
    close->trigger();
    EXPECT_TRUE(asked.contains("unsaved changes")) << asked.toStdString();
    EXPECT_EQ(window.document()->project().contour.size(), 13u);  // nothing lost
    EXPECT_EQ(window.document()->project().motion.unit, SpeedUnit::Rpm);
    answerNextMessageBox(QMessageBox::Discard);
    close->trigger();
    EXPECT_TRUE(window.document()->filePath().isEmpty());
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_EQ(window.document()->project().contour.size(), 2u);  // the new-project circle
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith("Closed "))
        << window.statusBar()->currentMessage().toStdString();
}

TEST(MainWindow, ARecentFileThatIsGoneIsRemovedWithOneMessage) {
    QTemporaryDir dir;
    const QString gone = dir.filePath("gone.cam.json");
    const QString kept = QFileInfo(privateExample(dir)).absoluteFilePath();
    QSettings().setValue("files/recent", QStringList{gone, kept});
    MainWindow window;
    auto* recent = window.findChild<QMenu*>("menuRecent");
    ASSERT_NE(recent, nullptr);
    ASSERT_EQ(recent->actions().size(), 4);  // two files, a separator, Clear Menu
    EXPECT_EQ(recent->actions().front()->text(), QDir::toNativeSeparators(gone));
    QString told;
    answerNextMessageBox(QMessageBox::Ok, &told);
    recent->actions().front()->trigger();
    EXPECT_TRUE(told.contains("gone.cam.json") && told.contains("no longer exists"))
        << told.toStdString();
    EXPECT_EQ(QSettings().value("files/recent").toStringList(), QStringList{kept});
    EXPECT_EQ(recent->actions().front()->text(), QDir::toNativeSeparators(kept));
    EXPECT_EQ(window.document()->project().contour.size(), 2u);  // nothing else happened
    // The one left opens.
    recent->actions().front()->trigger();
    EXPECT_EQ(window.document()->filePath(), kept);
}

TEST(MainWindow, ClearMenuForgetsTheRecentFiles) {
    QSettings().setValue("files/recent", QStringList{QFileInfo(kExampleFile).absoluteFilePath()});
    MainWindow window;
    auto* clear = window.findChild<QAction*>("actionClearRecent");
    ASSERT_NE(clear, nullptr);
    EXPECT_FALSE(clear->icon().isNull());
    clear->trigger();
    EXPECT_TRUE(QSettings().value("files/recent").toStringList().isEmpty());
    auto* recent = window.findChild<QMenu*>("menuRecent");
    EXPECT_TRUE(recent->actions().isEmpty());
    EXPECT_FALSE(recent->isEnabled());
    EXPECT_TRUE(QFileInfo::exists(kExampleFile));  // only the list is forgotten
}

TEST(MainWindow, ProjectNameRenamesTheProjectAsOneUndoStep) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    const std::string before = window.document()->project().name;
    auto* rename = window.findChild<QAction*>("actionRenameProject");
    ASSERT_NE(rename, nullptr);
    // File → Project Name… asks with the current name filled in; the user types a new one.
    QString offered;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        offered = dialog->textValue();
        dialog->setTextValue("  Lobe cam 7 ");
        dialog->accept();
    });
    rename->trigger();
    EXPECT_EQ(offered.toStdString(), before);
    EXPECT_EQ(window.document()->project().name, "Lobe cam 7");  // trimmed
    EXPECT_TRUE(window.document()->isModified());
    window.renameProject("Lobe cam 7");  // unchanged: no second step
    EXPECT_EQ(window.document()->undoStack()->count(), 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), "Rename project");
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().name, before);
    window.document()->undoStack()->redo();
    // Saved with the project.
    QTemporaryDir dir;
    ASSERT_TRUE(window.saveFile(dir.filePath("named.cam.json")).isEmpty());
    EXPECT_EQ(loadProjectFile(dir.filePath("named.cam.json").toStdString()).value().name,
              "Lobe cam 7");
}

TEST(MainWindow, ExamplesOpenAsUntitledCopies) {
    MainWindow window;
    auto* examples = window.findChild<QMenu*>("menuExamples");
    ASSERT_NE(examples, nullptr);
    ASSERT_FALSE(examples->actions().isEmpty());
    // Every bundled example, read from the binary's resources: no source tree needed
    // (packaging.NoSourcePathsInTheBinaries checks that its path is not even in the binary).
    QStringList bundled, listed;
    for (const auto& e : std::filesystem::directory_iterator(CAMWRIGHT_EXAMPLES)) {
        const QString name = QString::fromStdString(e.path().filename().string());
        if (name.endsWith(".cam.json")) bundled << name.chopped(9);
    }
    bundled.sort();
    for (const QAction* a : examples->actions()) listed << a->text();
    EXPECT_EQ(listed.join(", ").toStdString(), bundled.join(", ").toStdString());
    EXPECT_TRUE(QFile::exists(":/examples/six-lobe-arc-cam.cam.json"));
    const QList<QAction*> actions = examples->actions();
    const auto sixLobe = std::find_if(actions.begin(), actions.end(),
                                      [](QAction* a) { return a->text() == "six-lobe-arc-cam"; });
    ASSERT_NE(sixLobe, actions.end());
    (*sixLobe)->trigger();
    EXPECT_EQ(window.document()->project().contour.size(), 13u);
    EXPECT_TRUE(window.document()->filePath().isEmpty());  // Save asks where: never over it
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(ContourView, DraggingABezierHandleShapesTheCurveInOneUndoStep) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    SegmentTableModel* model = window.tableModel();
    ASSERT_TRUE(
        model->setData(model->index(3, SegmentTableModel::Type), 2, Qt::EditRole));  // Bézier
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    ContourView* view = window.contourView();
    view->setSelectedSegment(3);
    view->replot(QCustomPlot::rpImmediateRefresh);
    const SegmentSpec before = window.document()->project().contour[3];
    const int steps = window.document()->undoStack()->count();
    const CubicBezier& curveBefore = std::get<CubicBezier>(before.shape);
    const Eigen::Vector2d p1 = curveBefore.p[1];
    dragInView(view, p1, p1 + Eigen::Vector2d(0, 1), 4);
    const CubicBezier curveAfter =
        std::get<CubicBezier>(window.document()->project().contour[3].shape);
    EXPECT_NEAR((curveAfter.p[1] - (p1 + Eigen::Vector2d(0, 1))).norm(), 0.0, 0.1);
    EXPECT_EQ(curveAfter.p[0], curveBefore.p[0]);  // the ends stay on the joints
    EXPECT_EQ(curveAfter.p[3], curveBefore.p[3]);
    EXPECT_EQ(curveAfter.p[2], curveBefore.p[2]);
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().contour[3], before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MainWindow, ApproximatingAnArcIsOneUndoStepAndKeepsTheCamValid) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    const Project before = window.document()->project();
    EXPECT_TRUE(window.approximateArc(1, 1e-5).isEmpty());
    const auto& contour = window.document()->project().contour;
    EXPECT_GT(contour.size(), before.contour.size());
    EXPECT_EQ(contour[1].type(), SegmentType::Bezier);
    EXPECT_TRUE(window.document()->isValid());
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), before);
    EXPECT_FALSE(window.approximateArc(-1, 1e-5).isEmpty());  // nothing selected
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MainWindow, RoundingACornerIsOneUndoStepOrSaysWhyNot) {
    MainWindow window;
    const QString square = QString::fromStdString(
        (std::filesystem::temp_directory_path() / "camwright_app_square.cam.json").string());
    {
        std::ofstream(square.toStdString()) << R"({"format": "camwright", "version": 1,
          "motion": {"period_s": 1},
          "contour": [{"type": "line", "from": [10, -10], "to": [10, 10]},
                      {"type": "line", "from": [10, 10], "to": [-10, 10]},
                      {"type": "line", "from": [-10, 10], "to": [-10, -10]},
                      {"type": "line", "from": [-10, -10], "to": [10, -10]}]})";
    }
    ASSERT_TRUE(window.loadFile(square).isEmpty());
    const Project before = window.document()->project();
    EXPECT_TRUE(window.roundCorner(1, 4.0).isEmpty());
    EXPECT_EQ(window.document()->project().contour.size(), 5u);
    EXPECT_TRUE(window.document()->isValid());
    const QString refused = window.roundCorner(2, 30.0);
    EXPECT_TRUE(refused.contains("30 mm")) << refused.toStdString();
    EXPECT_EQ(window.document()->undoStack()->count(), 1);  // the refusal changed nothing
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(JointsPanel, ListsEveryJointAndClickingOneGoesThere) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    JointsPanel* joints = window.jointsPanel();
    ASSERT_EQ(joints->rowCount(), 13);
    EXPECT_EQ(joints->item(0, 2)->text(), "C1");   // lobe meets notch: the acceleration jumps
    EXPECT_EQ(joints->item(12, 2)->text(), "C2");  // the notch at 0° split in two
    // Joint 2|3 sits at 69.69141°: clicking it moves the readout there.
    QTest::mouseClick(joints->viewport(), Qt::LeftButton, {},
                      joints->visualItemRect(joints->item(2, 0)).center());
    EXPECT_TRUE(window.readout()->text().contains("φ 69.69141°"))
        << window.readout()->text().toStdString();
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(PathStudyPanel, ShowsTheSplinesAnalyticAndByDifferenceQuotient) {
    MainWindow window;
    const QString mixed = QString::fromStdString(test::dataPath("reference/spline-mix.cam.json"));
    ASSERT_TRUE(window.loadFile(mixed).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("pathStudyDock")->show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    // One Bézier and one Hermite: two pieces of 101 samples each.
    QCustomPlot* first = window.pathStudyPanel()->plot(1);
    EXPECT_EQ(first->graph(0)->data()->size(), 202);
    EXPECT_EQ(first->graph(2)->data()->size(), 202);
    // The differences are the O(h²) truncation: small against the derivatives themselves.
    QCustomPlot* diff = window.pathStudyPanel()->plot(3);
    double worst = 0.0;
    for (auto it = diff->graph(0)->data()->constBegin(); it != diff->graph(0)->data()->constEnd();
         ++it) {
        worst = std::max(worst, std::abs(it->value));
    }
    EXPECT_GT(worst, 0.0);
    EXPECT_LT(worst, 1e-2);
    EXPECT_TRUE(first->isVisible());
    // A contour of arcs only: the note says there is nothing to study, and no empty axes show.
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    QCoreApplication::processEvents();
    for (int p = 0; p < 4; ++p) EXPECT_FALSE(window.pathStudyPanel()->plot(p)->isVisible()) << p;
    const auto* note = window.pathStudyPanel()->findChild<QLabel*>();
    ASSERT_NE(note, nullptr);
    EXPECT_EQ(note->text(), "The contour has no Bézier or Hermite segment.");
    EXPECT_TRUE(note->isVisible());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MainWindow, ContourThroughPointsIsOneUndoStepAndBadLinesAreNamed) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    const Project before = window.document()->project();
    const QString points = "20, 0\n14, 15\n-3, 22\n-18, 9\n-16, -12\n5, -19\n";
    EXPECT_TRUE(window.contourThroughPoints(points, 2, 1.0).isEmpty());
    EXPECT_EQ(window.document()->project().contour.size(), 6u);
    EXPECT_EQ(window.document()->project().contour[0].type(), SegmentType::Bezier);
    EXPECT_TRUE(window.document()->isValid());
    EXPECT_TRUE(window.contourThroughPoints("20, 0\n14, x\n", 2, 1.0).contains("line 2"));
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), before);
}

}  // namespace
}  // namespace cam
