// Teach-in splines: each handle rule checked against its own definition (math.md §4), points on
// a circle giving that circle under the oval rule, the bulge factor, no parasitic loops, and a
// closed contour that validates with tangent joints.

#include <gtest/gtest.h>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "spline/circle_approximation.h"
#include "spline/teach_in.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

std::vector<Vec> onCircle(int n, double R, double start) {
    std::vector<Vec> k;
    for (int i = 0; i < n; ++i) {
        const double a = start + kTwoPi * i / n;
        k.emplace_back(R * std::cos(a), R * std::sin(a));
    }
    return k;
}

const std::vector<Vec> kIrregular{{20, 0}, {14, 15}, {-3, 22}, {-18, 9}, {-16, -12}, {5, -19}};

TEST(TeachIn, OvalRuleOnCirclePointsGivesTheCircleApproximation) {
    for (int n : {4, 6, 8}) {
        const auto spline = splineThroughPoints(onCircle(n, 20.0, 0.2), true, HandleRule::Oval);
        ASSERT_TRUE(spline.ok());
        for (int i = 0; i < n; ++i) {
            const CubicBezier expected = bezierArc({0, 0}, 20.0, 0.2 + kTwoPi * i / n, kTwoPi / n);
            for (int c = 0; c < 4; ++c) {
                EXPECT_LT((spline.value()[static_cast<std::size_t>(i)].p[c] - expected.p[c]).norm(),
                          1e-12)
                    << n << " " << i << " " << c;
            }
        }
    }
}

TEST(TeachIn, CircumcircleRuleIsTangentWithThirdLegHandles) {
    const auto spline = splineThroughPoints(onCircle(6, 15.0, 0.0), true, HandleRule::Circumcircle);
    ASSERT_TRUE(spline.ok());
    for (const CubicBezier& b : spline.value()) {
        const Vec out = b.p[1] - b.p[0];
        EXPECT_NEAR(out.dot(b.p[0]), 0.0, 1e-12);  // tangent: perpendicular to the radius
        EXPECT_NEAR(out.norm(), (b.p[3] - b.p[0]).norm() / 3.0, 1e-12);
    }
}

TEST(TeachIn, ChordRuleFollowsItsDefinition) {
    const auto spline = splineThroughPoints(kIrregular, true, HandleRule::Chord);
    ASSERT_TRUE(spline.ok());
    const std::size_t n = kIrregular.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec& a = kIrregular[(i + n - 1) % n];
        const Vec& b = kIrregular[i];
        const Vec& c = kIrregular[(i + 1) % n];
        const Vec chord = (c + b) / 2.0 - (b + a) / 2.0;  // joins the legs' midpoints
        const Vec out = spline.value()[i].p[1] - b;
        const Vec in = b - spline.value()[(i + n - 1) % n].p[2];
        EXPECT_NEAR(std::abs(out.x() * chord.y() - out.y() * chord.x()), 0.0, 1e-12);  // parallel
        EXPECT_NEAR(in.norm() + out.norm(), chord.norm(), 1e-12);  // total = the chord
        EXPECT_NEAR(out.norm() / in.norm(), (c - b).norm() / (b - a).norm(), 1e-12);  // ratio
    }
}

TEST(TeachIn, BulgeScalesEveryHandle) {
    const auto one = splineThroughPoints(kIrregular, false, HandleRule::Oval, 1.0);
    const auto two = splineThroughPoints(kIrregular, false, HandleRule::Oval, 1.7);
    ASSERT_TRUE(one.ok() && two.ok());
    for (std::size_t i = 0; i < one.value().size(); ++i) {
        const auto& a = one.value()[i].p;
        const auto& b = two.value()[i].p;
        EXPECT_LT(((b[1] - b[0]) - 1.7 * (a[1] - a[0])).norm(), 1e-12);
        EXPECT_LT(((b[2] - b[3]) - 1.7 * (a[2] - a[3])).norm(), 1e-12);
    }
    EXPECT_FALSE(splineThroughPoints(kIrregular, false, HandleRule::Oval, 0.0).ok());
}

TEST(TeachIn, NoParasiticLoopsWhicheverWayThePointsTurn) {
    // A zig-zag turns left and right in turn; every leg must leave and arrive going forwards.
    const std::vector<Vec> zigzag{{0, 0}, {10, 8}, {20, -6}, {30, 9}, {40, -7}, {50, 5}};
    for (HandleRule rule : {HandleRule::Chord, HandleRule::Circumcircle, HandleRule::Oval}) {
        const auto spline = splineThroughPoints(zigzag, false, rule);
        ASSERT_TRUE(spline.ok());
        for (const CubicBezier& b : spline.value()) {
            const Vec leg = b.p[3] - b.p[0];
            for (double s = 0.0; s <= 1.0; s += 0.05) {
                EXPECT_GT(b.derivative(s, 1).dot(leg), 0.0) << static_cast<int>(rule) << " s=" << s;
            }
        }
    }
}

TEST(TeachIn, AClosedContourThroughThePointsValidatesWithTangentJoints) {
    for (HandleRule rule : {HandleRule::Circumcircle, HandleRule::Oval, HandleRule::Chord}) {
        const auto contour = contourThroughPoints(kIrregular, rule);
        ASSERT_TRUE(contour.ok()) << contour.errors().front().text();
        Project p;
        p.contour = contour.value();
        const ContourAnalysis a = analyzeContour(Contour::build(p).value(), kTwoPi);
        for (const JointAnalysis& j : a.joints) {
            EXPECT_LT(j.tangentBreakDeg, 1e-9) << static_cast<int>(rule);
            EXPECT_NE(j.continuity, Continuity::C0);
        }
    }
}

}  // namespace
}  // namespace cam
