// A swinging arm's smallest base radius and best pivot (design/sizing.h) against pressure angles
// computed here from math.md §7 alone: the roller centre X = A + L·e(ψ) with
// ψ = π + θ0 + ψ_lift(φ) (a counter-clockwise arm about a pivot A = (a, 0), cos θ0 =
// (a² + L² − Rp²) / (2aL)), turned by φ into the cam frame; the pitch curve's tangent by a
// fourth-order central difference; the pressure angle as the angle between the curve's normal
// and the direction the roller centre swings (perpendicular to the arm). No Jets, no
// ExactProfile: only the motion law in closed form and plane geometry.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "common/angles.h"
#include "design/sizing.h"

namespace cam {
namespace {

constexpr double kArm = 60.0, kRoller = 6.0, kSwingDeg = 15.0, kLimitDeg = 45.0;

/// The bundled swinging-arm example's motion: a cycloidal swing of 15° over 0–120°, a dwell to
/// 180°, a cycloidal return over 180–300°, a dwell.
DesignSpec armDesign() {
    DesignSpec d;
    d.baseRadius = 35.0;
    d.segments = {{MotionLawType::Cycloidal, 120.0, kSwingDeg},
                  {MotionLawType::Dwell, 180.0, kSwingDeg},
                  {MotionLawType::Cycloidal, 300.0, 0.0},
                  {MotionLawType::Dwell, 360.0, 0.0}};
    return d;
}

FollowerSpec armAt(double pivotDistance) {
    FollowerSpec f;
    f.type = FollowerType::Roller;
    f.motion = FollowerMotion::Oscillating;
    f.radius = kRoller;
    f.armLength = kArm;
    f.arm = ArmSide::Ccw;
    f.pivot = Eigen::Vector2d(pivotDistance, 0.0);
    f.maxPressureAngleDeg = kLimitDeg;
    return f;
}

/// The swing (rad) and its slope by φ, in closed form.
std::array<double, 2> swing(double phi) {
    const double h = degToRad(kSwingDeg), beta = degToRad(120.0);
    const auto cycloid = [&](double x) {
        return std::array<double, 2>{h * (x - std::sin(kTwoPi * x) / kTwoPi),
                                     h * (1.0 - std::cos(kTwoPi * x)) / beta};
    };
    if (phi < beta) return cycloid(phi / beta);
    if (phi < kPi) return {h, 0.0};
    if (phi < kPi + beta) {
        const auto c = cycloid((phi - kPi) / beta);
        return {h - c[0], -c[1]};
    }
    return {0.0, 0.0};
}

struct Angles {
    double rise = 0.0, back = 0.0;  ///< the largest |α| (rad) while the arm swings out, back
};

/// The reference: the largest |α| on rise and return of base radius rb with the pivot a out,
/// none where the arm cannot reach the pitch base circle (a > Rp > |a − L|).
std::optional<Angles> referenceAngles(double rb, double a) {
    const double rp = rb + kRoller;
    if (!(a > rp) || !(std::abs(a - kArm) < rp)) return std::nullopt;
    const double theta0 = std::acos((a * a + kArm * kArm - rp * rp) / (2.0 * a * kArm));
    const auto rotate = [](double phi, Eigen::Vector2d v) {
        return Eigen::Vector2d(std::cos(phi) * v.x() - std::sin(phi) * v.y(),
                               std::sin(phi) * v.x() + std::cos(phi) * v.y());
    };
    const auto psi = [&](double phi) { return kPi + theta0 + swing(phi)[0]; };
    const auto centre = [&](double phi) {
        const double p = psi(phi);
        return rotate(phi, Eigen::Vector2d(a + kArm * std::cos(p), kArm * std::sin(p)));
    };
    const auto alpha = [&](double phi) {
        const double h = 1e-4;
        const Eigen::Vector2d t = (-centre(phi + 2 * h) + 8.0 * centre(phi + h) -
                                   8.0 * centre(phi - h) + centre(phi - 2 * h)) /
                                  (12.0 * h);
        const double p = psi(phi);
        const Eigen::Vector2d m = rotate(phi, Eigen::Vector2d(-std::sin(p), std::cos(p)));
        // The normal is t turned by 90°: cos α = |n̂·m̂| = |t̂ × m̂|, sin α = |t̂·m̂|.
        return std::atan2(std::abs(t.dot(m)), std::abs(t.x() * m.y() - t.y() * m.x()));
    };
    Angles worst;
    const int n = 4000;
    for (double* phase : {&worst.rise, &worst.back}) {
        const double sign = phase == &worst.rise ? 1.0 : -1.0;
        double best = -1.0, at = 0.0;
        for (int i = 0; i < n; ++i) {
            const double phi = kTwoPi * i / n;
            if (sign * swing(phi)[1] <= 0.0) continue;
            if (const double v = alpha(phi); v > best) {
                best = v;
                at = phi;
            }
        }
        // Ternary search within a step either side (inside one phase: the peaks lie well
        // inside the 120° phases).
        double lo = at - kTwoPi / n, hi = at + kTwoPi / n;
        while (hi - lo > 1e-12) {
            const double l = lo + (hi - lo) / 3.0, r = hi - (hi - lo) / 3.0;
            if (alpha(l) < alpha(r)) {
                lo = l;
            } else {
                hi = r;
            }
        }
        *phase = std::max(best, alpha(0.5 * (lo + hi)));
    }
    return worst;
}

bool referencePasses(double rb, double a) {
    const auto angles = referenceAngles(rb, a);
    return angles && angles->rise <= degToRad(kLimitDeg) && angles->back <= degToRad(kLimitDeg);
}

/// The reference's smallest base radius with the pivot a out: the first of a 0.25 mm grid from
/// the arm's reach that passes, then bisection between it and the one before; none when no
/// grid radius passes.
std::optional<double> referenceSmallest(double a) {
    double previous = std::max(std::abs(a - kArm) - kRoller, 0.0);
    for (double rb = previous + 0.25; rb + kRoller < a; rb += 0.25) {
        if (referencePasses(rb, a)) {
            double lo = previous, hi = rb;
            while (hi - lo > 1e-10) {
                const double mid = 0.5 * (lo + hi);
                (referencePasses(mid, a) ? hi : lo) = mid;
            }
            return hi;
        }
        previous = rb;
    }
    return std::nullopt;
}

TEST(SizingArm, TheSmallestBaseRadiusMeetsTheLimitByTheAngleBetweenNormalAndSwing) {
    const auto sized = sizeBaseRadius(armDesign(), armAt(70.0));
    ASSERT_TRUE(sized.ok());
    const SizingResult& s = sized.value();
    const auto reference = referenceSmallest(70.0);
    ASSERT_TRUE(reference);
    EXPECT_NEAR(s.baseRadius, *reference, 1e-6);
    // The return binds: at the limit there, and beyond it 1e-5 mm below.
    EXPECT_EQ(s.binding, SizingCheck::PressureReturn);
    const auto at = referenceAngles(s.baseRadius, 70.0);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->back, degToRad(kLimitDeg), 1e-7);
    EXPECT_LT(at->rise, degToRad(kLimitDeg) - 0.1);
    ASSERT_TRUE(s.pressureRise && s.pressureReturn);
    EXPECT_NEAR(*s.pressureRise, at->rise, 1e-7);
    EXPECT_NEAR(*s.pressureReturn, at->back, 1e-7);
    EXPECT_FALSE(referencePasses(s.baseRadius - 1e-5, 70.0));
}

TEST(SizingArm, TheBestPivotIsWhereNeitherANearerNorAFartherOneAllowsASmallerCam) {
    const FollowerSpec arm = armAt(70.0);
    ASSERT_EQ(placementOf(arm), Placement::PivotDistance);
    const auto sized = sizePlacement(armDesign(), arm, {}, 9);
    ASSERT_TRUE(sized.ok());
    const PlacementSizing& p = sized.value();
    const double a = p.value, rb = p.sizing.baseRadius;
    // The reference agrees on the base radius at that pivot, and a pivot 0.05 mm nearer or
    // farther needs a larger cam.
    const auto here = referenceSmallest(a);
    ASSERT_TRUE(here);
    EXPECT_NEAR(rb, *here, 1e-6);
    for (const double other : {a - 0.05, a + 0.05}) {
        const auto there = referenceSmallest(other);
        ASSERT_TRUE(there) << other;
        EXPECT_GT(*there, rb + 0.01) << other;
    }
    // Far smaller than at the example's own pivot (11.4 mm), and rise and return bind together.
    EXPECT_LT(rb, 5.0);
    const auto angles = referenceAngles(rb, a);
    ASSERT_TRUE(angles);
    EXPECT_NEAR(angles->rise, degToRad(kLimitDeg), 1e-5);
    EXPECT_NEAR(angles->back, degToRad(kLimitDeg), 1e-5);
    // The pivot moved along its own line; the arm kept its length.
    const FollowerSpec moved = placedAt(arm, Placement::PivotDistance, a);
    EXPECT_DOUBLE_EQ(moved.pivot.x(), a);
    EXPECT_EQ(moved.pivot.y(), 0.0);
    EXPECT_EQ(moved.armLength, kArm);

    // The region: where it lists radii, the smallest and the largest pass and 1e-4 mm beyond
    // them fail (the largest is the arm's reach, Rb + ρ < a, where the checks hold up to it);
    // where it lists none, none passes on a 0.25 mm grid.
    ASSERT_EQ(p.region.size(), 9U);
    int feasible = 0, infeasible = 0;
    for (const FeasibleSpan& span : p.region) {
        if (!std::isfinite(span.smallest)) {
            EXPECT_FALSE(std::isfinite(span.largest));
            EXPECT_FALSE(referenceSmallest(span.placement)) << span.placement;
            ++infeasible;
            continue;
        }
        ++feasible;
        EXPECT_GE(span.smallest, rb - 1e-9) << span.placement;
        EXPECT_TRUE(referencePasses(span.smallest + 1e-6, span.placement)) << span.placement;
        EXPECT_FALSE(referencePasses(span.smallest - 1e-4, span.placement)) << span.placement;
        ASSERT_TRUE(std::isfinite(span.largest)) << span.placement;
        EXPECT_TRUE(referencePasses(span.largest - 1e-4, span.placement)) << span.placement;
        EXPECT_FALSE(referencePasses(span.largest + 1e-4, span.placement)) << span.placement;
    }
    EXPECT_GT(feasible, 5);
    // A pivot too near the cam swings the arm too steeply: the region starts where radii
    // begin to pass, within a tenth of the distances searched.
    EXPECT_GE(infeasible, 1);
    EXPECT_FALSE(std::isfinite(p.region.front().smallest));
}

TEST(SizingArm, OnABigCamTheRiseEndsTheRadiiThatPassBeforeTheArmsReachDoes) {
    // With the pivot 56 mm out the rise's |α| falls and grows again as the cam grows: the
    // radii that pass end at about 48 mm, short of the reach of 50 mm.
    const FollowerSpec arm = armAt(56.0);
    const auto sized = sizeBaseRadius(armDesign(), arm);
    ASSERT_TRUE(sized.ok());
    const double smallest = sized.value().baseRadius;
    const double largest = largestBaseRadius(armDesign(), arm, {}, smallest);
    EXPECT_LT(largest, 56.0 - kRoller - 1.0);
    EXPECT_GT(largest, smallest + 10.0);
    EXPECT_TRUE(referencePasses(largest - 1e-4, 56.0));
    EXPECT_FALSE(referencePasses(largest + 1e-4, 56.0));
    const auto atLargest = referenceAngles(largest, 56.0);
    ASSERT_TRUE(atLargest);
    EXPECT_NEAR(atLargest->rise, degToRad(kLimitDeg), 1e-6);
    // A translating follower's radii do not end.
    FollowerSpec knife;
    EXPECT_EQ(largestBaseRadius(armDesign(), knife, {}, 10.0),
              std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace cam
