// Construction help in the window, driven through the real actions, table cells and mouse
// events: the lobe cam by a handful of clicks, a tangent arc through a clicked point, snapping
// and the axis lock of dragged centres, and a spline's control points edited by value. Every
// expected number comes from a closed form written here.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QMouseEvent>
#include <QTableView>
#include <QTest>
#include <cmath>

#include "app_test_support.h"
#include "document/contour_edits.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/control_points_panel.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

using test::arcOf;
using test::lineOf;
using Vec = Eigen::Vector2d;

class Construction : public ::testing::Test {
protected:
    void SetUp() override {
        window.resize(1400, 860);
        window.show();
        QApplication::setActiveWindow(&window);
        table = window.findChild<QTableView*>("segmentTable");
        ASSERT_NE(table, nullptr);
    }

    /// Types into a cell as a user does and commits with Enter. The window is made active
    /// again first: a keyboard focus exists only in the active window, and under a loaded
    /// machine the window was sometimes no longer active by then (QTest then asserted on a
    /// null focus widget, about 1 run in 16 with two test processes side by side).
    void typeInto(int row, int column, const QString& text) {
        QApplication::setActiveWindow(&window);
        table->setFocus();
        table->setCurrentIndex(window.tableModel()->index(row, column));
        for (const QChar c : text) QTest::keyClick(focused(), c.toLatin1());
        QTest::keyClick(focused(), Qt::Key_Return);
    }
    /// The widget keys go to: the focused one (the cell's editor once it is open), else the
    /// table, whose first key opens the editor.
    QWidget* focused() const {
        QWidget* w = QApplication::focusWidget();
        return w ? w : table;
    }
    void trigger(const char* action) {
        QAction* a = window.findChild<QAction*>(action);
        ASSERT_NE(a, nullptr) << action;
        a->trigger();
    }
    const std::vector<SegmentSpec>& contour() const { return window.document()->project().contour; }
    QPointF pixelOf(const Vec& p) const {
        const ContourView* v = window.contourView();
        return {v->xAxis->coordToPixel(p.x()), v->yAxis->coordToPixel(p.y())};
    }
    void mouse(QEvent::Type type, const QPointF& at, Qt::MouseButtons buttons,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        ContourView* v = window.contourView();
        const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
        QMouseEvent e(type, at, v->mapToGlobal(at), button, buttons, modifiers);
        QApplication::sendEvent(v, &e);
    }
    /// Presses the left button at `from`, moves to `to` and releases.
    void drag(const QPointF& from, const QPointF& to, Qt::KeyboardModifiers modifiers) {
        mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, modifiers);
        mouse(QEvent::MouseMove, (from + to) / 2.0, Qt::LeftButton, modifiers);
        mouse(QEvent::MouseMove, to, Qt::LeftButton, modifiers);
        mouse(QEvent::MouseButtonRelease, to, Qt::NoButton, modifiers);
    }

    MainWindow window;
    QTableView* table = nullptr;
};

void expectNear(const Vec& actual, const Vec& expected, double tol, const char* what) {
    EXPECT_NEAR((actual - expected).norm(), 0.0, tol)
        << what << ": (" << actual.x() << ", " << actual.y() << ") instead of (" << expected.x()
        << ", " << expected.y() << ")";
}

// Base circle R20 about the origin, nose arc R6 about (0, 24), two tangent lines: five cells
// typed and two actions, no hand calculation.
TEST_F(Construction, TheLobeCamTakesAHandfulOfClicks) {
    trigger("actionNew");  // two arcs of one circle
    ASSERT_EQ(contour().size(), 2u);
    typeInto(0, SegmentTableModel::CenterX, "0");
    typeInto(0, SegmentTableModel::Radius, "20");
    typeInto(1, SegmentTableModel::CenterX, "0");
    typeInto(1, SegmentTableModel::CenterY, "24");
    typeInto(1, SegmentTableModel::Radius, "6");
    table->selectRow(0);
    trigger("actionTangentLine");  // base circle → nose
    ASSERT_EQ(contour().size(), 3u);
    table->selectRow(2);
    trigger("actionTangentLine");  // nose → base circle, across the start of the turn
    ASSERT_EQ(contour().size(), 4u);

    // The outer common tangents of circles on the y axis, d = 24: the unit normal m of a
    // tangent has m_y = (R1 − R2)/d = 14/24, m_x = ±√(1 − m_y²); it touches at c_i + R_i·m.
    const double my = 14.0 / 24.0, mx = std::sqrt(1.0 - my * my);
    const auto& c = contour();
    ASSERT_EQ(c[0].type(), SegmentType::Arc);
    ASSERT_EQ(c[1].type(), SegmentType::Line);
    ASSERT_EQ(c[2].type(), SegmentType::Arc);
    ASSERT_EQ(c[3].type(), SegmentType::Line);
    expectNear(lineOf(c[1]).from, {20.0 * mx, 20.0 * my}, 1e-12, "right flank on the base");
    expectNear(lineOf(c[1]).to, {6.0 * mx, 24.0 + 6.0 * my}, 1e-12, "right flank on the nose");
    expectNear(lineOf(c[3]).from, {-6.0 * mx, 24.0 + 6.0 * my}, 1e-12, "left flank on the nose");
    expectNear(lineOf(c[3]).to, {-20.0 * mx, 20.0 * my}, 1e-12, "left flank on the base");
    // The windows were written from the tangent points.
    const double right = std::atan2(my, mx) * 180.0 / M_PI;
    EXPECT_NEAR(c[0].phiEndDeg, right, 1e-9);
    EXPECT_NEAR(c[0].phiStartDeg, 180.0 - right - 360.0, 1e-9);
    EXPECT_NEAR(c[2].phiStartDeg, std::atan2(24.0 + 6.0 * my, 6.0 * mx) * 180.0 / M_PI, 1e-9);
    // A valid cam: no message at all.
    for (const Diagnostic& d : window.document()->diagnostics()) ADD_FAILURE() << d.text();
    EXPECT_TRUE(window.document()->diagnostics().empty());

    // Each construction is one undo step.
    window.document()->undoStack()->undo();
    EXPECT_EQ(contour().size(), 3u);
    window.document()->undoStack()->undo();
    EXPECT_EQ(contour().size(), 2u);
}

TEST_F(Construction, ATangentLineThatCannotBeIsRefusedWithAMessageAndNothingChanges) {
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    const Project before = window.document()->project();
    // No row selected.
    EXPECT_FALSE(ContourEdits::tangentLineToNext(*window.document(), -1).ok());
    // A circle inside the other: no common tangent; the message names the two segments as the
    // table numbers them.
    trigger("actionNew");
    typeInto(1, SegmentTableModel::Radius, "3");
    const Project nested = window.document()->project();
    const EditOutcome refused = ContourEdits::tangentLineToNext(*window.document(), 0);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.problem.contains("the circle of segment 1 lies inside that of segment 0"))
        << refused.problem.toStdString();
    EXPECT_EQ(window.document()->project(), nested);
    EXPECT_NE(nested, before);
}

TEST_F(Construction, ATangentArcGoesThroughTheClickedPointAndEscapeCancels) {
    trigger("actionNew");
    typeInto(0, SegmentTableModel::CenterX, "0");
    typeInto(0, SegmentTableModel::Radius, "20");
    typeInto(1, SegmentTableModel::CenterX, "0");
    typeInto(1, SegmentTableModel::Radius, "20");
    window.contourView()->resetZoom();
    const Project before = window.document()->project();

    // Escape cancels the pick: nothing changes.
    table->selectRow(0);
    trigger("actionTangentArc");
    ASSERT_TRUE(window.contourView()->isPickingPoint());
    QTest::keyClick(window.contourView(), Qt::Key_Escape);
    EXPECT_FALSE(window.contourView()->isPickingPoint());
    EXPECT_EQ(window.document()->project(), before);

    // Row 0 ends at 180°, at T = (−20, 0), running downwards. Click near P = (−10, −15).
    table->selectRow(0);
    trigger("actionTangentArc");
    const QPointF at = pixelOf({-10.0, -15.0});
    const Vec p = window.contourView()->snap(at, Qt::NoModifier);
    EXPECT_LE((p - Vec(-10.0, -15.0)).norm(), window.contourView()->gridStep());
    mouse(QEvent::MouseButtonPress, at, Qt::LeftButton);
    mouse(QEvent::MouseButtonRelease, at, Qt::NoButton);
    ASSERT_EQ(contour().size(), 3u);
    // The circle tangent to the line x = −20 at T through P: its centre is T + s·(1, 0) with
    // s = |P − T|² / (2·(P − T)·(1, 0)).
    const Vec t(-20.0, 0.0);
    const double s = (p - t).squaredNorm() / (2.0 * (p - t).x());
    const Arc& arc = arcOf(contour()[1]);
    expectNear(arc.center, t + Vec(s, 0.0), 1e-9, "centre");
    EXPECT_NEAR(arc.radius, s, 1e-9);
    EXPECT_NEAR(contour()[1].phiStartDeg, 180.0, 1e-9);
    EXPECT_NEAR(contour()[1].phiEndDeg, 360.0 + std::atan2(p.y(), p.x()) * 180.0 / M_PI, 1e-9);
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), before);
}

TEST_F(Construction, DraggedCentresSnapToTheGridToCentresAndLockAnAxisWithShift) {
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    ContourView* view = window.contourView();
    view->resetZoom();
    table->selectRow(1);
    ASSERT_EQ(contour()[1].type(), SegmentType::Arc);
    const double step = view->gridStep();
    // A 1-2-5 step of at least kGridPixels on screen, and not a whole decade more.
    const double pixelsPerMm =
        std::abs(view->xAxis->coordToPixel(1.0) - view->xAxis->coordToPixel(0.0));
    EXPECT_GE(step * pixelsPerMm, ContourView::kGridPixels - 1e-9);
    EXPECT_LT(step * pixelsPerMm, 2.5 * ContourView::kGridPixels + 1e-9);
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                std::abs(mantissa - 5.0) < 1e-9)
        << step;

    // Grid: a free drag lands on multiples of the step (away from every centre and joint).
    Vec centre = arcOf(contour()[1]).center;
    QPointF target = pixelOf(centre) + QPointF(37.3, -23.7);
    drag(pixelOf(centre), target, Qt::NoModifier);
    centre = arcOf(contour()[1]).center;
    EXPECT_NEAR(centre.x() / step, std::round(centre.x() / step), 1e-9);
    EXPECT_NEAR(centre.y() / step, std::round(centre.y() / step), 1e-9);
    EXPECT_LE(std::abs(view->xAxis->coordToPixel(centre.x()) - target.x()), step * pixelsPerMm);

    // Shift: a mostly horizontal drag keeps y bit for bit.
    const Vec beforeShift = centre;
    drag(pixelOf(centre), pixelOf(centre) + QPointF(41.0, 6.0), Qt::ShiftModifier);
    centre = arcOf(contour()[1]).center;
    EXPECT_EQ(centre.y(), beforeShift.y());
    EXPECT_NE(centre.x(), beforeShift.x());

    // Another arc's centre within kSnapPixels wins over the grid: exactly that centre.
    const Vec other = arcOf(contour()[3]).center;
    drag(pixelOf(centre), pixelOf(other) + QPointF(4.0, -3.0), Qt::NoModifier);
    EXPECT_EQ(arcOf(contour()[1]).center, other);

    // Alt: no snapping at all.
    const QPointF free = pixelOf(other) + QPointF(53.0, 29.0);
    drag(pixelOf(other), free, Qt::AltModifier);
    expectNear(arcOf(contour()[1]).center,
               {view->xAxis->pixelToCoord(free.x()), view->yAxis->pixelToCoord(free.y())}, 1e-9,
               "unsnapped");
}

// A spline's control points by value in the Control Points tab.
class ControlPoints : public Construction {
protected:
    void SetUp() override {
        Construction::SetUp();
        ASSERT_TRUE(window.contourThroughPoints("30, 0\n0, 25\n-30, 0\n0, -25", 0, 1.0).isEmpty());
        ASSERT_EQ(contour()[1].type(), SegmentType::Bezier);
        table->selectRow(1);
        panel = window.controlPointsPanel();
        ASSERT_EQ(panel->row(), 1);
    }
    const CubicBezier& bezier() const { return std::get<CubicBezier>(contour()[1].shape); }
    ControlPointsPanel* panel = nullptr;
};

TEST_F(ControlPoints, EveryEditorShowsItsOwnPoint) {
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(panel->pointEditor(k, 0)->value(), bezier().p[k].x()) << "P" << k;
        EXPECT_EQ(panel->pointEditor(k, 1)->value(), bezier().p[k].y()) << "P" << k;
    }
    window.tableModel()->setData(window.tableModel()->index(1, SegmentTableModel::Type), 3,
                                 Qt::EditRole);
    const HermiteCurve& h = std::get<HermiteCurve>(contour()[1].shape);
    const Vec fields[4] = {h.p0, h.t0, h.p3, h.t1};
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(panel->pointEditor(k, 0)->value(), fields[k].x()) << "Hermite row " << k;
        EXPECT_EQ(panel->pointEditor(k, 1)->value(), fields[k].y()) << "Hermite row " << k;
    }
}

TEST_F(ControlPoints, AnInnerPointIsTypedExactlyAndUndone) {
    const Project before = window.document()->project();
    EXPECT_EQ(panel->pointEditor(1, 0)->value(), bezier().p[1].x());
    test::typeInto(panel->pointEditor(1, 0), "12.5");
    EXPECT_EQ(bezier().p[1].x(), 12.5);
    EXPECT_EQ(window.document()->undoStack()->count(), 2);  // teach-in, then this edit
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), before);
    EXPECT_EQ(panel->pointEditor(1, 0)->value(), bezier().p[1].x());
}

TEST_F(ControlPoints, AnEndPointTakesItsHandleAlongAndTheWindowFollows) {
    const Vec handle = bezier().p[1] - bezier().p[0];
    test::typeInto(panel->pointEditor(0, 1), "26");
    EXPECT_EQ(bezier().p[0].y(), 26.0);
    expectNear(bezier().p[1] - bezier().p[0], handle, 1e-12, "handle");
    EXPECT_NEAR(contour()[1].phiStartDeg,
                std::atan2(bezier().p[0].y(), bezier().p[0].x()) * 180.0 / M_PI, 1e-9);
}

TEST_F(ControlPoints, AHandleIsSetByLengthAndAngle) {
    test::typeInto(panel->pointEditor(3, 0), "1.5");  // P3's own row: P3 and its handle move
    EXPECT_EQ(bezier().p[3].x(), 1.5);
    const Vec p3 = bezier().p[3];
    const Vec handle = bezier().p[2] - p3;
    test::typeInto(panel->handleLengthEditor(1), "7.5");
    EXPECT_NEAR((bezier().p[2] - p3).norm(), 7.5, 1e-12);
    expectNear((bezier().p[2] - p3).normalized(), handle.normalized(), 1e-12, "direction kept");
    test::typeInto(panel->handleAngleEditor(1), "30");
    const Vec h = bezier().p[2] - p3;
    EXPECT_NEAR(std::atan2(h.y(), h.x()) * 180.0 / M_PI, 30.0, 1e-12);
    EXPECT_NEAR(h.norm(), 7.5, 1e-12);
    EXPECT_EQ(bezier().p[3], p3);  // the end point stays
}

TEST_F(ControlPoints, AHermiteRowEditsItsTangentVector) {
    window.tableModel()->setData(window.tableModel()->index(1, SegmentTableModel::Type), 3,
                                 Qt::EditRole);
    ASSERT_EQ(contour()[1].type(), SegmentType::Hermite);
    table->selectRow(1);
    test::typeInto(panel->pointEditor(1, 1), "-40");
    const HermiteCurve& h = std::get<HermiteCurve>(contour()[1].shape);
    EXPECT_EQ(h.t0.y(), -40.0);
    // The handle shown is a third of the tangent (P1 = p0 + t0/3).
    EXPECT_NEAR(panel->handleLengthEditor(0)->value(), h.t0.norm() / 3.0, 1e-12);
}

TEST_F(ControlPoints, AnArcRowSaysWhereItsValuesAre) {
    EXPECT_TRUE(panel->pointEditor(0, 0)->isVisibleTo(panel));
    window.tableModel()->setData(window.tableModel()->index(0, SegmentTableModel::Type), 0,
                                 Qt::EditRole);
    ASSERT_EQ(contour()[0].type(), SegmentType::Arc);
    table->selectRow(0);
    EXPECT_FALSE(panel->pointEditor(0, 0)->isVisibleTo(panel));
    EXPECT_TRUE(panel->findChild<QLabel*>("controlPointsTitle")->text().contains("not a spline"));
}

}  // namespace
}  // namespace cam
