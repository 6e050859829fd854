// The segment table model: Qt's model checks, and every edit → undo → redo checked against
// both the document and the model.

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <set>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/fit_windows.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "geometry/line.h"
#include "models/segment_table_model.h"

namespace cam {
namespace {

class SegmentTableModelTest : public ::testing::Test {
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
    SegmentTableModel model{&document};
    std::unique_ptr<QAbstractItemModelTester> tester;
};

TEST_F(SegmentTableModelTest, ShowsTheDocument) {
    EXPECT_EQ(model.rowCount(), 13);
    EXPECT_EQ(model.columnCount(), SegmentTableModel::ColumnCount);
    EXPECT_DOUBLE_EQ(number(1, SegmentTableModel::Radius), 8.103180550000001);
    EXPECT_EQ(cell(0, SegmentTableModel::Branch).data().toString(), "inner");
    EXPECT_EQ(cell(1, SegmentTableModel::Type).data().toString(), "Arc");
    // Line columns of an arc row are empty and not editable.
    EXPECT_FALSE(cell(1, SegmentTableModel::FromX).data().isValid());
    EXPECT_FALSE(model.flags(cell(1, SegmentTableModel::FromX)) & Qt::ItemIsEditable);
}

TEST_F(SegmentTableModelTest, EveryColumnHeaderExplainsItsColumn) {
    for (int c = 0; c < SegmentTableModel::ColumnCount; ++c) {
        const QString tip = model.headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString();
        EXPECT_GE(tip.size(), 20) << c << ": \"" << tip.toStdString() << "\"";
    }
    const QString branch =
        model.headerData(SegmentTableModel::Branch, Qt::Horizontal, Qt::ToolTipRole).toString();
    EXPECT_TRUE(branch.contains("outer") && branch.contains("inner")) << branch.toStdString();
}

TEST_F(SegmentTableModelTest, EditUndoRedoOfARadius) {
    const double before = number(3, SegmentTableModel::Radius);
    ASSERT_TRUE(model.setData(cell(3, SegmentTableModel::Radius), 9.5, Qt::EditRole));
    EXPECT_DOUBLE_EQ(test::arcOf(document.project().contour[3]).radius, 9.5);
    EXPECT_DOUBLE_EQ(number(3, SegmentTableModel::Radius), 9.5);
    EXPECT_TRUE(document.isModified());
    EXPECT_EQ(stack().count(), 1);

    stack().undo();
    EXPECT_DOUBLE_EQ(test::arcOf(document.project().contour[3]).radius, before);
    EXPECT_DOUBLE_EQ(number(3, SegmentTableModel::Radius), before);
    EXPECT_FALSE(document.isModified());  // back at the clean state

    stack().redo();
    EXPECT_DOUBLE_EQ(test::arcOf(document.project().contour[3]).radius, 9.5);
    EXPECT_DOUBLE_EQ(number(3, SegmentTableModel::Radius), 9.5);
    EXPECT_TRUE(document.isModified());
}

TEST_F(SegmentTableModelTest, StepsOfOneGestureMergeIntoOneUndoStep) {
    const double before = test::arcOf(document.project().contour[5]).center.x();
    for (double x : {-18.0, -17.9, -17.8, -17.7}) {
        ASSERT_TRUE(model.setData(cell(5, SegmentTableModel::CenterX), QVariantList{x, 4711},
                                  SegmentTableModel::MergingEditRole));
    }
    EXPECT_EQ(stack().count(), 1);
    EXPECT_DOUBLE_EQ(test::arcOf(document.project().contour[5]).center.x(), -17.7);
    stack().undo();
    EXPECT_DOUBLE_EQ(test::arcOf(document.project().contour[5]).center.x(), before);
    // A new gesture is a new undo step; an edit without a gesture never merges.
    model.setData(cell(5, SegmentTableModel::CenterX), QVariantList{-17.0, 4712},
                  SegmentTableModel::MergingEditRole);
    model.setData(cell(5, SegmentTableModel::CenterX), -16.0, Qt::EditRole);
    model.setData(cell(5, SegmentTableModel::CenterX), -15.0, Qt::EditRole);
    EXPECT_EQ(stack().count(), 3);
}

TEST_F(SegmentTableModelTest, RefusesNonFiniteValuesAndLeavesNoUndoStep) {
    EXPECT_FALSE(model.setData(cell(2, SegmentTableModel::Radius), std::nan(""), Qt::EditRole));
    EXPECT_FALSE(model.setData(cell(2, SegmentTableModel::Radius), "abc", Qt::EditRole));
    EXPECT_FALSE(model.setData(cell(2, SegmentTableModel::Branch), 7, Qt::EditRole));
    EXPECT_EQ(stack().count(), 0);
    EXPECT_TRUE(model.setData(cell(2, SegmentTableModel::Radius),
                              number(2, SegmentTableModel::Radius), Qt::EditRole));
    EXPECT_EQ(stack().count(), 0);  // same value: nothing to undo
}

TEST_F(SegmentTableModelTest, MarksTheInvalidCellWithItsMessage) {
    model.setData(cell(4, SegmentTableModel::Radius), 0.0, Qt::EditRole);
    EXPECT_FALSE(document.isValid());
    const QString tip = cell(4, SegmentTableModel::Radius).data(Qt::ToolTipRole).toString();
    EXPECT_TRUE(tip.contains("must be > 0")) << tip.toStdString();
    EXPECT_TRUE(cell(4, SegmentTableModel::Radius).data(Qt::BackgroundRole).isValid());
    EXPECT_TRUE(model.problemsAt(4, SegmentTableModel::CenterX).isEmpty());
    stack().undo();
    EXPECT_TRUE(document.isValid());
    EXPECT_TRUE(model.problemsAt(4, SegmentTableModel::Radius).isEmpty());
}

TEST_F(SegmentTableModelTest, AWindowGapMarksBothNeighbouringCells) {
    model.setData(cell(2, SegmentTableModel::PhiStart), 51.0, Qt::EditRole);
    EXPECT_FALSE(model.problemsAt(1, SegmentTableModel::PhiEnd).isEmpty());
    EXPECT_FALSE(model.problemsAt(2, SegmentTableModel::PhiStart).isEmpty());
}

TEST_F(SegmentTableModelTest, AnEditRefreshesItsRowAndTheRowsWhoseProblemsChangedOnly) {
    // The rows each edit announces as changed (the view repaints exactly those).
    std::set<int> announced;
    QObject::connect(&model, &QAbstractItemModel::dataChanged,
                     [&](const QModelIndex& topLeft, const QModelIndex& bottomRight) {
                         for (int row = topLeft.row(); row <= bottomRight.row(); ++row)
                             announced.insert(row);
                     });
    // Row 0 from arc to line, through its end points: every joint still meets, and no cell
    // of another row gains or loses a mark, so its row alone.
    model.setData(cell(0, SegmentTableModel::Type), 1, Qt::EditRole);
    ASSERT_TRUE(document.isValid());
    EXPECT_EQ(announced, (std::set<int>{0}));
    // A window gap between rows 1 and 2: row 2 (edited) and row 1 (its end now marked).
    announced.clear();
    model.setData(cell(2, SegmentTableModel::PhiStart), 51.0, Qt::EditRole);
    EXPECT_EQ(announced, (std::set<int>{1, 2}));
    // Undone: the same two rows lose their marks.
    announced.clear();
    stack().undo();
    EXPECT_EQ(announced, (std::set<int>{1, 2}));
    EXPECT_TRUE(model.problemsAt(1, SegmentTableModel::PhiEnd).isEmpty());
}

TEST_F(SegmentTableModelTest, InsertRemoveMoveAreUndoable) {
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

TEST_F(SegmentTableModelTest, ChangingTypeToLineKeepsTheContourClosed) {
    // Segment 0 is the inner notch arc: as a line it joins the same two contour points.
    ASSERT_TRUE(model.setData(cell(0, SegmentTableModel::Type), 1, Qt::EditRole));
    const SegmentSpec& s = document.project().contour[0];
    EXPECT_EQ(s.type(), SegmentType::Line);
    EXPECT_TRUE(document.isValid()) << document.diagnostics().front().text();
    EXPECT_TRUE(model.flags(cell(0, SegmentTableModel::FromX)) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.flags(cell(0, SegmentTableModel::PhiStart)) & Qt::ItemIsEditable);
    stack().undo();
    EXPECT_EQ(document.project().contour[0].type(), SegmentType::Arc);
}

TEST_F(SegmentTableModelTest, FitWindowsIsOneUndoStep) {
    for (int row : {1, 2}) {  // disturb two boundaries consistently
        model.setData(cell(row, SegmentTableModel::PhiEnd), 50.0 + row, Qt::EditRole);
        model.setData(cell(row + 1, SegmentTableModel::PhiStart), 50.0 + row, Qt::EditRole);
    }
    const int steps = stack().count();
    const std::vector<SegmentSpec> before = document.project().contour;
    const auto fitted = fitWindows(before);
    ASSERT_TRUE(fitted.ok());
    stack().push(new ReplaceContour(&document, fitted.value().contour, "Fit windows"));
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

TEST_F(SegmentTableModelTest, SplineTypesConvertExactlyAndUndo) {
    const Project original = document.project();
    // Arc → Bézier: the κ-approximation through the same end points keeps the contour valid,
    // and r stays within the approximation's 0.03 % of the arc.
    ASSERT_TRUE(model.setData(cell(1, SegmentTableModel::Type), 2, Qt::EditRole));
    ASSERT_EQ(document.project().contour[1].type(), SegmentType::Bezier);
    EXPECT_TRUE(document.isValid()) << document.diagnostics().front().text();
    const double mid = degToRad(30.0);  // the lobe tip: 29 mm on the arc
    EXPECT_NEAR(bezierOf(document.project().contour[1]).evaluate(mid).r, 29.0, 29.0 * 3e-4);
    const SegmentSpec bezier = document.project().contour[1];
    // Bézier → Hermite → Bézier: the same curve both ways (t = 3·handle, handle = t/3).
    ASSERT_TRUE(model.setData(cell(1, SegmentTableModel::Type), 3, Qt::EditRole));
    const SegmentSpec hermite = document.project().contour[1];
    EXPECT_EQ(hermite.type(), SegmentType::Hermite);
    const CubicBezier& b = std::get<CubicBezier>(bezier.shape);
    EXPECT_LT((std::get<HermiteCurve>(hermite.shape).t0 - 3.0 * (b.p[1] - b.p[0])).norm(), 1e-12);
    ASSERT_TRUE(model.setData(cell(1, SegmentTableModel::Type), 2, Qt::EditRole));
    for (int i = 0; i < 4; ++i) {
        EXPECT_LT((bezierOf(document.project().contour[1]).p[i] - b.p[i]).norm(), 1e-12);
    }
    // The window cells of a spline follow its end points: not editable.
    EXPECT_FALSE(model.flags(cell(1, SegmentTableModel::PhiEnd)) & Qt::ItemIsEditable);
    EXPECT_TRUE(
        cell(1, SegmentTableModel::Type).data(Qt::ToolTipRole).toString().contains("P1 = ("));
    // Three conversions, three undo steps, back to the arc exactly.
    for (int i = 0; i < 3; ++i) stack().undo();
    EXPECT_EQ(document.project(), original);
}

TEST_F(SegmentTableModelTest, ALineBecomesTheSameStraightBezier) {
    ASSERT_TRUE(model.setData(cell(0, SegmentTableModel::Type), 1, Qt::EditRole));  // arc → line
    const SegmentSpec line = document.project().contour[0];
    ASSERT_TRUE(model.setData(cell(0, SegmentTableModel::Type), 2, Qt::EditRole));  // line → Bézier
    EXPECT_TRUE(document.isValid());
    const CubicBezier b = bezierOf(document.project().contour[0]);
    const Line l = test::lineOf(line);
    for (double deg : {1.0, 4.0, 8.0}) {
        EXPECT_NEAR(b.evaluate(degToRad(deg)).r, l.evaluate(degToRad(deg)).r, 1e-12);
    }
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(SegmentTableProblems, ASplinePointProblemMarksItsRowsTypeCell) {
    // Four κ-quarter Béziers make a circle; one control point beyond the 1e6 mm limit is a
    // problem located at contour[2].points[2][0]: the cell that lists the points shows it.
    const double R = 20.0, k = 4.0 / 3.0 * std::tan(kPi / 8.0) * R;
    Project p;
    for (int q = 0; q < 4; ++q) {
        const double a = kPi / 2 * q, b = a + kPi / 2;
        const Eigen::Vector2d u(std::cos(a), std::sin(a)), v(std::cos(b), std::sin(b));
        p.contour.push_back(SegmentSpec{CubicBezier{{R * u, R * u + k * v, R * v + k * u, R * v}},
                                        90.0 * q, 90.0 * q + 90.0});
    }
    std::get<CubicBezier>(p.contour[2].shape).p[2].x() = 2e6;
    ProjectDocument document;
    SegmentTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    document.reset(p, {});
    const QStringList problems = model.problemsAt(2, SegmentTableModel::Type);
    ASSERT_EQ(problems.size(), 1) << document.diagnostics().front().text();
    EXPECT_TRUE(
        problems.front().startsWith("Segment 2, control point P2, x: magnitude must be at most"))
        << problems.front().toStdString();
    EXPECT_EQ(model.index(2, SegmentTableModel::Type).data(Qt::BackgroundRole).value<QColor>(),
              QColor(255, 205, 205));
    for (int row : {0, 1, 3}) EXPECT_TRUE(model.problemsAt(row, SegmentTableModel::Type).isEmpty());
    EXPECT_TRUE(model.problemsAt(2, SegmentTableModel::PhiEnd).isEmpty());
}

}  // namespace
}  // namespace cam
