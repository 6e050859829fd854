// No sequence of table edits makes the app terminate: thousands of random edits of every kind
// (cells with sane and absurd values, kinds, rows inserted, deleted and moved, fitted windows,
// rounded corners, undo, redo) on the real window, with the engine computing and the views
// drawing in between, under QAbstractItemModelTester. Seeded, so a failure can be replayed;
// the last operations are printed with it.

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QAction>
#include <QTableView>
#include <deque>
#include <random>

#include "app_test_support.h"
#include "document/contour_edits.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"

namespace cam {
namespace {

TEST(RandomEdits, NoSequenceOfTableEditsEndsTheProgram) {
    MainWindow window;
    QAbstractItemModelTester tester(window.tableModel(),
                                    QAbstractItemModelTester::FailureReportingMode::Fatal);
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    window.resize(1200, 800);
    window.show();
    auto* table = window.findChild<QTableView*>("segmentTable");
    SegmentTableModel* model = window.tableModel();
    QUndoStack* stack = window.document()->undoStack();
    std::mt19937 random(20261122);
    auto pick = [&](int n) {
        return n <= 0 ? 0 : std::uniform_int_distribution<int>(0, n - 1)(random);
    };
    const double values[] = {0.0, -5.0, 1e-9, 1e6, -1e6, 2e6, 1e300, 0.5, 3.25, 20.0, 359.9, 720.0};
    std::deque<std::string> log;
    constexpr int kOperations = 3000;
    for (int i = 0; i < kOperations; ++i) {
        const int rows = model->rowCount();
        const int row = pick(rows);
        if (rows > 0) table->selectRow(row);
        const int what = pick(14);
        std::string op;
        switch (what) {
            case 0:
                op = "insert";
                window.findChild<QAction*>("actionInsertSegment")->trigger();
                break;
            case 1:
                op = "delete";
                window.findChild<QAction*>("actionDeleteSegment")->trigger();
                break;
            case 2:
                op = "move up";
                window.findChild<QAction*>("actionMoveUp")->trigger();
                break;
            case 3:
                op = "move down";
                window.findChild<QAction*>("actionMoveDown")->trigger();
                break;
            case 4:
                op = "fit windows";  // the action would show a message box when it cannot fit
                (void)ContourEdits::fitWindows(*window.document());
                break;
            case 5:
                op = "round corner";
                (void)window.roundCorner(row, values[pick(12)]);
                break;
            case 6:
                op = "approximate";
                (void)window.approximateArc(row, 1e-3);
                break;
            case 7:
            case 8:
                op = "undo";
                if (stack->canUndo()) stack->undo();
                break;
            case 9:
                op = "redo";
                if (stack->canRedo()) stack->redo();
                break;
            default: {
                const int column = pick(SegmentTableModel::ColumnCount);
                const QModelIndex index = model->index(row, column);
                QVariant value;
                if (column == SegmentTableModel::Type) {
                    value = pick(4);
                } else if (column == SegmentTableModel::Branch) {
                    value = pick(2);
                } else if (pick(2) == 0) {
                    value = index.data(Qt::EditRole).toDouble() + (pick(21) - 10) * 0.37;
                } else {
                    value = values[pick(12)];
                }
                op = "set " + std::to_string(row) + "," + std::to_string(column) + " = " +
                     value.toString().toStdString();
                if (rows > 0) model->setData(index, value, Qt::EditRole);
            }
        }
        log.push_back(std::to_string(i) + ": " + op);
        if (log.size() > 12) log.pop_front();
        ASSERT_EQ(model->rowCount(), static_cast<int>(window.document()->project().contour.size()))
            << "after " << op;
        // Let the engine answer and the views draw now and then.
        if (i % 25 == 0) {
            test::processEventsUntil([] { return false; }, 20);
            (void)window.grab();
        }
        if (HasFatalFailure()) {
            for (const auto& line : log) ADD_FAILURE() << line;
            return;
        }
    }
    EXPECT_GT(stack->count(), 0);
}

}  // namespace
}  // namespace cam
