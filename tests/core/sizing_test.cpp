// The smallest base radius (design/sizing.h) against closed forms written here: for a
// translating knife or roller with offset e, tan|α| = |s' − e| / (s0 + s) with s0 = √(Rp² − e²),
// so the limit holds everywhere when s0 ≥ max(|s' − e| / tan α_max − s), i.e.
// Rp = √(e² + max(|s' − e| / tan α_max − s)²) (math.md §7: 1.75094 for 30° without offset);
// a flat face's profile radius is Rb + s + s'' (math.md §7: Rb ≥ 1.89263 for ρ ≥ 0.25).

#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "design/sizing.h"

namespace cam {
namespace {

/// A cycloidal rise of 1 mm from 0 to riseEndDeg, a dwell to 180°, a cycloidal return to
/// returnEndDeg and a dwell.
DesignSpec riseAndReturn(double riseEndDeg, double returnEndDeg) {
    DesignSpec d;
    d.baseRadius = 10.0;
    d.segments = {{MotionLawType::Cycloidal, riseEndDeg, 1.0},
                  {MotionLawType::Dwell, 180.0, 1.0},
                  {MotionLawType::Cycloidal, returnEndDeg, 0.0},
                  {MotionLawType::Dwell, 360.0, 0.0}};
    return d;
}

/// That motion in closed form: s, s', s'' per radian.
std::array<double, 3> riseAndReturnLaw(double phi, double riseEndDeg, double returnEndDeg) {
    const auto cycloid = [](double x, double beta) {
        return std::array<double, 3>{x - std::sin(kTwoPi * x) / kTwoPi,
                                     (1.0 - std::cos(kTwoPi * x)) / beta,
                                     kTwoPi * std::sin(kTwoPi * x) / (beta * beta)};
    };
    const double rise = degToRad(riseEndDeg), back = degToRad(returnEndDeg) - kPi;
    if (phi < rise) return cycloid(phi / rise, rise);
    if (phi < kPi) return {1.0, 0.0, 0.0};
    if (phi < kPi + back) {
        const auto c = cycloid((phi - kPi) / back, back);
        return {1.0 - c[0], -c[1], -c[2]};
    }
    return {0.0, 0.0, 0.0};
}

/// A cycloidal rise over 90° and return over 90°: rise and return mirror each other.
DesignSpec cycloidalDesign() { return riseAndReturn(90.0, 270.0); }
std::array<double, 3> law(double phi) { return riseAndReturnLaw(phi, 90.0, 270.0); }

/// The closed form's prime-circle radius for offset e and limit α_max (dense in φ).
double primeRadius(double e, double limitDeg) {
    double worst = -1e300;
    for (int i = 0; i < 400000; ++i) {
        const auto s = law(kTwoPi * i / 400000);
        worst = std::max(worst, std::abs(s[1] - e) / std::tan(degToRad(limitDeg)) - s[0]);
    }
    return std::sqrt(e * e + worst * worst);
}

FollowerSpec translating(FollowerType type, double offset, double radius, double limitDeg) {
    FollowerSpec f;
    f.type = type;
    f.offset = offset;
    f.radius = radius;
    f.maxPressureAngleDeg = limitDeg;
    return f;
}

TEST(Sizing, AKnifesSmallestBaseRadiusIsMathSection7s) {
    const auto r = sizeBaseRadius(cycloidalDesign(), translating(FollowerType::Knife, 0, 0, 30));
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.value().baseRadius, primeRadius(0.0, 30.0), 1e-7);
    EXPECT_NEAR(r.value().baseRadius, 1.75094, 1e-5);
    // Without offset rise and return are mirror images: either binds, at its steepest point.
    ASSERT_TRUE(r.value().pressureRise && r.value().pressureReturn);
    EXPECT_NEAR(*r.value().pressureRise, degToRad(30.0), 1e-8);
    EXPECT_NEAR(*r.value().pressureReturn, degToRad(30.0), 1e-8);
    EXPECT_TRUE(r.value().binding == SizingCheck::PressureRise ||
                r.value().binding == SizingCheck::PressureReturn);
}

TEST(Sizing, AnOffsetRollerAndAnOffsetKnifeFollowTheClosedForm) {
    // A roller 0.2 mm, offset +0.3, limit 35°: the return is steeper (|s' − e| = |s'| + e).
    const auto roller =
        sizeBaseRadius(cycloidalDesign(), translating(FollowerType::Roller, 0.3, 0.2, 35));
    ASSERT_TRUE(roller.ok());
    EXPECT_NEAR(roller.value().baseRadius + 0.2, primeRadius(0.3, 35.0), 1e-7);
    EXPECT_EQ(roller.value().binding, SizingCheck::PressureReturn);
    // Where it binds, the closed form's pressure angle is the limit.
    const double phi = roller.value().bindingPhi;
    const auto s = law(phi);
    const double s0 = std::sqrt(std::pow(roller.value().baseRadius + 0.2, 2) - 0.09);
    EXPECT_GT(phi, kPi);
    EXPECT_LT(phi, 1.5 * kPi);
    EXPECT_NEAR(std::atan(std::abs(s[1] - 0.3) / (s0 + s[0])), degToRad(35.0), 1e-7);

    // A knife offset −0.2 with a 25° limit: the rise binds.
    const auto knife =
        sizeBaseRadius(cycloidalDesign(), translating(FollowerType::Knife, -0.2, 0.0, 25));
    ASSERT_TRUE(knife.ok());
    EXPECT_NEAR(knife.value().baseRadius, primeRadius(-0.2, 25.0), 1e-7);
    EXPECT_EQ(knife.value().binding, SizingCheck::PressureRise);
    EXPECT_LT(knife.value().bindingPhi, kPi / 2);
}

TEST(Sizing, AFlatFacesBaseRadiusIsSetByItsSmallestRadius) {
    // min(s + s'') = −1.64263: Rb = 1.89263 leaves a radius of 0.25 mm (math.md §7); the face
    // spans s' from −1.27324 to +1.27324 whatever the base radius.
    SizingOptions options;
    options.minRadius = 0.25;
    const auto r =
        sizeBaseRadius(cycloidalDesign(), translating(FollowerType::Flat, 0, 0, 30), options);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.value().baseRadius, 1.89263, 1e-5);
    double least = 1e300;
    for (int i = 0; i < 400000; ++i) {
        const auto s = law(kTwoPi * i / 400000);
        least = std::min(least, s[0] + s[2]);
    }
    EXPECT_NEAR(r.value().baseRadius, 0.25 - least, 1e-8);
    EXPECT_EQ(r.value().binding, SizingCheck::ConvexRadius);
    EXPECT_FALSE(r.value().pressureRise);  // a flat face's pressure angle is 0
    ASSERT_TRUE(r.value().faceWidth);
    EXPECT_NEAR(*r.value().faceWidth, 2 * 4 / kPi, 1e-9);  // 2·max s' = 2·2/β
    ASSERT_TRUE(r.value().minConvexRadius);
    EXPECT_NEAR(*r.value().minConvexRadius, 0.25, 1e-8);
}

TEST(Sizing, ABigRollerIsSizedByItsPitchCurvesTightestBend) {
    // A roller of 0.5 mm with a loose 85° limit and --min-radius 0.1: the pitch curve's convex
    // radius must stay at 0.6 mm. The pitch curve P = e·n + (s0 + s)·u, its curvature from P'
    // = (s' − e)u + S·n and P'' = (s'' − S)u + (2s' − e)n with S = s0 + s, in closed form.
    SizingOptions options;
    options.minRadius = 0.1;
    const double e = 0.0;
    const auto r =
        sizeBaseRadius(cycloidalDesign(), translating(FollowerType::Roller, e, 0.5, 85), options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value().binding, SizingCheck::ConvexRadius);
    const double s0 = r.value().baseRadius + 0.5;
    double tightest = 1e300;
    for (int i = 0; i < 400000; ++i) {
        const auto s = law(kTwoPi * i / 400000);
        const double S = s0 + s[0];
        const double cross = (s[1] - e) * (2 * s[1] - e) + S * S - S * s[2];
        const double speed = std::hypot(s[1] - e, S);
        if (cross > 0) tightest = std::min(tightest, speed * speed * speed / cross);
    }
    EXPECT_NEAR(tightest, 0.6, 1e-7);
    ASSERT_TRUE(r.value().minConvexRadius);
    EXPECT_NEAR(*r.value().minConvexRadius, 0.1, 1e-7);
}

TEST(Sizing, AnArmThatNoBaseRadiusSuitsIsNamed) {
    // An arm of 5 mm about a pivot 6 mm out: the pivot ends the radii the arm can reach, and
    // a 10° limit is never met below that.
    FollowerSpec arm;
    arm.motion = FollowerMotion::Oscillating;
    arm.pivot = Eigen::Vector2d(6.0, 0.0);
    arm.armLength = 5.0;
    arm.maxPressureAngleDeg = 10.0;
    DesignSpec d = cycloidalDesign();
    for (auto& s : d.segments) s.lift = s.lift * 20.0;  // degrees swung
    const auto r = sizeBaseRadius(d, arm);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors().front().code, DiagnosticCode::NoBaseRadiusPasses);
    EXPECT_EQ(r.errors().front().location, "design.base_radius");
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// A rise over 60° and a return over 120°: the rise is twice as steep as the return, so an
/// offset towards it lets a smaller cam meet the limit.
DesignSpec lopsidedDesign() { return riseAndReturn(60.0, 300.0); }
std::array<double, 3> lopsidedLaw(double phi) { return riseAndReturnLaw(phi, 60.0, 300.0); }

/// The closed form's prime-circle radius of a knife with offset e and a 30° limit.
double lopsidedPrimeRadius(double e) {
    double worst = -1e300;
    for (int i = 0; i < 200000; ++i) {
        const auto s = lopsidedLaw(kTwoPi * i / 200000);
        worst = std::max(worst, std::abs(s[1] - e) / std::tan(degToRad(30.0)) - s[0]);
    }
    return std::sqrt(e * e + worst * worst);
}

TEST(Sizing, TheBestOffsetIsTheClosedFormsSmallestOverOffsets) {
    // The reference: the closed form's prime radius minimised over e by a scan of 400 offsets
    // over ±2 mm and golden sections round the best, all on the closed form.
    double bestE = 0.0, bestR = 1e300;
    for (int i = 0; i <= 400; ++i) {
        const double e = -2.0 + 4.0 * i / 400;
        const double r = lopsidedPrimeRadius(e);
        if (r < bestR) {
            bestR = r;
            bestE = e;
        }
    }
    double lo = bestE - 0.01, hi = bestE + 0.01;
    while (hi - lo > 1e-9) {
        const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        if (lopsidedPrimeRadius(a) < lopsidedPrimeRadius(b)) {
            hi = b;
        } else {
            lo = a;
        }
    }
    bestE = 0.5 * (lo + hi);
    bestR = lopsidedPrimeRadius(bestE);
    // Without offset the rise binds at a larger radius.
    ASSERT_GT(lopsidedPrimeRadius(0.0), bestR + 0.1);

    const FollowerSpec knife = translating(FollowerType::Knife, 0.0, 0.0, 30);
    ASSERT_EQ(placementOf(knife), Placement::Offset);
    const auto sized = sizePlacement(lopsidedDesign(), knife);
    ASSERT_TRUE(sized.ok());
    const PlacementSizing& s = sized.value();
    EXPECT_NEAR(s.sizing.baseRadius, bestR, 1e-7);
    EXPECT_NEAR(s.value, bestE, 1e-4);
    EXPECT_GT(s.value, 0.0);  // towards the steeper rise: |s' − e| shrinks there
    // At the best offset rise and return bind together: both pressure angles at the limit.
    ASSERT_TRUE(s.sizing.pressureRise && s.sizing.pressureReturn);
    EXPECT_NEAR(*s.sizing.pressureRise, degToRad(30.0), 1e-4);
    EXPECT_NEAR(*s.sizing.pressureReturn, degToRad(30.0), 1e-4);
    // The feasible region's edge is the closed form at every offset it lists.
    ASSERT_EQ(s.region.size(), 41U);
    for (std::size_t i = 0; i < s.region.size(); i += 5) {
        const FeasibleSpan& span = s.region[i];
        EXPECT_NEAR(span.smallest, lopsidedPrimeRadius(span.placement), 1e-7) << span.placement;
        EXPECT_EQ(span.largest, std::numeric_limits<double>::infinity());
    }
    // A flat face has no placement to size.
    EXPECT_FALSE(placementOf(translating(FollowerType::Flat, 0.0, 0.0, 30)));
}

}  // namespace
}  // namespace cam
