// The segment table model: Qt's model checks, and every edit → undo → redo checked against
// both the document and the model.

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/fit_windows.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "geometry/line.h"
#include "models/arc_table_model.h"

namespace cam {
namespace {

class ArcTableModelTest : public ::testing::Test {
protected:
    void SetUp() override {
        document.reset(test::loadExample(), {});
        tester = std::make_unique<QAbstractItemModelTester>(
            &model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    }
    QUndoStack& stack() { return *document.undoStack(); }
    QModelIndex cell(int row, int column) { return model.index(row, column); }
    double number(int row, int column) { return cell(row, column).data(Qt::EditRole).toDouble(); }

    ProjectDocument document;
    ArcTableModel model{&document};
    std::unique_ptr<QAbstractItemModelTester> tester;
};

TEST_F(ArcTableModelTest, ShowsTheDocument) {
    EXPECT_EQ(model.rowCount(), 13);
    EXPECT_EQ(model.columnCount(), ArcTableModel::ColumnCount);
    EXPECT_DOUBLE_EQ(number(1, ArcTableModel::Radius), 8.103180550000001);
    EXPECT_EQ(cell(0, ArcTableModel::Branch).data().toString(), "inner");
    EXPECT_EQ(cell(1, ArcTableModel::Type).data().toString(), "Arc");
    // Line columns of an arc row are empty and not editable.
    EXPECT_FALSE(cell(1, ArcTableModel::FromX).data().isValid());
    EXPECT_FALSE(model.flags(cell(1, ArcTableModel::FromX)) & Qt::ItemIsEditable);
}

TEST_F(ArcTableModelTest, EditUndoRedoOfARadius) {
    const double before = number(3, ArcTableModel::Radius);
    ASSERT_TRUE(model.setData(cell(3, ArcTableModel::Radius), 9.5, Qt::EditRole));
    EXPECT_DOUBLE_EQ(document.project().contour[3].radius, 9.5);
    EXPECT_DOUBLE_EQ(number(3, ArcTableModel::Radius), 9.5);
    EXPECT_TRUE(document.isModified());
    EXPECT_EQ(stack().count(), 1);

    stack().undo();
    EXPECT_DOUBLE_EQ(document.project().contour[3].radius, before);
    EXPECT_DOUBLE_EQ(number(3, ArcTableModel::Radius), before);
    EXPECT_FALSE(document.isModified());  // back at the clean state

    stack().redo();
    EXPECT_DOUBLE_EQ(document.project().contour[3].radius, 9.5);
    EXPECT_DOUBLE_EQ(number(3, ArcTableModel::Radius), 9.5);
    EXPECT_TRUE(document.isModified());
}

TEST_F(ArcTableModelTest, StepsOfOneGestureMergeIntoOneUndoStep) {
    const double before = document.project().contour[5].center.x();
    for (double x : {-18.0, -17.9, -17.8, -17.7}) {
        ASSERT_TRUE(model.setData(cell(5, ArcTableModel::CenterX), QVariantList{x, 4711},
                                  ArcTableModel::MergingEditRole));
    }
    EXPECT_EQ(stack().count(), 1);
    EXPECT_DOUBLE_EQ(document.project().contour[5].center.x(), -17.7);
    stack().undo();
    EXPECT_DOUBLE_EQ(document.project().contour[5].center.x(), before);
    // A new gesture is a new undo step; an edit without a gesture never merges.
    model.setData(cell(5, ArcTableModel::CenterX), QVariantList{-17.0, 4712},
                  ArcTableModel::MergingEditRole);
    model.setData(cell(5, ArcTableModel::CenterX), -16.0, Qt::EditRole);
    model.setData(cell(5, ArcTableModel::CenterX), -15.0, Qt::EditRole);
    EXPECT_EQ(stack().count(), 3);
}

TEST_F(ArcTableModelTest, RefusesNonFiniteValuesAndLeavesNoUndoStep) {
    EXPECT_FALSE(model.setData(cell(2, ArcTableModel::Radius), std::nan(""), Qt::EditRole));
    EXPECT_FALSE(model.setData(cell(2, ArcTableModel::Radius), "abc", Qt::EditRole));
    EXPECT_FALSE(model.setData(cell(2, ArcTableModel::Branch), 7, Qt::EditRole));
    EXPECT_EQ(stack().count(), 0);
    EXPECT_TRUE(model.setData(cell(2, ArcTableModel::Radius), number(2, ArcTableModel::Radius),
                              Qt::EditRole));
    EXPECT_EQ(stack().count(), 0);  // same value: nothing to undo
}

TEST_F(ArcTableModelTest, MarksTheInvalidCellWithItsMessage) {
    model.setData(cell(4, ArcTableModel::Radius), 0.0, Qt::EditRole);
    EXPECT_FALSE(document.isValid());
    const QString tip = cell(4, ArcTableModel::Radius).data(Qt::ToolTipRole).toString();
    EXPECT_TRUE(tip.contains("must be > 0")) << tip.toStdString();
    EXPECT_TRUE(cell(4, ArcTableModel::Radius).data(Qt::BackgroundRole).isValid());
    EXPECT_TRUE(model.problemsAt(4, ArcTableModel::CenterX).isEmpty());
    stack().undo();
    EXPECT_TRUE(document.isValid());
    EXPECT_TRUE(model.problemsAt(4, ArcTableModel::Radius).isEmpty());
}

TEST_F(ArcTableModelTest, AWindowGapMarksBothNeighbouringCells) {
    model.setData(cell(2, ArcTableModel::PhiStart), 51.0, Qt::EditRole);
    EXPECT_FALSE(model.problemsAt(1, ArcTableModel::PhiEnd).isEmpty());
    EXPECT_FALSE(model.problemsAt(2, ArcTableModel::PhiStart).isEmpty());
}

TEST_F(ArcTableModelTest, InsertRemoveMoveAreUndoable) {
    const Project original = document.project();
    SegmentSpec extra = original.contour[0];
    stack().push(new InsertSegment(&document, 2, extra));
    EXPECT_EQ(model.rowCount(), 14);
    EXPECT_EQ(document.project().contour[2], extra);
    stack().push(new MoveSegment(&document, 2, 5));
    // [0, 1, X, 2, 3, 4, 5, …] → X moves to index 5 → [0, 1, 2, 3, 4, X, 5, …]
    EXPECT_EQ(document.project().contour[5], extra);
    EXPECT_EQ(document.project().contour[2], original.contour[2]);
    EXPECT_EQ(document.project().contour[4], original.contour[4]);
    EXPECT_EQ(document.project().contour[6], original.contour[5]);
    stack().push(new RemoveSegment(&document, 5));
    EXPECT_EQ(model.rowCount(), 13);
    EXPECT_EQ(document.project(), original);
    for (int i = 0; i < 3; ++i) stack().undo();
    EXPECT_EQ(document.project(), original);
    EXPECT_EQ(model.rowCount(), 13);
    for (int i = 0; i < 3; ++i) stack().redo();
    EXPECT_EQ(document.project(), original);
}

TEST_F(ArcTableModelTest, ChangingTypeToLineKeepsTheContourClosed) {
    // Segment 0 is the inner notch arc: as a line it joins the same two contour points.
    ASSERT_TRUE(model.setData(cell(0, ArcTableModel::Type), 1, Qt::EditRole));
    const SegmentSpec& s = document.project().contour[0];
    EXPECT_EQ(s.type, SegmentType::Line);
    EXPECT_TRUE(document.isValid()) << document.diagnostics().front().text();
    EXPECT_TRUE(model.flags(cell(0, ArcTableModel::FromX)) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.flags(cell(0, ArcTableModel::PhiStart)) & Qt::ItemIsEditable);
    stack().undo();
    EXPECT_EQ(document.project().contour[0].type, SegmentType::Arc);
}

TEST_F(ArcTableModelTest, FitWindowsIsOneUndoStep) {
    for (int row : {1, 2}) {  // disturb two boundaries consistently
        model.setData(cell(row, ArcTableModel::PhiEnd), 50.0 + row, Qt::EditRole);
        model.setData(cell(row + 1, ArcTableModel::PhiStart), 50.0 + row, Qt::EditRole);
    }
    const int steps = stack().count();
    const std::vector<SegmentSpec> before = document.project().contour;
    const auto fitted = fitWindows(before);
    ASSERT_TRUE(fitted.ok());
    stack().push(new ReplaceContour(&document, fitted.value(), "Fit windows"));
    EXPECT_EQ(stack().count(), steps + 1);
    EXPECT_TRUE(document.isValid());
    EXPECT_NEAR(document.project().contour[1].phiEndDeg, 50.30859, 1e-5);
    stack().undo();
    EXPECT_EQ(document.project().contour, before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST_F(ArcTableModelTest, SplineTypesConvertExactlyAndUndo) {
    const Project original = document.project();
    // Arc → Bézier: the κ-approximation through the same end points keeps the contour valid,
    // and r stays within the approximation's 0.03 % of the arc.
    ASSERT_TRUE(model.setData(cell(1, ArcTableModel::Type), 2, Qt::EditRole));
    ASSERT_EQ(document.project().contour[1].type, SegmentType::Bezier);
    EXPECT_TRUE(document.isValid()) << document.diagnostics().front().text();
    const double mid = degToRad(30.0);  // the lobe tip: 29 mm on the arc
    EXPECT_NEAR(bezierOf(document.project().contour[1]).evaluate(mid).r, 29.0, 29.0 * 3e-4);
    const SegmentSpec bezier = document.project().contour[1];
    // Bézier → Hermite → Bézier: the same curve both ways (t = 3·handle, handle = t/3).
    ASSERT_TRUE(model.setData(cell(1, ArcTableModel::Type), 3, Qt::EditRole));
    const SegmentSpec hermite = document.project().contour[1];
    EXPECT_EQ(hermite.type, SegmentType::Hermite);
    EXPECT_LT((hermite.controls[1] - 3.0 * (bezier.controls[1] - bezier.controls[0])).norm(),
              1e-12);
    ASSERT_TRUE(model.setData(cell(1, ArcTableModel::Type), 2, Qt::EditRole));
    for (int i = 0; i < 4; ++i) {
        EXPECT_LT((document.project().contour[1].controls[i] - bezier.controls[i]).norm(), 1e-12);
    }
    // The window cells of a spline follow its end points: not editable.
    EXPECT_FALSE(model.flags(cell(1, ArcTableModel::PhiEnd)) & Qt::ItemIsEditable);
    EXPECT_TRUE(cell(1, ArcTableModel::Type).data(Qt::ToolTipRole).toString().contains("P1 = ("));
    // Three conversions, three undo steps, back to the arc exactly.
    for (int i = 0; i < 3; ++i) stack().undo();
    EXPECT_EQ(document.project(), original);
}

TEST_F(ArcTableModelTest, ALineBecomesTheSameStraightBezier) {
    ASSERT_TRUE(model.setData(cell(0, ArcTableModel::Type), 1, Qt::EditRole));  // arc → line
    const SegmentSpec line = document.project().contour[0];
    ASSERT_TRUE(model.setData(cell(0, ArcTableModel::Type), 2, Qt::EditRole));  // line → Bézier
    EXPECT_TRUE(document.isValid());
    const CubicBezier b = bezierOf(document.project().contour[0]);
    const Line l{line.from, line.to};
    for (double deg : {1.0, 4.0, 8.0}) {
        EXPECT_NEAR(b.evaluate(degToRad(deg)).r, l.evaluate(degToRad(deg)).r, 1e-12);
    }
}

}  // namespace
}  // namespace cam
