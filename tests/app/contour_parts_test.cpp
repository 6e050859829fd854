// The contour view's parts that need no window: snapping a point in mm
// (views/contour_snapping.h). Every expectation is worked out by hand, not read from the code
// under test.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "views/contour_snapping.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ContourSnapping, TheGridStepIsTheSmallestOneTwoFiveStepOfAtLeastTheMinimum) {
    EXPECT_EQ(gridStepFor(0.13).value(), 0.2);
    EXPECT_EQ(gridStepFor(0.2).value(), 0.2);  // exactly the minimum is enough
    EXPECT_EQ(gridStepFor(0.21).value(), 0.5);
    EXPECT_EQ(gridStepFor(0.6).value(), 1.0);
    EXPECT_EQ(gridStepFor(7.0).value(), 10.0);
    EXPECT_EQ(gridStepFor(30.0).value(), 50.0);
    EXPECT_EQ(gridStepFor(0.0042).value(), 0.005);
    // No sensible minimum (a plot of no size): 1 mm.
    for (double nonsense : {0.0, -3.0, kNaN, std::numeric_limits<double>::infinity()}) {
        EXPECT_EQ(gridStepFor(nonsense).value(), 1.0) << nonsense;
    }
    // Multiples are the decimals, not products that pick up rounding: 3 × 0.1 is 0.3.
    const GridStep tenth = gridStepFor(0.08);
    EXPECT_EQ(tenth.value(), 0.1);
    EXPECT_EQ(tenth.multiple(3.0), 0.3);
    EXPECT_EQ(tenth.round(0.27), 0.3);
    EXPECT_EQ(gridStepFor(0.15).round(-0.71), -0.8);
}

TEST(ContourSnapping, TheNearestPointWithinTheToleranceWins) {
    const std::vector<Vec> candidates{{0.0, 0.0}, {10.0, 4.0}, {10.5, 4.0}};
    // (10.3, 4.1) is 0.316 from (10, 4) and 0.224 from (10.5, 4).
    const Snapped s = snapPoint({10.3, 4.1}, candidates, 0.5, gridStepFor(1.0), Qt::NoModifier);
    EXPECT_EQ(s.target, SnapTarget::Point);
    EXPECT_EQ(s.candidate, 2);
    EXPECT_EQ(s.point, Vec(10.5, 4.0));
    EXPECT_EQ(s.keptAxis, -1);

    // A point exactly at the tolerance counts: (3, 4) is 5 from the origin.
    const std::vector<Vec> far{{3.0, 4.0}};
    EXPECT_EQ(snapPoint({0.0, 0.0}, far, 5.0, gridStepFor(1.0), Qt::NoModifier).point,
              Vec(3.0, 4.0));
    // At equal distances the later candidate wins.
    const std::vector<Vec> tie{{1.0, 0.0}, {-1.0, 0.0}};
    const Snapped t = snapPoint({0.0, 0.0}, tie, 2.0, gridStepFor(1.0), Qt::NoModifier);
    EXPECT_EQ(t.candidate, 1);
    EXPECT_EQ(t.point, Vec(-1.0, 0.0));
}

TEST(ContourSnapping, AwayFromEveryPointItLandsOnTheGrid) {
    // 10.37 / 0.2 = 51.85 → 52 steps; −4.12 / 0.2 = −20.6 → −21 steps.
    const std::vector<Vec> candidates{{0.0, 0.0}, {10.0, -4.0}, {kNaN, kNaN}};
    const Snapped s = snapPoint({10.37, -4.12}, candidates, 0.1, gridStepFor(0.2), Qt::NoModifier);
    EXPECT_EQ(s.target, SnapTarget::Grid);
    EXPECT_EQ(s.candidate, -1);
    EXPECT_EQ(s.point, Vec(10.4, -4.2));
    // No candidates at all: the grid too.
    EXPECT_EQ(snapPoint({0.74, 0.76}, {}, 0.1, gridStepFor(0.5), Qt::NoModifier).point,
              Vec(0.5, 1.0));
}

TEST(ContourSnapping, AltPlacesFreelyAndShiftKeepsTheAxisMovedLessAlong) {
    const std::vector<Vec> candidates{{5.3, 1.7}};
    const Vec origin(1.0, 1.0);
    // Alt: where it is, even on a candidate.
    const Snapped free =
        snapPoint({5.31, 1.72}, candidates, 1.0, gridStepFor(1.0), Qt::AltModifier);
    EXPECT_EQ(free.target, SnapTarget::Nothing);
    EXPECT_EQ(free.point, Vec(5.31, 1.72));

    // Shift, moved mostly along x: snapped to the grid (5, 2), then y back to the origin's.
    const Snapped alongX =
        snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin);
    EXPECT_EQ(alongX.point, Vec(5.0, 1.0));
    EXPECT_EQ(alongX.keptAxis, 1);
    // Mostly along y: x stays.
    const Snapped alongY =
        snapPoint({1.4, 6.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin);
    EXPECT_EQ(alongY.point, Vec(1.0, 7.0));
    EXPECT_EQ(alongY.keptAxis, 0);
    // As far along both: y stays.
    EXPECT_EQ(snapPoint({3.0, 3.0}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin).point,
              Vec(3.0, 1.0));
    // Shift with Alt: unsnapped, one axis kept. Shift without an origin: no axis kept.
    EXPECT_EQ(snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier | Qt::AltModifier,
                        origin)
                  .point,
              Vec(5.4, 1.0));
    const Snapped noOrigin = snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier);
    EXPECT_EQ(noOrigin.point, Vec(5.0, 2.0));
    EXPECT_EQ(noOrigin.keptAxis, -1);
}

TEST(ContourSnapping, ADraggedLengthSnapsToTheGridUnlessAlt) {
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.5), Qt::NoModifier), 12.5);
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.02), Qt::NoModifier), 12.34);
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.5), Qt::AltModifier), 12.34);
}

}  // namespace
}  // namespace cam
