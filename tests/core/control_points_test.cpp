// Editing a spline's control points by value (spline/control_points.h), checked against the
// definitions written out by hand: a Bézier's handles are P1 − P0 and P2 − P3, a Hermite's
// t0 = 3·(P1 − P0) and t1 = 3·(P3 − P2); the window runs between the end points' polar angles.

#include <gtest/gtest.h>

#include <cmath>

#include "spline/control_points.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

SegmentSpec quarterBezier() {
    return SegmentSpec{CubicBezier{{Vec(20, 0), Vec(22, 8), Vec(12, 18), Vec(0, 20)}}, 0.0, 90.0};
}

double degreesOf(const Vec& p) { return std::atan2(p.y(), p.x()) * 180.0 / M_PI; }

TEST(ControlPointEdits, MovingABezierEndTakesItsHandleAlongAndTheWindowFollows) {
    const SegmentSpec moved = withControlPoint(quarterBezier(), 0, 1, 3.0);  // P0.y: 0 → 3
    const CubicBezier& b = *moved.as<CubicBezier>();
    EXPECT_EQ(b.p[0], Vec(20, 3));
    EXPECT_EQ(b.p[1], Vec(22, 11));  // the handle (2, 8) kept
    EXPECT_EQ(b.p[2], Vec(12, 18));
    EXPECT_EQ(b.p[3], Vec(0, 20));
    EXPECT_NEAR(moved.phiStartDeg, degreesOf(Vec(20, 3)), 1e-12);  // 8.530765…°
    EXPECT_NEAR(moved.phiEndDeg, 90.0, 1e-12);
    // An inner point moves alone.
    const SegmentSpec inner = withControlPoint(quarterBezier(), 2, 0, 10.0);
    EXPECT_EQ(inner.as<CubicBezier>()->p[2], Vec(10, 18));
    EXPECT_EQ(inner.as<CubicBezier>()->p[3], Vec(0, 20));
}

TEST(ControlPointEdits, AHandleTakesALengthAlongItsDirectionAndAnAngleAtItsLength) {
    // End 1's handle P3 → P2 = (12, −2): length √148, direction (12, −2)/√148.
    const SegmentSpec longer = withHandleLength(quarterBezier(), 1, 7.0);
    const Vec p2 = longer.as<CubicBezier>()->p[2];
    const Vec expected = Vec(0, 20) + 7.0 * Vec(12, -2) / std::sqrt(148.0);
    EXPECT_NEAR((p2 - expected).norm(), 0.0, 1e-12);
    // End 0's handle (2, 8), length √68, turned to 90°: P1 = P0 + (0, √68).
    const SegmentSpec turned = withHandleAngle(quarterBezier(), 0, 90.0);
    const Vec p1 = turned.as<CubicBezier>()->p[1];
    EXPECT_NEAR(p1.x(), 20.0, 1e-12);
    EXPECT_NEAR(p1.y(), std::sqrt(68.0), 1e-12);
    EXPECT_NEAR(splineHandle(turned, 0).norm(), std::sqrt(68.0), 1e-12);
}

TEST(ControlPointEdits, AHermitesTangentsAreThreeTimesItsHandles) {
    // The quarter Bézier as Hermite data: t0 = 3·(2, 8), t1 = 3·((0, 20) − (12, 18)).
    const SegmentSpec h{HermiteCurve{Vec(20, 0), Vec(6, 24), Vec(0, 20), Vec(-36, 6)}, 0.0, 90.0};
    EXPECT_NEAR((splineHandle(h, 0) - Vec(2, 8)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((splineHandle(h, 1) - Vec(12, -2)).norm(), 0.0, 1e-12);
    const SegmentSpec shorter = withHandleLength(h, 1, std::sqrt(148.0) / 2.0);
    EXPECT_NEAR((shorter.as<HermiteCurve>()->t1 - Vec(-18, 3)).norm(), 0.0, 1e-12);
    const SegmentSpec turned = withHandleAngle(h, 0, 0.0);
    EXPECT_NEAR((turned.as<HermiteCurve>()->t0 - Vec(3.0 * std::sqrt(68.0), 0)).norm(), 0.0, 1e-12);
    // A Hermite's tangent is a point of its own: setting it moves nothing else.
    const SegmentSpec t = withControlPoint(h, 1, 0, 1.5);
    EXPECT_EQ(t.as<HermiteCurve>()->t0, Vec(1.5, 24));
    EXPECT_EQ(t.as<HermiteCurve>()->p0, Vec(20, 0));
}

TEST(ControlPointEdits, AHandleWithoutLengthGrowsAlongTheChord) {
    const SegmentSpec s{CubicBezier{{Vec(20, 0), Vec(20, 0), Vec(12, 18), Vec(0, 20)}}, 0.0, 90.0};
    const Vec direction = splineHandleDirection(s, 0);
    EXPECT_NEAR((direction - Vec(-20, 20) / std::sqrt(800.0)).norm(), 0.0, 1e-12);
    const SegmentSpec grown = withHandleLength(s, 0, 2.0);
    EXPECT_NEAR((grown.as<CubicBezier>()->p[1] - (Vec(20, 0) + 2.0 * direction)).norm(), 0.0,
                1e-12);
}

}  // namespace
}  // namespace cam
