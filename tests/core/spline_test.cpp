// Bézier and Hermite segments: exact derivatives against finite differences and against the
// closed form of a line, the Hermite ↔ Bézier identities, the circle approximation's known
// error and speed ratio, uniform speed of 1/3-chord handles, and a mixed contour end to end.

#include <gtest/gtest.h>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "geometry/bezier.h"
#include "geometry/line.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"
#include "project/validate.h"
#include "test_support.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;
using test::relClose;

template <class F>
double centralDiff(const F& f, double x, double h) {
    return (f(x + h) - f(x - h)) / (2.0 * h);
}

void expectDerivativesMatchFiniteDifferences(const CubicBezier& b, double phiLo, double phiHi) {
    for (int i = 1; i < 40; ++i) {
        const double phi = phiLo + (phiHi - phiLo) * i / 40.0;
        const PolarDerivatives d = b.evaluate(phi);
        const double h = 1e-5;
        const double scale = std::abs(d.r);
        EXPECT_TRUE(relClose(d.dr, centralDiff([&](double p) { return b.evaluate(p).r; }, phi, h),
                             1e-7, scale))
            << "r' at " << phi;
        EXPECT_TRUE(relClose(d.d2r, centralDiff([&](double p) { return b.evaluate(p).dr; }, phi, h),
                             1e-7, scale))
            << "r'' at " << phi;
        EXPECT_TRUE(relClose(
            d.d3r, centralDiff([&](double p) { return b.evaluate(p).d2r; }, phi, h), 1e-6, scale))
            << "r''' at " << phi;
    }
}

TEST(Bezier, DerivativesAgreeWithFiniteDifferences) {
    // A bulging curve and an S-shaped one, each met once by every ray of its window.
    expectDerivativesMatchFiniteDifferences(
        CubicBezier{{Vec(20, 0), Vec(22, 8), Vec(12, 18), Vec(5, 20)}}, degToRad(2), degToRad(74));
    expectDerivativesMatchFiniteDifferences(
        CubicBezier{{Vec(20, 0), Vec(26, 9), Vec(7, 25), Vec(0, 20)}}, degToRad(1), degToRad(89));
    expectDerivativesMatchFiniteDifferences(
        CubicBezier{{Vec(-10, -15), Vec(-2, -25), Vec(8, -12), Vec(14, -16)}}, degToRad(-120),
        degToRad(-52));
}

TEST(Bezier, StraightWithThirdChordHandlesIsTheLineExactly) {
    // Independent closed form: r = d/(n·u) and its derivatives (math.md §1).
    const Vec a(20, -5), b(3, 18);
    const CubicBezier bez{{a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b}};
    const Line line{a, b};
    const double from = std::atan2(a.y(), a.x()), to = std::atan2(b.y(), b.x());
    for (int i = 1; i < 30; ++i) {
        const double phi = from + (to - from) * i / 30.0;
        const PolarDerivatives p = bez.evaluate(phi), q = line.evaluate(phi);
        EXPECT_TRUE(relClose(p.r, q.r, 1e-13));
        EXPECT_TRUE(relClose(p.dr, q.dr, 1e-12, q.r));
        EXPECT_TRUE(relClose(p.d2r, q.d2r, 1e-12, q.r));
        EXPECT_TRUE(relClose(p.d3r, q.d3r, 1e-11, q.r));
    }
}

TEST(Bezier, HermiteConversionIsExact) {
    const Vec p0(3, 4), t0(10, -2), p3(-6, 9), t1(-4, 12);
    const CubicBezier b = CubicBezier::fromHermite(p0, t0, p3, t1);
    // Same end points and end derivatives: B(0) = p0, B'(0) = t0, B(1) = p3, B'(1) = t1.
    EXPECT_EQ(b.point(0.0), p0);
    EXPECT_EQ(b.point(1.0), p3);
    EXPECT_LT((b.derivative(0.0, 1) - t0).norm(), 1e-12);  // power basis: some cancellation
    EXPECT_LT((b.derivative(1.0, 1) - t1).norm(), 1e-12);
    // Same curve: the Hermite basis written out independently.
    for (double s : {0.1, 0.37, 0.5, 0.81}) {
        const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
        const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
        const Vec hermite = h00 * p0 + h10 * t0 + h01 * p3 + h11 * t1;
        EXPECT_LT((b.point(s) - hermite).norm(), 1e-13) << s;
    }
    const auto back = b.hermiteTangents();
    EXPECT_LT((back[0] - t0).norm(), 1e-13);
    EXPECT_LT((back[1] - t1).norm(), 1e-13);
}

TEST(Bezier, QuarterCircleApproximationHasTheKnownErrorAndSpeedRatio) {
    // kappa = 4/3·tan(θ/4) = 0.5523 for 90°. The midpoint B(1/2) = (P0 + 3P1 + 3P2 + P3)/8 then
    // lies exactly on the circle; the radius peaks 0.0273 % too long near s = 0.21 and 0.79
    // (the classic figure). |B'| is 3κR at the ends and 3√2·(1/2 − κ/4)·R in the middle, about
    // 8 % apart (math.md §4).
    const double R = 20.0, kappa = 4.0 / 3.0 * std::tan(kPi / 8.0);
    EXPECT_NEAR(kappa, 0.5523, 1e-4);
    const CubicBezier b{{Vec(R, 0), Vec(R, kappa * R), Vec(kappa * R, R), Vec(0, R)}};
    EXPECT_NEAR((4.0 + 3.0 * kappa) / 8.0 * std::sqrt(2.0), 1.0, 1e-15);
    EXPECT_NEAR(b.evaluate(kPi / 4).r, R, 1e-12);
    double worst = 0.0;
    for (int i = 0; i <= 9000; ++i) {
        worst = std::max(worst, b.evaluate(kPi / 2 * i / 9000.0).r / R - 1.0);
    }
    EXPECT_NEAR(worst, 2.7253e-4, 2e-8);
    EXPECT_NEAR(b.derivative(0.0, 1).norm(), 3.0 * kappa * R, 1e-12);
    EXPECT_NEAR(b.derivative(0.5, 1).norm(), 3.0 * std::sqrt(2.0) * (0.5 - kappa / 4.0) * R, 1e-12);
    const double ratio = b.derivative(0.0, 1).norm() / b.derivative(0.5, 1).norm();
    EXPECT_GT(ratio, 1.075);  // "about 8 % above mid-segment"
    EXPECT_LT(ratio, 1.085);
}

TEST(Bezier, ThirdChordHandlesGiveUniformSpeed) {
    const Vec a(5, 2), c(17, -3);
    const CubicBezier uniform{{a, a + (c - a) / 3.0, a + 2.0 * (c - a) / 3.0, c}};
    for (double s = 0.0; s <= 1.0; s += 0.125) {
        EXPECT_NEAR(uniform.derivative(s, 1).norm(), (c - a).norm(), 1e-12) << s;
    }
    // Other handle lengths keep the line but bend the path-time function.
    const CubicBezier uneven{{a, a + (c - a) / 10.0, a + 9.0 * (c - a) / 10.0, c}};
    EXPECT_GT(uneven.derivative(0.5, 1).norm(), 1.2 * uneven.derivative(0.0, 1).norm());
}

/// A circle of radius 20 about the origin with its first quarter a Bézier (ends on the circle),
/// the third quarter a chord, the last a Hermite — arcs, a line and both spline kinds.
const char* kMixed = R"({
  "format": "camwright", "version": 1, "name": "mixed", "motion": {"rpm": 60},
  "contour": [
    {"type": "bezier", "points": [[20, 0], [24, 9], [7, 25], [0, 20]]},
    {"type": "arc", "center": [0, 0], "radius": 20, "branch": "outer", "phi_start": 90,
     "phi_end": 180},
    {"type": "line", "from": [-20, 0], "to": [0, -20]},
    {"type": "hermite", "p0": [0, -20], "t0": [30, 0], "p3": [20, 0], "t1": [0, 30]}
  ]
})";

TEST(SplineContour, MixedContourLoadsEvaluatesAndRoundTrips) {
    const auto project = parseProject(kMixed);
    ASSERT_TRUE(project.ok()) << project.errors().front().text();
    EXPECT_NEAR(project.value().contour[0].phiEndDeg, 90.0, 1e-12);  // default window
    EXPECT_NEAR(project.value().contour[3].phiStartDeg, 270.0, 1e-12);
    const std::string saved = serializeProject(project.value());
    EXPECT_EQ(serializeProject(parseProject(saved).value()), saved);
    EXPECT_NE(saved.find(R"("t1": [)"), std::string::npos);

    const Contour c = Contour::build(project.value()).value();
    // Each spline window: r and derivatives from the contour equal the curve's own evaluation,
    // and the sampled turn equals the state at each instant.
    SampledTurn turn;
    sampleTurn(c, kTwoPi, 720, turn);
    for (std::size_t k = 0; k < turn.size(); ++k) {
        const KinematicState s = stateAt(c, kTwoPi, turn.t[k]);
        ASSERT_EQ(static_cast<std::size_t>(turn.segment[k]), s.segment);
        ASSERT_TRUE(relClose(turn.r[k], s.polar.r, 1e-12)) << k;
        ASSERT_TRUE(relClose(turn.aR[k], s.motion.aR, 1e-9, s.motion.a)) << k;
    }
    // At φ = 45° the ray meets the Bézier: |B(s*)| with u × B(s*) = 0, checked by the point.
    const double r45 = c.evaluate(kPi / 4).r;
    const CubicBezier b = bezierOf(project.value().contour[0]);
    const auto hits = b.rayParameters(std::cos(kPi / 4), std::sin(kPi / 4));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR((b.point(hits[0]) - r45 * Vec(std::cos(kPi / 4), std::sin(kPi / 4))).norm(), 0.0,
                1e-12);
}

TEST(SplineContour, RefusesACurveTheRayMeetsTwiceAndAWrongWindow) {
    std::string folded = kMixed;
    // Handles that fold the curve: the ray at 36° meets it three times.
    folded.replace(folded.find("[24, 9], [7, 25]"), 16, "[0, 40], [30, -10]");
    const auto p = parseProject(folded);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.errors().front().location, "contour[0]");
    EXPECT_NE(p.errors().front().message.find("exactly once"), std::string::npos)
        << p.errors().front().message;

    std::string window = kMixed;
    const std::string points = R"("points": [[20, 0], [24, 9], [7, 25], [0, 20]])";
    window.replace(window.find(points), points.size(),
                   points + R"(, "phi_start": 0, "phi_end": 80)");
    const auto w = parseProject(window);
    ASSERT_FALSE(w.ok());
    bool named = false;
    for (const auto& d : w.errors()) named = named || d.location == "contour[0]";
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// A circle of radius R about the origin from four κ-Bézier quarters (equal, collinear handles
/// at every knot); `stretch` scales the second handle of the first quarter (P2 − P3).
Project bezierCircle(double R, double stretch) {
    const double k = 4.0 / 3.0 * std::tan(kPi / 8.0) * R;
    Project p;
    p.motion = {SpeedUnit::PeriodS, 1.0};
    for (int q = 0; q < 4; ++q) {
        const double a = kPi / 2 * q, b = a + kPi / 2;
        const Vec u(std::cos(a), std::sin(a)), v(std::cos(b), std::sin(b));
        CubicBezier curve{{R * u, R * u + k * v, R * v + k * u, R * v}};
        if (q == 0) curve.p[2] = R * v + stretch * k * u;
        SegmentSpec s{curve};
        std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, 90.0 * q);
        p.contour.push_back(s);
    }
    return p;
}

TEST(SplineContinuity, EqualHandlesAreC1AndALongerHandleIsOnlyG1) {
    const auto even = Contour::build(bezierCircle(20.0, 1.0));
    ASSERT_TRUE(even.ok()) << even.errors().front().text();
    const JointAnalysis knot = analyzeJoint(even.value(), 0, kTwoPi);
    // The two quarters mirror each other about the knot's ray: equal curvature, so even the
    // follower's acceleration is continuous there.
    EXPECT_EQ(knot.continuity, Continuity::C2);
    EXPECT_NEAR(knot.curveRelativeD1, 0.0, 1e-12);  // B'(1) = B'(0) of the next
    EXPECT_NE(knot.geometric, Continuity::G1);
    // Doubling one handle keeps its direction: the tangent stays, the derivative halves.
    const auto stretched = Contour::build(bezierCircle(20.0, 2.0));
    ASSERT_TRUE(stretched.ok()) << stretched.errors().front().text();
    const JointAnalysis g1 = analyzeJoint(stretched.value(), 0, kTwoPi);
    EXPECT_EQ(g1.geometric, Continuity::G1);
    EXPECT_LT(g1.tangentBreakDeg, 1e-9);
    EXPECT_NEAR(g1.curveRelativeD1, 0.5, 1e-12);  // |3κR − 6κR| / 6κR
    EXPECT_NEAR(g1.curveJumpD1.norm(), 3.0 * 4.0 / 3.0 * std::tan(kPi / 8.0) * 20.0, 1e-12);
}

}  // namespace
}  // namespace cam
