// math.md §7's numbers for a cam made from a motion law: a cycloidal rise of 1 over 90°, dwell
// 90°, cycloidal return over 90°, dwell 90°. The cam is built here, independently of the
// follower code, as a dense chain of Hermite cubics through the exact profile (points and
// tangents from the law in closed form); the follower placed on it by contact must show the
// pressure angles, the flat face's smallest radius and its face width that math.md states.

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "common/angles.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "io/project_json.h"
#include "project/project.h"
#include "test_support.h"

namespace cam {
namespace {

/// The law s(φ) and its first two derivatives (per rad), φ in [0, 2π).
struct Law {
    double s, s1, s2;
};

Law cycloidal(double phi) {
    const double beta = kPi / 2.0;
    const auto rise = [&](double x) {  // x in [0, 1]
        return Law{x - std::sin(kTwoPi * x) / kTwoPi, (1.0 - std::cos(kTwoPi * x)) / beta,
                   kTwoPi * std::sin(kTwoPi * x) / (beta * beta)};
    };
    if (phi < beta) return rise(phi / beta);
    if (phi < 2 * beta) return {1.0, 0.0, 0.0};
    if (phi < 3 * beta) {
        const Law r = rise((phi - 2 * beta) / beta);
        return {1.0 - r.s, -r.s1, -r.s2};
    }
    return {0.0, 0.0, 0.0};
}

/// A contour of n Hermite cubics through points P(φ_k) with tangents Δφ·P'(φ_k).
template <class Point, class Tangent>
Contour hermiteChain(int n, const Point& point, const Tangent& tangent) {
    Project p;
    const double step = kTwoPi / n;
    double previous = 0.0, first = 0.0;
    for (int k = 0; k < n; ++k) {
        const double a = step * k, b = step * (k + 1);
        const Eigen::Vector2d p0 = point(a), p3 = point(b);
        // The window: the polar angles of the ends, unwrapped along the turn.
        double start = std::atan2(p0.y(), p0.x());
        if (k == 0) {
            first = start;
        } else {
            start = previous;
        }
        double end = std::atan2(p3.y(), p3.x());
        while (end < start) end += kTwoPi;
        if (k == n - 1) end = first + kTwoPi;
        previous = end;
        p.contour.push_back(SegmentSpec{HermiteCurve{p0, step * tangent(a), p3, step * tangent(b)},
                                        radToDeg(start), radToDeg(end)});
    }
    auto contour = Contour::build(p);
    EXPECT_TRUE(contour.ok()) << (contour.ok() ? "" : contour.errors().front().text());
    return std::move(contour).value();
}

/// A knife (prime circle Rp, offset e) on the law: the pitch curve is the profile,
/// P = e·n + (s0 + s)·u with s0 = √(Rp² − e²); P' = (s' − e)·u + (s0 + s)·n.
Contour knifeCam(double Rp, double e, int n) {
    const double s0 = std::sqrt(Rp * Rp - e * e);
    return hermiteChain(
        n,
        [&](double phi) {
            const Law l = cycloidal(std::fmod(phi, kTwoPi));
            const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
            return Eigen::Vector2d(e * nn + (s0 + l.s) * u);
        },
        [&](double phi) {
            const Law l = cycloidal(std::fmod(phi, kTwoPi));
            const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
            return Eigen::Vector2d((l.s1 - e) * u + (s0 + l.s) * nn);
        });
}

double largestPressureAngleDeg(const Contour& cam, double e) {
    FollowerSpec spec;
    spec.offset = e;
    const FollowerModel model = FollowerModel::build(cam, spec).value();
    const FollowerAnalysis a = analyzeFollower(model, 1.0, cam.phiBegin());
    return radToDeg(a.pressure.max.value);
}

TEST(FollowerMotionLaw, TheKnifesLargestPressureAnglesAreMathSection7s) {
    // 720 cubics: the Hermite chain is within about 1e-9 of the exact profile and its slope
    // within about 1e-7, far below the 1e-3° that math.md's five digits state.
    EXPECT_NEAR(largestPressureAngleDeg(knifeCam(1.5, 0.0, 720), 0.0), 33.163, 1e-3);
    EXPECT_NEAR(largestPressureAngleDeg(knifeCam(1.5, 0.25, 720), 0.25), 38.477, 1e-3);
    // The smallest prime circle for a 30° limit without offset.
    EXPECT_NEAR(largestPressureAngleDeg(knifeCam(1.75094, 0.0, 720), 0.0), 30.0, 1e-3);
}

TEST(FollowerMotionLaw, AnOffsetKnifesPressureAngleInEachPhaseIsTheClosedForm) {
    // The tip P = e·n + (s0 + s)·u moves along u; the profile's tangent is P' = (s' − e)·u +
    // (s0 + s)·n, so tan|α| = |s' − e| / (s0 + s) (math.md §7). In the dwells s' = 0: the
    // largest |α| there is atan(e / s0), at the low dwell — not zero.
    const double Rp = 1.5, e = 0.25, s0 = std::sqrt(Rp * Rp - e * e);
    FollowerSpec spec;
    spec.offset = e;
    const Contour cam = knifeCam(Rp, e, 720);
    const FollowerAnalysis a =
        analyzeFollower(FollowerModel::build(cam, spec).value(), 1.0, cam.phiBegin());
    double rise = 0.0, fall = 0.0;
    for (int i = 1; i < 200000; ++i) {
        const double phi = kTwoPi * i / 200000;
        const Law l = cycloidal(phi);
        const double alpha = std::atan(std::abs(l.s1 - e) / (s0 + l.s));
        if (l.s1 > 1e-12) rise = std::max(rise, alpha);
        if (l.s1 < -1e-12) fall = std::max(fall, alpha);
    }
    ASSERT_TRUE(a.pressure.rise && a.pressure.fall && a.pressure.dwell);
    EXPECT_NEAR(a.pressure.rise->value, rise, 1e-6);
    EXPECT_NEAR(a.pressure.fall->value, fall, 1e-6);
    EXPECT_NEAR(radToDeg(a.pressure.fall->value), 38.477, 1e-3);  // math.md §7
    EXPECT_NEAR(a.pressure.dwell->value, std::atan(e / s0), 1e-6);
    EXPECT_NEAR(radToDeg(a.pressure.dwell->value), 9.594, 1e-3);
    EXPECT_EQ(a.pressure.max.value, a.pressure.fall->value);
    // The dwell's angle is where the law's ds/dφ is within the dwell's tolerance of its
    // largest value 4/π.
    const double dwellAt = std::fmod(a.pressure.dwell->phi + kTwoPi, kTwoPi);
    EXPECT_LE(std::abs(cycloidal(dwellAt).s1), kDwellSlope * 4.0 / kPi) << dwellAt;
}

TEST(FollowerMotionLaw, ASwingingArmsPressureAngleIsNotZeroInItsDwells) {
    // A knife on an arm of L = 2.5 about a pivot at d = 3 from the cam's axis, riding the
    // same cam (base circle 1.5, lift 1). In a dwell the profile is a circle about the axis:
    // the normal is radial, the tip moves perpendicular to the arm, so |α| = |90° − γ| with γ
    // the angle at the tip between the axis and the pivot: cos γ = (R² + L² − d²) / (2RL).
    // Low dwell R = 1.5: |α| = 3.822°; high dwell R = 2.5: |α| = 16.26°.
    const double d = 3.0, L = 2.5;
    FollowerSpec spec;
    spec.motion = FollowerMotion::Oscillating;
    spec.pivot = Eigen::Vector2d(d, 0.0);
    spec.armLength = L;
    const Contour cam = knifeCam(1.5, 0.0, 720);
    const FollowerModel m = FollowerModel::build(cam, spec).value();
    const FollowerAnalysis a = analyzeFollower(m, 1.0, cam.phiBegin());
    const auto dwellAlpha = [&](double R) {
        return std::abs(kPi / 2 - std::acos((R * R + L * L - d * d) / (2 * R * L)));
    };
    ASSERT_NEAR(radToDeg(dwellAlpha(2.5)), 16.26, 5e-3);
    ASSERT_TRUE(a.pressure.rise && a.pressure.fall && a.pressure.dwell);
    EXPECT_NEAR(a.pressure.dwell->value, std::max(dwellAlpha(1.5), dwellAlpha(2.5)), 1e-6);

    // On rise and return: the angle between the normal of the tip's path C(φ) (the pitch
    // curve, by central differences) and the direction the tip moves (perpendicular to the
    // arm from the pivot turned by φ), largest where the tip moves away from the axis (rise)
    // and towards it (return).
    // A grid of 4000, then a grid of 2000 over the two steps round each phase's best: the
    // same maximum as a grid of 100000 at a twentieth of the evaluations (the debug build
    // with sanitizers runs this within its time limit).
    constexpr double h = 1e-5;
    struct Sample {
        double alpha = 0.0, away = 0.0;
    };
    const auto sample = [&](double phi) {
        const Eigen::Vector2d c = m.at(phi, 1.0).center;
        const Eigen::Vector2d tangent = (m.at(phi + h, 1.0).center - m.at(phi - h, 1.0).center);
        const double away = m.at(phi + h, 1.0).center.norm() - m.at(phi - h, 1.0).center.norm();
        const Eigen::Vector2d pivot(std::cos(phi) * d, std::sin(phi) * d);
        const Eigen::Vector2d arm = (c - pivot).normalized();
        const Eigen::Vector2d normal = Eigen::Vector2d(tangent.y(), -tangent.x()).normalized();
        const Eigen::Vector2d moves(-arm.y(), arm.x());
        return Sample{std::acos(std::min(1.0, std::abs(normal.dot(moves)))), away};
    };
    const auto largest = [&](double from, double to, int n, bool rising) {
        double best = 0.0, at = from;
        for (int i = 0; i <= n; ++i) {
            const double phi = from + (to - from) * i / n;
            const Sample s = sample(phi);
            if ((rising ? s.away > 1e-9 : s.away < -1e-9) && s.alpha > best) {
                best = s.alpha;
                at = phi;
            }
        }
        return std::pair{best, at};
    };
    const auto refined = [&](bool rising) {
        constexpr int kCoarse = 4000;
        const double step = kTwoPi / kCoarse;
        const auto [coarse, at] = largest(cam.phiBegin(), cam.phiBegin() + kTwoPi, kCoarse, rising);
        return std::max(coarse, largest(at - 2 * step, at + 2 * step, 2000, rising).first);
    };
    const double rise = refined(true);
    const double fall = refined(false);
    EXPECT_NEAR(a.pressure.rise->value, rise, 1e-5);
    EXPECT_NEAR(a.pressure.fall->value, fall, 1e-5);
    // Both largest inside their phase, not at a dwell's edge.
    EXPECT_GT(a.pressure.rise->value, a.pressure.dwell->value + 0.1);
    EXPECT_GT(a.pressure.fall->value, a.pressure.dwell->value + 0.1);
}

TEST(FollowerMotionLaw, AnArcTablesRippleRoundADwellIsPartOfTheDwell) {
    // The bundled swinging arm: an arc table fitted within 0.001 mm to a cycloidal rise over
    // 0–120°, a dwell to 180°, a cycloidal return over 180–300° and a dwell to 360°. Round its
    // dwells the fitted arm rises and falls by up to 3e-5 rad: from 152° it sinks steadily
    // into the return, and over the rise's last degree (119.2–120°) it falls by 5e-7 rad.
    // Neither is a return: the design's phases are the phases. The reference: the largest |α|
    // over a dense grid of each of the design's phases, and each phase's reported angle inside
    // that phase of the design.
    auto project = loadProjectFile(test::examplePath("swinging-arm-cam.cam.json"));
    ASSERT_TRUE(project.ok());
    ASSERT_TRUE(project.value().design);
    const Contour cam = Contour::build(project.value()).value();
    const FollowerModel m = FollowerModel::build(cam, *project.value().follower).value();
    const std::vector<PhaseSpan> phases = designPhases(*project.value().design);
    const std::vector<PhaseSpan> expected{{0.0, 120.0, MotionPhase::Rise},
                                          {120.0, 180.0, MotionPhase::Dwell},
                                          {180.0, 300.0, MotionPhase::Fall},
                                          {300.0, 360.0, MotionPhase::Dwell}};
    ASSERT_EQ(phases.size(), expected.size());
    for (std::size_t k = 0; k < phases.size(); ++k) {
        EXPECT_NEAR(radToDeg(phases[k].from), expected[k].from, 1e-12) << k;
        EXPECT_NEAR(radToDeg(phases[k].to), expected[k].to, 1e-12) << k;
        EXPECT_EQ(phases[k].phase, expected[k].phase) << k;
    }
    const FollowerAnalysis a =
        analyzeFollower(m, 1.0, cam.phiBegin(), kFollowerCheckSamples, nullptr, phases);
    ASSERT_TRUE(a.pressure.rise && a.pressure.fall && a.pressure.dwell);
    const auto largest = [&](double fromDeg, double toDeg) {
        double best = 0.0;
        for (int i = 0; i <= 20000; ++i) {
            const double phi = degToRad(fromDeg + (toDeg - fromDeg) * i / 20000.0);
            best = std::max(best, std::abs(m.at(phi, 1.0).pressureAngle));
        }
        return best;
    };
    const auto inside = [](double phi, double fromDeg, double toDeg) {
        const double deg = std::fmod(radToDeg(phi) + 720.0, 360.0);
        return deg >= fromDeg && deg <= toDeg;
    };
    EXPECT_TRUE(inside(a.pressure.rise->phi, 0.0, 120.0)) << radToDeg(a.pressure.rise->phi);
    EXPECT_TRUE(inside(a.pressure.fall->phi, 180.0, 300.0)) << radToDeg(a.pressure.fall->phi);
    EXPECT_TRUE(inside(a.pressure.dwell->phi, 120.0, 180.0) ||
                inside(a.pressure.dwell->phi, 300.0, 360.0))
        << radToDeg(a.pressure.dwell->phi);
    // Each value the dense grid's over its phase (the grid resolves 0.006°, over which |α|
    // changes by under 1e-5 rad), never below it.
    EXPECT_GE(a.pressure.rise->value, largest(0.0, 120.0) - 1e-12);
    EXPECT_NEAR(a.pressure.rise->value, largest(0.0, 120.0), 1e-5);
    EXPECT_GE(a.pressure.fall->value, largest(180.0, 300.0) - 1e-12);
    EXPECT_NEAR(a.pressure.fall->value, largest(180.0, 300.0), 1e-5);
    const double dwell = std::max(largest(120.0, 180.0), largest(300.0, 360.0));
    EXPECT_GE(a.pressure.dwell->value, dwell - 1e-12);
    EXPECT_NEAR(a.pressure.dwell->value, dwell, 1e-5);
}

/// The flat face's design checks on h = Rb + s, the cam a chain of n cubics.
FollowerAnalysis flatFaceChecks(double Rb, int n) {
    // The profile is the envelope p = h·u + h'·n; its tangent p' = (h + h'')·n.
    const Contour cam = hermiteChain(
        n,
        [&](double phi) {
            const Law l = cycloidal(std::fmod(phi, kTwoPi));
            const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
            return Eigen::Vector2d((Rb + l.s) * u + l.s1 * nn);
        },
        [&](double phi) {
            const Law l = cycloidal(std::fmod(phi, kTwoPi));
            const Eigen::Vector2d nn(-std::sin(phi), std::cos(phi));
            return Eigen::Vector2d((Rb + l.s + l.s2) * nn);
        });
    FollowerSpec spec;
    spec.type = FollowerType::Flat;
    const FollowerModel model = FollowerModel::build(cam, spec).value();
    return analyzeFollower(model, 1.0, cam.phiBegin());
}

TEST(FollowerMotionLaw, TheFlatFacesSmallestRadiusAndWidthAreMathSection7s) {
    // A chain of cubics follows the profile's curvature only to a power of Δφ: the smallest
    // radius comes out 1.4e-3 mm low at 360 cubics and 1.8e-4 mm low at 720 (finer chains trip
    // the window validation of very short cubics: a known limit). So 720 cubics and 3e-4 mm:
    // still a thousandth of what any wrong curvature formula would give.
    const double Rb = 1.89263;
    const FollowerAnalysis fine = flatFaceChecks(Rb, 720);
    // min(s + s'') = −1.64263, so Rb = 1.89263 leaves 0.25 mm.
    ASSERT_TRUE(fine.profileCurvature.minConvex);
    EXPECT_NEAR(fine.profileCurvature.minConvex->value, 0.25, 3e-4);
    EXPECT_LT(fine.profileCurvature.minConvex->value, 0.25);  // the chain's error has this sign
    EXPECT_FALSE(fine.profileCurvature.minConcave);           // convex all round
    // The face spans s' from −1.27324 to +1.27324.
    EXPECT_NEAR(fine.faceWidth, 2.54648, 1e-5);
    EXPECT_TRUE(fine.undercut.empty());
}

}  // namespace
}  // namespace cam
