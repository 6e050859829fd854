// The Motion Design dock (math.md §8): a design without a contour opens and draws its law;
// every edit of the segment table, base radius and tolerance is an undo step; Synthesize runs
// in a worker, replaces the contour in one undo step (or says why not and changes nothing),
// and can be cancelled; the kinematics plots then draw the law over the follower on the arcs.
// The law's numbers are checked against the closed form of the cycloid, written out here.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <limits>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "design/sizing.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "follower/follower.h"
#include "mainwindow.h"
#include "models/delegates.h"
#include "models/design_table_model.h"
#include "models/segment_table_model.h"
#include "views/feasible_region_plot.h"
#include "views/kinematics_plots.h"
#include "views/motion_design_panel.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

const QString kDesignOnly =
    QString::fromStdString(test::dataPath("app/design-roller-no-contour.cam.json"));
constexpr double kPi_ = 3.14159265358979323846;

/// The cycloidal rise of h over beta (rad) at phi (math.md §8, VDI 2143), and its first and
/// second derivatives by phi: h(x − sin 2πx / 2π), x = phi/beta.
struct Cycloid {
    double h, beta;
    [[nodiscard]] double s(double phi) const {
        const double x = phi / beta;
        return h * (x - std::sin(2 * kPi_ * x) / (2 * kPi_));
    }
    [[nodiscard]] double ds(double phi) const {
        return h / beta * (1 - std::cos(2 * kPi_ * phi / beta));
    }
    [[nodiscard]] double dds(double phi) const {
        return 2 * kPi_ * h / (beta * beta) * std::sin(2 * kPi_ * phi / beta);
    }
};

/// The example design's lift at phi (deg): cycloidal rise 0–120°, dwell, cycloidal return
/// 180–300°, dwell; 10 mm.
double liftDeg(double deg) {
    const Cycloid rise{10.0, degToRad(120.0)};
    if (deg <= 120.0) return rise.s(degToRad(deg));
    if (deg <= 180.0) return 10.0;
    if (deg <= 300.0) return 10.0 - rise.s(degToRad(deg - 180.0));
    return 0.0;
}

/// The graph's value at the sample nearest x.
double valueAt(const QCPGraph* graph, double x) {
    auto it = graph->data()->findBegin(x, true);
    double best = it->value, distance = std::abs(it->key - x);
    for (int k = 0; k < 2 && it != graph->data()->constEnd(); ++k, ++it) {
        if (std::abs(it->key - x) < distance) {
            distance = std::abs(it->key - x);
            best = it->value;
        }
    }
    EXPECT_LT(distance, 0.06) << "no sample near " << x;
    return best;
}

/// Shows the window at the development screen's size, active, with the design without a
/// contour loaded.
bool showWithTheDesign(MainWindow& w) {
    w.resize(1400, 860);
    w.show();
    QApplication::setActiveWindow(&w);
    return w.loadFile(kDesignOnly).isEmpty();
}

bool waitForResult(MainWindow& w) {
    return w.waitForCurrentResult(test::kSanitized ? 60000 : 20000);
}

/// Runs Synthesize and waits for its end; the problem (empty: the contour was replaced).
QString synthesizeAndWait(MainWindow& w) {
    QSignalSpy finished(&w, &MainWindow::synthesisFinished);
    if (!w.synthesize()) return QStringLiteral("not started");
    if (!finished.wait(test::kSanitized ? 120000 : 30000)) return QStringLiteral("no end");
    return finished.front().front().toString();
}

TEST(MotionDesign, ADesignWithoutAContourOpensAndDrawsItsLaw) {
    MainWindow window;
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ASSERT_TRUE(waitForResult(window));
    ProjectDocument* doc = window.document();
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    EXPECT_TRUE(doc->awaitsSynthesis());
    const ComputeResultPtr& result = window.engine()->latestResult();
    ASSERT_TRUE(result);
    EXPECT_TRUE(result->awaitsContour());
    // The views draw nothing of an earlier project and say what to do.
    EXPECT_NE(window.plots()->staleReason().indexOf("No contour yet"), -1)
        << window.plots()->staleReason().toStdString();
    for (int p = 0; p < 3; ++p) {
        for (int g = 0; g < window.plots()->plot(p)->graphCount(); ++g) {
            EXPECT_EQ(window.plots()->plot(p)->graph(g)->dataCount(), 0) << p << " " << g;
        }
    }
    EXPECT_FALSE(window.shownResult());
    EXPECT_NE(window.findChild<QLabel*>("validationLabel")->text().indexOf("no contour yet"), -1);
    EXPECT_TRUE(window.synthesizeAction()->isEnabled());
    // The dock is shown, and its lift is the cycloid's (1 rpm-free: 60 rpm, ω = 2π/s).
    EXPECT_TRUE(window.findChild<QDockWidget*>("motionDesignDock")->isVisible());
    MotionDesignPanel* panel = window.motionDesignPanel();
    const QCPGraph* lift = panel->plot(0)->graph(0);
    ASSERT_EQ(lift->dataCount(), 3601);
    EXPECT_EQ(panel->plot(0)->graph(1)->dataCount(), 0);  // no contour to ride yet
    const double omega = kTwoPi;
    const Cycloid rise{10.0, degToRad(120.0)};
    for (double deg : {0.0, 17.3, 45.0, 60.0, 100.1, 150.0, 200.0, 250.5, 330.0}) {
        EXPECT_NEAR(valueAt(lift, deg), liftDeg(deg), 1e-12) << deg;
    }
    // Velocity and acceleration at the project's speed: ω s', ω² s''.
    for (double deg : {10.0, 30.0, 60.0, 90.0}) {
        EXPECT_NEAR(valueAt(panel->plot(1)->graph(0), deg), omega * rise.ds(degToRad(deg)), 1e-9)
            << deg;
        EXPECT_NEAR(valueAt(panel->plot(2)->graph(0), deg), omega * omega * rise.dds(degToRad(deg)),
                    1e-8)
            << deg;
    }
    // Cv, Ca, Cj of the cycloid (math.md §8's table: 2, 2π, 4π²) in the table.
    DesignTableModel* model = panel->model();
    ASSERT_EQ(model->rowCount(), 4);
    EXPECT_NEAR(model->index(0, DesignTableModel::Cv).data(Qt::EditRole).toDouble(), 2.0, 1e-9);
    EXPECT_NEAR(model->index(0, DesignTableModel::Ca).data(Qt::EditRole).toDouble(), 2 * kPi_,
                1e-6);
    EXPECT_NEAR(model->index(0, DesignTableModel::Cj).data(Qt::EditRole).toDouble(),
                4 * kPi_ * kPi_, 1e-4);
    EXPECT_FALSE(model->index(1, DesignTableModel::Cv).data(Qt::EditRole).isValid());  // dwell
    // Nothing of a contour can be exported, and it says why.
    QSignalSpy exported(&window, &MainWindow::exportFinished);
    test::TempDir dir;
    ExportRequest request;
    request.format = ExportFormat::Dxf;
    request.path = QString::fromStdString(dir.file("none.dxf"));
    window.exportFile(request);
    ASSERT_EQ(exported.size(), 1);
    EXPECT_NE(exported.front().at(1).toString().indexOf("no contour yet"), -1);
    EXPECT_FALSE(std::filesystem::exists(dir.file("none.dxf")));
}

TEST(MotionDesign, SynthesizeReplacesTheContourInOneUndoStepAndThePlotsShowTheLaw) {
    MainWindow window;
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ASSERT_TRUE(waitForResult(window));
    ProjectDocument* doc = window.document();
    const int steps = doc->undoStack()->count();
    ASSERT_EQ(synthesizeAndWait(window), QString());
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    const Project made = doc->project();
    ASSERT_GT(made.contour.size(), 10u);
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    EXPECT_FALSE(doc->awaitsSynthesis());
    ASSERT_TRUE(waitForResult(window));
    ASSERT_TRUE(window.shownResult());
    // The kinematics plots draw the law (dashed) and the follower on the arcs.
    EXPECT_TRUE(window.plots()->showsDesign());
    // The follower placed by contact on the new contour, by the core here, follows the closed
    // form within the tolerance (0.001 mm, over cos of a pressure angle below 11°).
    auto contour = Contour::build(made);
    ASSERT_TRUE(contour.ok());
    auto follower = FollowerModel::build(contour.value(), *made.follower);
    ASSERT_TRUE(follower.ok());
    const double omega = made.motion.omegaRadS();
    double worst = 0.0;
    for (int k = 0; k < 720; ++k) {
        const double deg = 0.5 * k + 0.123;
        const FollowerState st = follower.value().at(degToRad(deg), omega);
        // s is the roller centre's distance from the cam centre: base + roller + lift.
        worst = std::max(worst, std::abs(st.s - (40.0 + 8.0 + liftDeg(deg))));
    }
    EXPECT_LT(worst, 0.00102);
    EXPECT_GT(worst, 1e-5);  // arcs, not the exact profile
    // The dock's follower curve is that follower: its lift within the same bound of the law.
    const QCPGraph* onContour = window.motionDesignPanel()->plot(0)->graph(1);
    ASSERT_EQ(onContour->dataCount(), 3601);
    for (double deg : {5.0, 60.0, 150.0, 240.0, 330.0}) {
        EXPECT_NEAR(valueAt(onContour, deg), liftDeg(deg), 0.00102) << deg;
    }
    EXPECT_NE(window.motionDesignPanel()->reportText().indexOf("Last synthesis"), -1);
    // The same design again gives the same arcs: no second undo step.
    ASSERT_EQ(synthesizeAndWait(window), QString());
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    // One undo step takes the whole contour back, one redo brings it again; the report
    // speaks only of the contour it made (issue 31: it stayed after Undo and Open).
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->project().contour.empty());
    EXPECT_TRUE(doc->awaitsSynthesis());
    EXPECT_EQ(window.motionDesignPanel()->reportText().indexOf("Last synthesis"), -1);
    EXPECT_NE(window.motionDesignPanel()->reportText().indexOf("Synthesize fits"), -1);
    doc->undoStack()->redo();
    EXPECT_EQ(doc->project().contour, made.contour);
    EXPECT_NE(window.motionDesignPanel()->reportText().indexOf("Last synthesis"), -1);
    // Another file: its own words.
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    EXPECT_EQ(window.motionDesignPanel()->reportText().indexOf("Last synthesis"), -1);
}

TEST(MotionDesign, EditingTheSegmentTableIsUndoableAndMarksTheCellsItBreaks) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    DesignTableModel* model = window.motionDesignPanel()->model();
    const DesignSpec before = *doc->project().design;
    // Typing 12.5 as the first segment's lift: the dwell after it now starts at 12.5, not 10.
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::Lift), 12.5, Qt::EditRole));
    EXPECT_EQ(doc->project().design->segments[0].lift, 12.5);
    EXPECT_FALSE(doc->isValid());
    EXPECT_FALSE(model->problemsAt(1, DesignTableModel::Lift).isEmpty());
    EXPECT_EQ(model->index(1, DesignTableModel::Lift).data(Qt::BackgroundRole).value<QColor>(),
              QColor(255, 205, 205));
    doc->undoStack()->undo();
    EXPECT_EQ(*doc->project().design, before);
    EXPECT_TRUE(doc->isValid());
    EXPECT_TRUE(model->problemsAt(1, DesignTableModel::Lift).isEmpty());
    // A law: harmonic's Cv is π/2; poly5 opens its boundary values for editing.
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::Law),
                               static_cast<int>(MotionLawType::Harmonic), Qt::EditRole));
    EXPECT_EQ(doc->project().design->segments[0].law, MotionLawType::Harmonic);
    EXPECT_NEAR(model->index(0, DesignTableModel::Cv).data(Qt::EditRole).toDouble(), kPi_ / 2,
                1e-9);
    EXPECT_FALSE(model->flags(model->index(0, DesignTableModel::V0)) & Qt::ItemIsEditable);
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::Law),
                               static_cast<int>(MotionLawType::Poly5), Qt::EditRole));
    EXPECT_TRUE(model->flags(model->index(0, DesignTableModel::V1)) & Qt::ItemIsEditable);
    // Steps of one gesture (a spin-box session) are one undo step.
    const int steps = doc->undoStack()->count();
    for (double v : {0.01, 0.02, 0.03}) {
        ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::V1), QVariantList{v, 777},
                                   SegmentTableModel::MergingEditRole));
    }
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_EQ(doc->project().design->segments[0].v1, 0.03);
    // A value that is no number is refused and leaves no step.
    EXPECT_FALSE(model->setData(model->index(0, DesignTableModel::ToDeg),
                                std::numeric_limits<double>::quiet_NaN(), Qt::EditRole));
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    // Read-only columns stay so.
    EXPECT_FALSE(model->setData(model->index(0, DesignTableModel::FromDeg), 5.0, Qt::EditRole));
    EXPECT_FALSE(model->setData(model->index(0, DesignTableModel::Cv), 5.0, Qt::EditRole));
    while (doc->undoStack()->canUndo()) doc->undoStack()->undo();
    EXPECT_EQ(*doc->project().design, before);
}

/// Collects what Qt's item views print of their editors (warnings) while it lives; other
/// threads' words (the engine's, the platform plugin's) are not this test's.
class QtMessages {
public:
    QtMessages() { m_previous = qInstallMessageHandler(&QtMessages::take); }
    ~QtMessages() { qInstallMessageHandler(m_previous); }
    static QStringList& list() {
        static QStringList messages;
        return messages;
    }

private:
    static void take(QtMsgType type, const QMessageLogContext&, const QString& text) {
        if (type != QtDebugMsg && type != QtInfoMsg && text.contains("edit", Qt::CaseInsensitive)) {
            list() << text;
        }
    }
    QtMessageHandler m_previous;
};

TEST(MotionDesign, PickingALawLeavesTheTableWhereItWas) {
    // Issue 31, point 7: the columns were fitted anew after each law change, so a click meant
    // for "To" landed in another cell; and Qt printed editor warnings when a law was picked.
    MainWindow window;
    ASSERT_TRUE(showWithTheDesign(window));
    QTableView* table = window.motionDesignPanel()->table();
    const QModelIndex law = table->model()->index(0, DesignTableModel::Law);
    table->setFocus();
    table->setCurrentIndex(law);
    table->edit(law);
    QCoreApplication::processEvents();
    auto* combo = table->findChild<QComboBox*>();
    ASSERT_NE(combo, nullptr);
    // The column and its editor fit the longest name of the list, whichever law is chosen.
    int longest = 0;
    for (const QString& name : DesignTableModel::lawNames()) {
        longest = std::max(longest, combo->fontMetrics().horizontalAdvance(name));
    }
    EXPECT_GE(table->columnWidth(DesignTableModel::Law), longest);
    EXPECT_GT(combo->width(), longest);
    QTest::keyClick(combo, Qt::Key_Escape);
    QCoreApplication::processEvents();
    std::vector<int> where;
    for (int c = 0; c < DesignTableModel::ColumnCount; ++c) {
        where.push_back(table->columnViewportPosition(c));
    }
    // Pick each law in turn from the open editor, as the keyboard does, and close it with
    // Enter: the document follows, the columns stay, the cell stays current, Qt says nothing.
    QtMessages messages;
    QtMessages::list().clear();
    ProjectDocument* doc = window.document();
    for (int pick = 0; pick < static_cast<int>(DesignTableModel::lawNames().size()); ++pick) {
        table->setCurrentIndex(law);
        table->edit(law);
        QCoreApplication::processEvents();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);  // closed editors
        combo = table->findChild<QComboBox*>();
        ASSERT_NE(combo, nullptr) << pick;
        combo->setCurrentIndex(pick);
        emit combo->activated(pick);
        QTest::keyClick(combo, Qt::Key_Return);
        QCoreApplication::processEvents();
        EXPECT_EQ(static_cast<int>(doc->project().design->segments[0].law), pick);
        EXPECT_EQ(table->currentIndex(), law) << pick;
        for (int c = 0; c < DesignTableModel::ColumnCount; ++c) {
            EXPECT_EQ(table->columnViewportPosition(c), where[static_cast<std::size_t>(c)])
                << "column " << c << " after law " << pick;
        }
    }
    EXPECT_TRUE(QtMessages::list().isEmpty()) << QtMessages::list().join('\n').toStdString();
}

TEST(MotionDesign, AKeyInAComputedCellIsAnsweredAndTabPassesOverCellsALawHasNot) {
    MainWindow window;
    ASSERT_TRUE(showWithTheDesign(window));
    QTableView* table = window.motionDesignPanel()->table();
    QAbstractItemModel* model = table->model();
    const Project before = window.document()->project();
    table->setFocus();
    table->setCurrentIndex(model->index(1, DesignTableModel::FromDeg));
    QTest::keyClick(table, Qt::Key_5);
    EXPECT_EQ(window.document()->project(), before);
    EXPECT_EQ(window.statusBar()->currentMessage().toStdString(),
              "From [°], row 1 is not typed in: Where the segment starts: the previous "
              "segment's end");
    // A cycloid has no boundary values or parameters: Tab from Lift goes past them to its
    // boundary classes.
    table->setCurrentIndex(model->index(1, DesignTableModel::Lift));
    QTest::keyClick(table, Qt::Key_Tab);
    EXPECT_EQ(table->currentIndex(), model->index(1, DesignTableModel::StartClass));
}

TEST(MotionDesign, AFieldSaysWhatItRefusesByItsLabel) {
    // Issue 31, point 7: a refused key or number used to vanish without a word.
    MainWindow window;
    ASSERT_TRUE(showWithTheDesign(window));
    ProjectDocument* doc = window.document();
    const Project before = doc->project();
    const int steps = doc->undoStack()->count();
    auto* box = window.motionDesignPanel()->findChild<NumberSpinBox*>("baseRadiusSpinBox");
    ASSERT_NE(box, nullptr);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, "-5");
    QTest::keyClick(box, Qt::Key_Return);
    EXPECT_EQ(doc->project(), before);
    EXPECT_EQ(doc->undoStack()->count(), steps);
    EXPECT_EQ(window.statusBar()->currentMessage().toStdString(),
              "Base radius: -5 is outside 1E-06 … 1000000 mm; it stays 40 mm.");
    QTest::keyClick(box, Qt::Key_Q);
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith("Base radius: “q” cannot be"))
        << window.statusBar()->currentMessage().toStdString();
    EXPECT_EQ(doc->project(), before);
}

TEST(MotionDesign, NewSplitDeleteAndRemoveAreUndoSteps) {
    MainWindow window;
    ProjectDocument* doc = window.document();
    MotionDesignPanel* panel = window.motionDesignPanel();
    ASSERT_FALSE(doc->project().design);
    EXPECT_FALSE(window.synthesizeAction()->isEnabled());
    panel->newDesign();
    ASSERT_TRUE(doc->project().design);
    EXPECT_TRUE(window.synthesizeAction()->isEnabled());
    const DesignSpec fresh = *doc->project().design;
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    EXPECT_EQ(fresh.segments.size(), 4u);
    panel->splitSegment(0);
    const auto& split = doc->project().design->segments;
    ASSERT_EQ(split.size(), 5u);
    EXPECT_EQ(split[0].toDeg, 60.0);
    EXPECT_EQ(split[1].law, MotionLawType::Dwell);
    EXPECT_EQ(split[1].toDeg, 120.0);
    EXPECT_EQ(split[1].lift, 10.0);
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    panel->deleteSegment(1);  // the rise takes its stretch back
    EXPECT_EQ(*doc->project().design, fresh);
    EXPECT_EQ(doc->undoStack()->count(), 3);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->project().design->segments.size(), 5u);
    doc->undoStack()->undo();
    EXPECT_EQ(*doc->project().design, fresh);
    panel->deleteSegment(99);  // no such row: nothing happens
    EXPECT_EQ(doc->undoStack()->index(), 1);
    auto* remove = panel->findChild<QPushButton*>("removeDesignButton");
    ASSERT_NE(remove, nullptr);
    remove->click();
    EXPECT_FALSE(doc->project().design);
    EXPECT_FALSE(window.synthesizeAction()->isEnabled());
    doc->undoStack()->undo();
    EXPECT_EQ(*doc->project().design, fresh);
}

TEST(MotionDesign, ADesignThatCannotBeMadeIsRefusedAndChangesNothing) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    // A 16 mm roller on a 30 mm rise over 60° from a 10 mm base circle: the pitch curve turns
    // tighter than the roller (undercut).
    FollowerSpec big = *doc->project().follower;
    big.radius = 16.0;
    doc->undoStack()->push(new SetFollower(doc, big));
    DesignSpec steep = *doc->project().design;
    steep.baseRadius = 10.0;
    steep.segments[0].toDeg = 60.0;
    steep.segments[0].lift = steep.segments[1].lift = 30.0;
    doc->undoStack()->push(new SetDesign(doc, steep, "steep"));
    ASSERT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    // The dock says so before anyone presses Synthesize.
    ASSERT_TRUE(waitForResult(window));
    EXPECT_NE(window.motionDesignPanel()->notesText().indexOf("undercut"), -1)
        << window.motionDesignPanel()->notesText().toStdString();
    const Project before = doc->project();
    const int steps = doc->undoStack()->count();
    const QString problem = synthesizeAndWait(window);
    EXPECT_NE(problem.indexOf("undercut"), -1) << problem.toStdString();
    EXPECT_EQ(doc->project().contour, before.contour);
    EXPECT_EQ(doc->undoStack()->count(), steps);
}

// Issue 27 point 6: a tolerance below what double precision can certify (a file may hold one;
// the dock's box goes down to 1e-6 mm) is refused with the limit, and nothing changes. The
// roller's profile reaches 40 + 10 = 50 mm from the centre: 16 machine epsilons of that is
// 1.776356839e-13 mm.
TEST(MotionDesign, AToleranceBelowDoublePrecisionIsRefusedWithTheLimit) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    DesignSpec fine = *doc->project().design;
    fine.tolerance = 1e-13;
    doc->undoStack()->push(new SetDesign(doc, fine, "fine"));
    ASSERT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    const Project before = doc->project();
    const int steps = doc->undoStack()->count();
    const QString problem = synthesizeAndWait(window);
    EXPECT_NE(problem.indexOf("Motion design, tolerance: 1e-13 mm is below what double precision "
                              "can certify for this cam: at least 1.776356839e-13 mm"),
              -1)
        << problem.toStdString();
    EXPECT_EQ(doc->project().contour, before.contour);
    EXPECT_EQ(doc->undoStack()->count(), steps);
}

TEST(MotionDesign, ACancelledOrOutdatedSynthesisChangesNothing) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    {
        QSignalSpy finished(&window, &MainWindow::synthesisFinished);
        ASSERT_TRUE(window.synthesize());
        EXPECT_FALSE(window.synthesize());  // one at a time
        window.cancelSynthesis();
        ASSERT_TRUE(finished.wait(30000));
        const QString problem = finished.front().front().toString();
        // Cancelled, or done before the flag was read: then it replaced the contour.
        if (problem.isEmpty()) {
            doc->undoStack()->undo();
        } else {
            EXPECT_NE(problem.indexOf("cancelled"), -1) << problem.toStdString();
        }
        EXPECT_TRUE(doc->project().contour.empty());
    }
    {
        // The design changes while the worker fits the old one: its arcs are never applied.
        QSignalSpy finished(&window, &MainWindow::synthesisFinished);
        ASSERT_TRUE(window.synthesize());
        DesignSpec changed = *doc->project().design;
        changed.baseRadius = 45.0;
        doc->undoStack()->push(new SetDesign(doc, changed, "test"));
        ASSERT_TRUE(finished.wait(30000));
        EXPECT_NE(finished.front().front().toString().indexOf("changed"), -1);
        EXPECT_TRUE(doc->project().contour.empty());
    }
    // And afterwards it works.
    EXPECT_EQ(synthesizeAndWait(window), QString());
    EXPECT_FALSE(doc->project().contour.empty());
}

TEST(MotionDesign, TheLawFollowsTheTimeAxis) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    window.findChild<QAction*>("actionAxisTime")->setChecked(true);
    ASSERT_TRUE(waitForResult(window));
    const QCPGraph* lift = window.motionDesignPanel()->plot(0)->graph(0);
    ASSERT_EQ(lift->dataCount(), 3601);
    // 60 rpm: one turn a second; 0.25 s is 90°.
    EXPECT_NEAR((lift->data()->constEnd() - 1)->key, 1.0, 1e-12);
    EXPECT_NEAR(valueAt(lift, 0.25), liftDeg(90.0), 1e-12);
    window.findChild<QAction*>("actionAxisTime")->setChecked(false);
    ASSERT_TRUE(waitForResult(window));
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MotionDesign, SmallestSetsTheSizedBaseRadiusInOneUndoStep) {
    // The button sizes in the background and applies what design/sizing finds for the
    // document's design and follower; the binding check is named; Undo restores the radius.
    MainWindow window;
    window.show();
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ASSERT_TRUE(waitForResult(window));
    ProjectDocument* doc = window.document();
    const double before = doc->project().design->baseRadius;
    const auto expected =
        sizeBaseRadius(*doc->project().design, doc->project().follower.value_or(FollowerSpec{}));
    ASSERT_TRUE(expected.ok());
    const int steps = doc->undoStack()->count();
    MotionDesignPanel* panel = window.motionDesignPanel();
    QSignalSpy finished(panel, &MotionDesignPanel::sizingFinished);
    auto* button = panel->findChild<QPushButton*>("sizeBaseRadiusButton");
    ASSERT_NE(button, nullptr);
    button->click();
    EXPECT_TRUE(panel->sizing());
    EXPECT_FALSE(button->isEnabled());
    ASSERT_TRUE(finished.wait(20000));
    EXPECT_EQ(doc->project().design->baseRadius, expected.value().baseRadius);
    EXPECT_NE(doc->project().design->baseRadius, before);
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_TRUE(button->isEnabled());
    EXPECT_NE(panel->sizingText().indexOf("binds at"), -1) << panel->sizingText().toStdString();
    auto* line = panel->findChild<QLabel*>("sizingLabel");
    ASSERT_NE(line, nullptr);
    EXPECT_FALSE(line->isHidden());
    // The line speaks of the sized design only: gone after Undo, back after Redo.
    doc->undoStack()->undo();
    EXPECT_EQ(doc->project().design->baseRadius, before);
    EXPECT_TRUE(line->isHidden());
    doc->undoStack()->redo();
    EXPECT_FALSE(line->isHidden());
    doc->undoStack()->undo();

    // A change while it sizes drops the answer: nothing is applied.
    button->click();
    doc->undoStack()->push(new SetDesign(
        doc,
        [&] {
            DesignSpec d = *doc->project().design;
            d.tolerance = 0.002;
            return d;
        }(),
        "tolerance"));
    ASSERT_TRUE(finished.wait(20000));
    EXPECT_EQ(doc->project().design->baseRadius, before);
    EXPECT_NE(panel->sizingText().indexOf("changed"), -1) << panel->sizingText().toStdString();
    EXPECT_FALSE(line->isHidden());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MotionDesignDock, BestOffsetSetsOffsetAndRadiusInOneStepAndDrawsTheFeasibleRegion) {
    MainWindow window;
    window.show();
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ASSERT_TRUE(waitForResult(window));
    ProjectDocument* doc = window.document();
    const Project before = doc->project();
    const FollowerSpec follower = before.follower.value_or(FollowerSpec{});
    ASSERT_EQ(placementOf(follower), Placement::Offset);
    // The core's answer (checked against the closed form in core_tests Sizing.*).
    const auto expected = sizePlacement(*before.design, follower);
    ASSERT_TRUE(expected.ok());
    const int steps = doc->undoStack()->count();
    MotionDesignPanel* panel = window.motionDesignPanel();
    QSignalSpy finished(panel, &MotionDesignPanel::sizingFinished);
    auto* button = panel->findChild<QPushButton*>("bestPlacementButton");
    ASSERT_NE(button, nullptr);
    ASSERT_TRUE(button->isEnabled());
    EXPECT_FALSE(panel->feasibleRegion()->isVisible());
    button->click();
    EXPECT_TRUE(panel->sizing());
    EXPECT_FALSE(button->isEnabled());
    ASSERT_TRUE(finished.wait(60000));
    EXPECT_EQ(doc->project().design->baseRadius, expected.value().sizing.baseRadius);
    EXPECT_EQ(doc->project().follower->offset, expected.value().value);
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);  // both in one step
    EXPECT_NE(panel->sizingText().indexOf("at offset"), -1) << panel->sizingText().toStdString();
    // The picture: the edge's 41 points, the chosen point on it, the design's marker where the
    // design now is (there).
    FeasibleRegionPlot* region = panel->feasibleRegion();
    EXPECT_TRUE(region->isVisible());
    ASSERT_EQ(region->edgeGraph()->dataCount(), 41);
    EXPECT_EQ(region->chosenGraph()->data()->at(0)->key, expected.value().value);
    EXPECT_EQ(region->chosenGraph()->data()->at(0)->value, expected.value().sizing.baseRadius);
    EXPECT_EQ(region->currentGraph()->data()->at(0)->key, expected.value().value);
    EXPECT_EQ(region->currentGraph()->data()->at(0)->value, expected.value().sizing.baseRadius);
    EXPECT_TRUE(region->yAxis->range().contains(before.design->baseRadius));
    EXPECT_TRUE(region->yAxis->range().contains(expected.value().sizing.baseRadius));
    // One undo brings back both; the region still holds (the same laws and follower but for
    // its axes) and its marker goes back with the design, while the sizing line is gone.
    doc->undoStack()->undo();
    EXPECT_EQ(doc->project().design, before.design);
    EXPECT_EQ(doc->project().follower, before.follower);
    EXPECT_FALSE(region->isHidden());
    EXPECT_EQ(region->currentGraph()->data()->at(0)->key, before.follower->offset);
    EXPECT_EQ(region->currentGraph()->data()->at(0)->value, before.design->baseRadius);
    EXPECT_TRUE(panel->findChild<QLabel*>("sizingLabel")->isHidden());
    EXPECT_EQ(button->text(), "Best Offset");
    EXPECT_EQ(region->xAxis->label(), "Offset [mm]");
    EXPECT_FALSE(region->legend->hasItemWithPlottable(region->topGraph()));
    // A swinging arm sizes its pivot instead; a flat face has nothing to place.
    FollowerSpec arm = follower;
    arm.motion = FollowerMotion::Oscillating;
    arm.pivot = Eigen::Vector2d(120.0, 0.0);
    arm.armLength = 100.0;
    doc->undoStack()->push(new SetFollower(doc, arm));
    EXPECT_TRUE(button->isEnabled());
    EXPECT_EQ(button->text(), "Best Pivot");
    EXPECT_TRUE(region->isHidden());  // made for a translating roller
    FollowerSpec flat = follower;
    flat.type = FollowerType::Flat;
    doc->undoStack()->push(new SetFollower(doc, flat));
    EXPECT_FALSE(button->isEnabled());
}

TEST(MotionDesignDock, TheFeasibleRegionOfAnArmIsShadedBetweenItsSmallestAndLargestRadius) {
    FeasibleRegionPlot region;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    region.setRegion(Placement::PivotDistance,
                     {{50.0, nan, nan}, {60.0, 3.0, 54.0}, {70.0, 11.0, 64.0}}, {60.0, 3.0},
                     {70.0, 35.0});
    EXPECT_EQ(region.xAxis->label(), "Pivot distance [mm]");
    ASSERT_EQ(region.topGraph()->dataCount(), 3);
    EXPECT_TRUE(std::isnan(region.topGraph()->data()->at(0)->value));
    EXPECT_EQ(region.topGraph()->data()->at(1)->value, 54.0);
    EXPECT_EQ(region.topGraph()->data()->at(2)->value, 64.0);
    EXPECT_TRUE(region.legend->hasItemWithPlottable(region.topGraph()));
    EXPECT_NE(region.topGraph()->pen().style(), Qt::NoPen);
    EXPECT_TRUE(region.yAxis->range().contains(64.0));
    EXPECT_TRUE(region.yAxis->range().contains(3.0));
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MotionDesignLaws, TheTableShowsClassesAndTheParametersEachLawTakes) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    DesignTableModel* model = window.motionDesignPanel()->model();
    // Every joint of the cycloidal cam is at rest.
    for (int row = 0; row < 4; ++row) {
        EXPECT_EQ(model->index(row, DesignTableModel::StartClass).data().toString(), "Rest");
        EXPECT_EQ(model->index(row, DesignTableModel::EndClass).data().toString(), "Rest");
    }
    // SCCA opens b and d, nothing else; at b = 0.5, d = 0.5 it is the cycloid: Ca = 2π
    // (math.md §8's 6.2832).
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::Law),
                               static_cast<int>(MotionLawType::Scca), Qt::EditRole));
    for (int c : {DesignTableModel::SccaB, DesignTableModel::SccaD}) {
        EXPECT_TRUE(model->flags(model->index(0, c)) & Qt::ItemIsEditable) << c;
    }
    for (int c : {DesignTableModel::V0, DesignTableModel::J0, DesignTableModel::Lambda,
                  DesignTableModel::Points}) {
        EXPECT_FALSE(model->flags(model->index(0, c)) & Qt::ItemIsEditable) << c;
    }
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::SccaB), 0.5, Qt::EditRole));
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::SccaD), 0.5, Qt::EditRole));
    EXPECT_NEAR(model->index(0, DesignTableModel::Ca).data(Qt::EditRole).toDouble(), 2 * kPi_,
                1e-12);
    EXPECT_NEAR(model->index(0, DesignTableModel::Cv).data(Qt::EditRole).toDouble(), 2.0, 1e-12);
    // b + d beyond 1 is refused at d's cell with the reason.
    ASSERT_TRUE(model->setData(model->index(0, DesignTableModel::SccaD), 0.75, Qt::EditRole));
    EXPECT_FALSE(doc->isValid());
    ASSERT_FALSE(model->problemsAt(0, DesignTableModel::SccaD).isEmpty());
    EXPECT_TRUE(model->problemsAt(0, DesignTableModel::SccaD).front().contains("b + d"));
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->isValid());
    // A line as the first segment: a cycloid cannot end at rest where the line runs, the
    // neighbour's class is shown and the cycloid's law cell says why.
    ASSERT_TRUE(model->setData(model->index(2, DesignTableModel::Law),
                               static_cast<int>(MotionLawType::ConstantVelocity), Qt::EditRole));
    EXPECT_EQ(model->index(1, DesignTableModel::EndClass).data().toString(), "Velocity");
    EXPECT_FALSE(doc->isValid());
    ASSERT_FALSE(model->problemsAt(2, DesignTableModel::Law).isEmpty())
        << diagnosticsText(doc->diagnostics()).toStdString();
    // The law list shows a picture and a tip per law.
    const QVariantList icons =
        model->index(0, DesignTableModel::Law).data(kChoiceIconsRole).toList();
    const QStringList tips =
        model->index(0, DesignTableModel::Law).data(kChoiceTipsRole).toStringList();
    EXPECT_EQ(icons.size(), static_cast<int>(kMotionLawCount));
    EXPECT_EQ(tips.size(), static_cast<int>(kMotionLawCount));
    EXPECT_FALSE(icons.front().value<QIcon>().isNull());
}

TEST(MotionDesignLaws, SuggestAllMakesEveryJointContinuousInOneUndoStep) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    MotionDesignPanel* panel = window.motionDesignPanel();
    DesignTableModel* model = panel->model();
    // The dwell after the rise becomes a line: the rise and the return cannot meet it.
    ASSERT_TRUE(model->setData(model->index(1, DesignTableModel::Law),
                               static_cast<int>(MotionLawType::ConstantVelocity), Qt::EditRole));
    ASSERT_TRUE(model->setData(model->index(1, DesignTableModel::Lift), 14.0, Qt::EditRole));
    EXPECT_FALSE(doc->isValid());
    const int steps = doc->undoStack()->count();
    auto* all = panel->findChild<QPushButton*>("suggestAllLawsButton");
    ASSERT_NE(all, nullptr);
    all->click();
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    const auto& s = doc->project().design->segments;
    // Rest → the line's 4/60 mm/°: poly5 with that velocity at its end (by hand).
    EXPECT_EQ(s[0].law, MotionLawType::Poly5);
    EXPECT_NEAR(s[0].v1, 4.0 / 60.0, 1e-15);
    EXPECT_EQ(s[1].law, MotionLawType::ConstantVelocity);
    EXPECT_EQ(s[2].law, MotionLawType::Poly5);
    EXPECT_NEAR(s[2].v0, 4.0 / 60.0, 1e-15);
    EXPECT_EQ(model->index(0, DesignTableModel::EndClass).data().toString(), "Velocity");
    auto* say = panel->findChild<QLabel*>("suggestionLabel");
    ASSERT_NE(say, nullptr);
    EXPECT_TRUE(say->text().contains("segment 0: Poly 5")) << say->text().toStdString();
    doc->undoStack()->undo();
    EXPECT_EQ(doc->project().design->segments[0].law, MotionLawType::Cycloidal);
}

TEST(MotionDesignLaws, ImportTableReadsInventorsTwoColumnsOrSaysWhereItCannot) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kDesignOnly).isEmpty());
    ProjectDocument* doc = window.document();
    MotionDesignPanel* panel = window.motionDesignPanel();
    const Project before = doc->project();
    // Line 3 is no number: said with its line, nothing changes.
    const QString bad = panel->importTable(0, "0 0\n0.5 0.5\n0.7 x\n1 1\n");
    EXPECT_TRUE(bad.startsWith("line 3")) << bad.toStdString();
    EXPECT_EQ(doc->project(), before);
    // Not ending at (1, 1): said, nothing changes.
    EXPECT_FALSE(panel->importTable(0, "0 0\n0.5 0.5\n1 0.9\n").isEmpty());
    EXPECT_EQ(doc->project(), before);
    // Points of the 3-4-5 law, tab- and comma-separated, with a comment: one undo step.
    const QString text = "# x\ty\n0\t0\n0.25\t0.103515625\n0.5,0.5\n0.75\t0.896484375\n1\t1\n";
    EXPECT_TRUE(panel->importTable(0, text).isEmpty());
    const DesignSegmentSpec& s = doc->project().design->segments[0];
    EXPECT_EQ(s.law, MotionLawType::Table);
    ASSERT_EQ(s.table.size(), 5u);
    EXPECT_EQ(s.table[1].x, 0.25);
    EXPECT_EQ(s.table[1].y, 0.103515625);  // 10u³ − 15u⁴ + 6u⁵ at 1/4
    EXPECT_TRUE(doc->isValid()) << diagnosticsText(doc->diagnostics()).toStdString();
    EXPECT_EQ(panel->model()->index(0, DesignTableModel::Points).data().toInt(), 5);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->project(), before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(MotionDesignLaws, ADesignWhoseLawsCannotMeetIsStillADesign) {
    // A cycloid beside a line: not computable, but the dock must not say there is no design.
    QTemporaryDir dir;
    const QString path = dir.filePath("line.cam.json");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "camwright", "version": 1, "name": "line", "motion": {"rpm": 60},
      "contour": [], "design": {"base_radius": 60, "segments": [
        {"law": "dwell", "to_deg": 60}, {"law": "cycloidal", "to_deg": 120, "lift": 5},
        {"law": "line", "to_deg": 200, "lift": 15}, {"law": "cycloidal", "to_deg": 360,
        "lift": 0}]}})");
    file.close();
    MainWindow window;
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_FALSE(window.document()->isValid());
    auto* report = window.motionDesignPanel()->findChild<QLabel*>("synthesisReportLabel");
    ASSERT_NE(report, nullptr);
    EXPECT_FALSE(report->text().contains("no motion design")) << report->text().toStdString();
    EXPECT_EQ(window.motionDesignPanel()->model()->index(1, DesignTableModel::EndClass).data(),
              "Velocity");
}

}  // namespace
}  // namespace cam
