// Followers placed by contact (math.md §7), checked without the follower's own formulas: on an
// eccentric circle against its closed form and plane geometry; on the six-lobe cam and on spline
// cams by the distance from the roller centre to the profile (sampled through r(φ), refined),
// by the support function taken as a maximum over the profile, by the knife at e = 0 equalling
// r(φ) of math.md §1, and by finite differences of s for its derivatives.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/follower_geometry.h"
#include "core/test_projects.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

using test::derivative;
using test::distanceToProfile;
using test::load;
using test::normalOf;
using test::profilePoint;
using test::relClose;
using test::sixLobe;
using test::unit;

FollowerModel model(const Contour& contour, FollowerType type, double offset, double radius) {
    FollowerSpec spec;
    spec.type = type;
    spec.offset = offset;
    spec.radius = radius;
    auto m = FollowerModel::build(contour, spec);
    EXPECT_TRUE(m.ok());
    return std::move(m).value();
}

TEST(FollowerOnACircle, KnifeWithOffsetIsTheOuterCrossingOfItsLine) {
    // A circle of radius 20 about (8, 3): s(φ) = c·u + √(R² − (e − c·n)²).
    const Eigen::Vector2d c(8.0, 3.0);
    const double R = 20.0, e = 5.0;
    const Contour contour = test::disc(c, R);
    const FollowerModel m = model(contour, FollowerType::Knife, e, 0.0);
    for (double deg = 0.0; deg < 360.0; deg += 7.3) {
        const double phi = degToRad(deg);
        const FollowerState st = m.at(phi, 2.0);
        const double a = c.dot(unit(phi)), b = c.dot(normalOf(phi));
        EXPECT_TRUE(relClose(st.s, a + std::sqrt(R * R - (e - b) * (e - b)), 1e-13)) << deg;
        // The tip on the circle and on the follower's line.
        EXPECT_NEAR((st.center - c).norm(), R, 1e-12) << deg;
        EXPECT_NEAR(st.center.dot(normalOf(phi)), e, 1e-12) << deg;
        // The normal is the circle's radius there; the pressure angle is its angle to u, signed
        // positive when the normal leans against n (the follower rises).
        const Eigen::Vector2d nu = (st.center - c).normalized();
        EXPECT_NEAR((st.normal - nu).norm(), 0.0, 1e-12) << deg;
        EXPECT_NEAR(st.pressureAngle, std::atan2(-nu.dot(normalOf(phi)), nu.dot(unit(phi))), 1e-12)
            << deg;
        EXPECT_TRUE(relClose(st.rhoProfile, R, 1e-9)) << deg;
        EXPECT_TRUE(relClose(st.v, 2.0 * st.sPhi[1], 1e-15));
    }
}

TEST(FollowerOnACircle, RollerRidesTheCircleOfRadiusRPlusRho) {
    const Eigen::Vector2d c(-6.0, 4.0);
    const double R = 25.0, rho = 4.0, e = -7.0;
    const Contour contour = test::disc(c, R);
    const FollowerModel m = model(contour, FollowerType::Roller, e, rho);
    for (double deg = 0.5; deg < 360.0; deg += 11.1) {
        const double phi = degToRad(deg);
        const FollowerState st = m.at(phi, 1.0);
        EXPECT_NEAR((st.center - c).norm(), R + rho, 1e-12) << deg;
        EXPECT_NEAR(st.center.dot(normalOf(phi)), e, 1e-12) << deg;
        EXPECT_NEAR((st.contact - (c + R * (st.center - c).normalized())).norm(), 0.0, 1e-12)
            << deg;
        EXPECT_TRUE(relClose(st.rhoPitch, R + rho, 1e-9)) << deg;
        EXPECT_TRUE(relClose(st.rhoProfile, R, 1e-9)) << deg;
    }
    // Its lowest point: the line's nearest crossing of the pitch circle over the turn is where
    // the centre c is farthest behind: s_min = √((R + ρ)² − e²)·… found by brute force.
    double lowest = 1e300;
    for (int i = 0; i < 200000; ++i) lowest = std::min(lowest, m.at(kTwoPi * i / 200000, 1.0).s);
    EXPECT_NEAR(m.minS(), lowest, 1e-8);
    EXPECT_LE(m.minS(), lowest + 1e-15);
}

TEST(FollowerOnACircle, FlatFaceRestsOnTheSupportFunction) {
    const Eigen::Vector2d c(5.0, -2.0);
    const double R = 18.0;
    const Contour contour = test::disc(c, R);
    const FollowerModel m = model(contour, FollowerType::Flat, 3.0, 0.0);
    for (double deg = 0.0; deg < 360.0; deg += 13.0) {
        const double phi = degToRad(deg);
        const FollowerState st = m.at(phi, 3.0);
        EXPECT_TRUE(relClose(st.s, c.dot(unit(phi)) + R, 1e-14)) << deg;
        EXPECT_NEAR((st.contact - (c + R * unit(phi))).norm(), 0.0, 1e-12) << deg;
        EXPECT_NEAR(st.sPhi[1], c.dot(normalOf(phi)), 1e-12) << deg;  // where along the face
        EXPECT_NEAR(st.sPhi[2], -c.dot(unit(phi)), 1e-12) << deg;
        EXPECT_TRUE(relClose(st.rhoProfile, R, 1e-12)) << deg;
        EXPECT_EQ(st.pressureAngle, 0.0);
    }
}

TEST(FollowerKnife, AtNoOffsetItIsTheRadiusOfMathSection1) {
    for (const std::string& path : {test::examplePath("six-lobe-arc-cam.cam.json"),
                                    test::dataPath("reference/spline-mix.cam.json"),
                                    test::dataPath("reference/spline-offset.cam.json"),
                                    test::dataPath("reference/d-flat.cam.json")}) {
        const Contour contour = load(path);
        const FollowerModel m = model(contour, FollowerType::Knife, 0.0, 0.0);
        for (int i = 0; i < 720; ++i) {
            const double phi = contour.phiBegin() + kTwoPi * (i + 0.37) / 720;
            const PolarDerivatives r = contour.evaluate(phi);
            const FollowerState st = m.at(phi, 1.0);
            EXPECT_TRUE(relClose(st.s, r.r, 1e-12)) << path << " " << phi;
            EXPECT_NEAR(st.sPhi[1], r.dr, 1e-9 * (1 + std::abs(r.dr))) << path << " " << phi;
            EXPECT_NEAR(st.sPhi[2], r.d2r, 1e-8 * (1 + std::abs(r.d2r))) << path << " " << phi;
            EXPECT_NEAR(st.sPhi[3], r.d3r, 1e-7 * (1 + std::abs(r.d3r))) << path << " " << phi;
        }
    }
}

/// A roller with offset keeps exactly its radius from the profile and touches it, and s, s', s''
/// are the derivatives of one another.
void checkRoller(const Contour& contour, double e, double rho, const char* name, int angles = 90) {
    const FollowerModel m = model(contour, FollowerType::Roller, e, rho);
    const auto s = [&](double phi) { return m.at(phi, 1.0).s; };
    const auto s1 = [&](double phi) { return m.at(phi, 1.0).sPhi[1]; };
    const auto s2 = [&](double phi) { return m.at(phi, 1.0).sPhi[2]; };
    int checked = 0;
    for (int i = 0; i < angles; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * (i + 0.41) / angles;
        const FollowerState st = m.at(phi, 1.0);
        EXPECT_NEAR(distanceToProfile(contour, st.center), rho, 1e-9) << name << " " << phi;
        EXPECT_NEAR(distanceToProfile(contour, st.contact), 0.0, 1e-9) << name << " " << phi;
        EXPECT_NEAR((st.center - st.contact).norm(), rho, 1e-12) << name;
        EXPECT_NEAR(st.center.dot(normalOf(phi)), e, 1e-12) << name;
        // Derivatives where the contact stays on one piece across the stencil.
        const double h = 1e-4;
        if (m.at(phi - 2 * h, 1.0).segment != st.segment ||
            m.at(phi + 2 * h, 1.0).segment != st.segment) {
            continue;
        }
        ++checked;
        EXPECT_NEAR(st.sPhi[1], derivative(s, phi, h), 1e-7 * (1 + std::abs(st.sPhi[1])))
            << name << " " << phi;
        EXPECT_NEAR(st.sPhi[2], derivative(s1, phi, h), 1e-6 * (1 + std::abs(st.sPhi[2])))
            << name << " " << phi;
        EXPECT_NEAR(st.sPhi[3], derivative(s2, phi, h), 1e-5 * (1 + std::abs(st.sPhi[3])))
            << name << " " << phi;
    }
    EXPECT_GT(checked, angles * 2 / 3) << name;
}

TEST(FollowerRoller, KeepsItsRadiusFromTheSixLobeCam) {
    checkRoller(sixLobe(), 3.0, 2.0, "six-lobe");
}

TEST(FollowerRoller, KeepsItsRadiusFromSplineCams) {
    // Fewer angles than for arcs: every distance to a spline profile solves thousands of cubics.
    checkRoller(load(test::dataPath("reference/spline-mix.cam.json")), -2.5, 1.5, "spline-mix", 36);
    checkRoller(load(test::dataPath("reference/spline-offset.cam.json")), 1.0, 2.0, "spline-offset",
                36);
}

TEST(FollowerRoller, WiderThanAConcaveArcIsRefusedNamingIt) {
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = 5.0;  // the six-lobe cam's concave arcs have radius 4.84
    const auto m = FollowerModel::build(sixLobe(), spec);
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.errors().front().location.rfind("contour[", 0), 0u) << m.errors().front().location;
}

TEST(FollowerFlat, TheFaceRestsOnTheHighestPointOfTheProfile) {
    // A convex spline cam: h(φ) = max over the profile of p·u, taken over 20 000 points and
    // refined; its derivatives by differences.
    for (const std::string& path : {test::dataPath("reference/spline-offset.cam.json"),
                                    test::dataPath("reference/eccentric-split.cam.json")}) {
        const Contour contour = load(path);
        const FollowerModel m = model(contour, FollowerType::Flat, 0.0, 0.0);
        for (int i = 0; i < 60; ++i) {
            const double phi = kTwoPi * (i + 0.23) / 60;
            const Eigen::Vector2d u = unit(phi);
            double best = -1e300, bestAt = 0.0;
            for (int k = 0; k < 20000; ++k) {
                const double a = contour.phiBegin() + kTwoPi * k / 20000;
                const double h = profilePoint(contour, a).dot(u);
                if (h > best) {
                    best = h;
                    bestAt = a;
                }
            }
            double lo = bestAt - kTwoPi / 20000, hi = bestAt + kTwoPi / 20000;
            for (int it = 0; it < 100; ++it) {
                const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
                if (profilePoint(contour, a).dot(u) > profilePoint(contour, b).dot(u)) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            best = std::max(best, profilePoint(contour, 0.5 * (lo + hi)).dot(u));
            const FollowerState st = m.at(phi, 1.0);
            EXPECT_NEAR(st.s, best, 1e-9) << path << " " << phi;
            EXPECT_NEAR(st.contact.dot(u), st.s, 1e-9) << path;
            const auto h0 = [&](double x) { return m.at(x, 1.0).s; };
            EXPECT_NEAR(st.sPhi[1], derivative(h0, phi, 1e-4), 1e-7) << path << " " << phi;
            // The contact sits h' along the face from the centre line (math.md §7).
            EXPECT_NEAR(st.contact.dot(normalOf(phi)), st.sPhi[1], 1e-9) << path;
        }
    }
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(FollowerAnalysisTest, ACancelledAnalysisStopsAtOnceAndReturnsNothing) {
    const Contour contour = sixLobe();
    const FollowerModel m = model(contour, FollowerType::Roller, 2.0, 3.0);
    const FollowerAnalysis whole = analyzeFollower(m, 1.0, contour.phiBegin());
    ASSERT_TRUE(whole.pressure.rise);
    ASSERT_GT(whole.pressure.rise->value, 0.0);
    ASSERT_GT(whole.limitRad, 0.0);
    const std::atomic<bool> cancel{true};
    const FollowerAnalysis stopped =
        analyzeFollower(m, 1.0, contour.phiBegin(), kFollowerCheckSamples, &cancel);
    EXPECT_FALSE(stopped.pressure.rise);
    EXPECT_EQ(stopped.limitRad, 0.0);
    EXPECT_TRUE(stopped.undercut.empty());
}

TEST(FollowerAnalysisTest, ExtremesAgreeWithADenseSampling) {
    // The refined extremes against the best of 200 000 evenly spaced angles: never worse, and
    // within what that grid can resolve. The pressure angle per phase: the largest |α| while
    // the roller rises (ds/dφ > 0) and while it returns.
    const Contour contour = sixLobe();
    const double omega = kTwoPi / 0.4;
    const FollowerModel m = model(contour, FollowerType::Roller, 2.0, 3.0);
    const FollowerAnalysis a = analyzeFollower(m, omega, contour.phiBegin());
    double riseMax = 0.0, returnMax = 0.0, sMin = 1e300, slopeMax = 0.0;
    double riseAt = 0.0, returnAt = 0.0;
    constexpr int grid = 200000;
    const double step = kTwoPi / grid;
    for (int i = 0; i < grid; ++i) {
        slopeMax = std::max(slopeMax, std::abs(m.at(contour.phiBegin() + step * i, omega).sPhi[1]));
    }
    const auto look = [&](double phi) {
        const FollowerState st = m.at(phi, omega);
        const double alpha = std::abs(st.pressureAngle);
        if (st.sPhi[1] > kDwellSlope * slopeMax && alpha > riseMax) {
            riseMax = alpha;
            riseAt = phi;
        }
        if (st.sPhi[1] < -kDwellSlope * slopeMax && alpha > returnMax) {
            returnMax = alpha;
            returnAt = phi;
        }
        sMin = std::min(sMin, st.s);
    };
    for (int i = 0; i < grid; ++i) look(contour.phiBegin() + step * i);
    // Round a concave arc the roller centre swings fast: look again, 10 000 times finer, within
    // two steps of the best grid angle.
    const double riseGrid = riseAt, returnGrid = returnAt;
    for (int i = -20000; i <= 20000; ++i) {
        look(riseGrid + step * i / 10000.0);
        look(returnGrid + step * i / 10000.0);
    }
    // The extremes sit at joints, where α turns sharply (about 8 rad per rad): the fine grid
    // (3e-9 rad) comes within 1e-7 rad of them, and never beyond.
    ASSERT_TRUE(a.pressure.rise && a.pressure.fall);
    EXPECT_FALSE(a.pressure.dwell);  // no arc of the six lobes is centred on the cam's axis
    EXPECT_GE(a.pressure.rise->value, riseMax - 1e-15);
    EXPECT_NEAR(a.pressure.rise->value, riseMax, 1e-7);
    EXPECT_GE(a.pressure.fall->value, returnMax - 1e-15);
    EXPECT_NEAR(a.pressure.fall->value, returnMax, 1e-7);
    EXPECT_EQ(a.pressure.max.value, std::max(a.pressure.rise->value, a.pressure.fall->value));
    EXPECT_NEAR(a.sMin.value, sMin, 1e-8);
    EXPECT_NEAR(a.sMin.value, m.minS(), 1e-12);
    EXPECT_TRUE(a.undercut.empty());
    // The value reported is the value at the angle reported, and in its phase.
    const FollowerState atRise = m.at(a.pressure.rise->phi, omega);
    EXPECT_NEAR(std::abs(atRise.pressureAngle), a.pressure.rise->value, 1e-15);
    EXPECT_GT(atRise.sPhi[1], 0.0);
    EXPECT_LT(m.at(a.pressure.fall->phi, omega).sPhi[1], 0.0);
}

TEST(FollowerAnalysisTest, TheSmallestConvexAndConcaveRadiiAreThoseOfTheCurvesOwnShape) {
    // The curvature of the pitch curve, the path of the roller centre C(φ), by central
    // differences of C (not the follower's own radii): κ = (x'y'' − y'x'') / |C'|³, positive
    // where it bends round the cam's axis. The profile is the pitch curve offset inwards by
    // the roller: its signed radius is the pitch curve's minus 3 mm.
    const Contour contour = sixLobe();
    const FollowerModel m = model(contour, FollowerType::Roller, 2.0, 3.0);
    const FollowerAnalysis a = analyzeFollower(m, 1.0, contour.phiBegin());
    double convex = 0.0, concave = 0.0;  // the largest curvature of each sign
    constexpr int grid = 20000;
    constexpr double d = 1e-4;
    for (int i = 0; i < grid; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * i / grid;
        const FollowerState s0 = m.at(phi - d, 1.0), s1 = m.at(phi, 1.0), s2 = m.at(phi + d, 1.0);
        // A stencil across a joint mixes two arcs' curvatures: not the curve's at any point.
        if (s0.segment != s1.segment || s1.segment != s2.segment) continue;
        const Eigen::Vector2d c0 = s0.center, c1 = s1.center, c2 = s2.center;
        const Eigen::Vector2d v = (c2 - c0) / (2 * d), w = (c2 - 2 * c1 + c0) / (d * d);
        const double kappa = (v.x() * w.y() - v.y() * w.x()) / std::pow(v.norm(), 3);
        convex = std::max(convex, kappa);
        concave = std::max(concave, -kappa);
    }
    ASSERT_GT(convex, 0.0);
    ASSERT_GT(concave, 0.0);
    ASSERT_TRUE(a.pitchCurvature.minConvex && a.pitchCurvature.minConcave);
    ASSERT_TRUE(a.profileCurvature.minConvex && a.profileCurvature.minConcave);
    // Arcs: each radius holds over a whole window, which the grid samples many times; central
    // differences are exact to O(d²) on a circle.
    EXPECT_NEAR(a.pitchCurvature.minConvex->value, 1.0 / convex, 1e-6);
    EXPECT_NEAR(a.pitchCurvature.minConcave->value, 1.0 / concave, 1e-6);
    EXPECT_NEAR(a.profileCurvature.minConvex->value, 1.0 / convex - 3.0, 1e-6);
    EXPECT_NEAR(a.profileCurvature.minConcave->value, 1.0 / concave + 3.0, 1e-6);
    // The seed's concave arc of radius 4.84 (math.md §3) under a 3 mm roller: 1.84 mm.
    EXPECT_NEAR(a.pitchCurvature.minConcave->value, 4.84070597 - 3.0, 1e-7);
    EXPECT_NEAR(a.profileCurvature.minConcave->value, 4.84070597, 1e-7);
    // Reported as magnitudes, at an angle where the curve has that radius and sense.
    EXPECT_NEAR(m.at(a.pitchCurvature.minConcave->phi, 1.0).rhoPitch,
                -a.pitchCurvature.minConcave->value, 1e-9);
    EXPECT_NEAR(m.at(a.profileCurvature.minConvex->phi, 1.0).rhoProfile,
                a.profileCurvature.minConvex->value, 1e-9);
    // The roller fits (no undercut: every convex pitch radius above 3 mm); a 5 mm cutter does
    // not enter the 4.84 mm hollow, a 4.8 mm one does.
    FollowerSpec spec = m.spec();
    EXPECT_EQ(curvatureVerdict(a, spec, 0.0).rollerFits, std::optional<bool>(true));
    EXPECT_FALSE(curvatureVerdict(a, spec, 0.0).toolFits);
    EXPECT_EQ(curvatureVerdict(a, spec, 5.0).toolFits, std::optional<bool>(false));
    EXPECT_EQ(curvatureVerdict(a, spec, 4.8).toolFits, std::optional<bool>(true));
    spec.radius = a.pitchCurvature.minConvex->value + 0.01;
    EXPECT_EQ(curvatureVerdict(a, spec, 0.0).rollerFits, std::optional<bool>(false));
}

TEST(FollowerAnalysisTest, TheRangesBeyondTheLimitEndWhereTheAngleIsTheLimit) {
    const Contour contour = sixLobe();
    const FollowerModel m = model(contour, FollowerType::Knife, 0.0, 0.0);
    const FollowerAnalysis a = analyzeFollower(m, 1.0, contour.phiBegin());
    const double limit = degToRad(30.0);
    EXPECT_EQ(a.limitRad, limit);
    // Six lobes, each rising and falling too steeply once: twelve ranges.
    ASSERT_EQ(a.pressureExceeded.size(), 12u);
    for (const AngleRange& r : a.pressureExceeded) {
        EXPECT_NEAR(std::abs(m.at(r.from, 1.0).pressureAngle), limit, 1e-9);
        EXPECT_NEAR(std::abs(m.at(r.to, 1.0).pressureAngle), limit, 1e-9);
        EXPECT_GT(std::abs(m.at(0.5 * (r.from + r.to), 1.0).pressureAngle), limit);
        EXPECT_GT(r.to, r.from);
    }
}

TEST(FollowerAnalysisTest, AFlatFaceBridgesEveryHollowAndSaysWhere) {
    // The six-lobe cam's six concave arcs cannot hold a flat face: it rests on the two lobes
    // beside each, and the hollow between is never touched. The hollows are where the project
    // puts its concave arcs (windows centred on 0°, 60°, …, 300°).
    const Contour contour = sixLobe();
    const FollowerModel m = model(contour, FollowerType::Flat, 0.0, 0.0);
    const FollowerAnalysis a = analyzeFollower(m, 1.0, contour.phiBegin());
    ASSERT_EQ(a.undercut.size(), 6u);
    for (const NonContact& c : a.undercut) {
        const double from = std::atan2(c.from.y(), c.from.x());
        const double to = std::atan2(c.to.y(), c.to.x());
        // The bridged stretch is centred on the hollow and spans its whole window (±9.69°).
        double centre = std::remainder(0.5 * (from + to + (to < from ? kTwoPi : 0.0)), kTwoPi);
        const double hollow = std::round(centre / degToRad(60.0)) * degToRad(60.0);
        EXPECT_NEAR(std::remainder(centre - hollow, kTwoPi), 0.0, 1e-9);
        EXPECT_GT(std::remainder(to - from, kTwoPi), degToRad(2 * 9.69141));
        // At that angle the face touches both lobes: both points lie on it.
        const Eigen::Vector2d u = unit(c.phi);
        EXPECT_NEAR(c.from.dot(u), c.to.dot(u), 1e-9);
        EXPECT_NEAR(std::remainder(c.phi - hollow, kTwoPi), 0.0, 1e-9);
    }
    // The face must hold every contact: h' runs over [−w/2, w/2] by symmetry.
    EXPECT_GT(a.faceWidth, 0.0);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(FollowerKnife, OnAStraightStretchTheRadiusIsInfiniteNotNoise) {
    // The D-flat cam: a knife on its flat side has no finite radius of curvature; on its arcs it
    // has the arc's.
    const Contour contour = load(test::dataPath("reference/d-flat.cam.json"));
    const FollowerModel m = model(contour, FollowerType::Knife, 1.5, 0.0);
    int straight = 0, curved = 0;
    for (int i = 0; i < 360; ++i) {
        const FollowerState st = m.at(contour.phiBegin() + kTwoPi * (i + 0.5) / 360, 1.0);
        const ContourSegment& seg = contour.segment(st.segment);
        if (seg.type == SegmentType::Line) {
            EXPECT_TRUE(std::isinf(st.rhoProfile) && st.rhoProfile > 0) << st.rhoProfile;
            ++straight;
        } else {
            EXPECT_TRUE(relClose(std::abs(st.rhoProfile), seg.arc.radius, 1e-9));
            ++curved;
        }
    }
    EXPECT_GT(straight, 10);
    EXPECT_GT(curved, 10);
}

}  // namespace
}  // namespace cam
