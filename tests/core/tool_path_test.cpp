// Tool paths from contours, checked against geometric facts that do not depend on the code:
// an outward offset of a closed curve by ρ grows its length by ρ times its total turning (2π),
// convex corners get arcs of radius ρ, concave corners lose ρ·tan(β/2) on each side.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "common/angles.h"
#include "core/test_projects.h"
#include "io/project_json.h"
#include "project/validate.h"
#include "test_support.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"

namespace cam {
namespace {

using test::sixLobe;

/// Consecutive segments meet within `tolerance` (the contour's own joints may be 1e-6 apart).
void expectClosedAndContinuous(const ToolPath& path, double tolerance = 1e-9) {
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
        const PathSegment& a = path.segments[k];
        const PathSegment& b = path.segments[(k + 1) % path.segments.size()];
        EXPECT_LT((a.end - b.start).norm(), tolerance)
            << "between segments " << k << " and " << k + 1;
        EXPECT_LT((a.point(a.length()) - a.end).norm(), 1e-9) << k;
    }
}

Contour polygon(const std::vector<Eigen::Vector2d>& corners) {
    Project p;
    p.motion = {SpeedUnit::PeriodS, 1.0};
    double previousEnd = 0.0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        SegmentSpec s{Line{corners[k], corners[(k + 1) % corners.size()]}};
        std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, k == 0 ? 0.0 : previousEnd);
        previousEnd = s.phiEndDeg;
        p.contour.push_back(s);
    }
    auto c = Contour::build(p);
    EXPECT_TRUE(c.ok()) << (c.ok() ? "" : c.errors().front().text());
    return c.value();
}

TEST(ToolPathFromContour, SixLobeOffsetGrowsByTwoPiTimesTheToolRadius) {
    const Contour contour = sixLobe();
    const auto zero = toolPathFromContour(contour, 0.0);
    ASSERT_TRUE(zero.ok());
    EXPECT_EQ(zero.value().segments.size(), 13u);  // tangent joints: no corner arcs
    expectClosedAndContinuous(zero.value(), kJointToleranceMm);
    for (double rho : {0.5, 2.0, 4.5}) {
        const auto path = toolPathFromContour(contour, rho);
        ASSERT_TRUE(path.ok()) << path.errors().front().text();
        expectClosedAndContinuous(path.value(), kJointToleranceMm);
        EXPECT_NEAR(path.value().length() - zero.value().length(), kTwoPi * rho, 1e-6) << rho;
        // Lobes (outer) grow, notches (inner) shrink; arcs stay arcs.
        for (std::size_t k = 0; k < 13; ++k) {
            const PathSegment& s = path.value().segments[k];
            ASSERT_EQ(s.kind, PathSegment::Kind::Arc);
            const double r = contour.segment(k).arc.radius;
            const bool lobe = contour.segment(k).arc.branch == Branch::Outer;
            EXPECT_NEAR(s.radius, lobe ? r + rho : r - rho, 1e-12) << k;
        }
    }
}

TEST(ToolPathFromContour, AToolWiderThanANotchIsAnErrorNamingTheSegment) {
    const auto path = toolPathFromContour(sixLobe(), 5.0);  // notch radius is 4.84 mm
    ASSERT_FALSE(path.ok());
    EXPECT_EQ(path.errors().front().location, "contour[0]");
    EXPECT_NE(path.errors().front().message.find("4.84070597"), std::string::npos);
}

TEST(ToolPathFromContour, ConvexCornersGetArcsOfTheToolRadius) {
    const Contour square = polygon({{10, -10}, {10, 10}, {-10, 10}, {-10, -10}});
    const auto path = toolPathFromContour(square, 1.5);
    ASSERT_TRUE(path.ok()) << path.errors().front().text();
    ASSERT_EQ(path.value().segments.size(), 8u);
    expectClosedAndContinuous(path.value());
    EXPECT_NEAR(path.value().length(), 80.0 + kTwoPi * 1.5, 1e-9);
    const PathSegment& corner = path.value().segments[1];
    EXPECT_EQ(corner.kind, PathSegment::Kind::Arc);
    EXPECT_NEAR(corner.radius, 1.5, 1e-12);
    EXPECT_NEAR(corner.sweep, kPi / 2, 1e-12);
    EXPECT_NEAR((corner.center - Eigen::Vector2d(10, 10)).norm(), 0.0, 1e-12);
}

TEST(ToolPathFromContour, ConcaveCornersAreTrimmed) {
    // A square with a dent at (0, 2): the turn there is concave by β = 2·atan(10/8).
    const std::vector<Eigen::Vector2d> corners{{10, -10}, {10, 10}, {0, 2}, {-10, 10}, {-10, -10}};
    const Contour dented = polygon(corners);
    const double rho = 1.0;
    const auto path = toolPathFromContour(dented, rho);
    ASSERT_TRUE(path.ok()) << path.errors().front().text();
    expectClosedAndContinuous(path.value());
    double perimeter = 0.0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        perimeter += (corners[(k + 1) % corners.size()] - corners[k]).norm();
    }
    // Turning: three convex corners of 90°, two of 90° + atan(8/10)… computed from the polygon:
    double convexTurn = 0.0, concaveCut = 0.0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Eigen::Vector2d a = corners[k] - corners[(k + corners.size() - 1) % corners.size()];
        const Eigen::Vector2d b = corners[(k + 1) % corners.size()] - corners[k];
        const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        if (turn > 0) {
            convexTurn += turn;
        } else {
            concaveCut += 2.0 * rho * std::tan(-turn / 2.0);
        }
    }
    EXPECT_NEAR(path.value().length(), perimeter + rho * convexTurn - concaveCut, 1e-9);
}

// tests/data/timing/notch-dwell.cam.json: the square ±10 with a V notch from (10, 10) and
// (−10, 10) down to a dwell arc of radius R = 0.87 about the origin, polar angles 60°..120°.
// Both ends of the arc are concave corners, so its offset (radius R + ρ) is trimmed from both
// sides; from a tool radius ρ* on, the trims meet on the y axis and nothing is left of it.
struct Notch {
    static constexpr double kR = 0.87;
    Eigen::Vector2d a{10, 10};  ///< the upper right corner, where line contour[1] starts
    Eigen::Vector2d d;          ///< unit direction of contour[1], towards the arc
    Eigen::Vector2d n;          ///< its outward (right-hand) normal
    Notch() {
        const Eigen::Vector2d p1 = kR * Eigen::Vector2d(std::cos(kPi / 3), std::sin(kPi / 3));
        d = (p1 - a).normalized();
        n = {d.y(), -d.x()};
    }
    /// The ρ at which the offset of contour[1], {X : (X − a)·n = ρ}, passes through (0, R + ρ):
    /// −10·n.x + (R + ρ − 10)·n.y = ρ.
    [[nodiscard]] double vanishingRadius() const {
        return (-10.0 * n.x() + (kR - 10.0) * n.y()) / (1.0 - n.y());
    }
    /// Where the offset of contour[1] first meets the circle R + ρ: its length t from the
    /// offset's start a + ρ·n, and the polar angle θ1 of the meeting point. The offset arc runs
    /// from θ1 to π − θ1 (the notch is symmetric about the y axis).
    [[nodiscard]] std::pair<double, double> meeting(double rho) const {
        const Eigen::Vector2d q0 = a + rho * n;
        // |q0 + t·d|² = (R + ρ)²: the smaller root is the first meeting.
        const double b = q0.dot(d), c = q0.squaredNorm() - (kR + rho) * (kR + rho);
        const double t = -b - std::sqrt(b * b - c);
        const Eigen::Vector2d x1 = q0 + t * d;
        return {t, std::atan2(x1.y(), x1.x())};
    }
    /// The length of the offset path by hand, for ρ < vanishingRadius(): the three outer sides
    /// (20 mm each, between convex corners); the convex corner arcs ρ·(π/2 + π/2 + 2·θc) with
    /// θc the turn at (±10, 10); twice the trimmed offset of contour[1]; the trimmed arc.
    [[nodiscard]] double pathLength(double rho) const {
        const double thetaC = std::atan2(-d.x(), d.y());  // the turn from (0, 1) to d
        const auto [t, theta1] = meeting(rho);
        return 60.0 + rho * (kPi + 2.0 * thetaC) + 2.0 * t + (kR + rho) * (kPi - 2.0 * theta1);
    }
};

Contour notchDwell() {
    auto project = loadProjectFile(test::dataPath("timing/notch-dwell.cam.json"));
    EXPECT_TRUE(project.ok()) << (project.ok() ? "" : project.errors().front().text());
    return Contour::build(project.value()).value();
}

TEST(ToolPathFromContour, AnArcTrimmedAwayByItsConcaveCornersIsAnErrorNamingIt) {
    const Contour contour = notchDwell();
    const Notch notch;
    const double vanishing = notch.vanishingRadius();
    // Worked by hand: p1 = 0.87·(cos 60°, sin 60°) = (0.435, 0.753442), |p1 − a| = 13.303686,
    // d = (−9.565, −9.246558)/13.303686 = (−0.718974, −0.695037), n = (−0.695037, 0.718974),
    // ρ* = (6.95037 − 9.13·0.718974)/(1 − 0.718974) = 0.386138/0.281026 = 1.37404.
    EXPECT_NEAR(vanishing, 1.37404, 2e-5);
    for (double rho : {3.0, 1.01 * vanishing}) {
        SCOPED_TRACE(rho);
        const auto path = toolPathFromContour(contour, rho);
        ASSERT_FALSE(path.ok()) << "a path of " << path.value().length() << " mm";
        ASSERT_EQ(path.errors().size(), 1u);
        EXPECT_EQ(path.errors().front().location, segmentLocation(2));
        EXPECT_NE(path.errors().front().message.find("too large"), std::string::npos);
    }
}

TEST(ToolPathFromContour, AToolJustSmallEnoughForTheNotchKeepsTheLengthWorkedByHand) {
    const Contour contour = notchDwell();
    const Notch notch;
    // At ρ = 0 the contour itself: 3·20 + 2·|p1 − a| + R·π/3 = 60 + 2·13.303686 + 0.911062.
    EXPECT_NEAR(notch.pathLength(0.0), 87.518434, 1e-6);
    for (double rho : {0.5, 0.99 * notch.vanishingRadius()}) {
        SCOPED_TRACE(rho);
        const auto path = toolPathFromContour(contour, rho);
        ASSERT_TRUE(path.ok()) << path.errors().front().text();
        ASSERT_EQ(path.value().segments.size(), 10u);  // six pieces and four convex corner arcs
        expectClosedAndContinuous(path.value());
        EXPECT_NEAR(path.value().length(), notch.pathLength(rho), 1e-9);
        // The trimmed arc is what is left between the two meeting points: short, not wrapped.
        const PathSegment& arc = path.value().segments[3];
        ASSERT_EQ(arc.kind, PathSegment::Kind::Arc);
        EXPECT_NEAR(arc.radius, Notch::kR + rho, 1e-12);
        EXPECT_NEAR(arc.sweep, kPi - 2.0 * notch.meeting(rho).second, 1e-9);
    }
}

TEST(ToolPathFromContour, ConcaveCornersNextToSplinesCutAsManyArcsAsTheyMust) {
    // The Bézier of spline-mix meets the arc at (0, 20) in a concave corner of 35.5°: the
    // offsets cross about ρ·tan(17.8°) from it, beyond the first few of the Bézier's short arcs
    // when the tolerance is fine. The path must not depend on how finely the Bézier is split.
    const Contour contour =
        Contour::build(loadProjectFile(test::dataPath("reference/spline-mix.cam.json")).value())
            .value();
    for (const double rho : {0.5, 2.0, 3.0, 5.0}) {
        const auto reference = offsetContour(contour, rho, 1e-7);
        ASSERT_TRUE(reference.ok()) << rho << ": " << reference.errors().front().text();
        for (const double tolerance : {1e-3, 1e-4, 1e-5, 1e-6}) {
            SCOPED_TRACE("tool radius " + std::to_string(rho) + ", tolerance " +
                         std::to_string(tolerance));
            const auto offset = offsetContour(contour, rho, tolerance);
            ASSERT_TRUE(offset.ok()) << offset.errors().front().text();
            expectClosedAndContinuous(offset.value().path, 1e-6);
            // Arcs within the tolerance of the curve are as long as it to a few tolerances.
            EXPECT_NEAR(offset.value().path.length(), reference.value().path.length(),
                        10 * tolerance);
        }
    }
}

TEST(ToolPathFromPoints, BulgesMakeArcsWithTheRightCentreAndRadius) {
    // Bulge 1: a half circle counter-clockwise from (0,0) to (10,0): centre (5,0), radius 5.
    auto half = toolPathFromPoints({{{0, 0, 0}, 1.0}, {{10, 0, 0}, 0.0}});
    ASSERT_TRUE(half.ok());
    EXPECT_NEAR((half.value().segments[0].center - Eigen::Vector2d(5, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR(half.value().segments[0].radius, 5.0, 1e-12);
    EXPECT_NEAR(half.value().segments[0].sweep, kPi, 1e-12);
    EXPECT_NEAR(half.value().segments[0].point(2.5 * kPi).y(), -5.0, 1e-12);  // passes below
    // A negative bulge turns clockwise: it passes above.
    auto cw = toolPathFromPoints({{{0, 0, 0}, -1.0}, {{10, 0, 0}, 0.0}});
    EXPECT_NEAR(cw.value().segments[0].point(2.5 * kPi).y(), 5.0, 1e-12);
}

TEST(ToolPathFromPoints, LocatesBadPoints) {
    auto repeated = toolPathFromPoints({{{0, 0, 0}, 0}, {{0, 0, 0}, 0}, {{1, 0, 0}, 0}});
    ASSERT_FALSE(repeated.ok());
    EXPECT_EQ(repeated.errors().front().location, "point[1]");
    auto climbing = toolPathFromPoints({{{0, 0, 0}, 0.5}, {{10, 0, 3}, 0}});
    ASSERT_FALSE(climbing.ok());
    EXPECT_EQ(climbing.errors().front().location, "point[0]");
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(ToolPathFromContour, TangentJointsStayTangentAfterOffsetting) {
    // The six-lobe data breaks its tangents by ~1e-8 rad (ten-digit numbers). Treated as corners,
    // the offsets would be intersected — ill-conditioned for nearly tangent circles — and the
    // planner would then stop at every joint. Offset arcs keep their angles about their centres,
    // so each joint of the path turns by exactly what the contour turns there: dP/dφ = r'·u +
    // r·u⊥ from the contour's own polar derivatives.
    const Contour contour = sixLobe();
    auto contourTangent = [&](std::size_t k, double phi) {
        const PolarDerivatives d = contour.segment(k).evaluate(phi);
        return Eigen::Vector2d(d.dr * std::cos(phi) - d.r * std::sin(phi),
                               d.dr * std::sin(phi) + d.r * std::cos(phi))
            .normalized();
    };
    auto turn = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    };
    const auto path = toolPathFromContour(contour, 2.0);
    ASSERT_TRUE(path.ok());
    const std::size_t n = contour.size();
    ASSERT_EQ(path.value().segments.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        const double expected = turn(contourTangent(k, contour.segment(k).phiEnd),
                                     contourTangent(next, contour.segment(next).phiStart));
        EXPECT_LE(std::abs(expected), degToRad(kTangentToleranceDeg)) << k;  // the premise
        const PathSegment& a = path.value().segments[k];
        const PathSegment& b = path.value().segments[next];
        EXPECT_NEAR(turn(a.tangent(a.length()).head<2>(), b.tangent(0.0).head<2>()), expected,
                    1e-12)
            << k;
    }
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// The square ±10 with its right side broken at (10, 0): the upper half leans by `breakRad`
/// (positive: the contour turns left there, a convex joint; negative: concave).
Contour squareBrokenAt(double breakRad) {
    const double lean = 10.0 * std::tan(breakRad);
    return polygon({{10, -10}, {10, 0}, {10 - lean, 10}, {-10, 10}, {-10, -10}});
}

/// Machine limits of these tests: a = 500 mm/s² on x and y, feed 100 mm/s.
MachineLimits squareLimits() {
    MachineLimits limits;
    limits.accel = {500, 500, 200};
    limits.feedMax = 100;
    return limits;
}

// The tool path rounds or trims a joint whose tangent breaks by more than kTangentToleranceDeg
// (1e-5° = 1.745e-7 rad); the planner used to stop only above 1e-6 rad. A break of 5e-7 rad lies
// between: the offset treated it as a corner and the planner as tangent. Now both see a corner.
TEST(ToolPathAndPlanner, AgreeThatABreakAboveTheToleranceIsACorner) {
    constexpr double kBreak = 5e-7;
    ASSERT_GT(kBreak, degToRad(kTangentToleranceDeg));
    ASSERT_LT(kBreak, 1e-6);

    // The offset: a corner arc of the tool radius through exactly the break (convex), ...
    const auto rounded = toolPathFromContour(squareBrokenAt(kBreak), 1.0);
    ASSERT_TRUE(rounded.ok()) << rounded.errors().front().text();
    ASSERT_EQ(rounded.value().segments.size(), 10u);  // five sides, five corner arcs
    const PathSegment& arc = rounded.value().segments[1];
    ASSERT_EQ(arc.kind, PathSegment::Kind::Arc);
    EXPECT_NEAR(arc.radius, 1.0, 1e-12);
    EXPECT_NEAR(arc.sweep, kBreak, 1e-12);

    // ... and the planner stops there: on the sides themselves (tool radius 0) every joint is a
    // corner, so the optimal time is the sum of each side rest to rest. Each side has
    // L <= F²/a = 20 mm: the triangle 2·sqrt(L/a_eff), a_eff = 500/max|n_i|.
    const auto sides = toolPathFromContour(squareBrokenAt(kBreak), 0.0);
    ASSERT_TRUE(sides.ok());
    ASSERT_EQ(sides.value().segments.size(), 5u);
    double restToRest = 0.0;
    for (const PathSegment& side : sides.value().segments) {
        const Eigen::Vector3d n = (side.end - side.start).normalized();
        restToRest += 2.0 * std::sqrt(side.length() * n.cwiseAbs().maxCoeff() / 500.0);
    }
    // By hand: two 10 mm halves (0.282843 s each), three 20 mm sides (0.4 s each).
    EXPECT_NEAR(restToRest, 4.0 * std::sqrt(0.02) + 1.2, 1e-6);
    const auto optimal = machiningTime(sides.value(), squareLimits(), TimingMethod::Optimal);
    ASSERT_TRUE(optimal.ok());
    EXPECT_EQ(optimal.value().segments[0].exitSpeed, 0.0);
    EXPECT_EQ(optimal.value().segments[1].entrySpeed, 0.0);
    EXPECT_TRUE(test::relClose(optimal.value().timeS, restToRest, 1e-6));

    // Concave: the offsets are trimmed where they cross, which leaves the same break in the
    // path, and the planner stops there too.
    const auto trimmed = toolPathFromContour(squareBrokenAt(-kBreak), 1.0);
    ASSERT_TRUE(trimmed.ok()) << trimmed.errors().front().text();
    ASSERT_EQ(trimmed.value().segments.size(), 9u);  // five sides, four convex corner arcs
    const PathSegment& before = trimmed.value().segments[0];
    const PathSegment& after = trimmed.value().segments[1];
    const Eigen::Vector3d t0 = before.tangent(before.length()), t1 = after.tangent(0.0);
    EXPECT_NEAR(std::atan2(t0.cross(t1).norm(), t0.dot(t1)), kBreak, 1e-12);
    const auto planned = machiningTime(trimmed.value(), squareLimits(), TimingMethod::Optimal);
    ASSERT_TRUE(planned.ok());
    EXPECT_EQ(planned.value().segments[0].exitSpeed, 0.0);
    EXPECT_EQ(planned.value().segments[1].entrySpeed, 0.0);
}

// And below the tolerance (1e-7 rad) both see a tangent joint: no corner arc in the offset, and
// the planner runs through it as through one 20 mm side, which reaches the feed 100 mm/s
// exactly at the joint (after v²/(2a) = 10 mm) and takes 20/100 + 100/500 = 0.4 s; so do the
// three other sides: 1.6 s.
TEST(ToolPathAndPlanner, AgreeThatABreakWithinTheToleranceIsTangent) {
    constexpr double kBreak = 1e-7;
    ASSERT_LT(kBreak, degToRad(kTangentToleranceDeg));
    const auto offset = toolPathFromContour(squareBrokenAt(kBreak), 1.0);
    ASSERT_TRUE(offset.ok());
    EXPECT_EQ(offset.value().segments.size(), 9u);  // no corner arc at the break
    const auto sides = toolPathFromContour(squareBrokenAt(kBreak), 0.0);
    ASSERT_TRUE(sides.ok());
    const auto optimal = machiningTime(sides.value(), squareLimits(), TimingMethod::Optimal);
    ASSERT_TRUE(optimal.ok());
    EXPECT_TRUE(test::relClose(optimal.value().segments[0].exitSpeed, 100.0, 1e-6));
    EXPECT_TRUE(test::relClose(optimal.value().timeS, 4.0 * 0.4, 1e-6));
}

}  // namespace
}  // namespace cam
