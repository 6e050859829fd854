// Every structural edit on contours of 1 to 5 segments at every position, through the real
// window: the row selected in the real table, the real actions triggered; then undo and redo.
// The table model runs under QAbstractItemModelTester (Fatal) the whole time, so an edit that
// lets a view read a row that is not there any more aborts the test. (Deleting the second-to-
// last segment used to end the program with std::out_of_range.)

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QAction>
#include <QTableView>
#include <cmath>
#include <functional>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/project_document.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "project/validate.h"
#include "views/contour_view.h"
#include "views/palette.h"

namespace cam {
namespace {

/// n arcs of one circle (centre (3, 0), radius 20) splitting the turn evenly.
Project splitCircle(int n) {
    Project p;
    for (int k = 0; k < n; ++k) {
        p.contour.push_back(
            SegmentSpec{Arc{{3.0, 0.0}, 20.0, Branch::Outer}, 360.0 * k / n, 360.0 * (k + 1) / n});
    }
    return p;
}

/// A regular polygon of n ≥ 3 lines around the origin (corners at radius 20).
Project polygon(int n) {
    Project p;
    double previousEnd = 0.0;
    for (int k = 0; k < n; ++k) {
        const double a = kTwoPi * k / n + 0.1, b = kTwoPi * (k + 1) / n + 0.1;
        SegmentSpec s{
            Line{{20 * std::cos(a), 20 * std::sin(a)}, {20 * std::cos(b), 20 * std::sin(b)}}};
        std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, k == 0 ? 0.0 : previousEnd);
        if (k > 0) s.phiStartDeg = previousEnd;
        previousEnd = s.phiEndDeg;
        p.contour.push_back(s);
    }
    p.contour.back().phiEndDeg = p.contour.front().phiStartDeg + 360.0;
    return p;
}

struct Edit {
    std::string name;
    std::function<void(MainWindow&, int row)> run;
};

std::vector<Edit> structuralEdits() {
    auto action = [](const char* name) {
        return [name](MainWindow& w, int) { w.findChild<QAction*>(name)->trigger(); };
    };
    std::vector<Edit> edits{
        {"insert", action("actionInsertSegment")},
        {"delete", action("actionDeleteSegment")},
        {"move up", action("actionMoveUp")},
        {"move down", action("actionMoveDown")},
        {"fit windows", action("actionFitWindows")},
        {"round corner", [](MainWindow& w, int row) { (void)w.roundCorner(row, 0.5); }},
        {"approximate", [](MainWindow& w, int row) { (void)w.approximateArc(row, 1e-3); }},
        {"through points",
         [](MainWindow& w, int) {
             (void)w.contourThroughPoints("20, 0\n14, 15\n-3, 22\n-18, 9\n-16, -12\n5, -19", 2,
                                          1.0);
         }},
    };
    for (int type = 0; type < 4; ++type) {
        edits.push_back({"type " + std::to_string(type), [type](MainWindow& w, int row) {
                             SegmentTableModel* m = w.tableModel();
                             m->setData(m->index(row, SegmentTableModel::Type), type, Qt::EditRole);
                         }});
    }
    return edits;
}

TEST(StructuralEdits, EveryEditAtEveryPositionOfOneToFiveSegmentsUndoesAndRedoes) {
    MainWindow window;
    QAbstractItemModelTester tester(window.tableModel(),
                                    QAbstractItemModelTester::FailureReportingMode::Fatal);
    auto* table = window.findChild<QTableView*>("segmentTable");
    ASSERT_NE(table, nullptr);
    ProjectDocument* document = window.document();
    int cases = 0;
    for (int n = 1; n <= 5; ++n) {
        std::vector<Project> shapes{splitCircle(n)};
        if (n >= 3) shapes.push_back(polygon(n));
        for (const Project& original : shapes) {
            ASSERT_TRUE(validateProject(original).empty())
                << validateProject(original).front().text();
            for (int row = 0; row < n; ++row) {
                for (const Edit& edit : structuralEdits()) {
                    SCOPED_TRACE(edit.name + " at row " + std::to_string(row) + " of " +
                                 std::to_string(n));
                    document->reset(original, {});
                    table->selectRow(row);
                    ASSERT_EQ(table->currentIndex().row(), row);
                    const int steps = document->undoStack()->count();
                    edit.run(window, row);
                    const Project after = document->project();
                    EXPECT_EQ(window.tableModel()->rowCount(),
                              static_cast<int>(after.contour.size()));
                    if (document->undoStack()->count() == steps) {
                        EXPECT_EQ(after, original);  // refused: nothing changed
                        ++cases;
                        continue;
                    }
                    EXPECT_EQ(document->undoStack()->count(), steps + 1);  // one undo step
                    document->undoStack()->undo();
                    EXPECT_EQ(document->project(), original);
                    EXPECT_EQ(window.tableModel()->rowCount(), n);
                    document->undoStack()->redo();
                    EXPECT_EQ(document->project(), after);
                    document->undoStack()->undo();
                    EXPECT_EQ(document->project(), original);
                    // A view of the table after all this: every cell can be read.
                    for (int r = 0; r < window.tableModel()->rowCount(); ++r) {
                        for (int c = 0; c < SegmentTableModel::ColumnCount; ++c) {
                            (void)window.tableModel()->index(r, c).data();
                        }
                    }
                    ++cases;
                }
            }
        }
    }
    EXPECT_EQ(cases, 12 * (1 + 2 + 3 + 4 + 5) + 12 * (3 + 4 + 5));
}

TEST(StructuralEdits, RepeatedInsertsDivideAWindowEvenlyAndTheProfileStays) {
    // Issue 31, point 7: Insert on the last row halved the last window each time (180°, 90°,
    // 45°, …). The copies of one segment now share its window evenly; the profile (the same
    // arc in every part) is unchanged, and each Insert is one undo step.
    MainWindow window;
    auto* table = window.findChild<QTableView*>("segmentTable");
    ASSERT_NE(table, nullptr);
    ProjectDocument* document = window.document();
    // [0°, 180°] on a circle of 25 mm, [180°, 360°] on one of 20 mm.
    Project original = splitCircle(2);
    original.contour[0].as<Arc>()->radius = 25.0;
    document->reset(original, {});
    auto* insert = window.findChild<QAction*>("actionInsertSegment");
    table->selectRow(1);
    for (int inserts = 1; inserts <= 3; ++inserts) {
        insert->trigger();
        const auto& contour = document->project().contour;
        ASSERT_EQ(contour.size(), static_cast<std::size_t>(2 + inserts));
        // The new one is current: the next Insert follows it.
        EXPECT_EQ(table->currentIndex().row(), 1 + inserts);
        const double width = 180.0 / (inserts + 1);
        for (int k = 0; k <= inserts; ++k) {
            const SegmentSpec& s = contour[static_cast<std::size_t>(1 + k)];
            EXPECT_DOUBLE_EQ(s.phiStartDeg, 180.0 + k * width) << inserts << " " << k;
            EXPECT_DOUBLE_EQ(s.phiEndDeg, 180.0 + (k + 1) * width) << inserts << " " << k;
            SegmentSpec shape = s;
            shape.phiStartDeg = original.contour[1].phiStartDeg;
            shape.phiEndDeg = original.contour[1].phiEndDeg;
            EXPECT_EQ(shape, original.contour[1]);  // the same arc: the profile stays
        }
        EXPECT_EQ(contour[0], original.contour[0]);  // another arc: not part of the run
        EXPECT_EQ(contour.back().phiEndDeg, 360.0);  // exactly, not by a sum of parts
    }
    for (int k = 0; k < 3; ++k) document->undoStack()->undo();
    EXPECT_EQ(document->project(), original);
    // Two windows of one circle are one run: an Insert after the second gives three thirds.
    document->reset(splitCircle(2), {});
    table->selectRow(1);
    insert->trigger();
    const auto& contour = document->project().contour;
    ASSERT_EQ(contour.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_DOUBLE_EQ(contour[static_cast<std::size_t>(k)].phiStartDeg, 120.0 * k);
        EXPECT_DOUBLE_EQ(contour[static_cast<std::size_t>(k)].phiEndDeg, 120.0 * (k + 1));
    }
    document->undoStack()->undo();
    EXPECT_EQ(document->project(), splitCircle(2));
}

TEST(StructuralEdits, ASegmentKeepsItsColourWhenOthersComeAndGo) {
    // Issue 31, point 7: colours followed the row, so all shifted after an insertion.
    MainWindow window;
    auto* table = window.findChild<QTableView*>("segmentTable");
    ProjectDocument* document = window.document();
    document->reset(splitCircle(5), {});
    const std::vector<int> fresh = document->segmentColourSlots();
    EXPECT_EQ(fresh, (std::vector<int>{0, 1, 2, 3, 4}));
    table->selectRow(2);
    window.findChild<QAction*>("actionInsertSegment")->trigger();
    const std::vector<int> inserted = document->segmentColourSlots();
    ASSERT_EQ(inserted.size(), 6u);
    // Everyone keeps theirs; the new one (row 3) differs from both neighbours and is one
    // nobody has.
    EXPECT_EQ(inserted, (std::vector<int>{0, 1, 2, inserted[3], 3, 4}));
    EXPECT_GE(inserted[3], 5);
    // Undo and redo: the same colours.
    document->undoStack()->undo();
    EXPECT_EQ(document->segmentColourSlots(), fresh);
    document->undoStack()->redo();
    EXPECT_EQ(document->segmentColourSlots(), inserted);
    // Deleted and undone, a segment comes back in its own colour; moved, it takes it along.
    table->selectRow(1);
    window.findChild<QAction*>("actionDeleteSegment")->trigger();
    EXPECT_EQ(document->segmentColourSlots(), (std::vector<int>{0, 2, inserted[3], 3, 4}));
    document->undoStack()->undo();
    EXPECT_EQ(document->segmentColourSlots(), inserted);
    // The contour view draws each segment in the curve of its slot's colour: the run of
    // segment k there starts at the contour point at its window's start (the polar angle of
    // a point of r(φ) is φ).
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    ContourView* view = window.contourView();
    for (int k = 0; k < 6; ++k) {
        const QCPCurve* curve = view->segmentCurve(k);
        EXPECT_EQ(curve->pen().color(), segmentColor(document->segmentColourSlot(k))) << k;
        const auto [first, count] = view->segmentRun(k);
        ASSERT_GT(count, 0) << k;
        const auto p = curve->data()->at(first);
        double angle = radToDeg(std::atan2(p->value, p->key));
        if (angle < -1e-9) angle += 360.0;
        EXPECT_NEAR(angle, document->project().contour[static_cast<std::size_t>(k)].phiStartDeg,
                    1e-6)
            << k;
    }
    // Moved, a segment takes its colour along.
    table->selectRow(0);
    window.findChild<QAction*>("actionMoveDown")->trigger();
    EXPECT_EQ(document->segmentColourSlots(), (std::vector<int>{1, 0, 2, inserted[3], 3, 4}));
}

TEST(StructuralEdits, DeletingDownToNothingAndBackThroughTheRealKeys) {
    // File → New gives two arcs; deleting row 0 twice with the Del shortcut's action leaves an
    // empty contour, which is a problem the status bar reports, not a crash; undo restores it.
    MainWindow window;
    QAbstractItemModelTester tester(window.tableModel(),
                                    QAbstractItemModelTester::FailureReportingMode::Fatal);
    auto* table = window.findChild<QTableView*>("segmentTable");
    const Project original = window.document()->project();
    ASSERT_EQ(original.contour.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        table->selectRow(0);
        window.findChild<QAction*>("actionDeleteSegment")->trigger();
    }
    EXPECT_TRUE(window.document()->project().contour.empty());
    EXPECT_FALSE(window.document()->isValid());
    EXPECT_EQ(window.tableModel()->rowCount(), 0);
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), original);
}

}  // namespace
}  // namespace cam
