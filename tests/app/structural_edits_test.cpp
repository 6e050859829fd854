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
