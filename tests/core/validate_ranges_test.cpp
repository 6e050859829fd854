// The ranges in which Camwright's arithmetic is sound (project-format.md, issue 9 point 3):
// every value outside them is refused by validation with its place and the range, every value
// at their edges is accepted, and a project at the edges computes finite numbers everywhere.
// At 612d090 a period of 1e-308 (ω = inf), an arc radius of 1e-300 and a window ending where
// the follower ray only touches its arc were all "valid", and the engine printed NaN for them.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/analysis.h"
#include "contour/contour.h"
#include "core/test_projects.h"
#include "kinematics/kinematics.h"
#include "project/validate.h"

namespace cam {
namespace {

/// The first error's location and message, or "" when the project validates.
std::pair<std::string, std::string> firstError(const Project& p) {
    for (const Diagnostic& d : validateProject(p)) {
        if (d.severity == Severity::Error) return {d.location, d.message};
    }
    return {};
}

/// Every sampled quantity and every analysed value of a project is finite.
void expectFiniteEverywhere(const Project& p, const char* what) {
    const auto contour = Contour::build(p);
    ASSERT_TRUE(contour.ok()) << what << ": " << contour.errors().front().text();
    const double omega = p.motion.omegaRadS();
    SampledTurn turn;
    sampleTurn(contour.value(), omega, 3600, turn);
    for (const auto* column : {&turn.r, &turn.v, &turn.a, &turn.j, &turn.vR, &turn.aR, &turn.jR,
                               &turn.vPhi, &turn.aPhi, &turn.jPhi}) {
        for (double v : *column) ASSERT_TRUE(std::isfinite(v)) << what;
    }
    const ContourAnalysis analysis = analyzeContour(contour.value(), omega);
    for (const JointAnalysis& j : analysis.joints) {
        EXPECT_TRUE(std::isfinite(j.tangentBreakDeg)) << what << " joint " << j.right;
        EXPECT_TRUE(std::isfinite(j.jumpD3r)) << what << " joint " << j.right;
    }
    for (const QuantityExtremes& e : analysis.extremes) {
        EXPECT_TRUE(std::isfinite(e.min.value) && std::isfinite(e.max.value)) << what;
    }
}

TEST(SoundRanges, SpeedsOutsideTheirRangeAreRefusedInTheUnitGiven) {
    struct Case {
        SpeedUnit unit;
        double value;
        const char* range;  // as the message must state it
    };
    const std::vector<Case> refused{
        {SpeedUnit::PeriodS, 1e-308, "between 1e-05 and 10000000 s"},  // ω = inf at 612d090
        {SpeedUnit::PeriodS, 9.9e-6, "between 1e-05 and 10000000 s"},
        {SpeedUnit::PeriodS, 1.1e7, "between 1e-05 and 10000000 s"},
        {SpeedUnit::Rpm, 1e300, "between 1e-05 and 10000000 rpm"},
        {SpeedUnit::Rpm, -2e7, "between 1e-05 and 10000000 rpm"},
        {SpeedUnit::Rpm, 1e-320, "between 1e-05 and 10000000 rpm"},  // a denormal
        {SpeedUnit::OmegaRadS, 1.5e6, "between 1e-06 and 1000000 rad/s"},
        {SpeedUnit::OmegaRadS, -1e-7, "between 1e-06 and 1000000 rad/s"},
    };
    for (const Case& c : refused) {
        const auto [where, message] =
            firstError(test::splitCircle(5, 20, {0, 180, 360}, {c.unit, c.value}));
        EXPECT_TRUE(where.rfind("motion.", 0) == 0) << c.value << ": " << where;
        EXPECT_TRUE(test::contains(message, c.range)) << c.value << ": " << message;
    }
    // The edges themselves are inside, in either turning direction, and compute finite values.
    for (const MotionSpec m :
         {MotionSpec{SpeedUnit::PeriodS, 1e-5}, MotionSpec{SpeedUnit::PeriodS, 1e7},
          MotionSpec{SpeedUnit::Rpm, -1e7}, MotionSpec{SpeedUnit::Rpm, 1e-5},
          MotionSpec{SpeedUnit::OmegaRadS, 1e6}, MotionSpec{SpeedUnit::OmegaRadS, -1e-6}}) {
        const Project p = test::splitCircle(5, 20, {0, 180, 360}, m);
        EXPECT_EQ(firstError(p).first, "") << m.value << ": " << firstError(p).second;
        expectFiniteEverywhere(p, "speed at the edge of its range");
    }
}

TEST(SoundRanges, RadiiBelowTheJointToleranceAreRefused) {
    // An arc of radius 1e-300 about a point next to the origin: valid at 612d090, NaN after.
    Project p = test::splitCircle(1e-301, 1e-300, {0, 180, 360});
    auto [where, message] = firstError(p);
    EXPECT_EQ(where, "contour[0].radius");
    EXPECT_TRUE(test::contains(message, "at least 1e-06 mm")) << message;
    // Radius 1e-6 mm itself is a (tiny) cam, and computes.
    p = test::splitCircle(1e-7, 1e-6, {0, 180, 360});
    EXPECT_EQ(firstError(p).first, "") << firstError(p).second;
    expectFiniteEverywhere(p, "radius 1e-6 mm");
    // So is the largest, 1e6 mm, at the fastest speed.
    p = test::splitCircle(0, 1e6, {0, 180, 360}, {SpeedUnit::OmegaRadS, 1e6});
    EXPECT_EQ(firstError(p).first, "") << firstError(p).second;
    expectFiniteEverywhere(p, "radius 1e6 mm at 1e6 rad/s");
}

/// An arc about (20, 0) of radius 10 (outer branch) on [-end, end], closed by a circle about
/// the origin through the arc's end points. The ray touches the arc at ±30° (sin 30° = 10/20).
Project lensCam(double endDeg) {
    const double phi = endDeg * std::numbers::pi / 180.0;
    // Where the ray at angle phi leaves the circle |p − (20, 0)| = 10: r² − 40 r cos φ + 300 = 0.
    const double mu = 20.0 * std::cos(phi);
    const double r = mu + std::sqrt(std::max(0.0, mu * mu - 300.0));
    Project p;
    p.motion = {SpeedUnit::PeriodS, 1.0};
    p.contour.push_back(SegmentSpec{Arc{{20.0, 0.0}, 10.0, Branch::Outer}, -endDeg, endDeg});
    p.contour.push_back(SegmentSpec{Arc{{0.0, 0.0}, r, Branch::Outer}, endDeg, 360.0 - endDeg});
    return p;
}

TEST(SoundRanges, AWindowEndingWhereTheRayOnlyTouchesItsArcIsRefused) {
    // At 612d090 this validated, and `analyze` gave the joint tangent_break_deg null, "C2".
    const auto [where, message] = firstError(lensCam(30.0));
    EXPECT_EQ(where, "contour[0].phi_start");
    EXPECT_TRUE(test::contains(message, "only grazes")) << message;
    EXPECT_TRUE(test::contains(message, "1e-06 rad")) << message;
    // 1e-8° before the tangent the ray still crosses at 2.5e-5 rad (tan ψ = r/|r'|, r' from
    // the circle's polar equation): steep enough, and every number stays finite.
    const Project close = lensCam(30.0 - 1e-8);
    EXPECT_EQ(firstError(close).first, "") << firstError(close).second;
    expectFiniteEverywhere(close, "window 1e-8° before the tangent");
}

TEST(SoundRanges, MachineLimitsOutsideTheirRangeAreRefused) {
    Project p = test::splitCircle(5, 20, {0, 180, 360});
    p.machining = MachiningSpec{};
    p.machining->axisAccel = {1e-320, 1000};  // a denormal: the timing divided by it
    auto [where, message] = firstError(p);
    EXPECT_EQ(where, "machining.axis_accel[0]");
    EXPECT_TRUE(test::contains(message, "between 1e-06 and 1e+12 mm/s²")) << message;
    p.machining->axisAccel = {1000, 1000};
    p.machining->feedMax = 1e300;
    std::tie(where, message) = firstError(p);
    EXPECT_EQ(where, "machining.feed_max");
    EXPECT_TRUE(test::contains(message, "between 1e-06 and 1000000000 mm/s")) << message;
    p.machining->feedMax = 100;
    p.machining->step = 1e-9;
    std::tie(where, message) = firstError(p);
    EXPECT_EQ(where, "machining.step");
    EXPECT_TRUE(test::contains(message, "at least 1e-06 mm")) << message;
}

TEST(SoundRanges, AnInstantManyTurnsOutKeepsItsAngle) {
    // t = 1e14 s at a period of 0.4 s is exactly 2.5e14 turns: the cam is where it was at t = 0.
    // ω·t in radians (1.57e15) carries a rounding of 0.25 rad, which gave r = 21.805 at 612d090.
    const Project p = test::splitCircle(5, 20, {0, 90, 180, 270, 360}, {SpeedUnit::PeriodS, 0.4});
    const auto contour = Contour::build(p);
    ASSERT_TRUE(contour.ok());
    const KinematicState s = stateAt(contour.value(), p.motion, 1e14);
    EXPECT_EQ(s.segment, 0u);
    EXPECT_NEAR(s.polar.r, 25.0, 1e-12);  // at φ = 0 the outer branch is 5 + 20 from the origin
    // A quarter period after a whole number of turns: r on the circle at 90°, sqrt(20² − 5²).
    const KinematicState q = stateAt(contour.value(), p.motion, 1e6 + 0.1);
    EXPECT_NEAR(q.polar.r, std::sqrt(375.0), 1e-6);
    EXPECT_DOUBLE_EQ(turnsAt(p.motion, 1e14), 2.5e14);
    EXPECT_DOUBLE_EQ(turnsAt({SpeedUnit::Rpm, 150.0}, 1e14), 2.5e14);
    EXPECT_NEAR(turnsAt({SpeedUnit::OmegaRadS, -2 * std::numbers::pi}, 3.0), -3.0, 1e-15);
}

}  // namespace
}  // namespace cam
