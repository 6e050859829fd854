// The swinging arm (math.md §7, "oscillating"), checked without the follower's own formulas: on
// an eccentric disc against the closed form of two circles in the follower frame; on arc and
// spline cams by plane geometry (the roller centre ρ from the profile, the arm's length kept)
// and by finite differences of ψ; refusals with their places.

#include <gtest/gtest.h>

#include "core/follower_geometry.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"

namespace cam {
namespace {

using test::armSpec;
using test::derivative;
using test::distanceToProfile;
using test::load;
using test::relClose;
using test::sixLobe;

FollowerModel armModel(const Contour& contour, const FollowerSpec& spec) {
    auto m = FollowerModel::build(contour, spec);
    EXPECT_TRUE(m.ok()) << (m.ok()
                                ? ""
                                : m.errors().front().location + ": " + m.errors().front().message);
    return std::move(m).value();
}

Eigen::Vector2d turned(const Eigen::Vector2d& v, double phi) {
    return {std::cos(phi) * v.x() - std::sin(phi) * v.y(),
            std::sin(phi) * v.x() + std::cos(phi) * v.y()};
}

/// The angle a − b brought into (−π, π].
double angleBetween(double a, double b) {
    double d = std::remainder(a - b, kTwoPi);
    if (d <= -kPi) d += kTwoPi;
    return d;
}

/// ψ(φ) of an arm on a disc (centre c, radius R) with a roller ρ, by the closed form in the
/// follower frame: the disc's centre is c turned by −φ; d = that − A; the arm's end meets the
/// circle of radius R + ρ where cos(ψ − γ) = (L² + |d|² − (R + ρ)²) / (2L|d|), γ = angle of d.
/// Of the two, the one farther from the line pivot → cam centre on the arm's side.
double discPsi(const Eigen::Vector2d& c, double R, const FollowerSpec& spec, double phi) {
    const double L = spec.armLength, Rp = R + spec.radius;
    const Eigen::Vector2d d = turned(c, -phi) - spec.pivot;
    const double gamma = std::atan2(d.y(), d.x());
    const double k = (L * L + d.squaredNorm() - Rp * Rp) / (2.0 * L * d.norm());
    const double beta = std::atan2(-spec.pivot.y(), -spec.pivot.x());
    const double sigma = spec.arm == ArmSide::Ccw ? 1.0 : -1.0;
    double best = 0.0, bestTheta = -1e300;
    for (double psi : {gamma + std::acos(k), gamma - std::acos(k)}) {
        const double theta = sigma * angleBetween(psi, beta);
        if (theta > bestTheta) {
            bestTheta = theta;
            best = psi;
        }
    }
    return best;
}

TEST(FollowerArm, OnAnEccentricDiscItIsTheClosedFormOfTwoCircles) {
    const Eigen::Vector2d c(7.0, -3.0);
    const double R = 20.0;
    const Contour contour = test::disc(c, R);
    for (const ArmSide side : {ArmSide::Ccw, ArmSide::Cw}) {
        for (const FollowerType type : {FollowerType::Roller, FollowerType::Knife}) {
            const double rho = type == FollowerType::Roller ? 3.0 : 0.0;
            // The arm about square to the radius at the tip (L² + r² ≈ |A|²): like a follower
            // without offset, its pressure angle has the sign of the swing.
            const FollowerSpec spec = armSpec(type, rho, {10.0, 45.0}, 40.0, side);
            const FollowerModel m = armModel(contour, spec);
            const double sigma = side == ArmSide::Ccw ? 1.0 : -1.0;
            const auto psi = [&](double phi) { return discPsi(c, R, spec, phi); };
            const auto psi1 = [&](double phi) { return derivative(psi, phi, 1e-3); };
            const auto psi2 = [&](double phi) { return derivative(psi1, phi, 1e-3); };
            double riseRate = -1e300, riseAlpha = 0.0, returnRate = 1e300, returnAlpha = 0.0;
            for (double deg = 0.25; deg < 360.0; deg += 4.7) {
                SCOPED_TRACE(std::to_string(deg) + (side == ArmSide::Ccw ? " ccw" : " cw"));
                const double phi = degToRad(deg), omega = 3.0;
                const FollowerState st = m.at(phi, omega);
                EXPECT_NEAR(angleBetween(st.s, psi(phi)), 0.0, 1e-13);
                // Contact geometry: the arm's length kept, the centre on the pitch circle, the
                // contact on the disc along its radius, the normal that radius.
                const Eigen::Vector2d pivot = turned(spec.pivot, phi);
                EXPECT_NEAR((st.center - pivot).norm(), spec.armLength, 1e-12);
                EXPECT_NEAR((st.center - c).norm(), R + rho, 1e-12);
                const Eigen::Vector2d nu = (st.center - c).normalized();
                EXPECT_NEAR((st.contact - (c + R * nu)).norm(), 0.0, 1e-12);
                EXPECT_NEAR((st.normal - nu).norm(), 0.0, 1e-12);
                EXPECT_TRUE(relClose(st.rhoPitch, R + rho, 1e-9));
                EXPECT_TRUE(relClose(st.rhoProfile, R, 1e-9));
                // The tip is where the arm says.
                const double big = phi + st.s;
                EXPECT_NEAR(
                    (pivot + spec.armLength * Eigen::Vector2d(std::cos(big), std::sin(big)) -
                     st.center)
                        .norm(),
                    0.0, 1e-12);
                // Derivatives against differences of the closed form; times ω, ω², ω³.
                EXPECT_NEAR(st.sPhi[1], psi1(phi), 1e-9);
                EXPECT_NEAR(st.sPhi[2], psi2(phi), 1e-6);
                EXPECT_NEAR(st.sPhi[3], derivative(psi2, phi, 1e-3), 1e-4);
                EXPECT_TRUE(relClose(st.v, omega * st.sPhi[1], 1e-15));
                EXPECT_TRUE(relClose(st.a, omega * omega * st.sPhi[2], 1e-15));
                EXPECT_TRUE(relClose(st.j, omega * omega * omega * st.sPhi[3], 1e-15));
                // |α| is the angle between the normal and the way the tip moves away from the
                // cam (across the arm).
                const Eigen::Vector2d away = sigma * Eigen::Vector2d(-std::sin(big), std::cos(big));
                EXPECT_NEAR(std::abs(st.pressureAngle), std::acos(nu.dot(away)), 1e-9);
                // The lift's rates are ψ's, turned to degrees, growing away from the cam.
                const auto lift = m.liftPhi(st);
                EXPECT_TRUE(relClose(lift[1], sigma * radToDeg(st.sPhi[1]), 1e-15));
                const double rate = sigma * st.sPhi[1];
                if (rate > riseRate) {
                    riseRate = rate;
                    riseAlpha = st.pressureAngle;
                }
                if (rate < returnRate) {
                    returnRate = rate;
                    returnAlpha = st.pressureAngle;
                }
            }
            // Where the arm swings away fastest the pressure angle is positive; back, negative.
            // (Measured from the tip's path like the translating follower's atan2(s' − e, s),
            // it is not tied to the swing's sign when the arm leans: that acts as an offset.)
            EXPECT_GT(riseAlpha, 0.1);
            EXPECT_LT(returnAlpha, -0.1);
            // The lift runs from 0 to the whole swing, in degrees.
            double lo = 1e300, hi = -1e300, liftHi = -1e300;
            for (int i = 0; i < 20000; ++i) {
                const FollowerState st = m.at(kTwoPi * i / 20000, 1.0);
                lo = std::min(lo, sigma * st.s);
                hi = std::max(hi, sigma * st.s);
                liftHi = std::max(liftHi, m.lift(st));
                EXPECT_GE(m.lift(st), -1e-12);
            }
            EXPECT_NEAR(liftHi, radToDeg(hi - lo), 1e-6);
        }
    }
}

/// A swinging roller (or knife, ρ = 0) on `contour`: the centre ρ from the profile and L from
/// the turned pivot, the contact on the profile; ψ's derivatives against differences.
void checkArm(const Contour& contour, const FollowerSpec& spec, const char* name, int angles = 90) {
    const FollowerModel m = armModel(contour, spec);
    const auto psi = [&](double phi) { return m.at(phi, 1.0).s; };
    const auto psi1 = [&](double phi) { return m.at(phi, 1.0).sPhi[1]; };
    const auto psi2 = [&](double phi) { return m.at(phi, 1.0).sPhi[2]; };
    int checked = 0;
    for (int i = 0; i < angles; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * (i + 0.37) / angles;
        SCOPED_TRACE(std::string(name) + " " + std::to_string(radToDeg(phi)));
        const FollowerState st = m.at(phi, 1.0);
        EXPECT_NEAR(distanceToProfile(contour, st.center), spec.radius, 1e-9);
        EXPECT_NEAR(distanceToProfile(contour, st.contact), 0.0, 1e-9);
        EXPECT_NEAR((st.center - st.contact).norm(), spec.radius, 1e-12);
        EXPECT_NEAR((st.center - turned(spec.pivot, phi)).norm(), spec.armLength, 1e-12);
        const double h = 1e-4;
        if (m.at(phi - 2 * h, 1.0).segment != st.segment ||
            m.at(phi + 2 * h, 1.0).segment != st.segment) {
            continue;
        }
        ++checked;
        EXPECT_NEAR(st.sPhi[1], derivative(psi, phi, h), 1e-8 * (1 + std::abs(st.sPhi[1])));
        EXPECT_NEAR(st.sPhi[2], derivative(psi1, phi, h), 1e-7 * (1 + std::abs(st.sPhi[2])));
        EXPECT_NEAR(st.sPhi[3], derivative(psi2, phi, h), 1e-5 * (1 + std::abs(st.sPhi[3])));
    }
    EXPECT_GT(checked, angles * 2 / 3) << name;
}

TEST(FollowerArm, KeepsItsLengthAndItsRadiusOnTheSixLobeCam) {
    checkArm(sixLobe(), armSpec(FollowerType::Roller, 2.0, {60.0, 0.0}, 50.0, ArmSide::Ccw),
             "six-lobe ccw roller");
    checkArm(sixLobe(), armSpec(FollowerType::Knife, 0.0, {-25.0, -30.0}, 35.0, ArmSide::Cw),
             "six-lobe cw knife");
}

TEST(FollowerArm, KeepsItsLengthAndItsRadiusOnSplineCams) {
    checkArm(load(test::dataPath("reference/spline-mix.cam.json")),
             armSpec(FollowerType::Roller, 1.5, {10.0, 40.0}, 33.0, ArmSide::Cw), "spline-mix", 36);
}

TEST(FollowerArm, TheLiftIsZeroWhereTheArmIsClosestToTheCam) {
    // The lift's zero (the smallest swing angle of the turn) is found while the model is built,
    // from the contacts in plain doubles; the lift the model reports comes from the contacts
    // with their derivatives. Over a dense turn the two agree: the lift never goes below 0
    // and comes down to 0, on arcs and on splines alike.
    const std::pair<Contour, FollowerSpec> cams[] = {
        {sixLobe(), armSpec(FollowerType::Roller, 2.0, {60.0, 0.0}, 50.0, ArmSide::Ccw)},
        {sixLobe(), armSpec(FollowerType::Knife, 0.0, {-25.0, -30.0}, 35.0, ArmSide::Cw)},
        {load(test::dataPath("reference/spline-mix.cam.json")),
         armSpec(FollowerType::Roller, 1.5, {10.0, 40.0}, 33.0, ArmSide::Cw)},
    };
    for (const auto& [contour, spec] : cams) {
        const FollowerModel m = armModel(contour, spec);
        double lowest = 1e300;
        constexpr int n = 200000;
        for (int i = 0; i < n; ++i) {
            lowest = std::min(lowest, m.lift(m.at(contour.phiBegin() + kTwoPi * i / n, 1.0)));
        }
        EXPECT_GE(lowest, -1e-9);
        // 200,000 angles find the minimum of a smooth lift to within (step)² · |lift''|.
        EXPECT_LT(lowest, 1e-6);
    }
}

TEST(FollowerLiftMotion, IsTheLiftsTimeDerivativesInTheLiftsUnitAndSense) {
    // The plots and the readout show the lift (mm, or degrees swung away from the cam) and its
    // time derivatives. Each is checked here against a five-point difference over time of the
    // lift alone (the one before it, for a and j), at ω = −2 rad/s (clockwise), on arms swinging
    // either way and on a translating roller: a sign or a unit (rad for °) wrong in any fails.
    const double omega = -2.0;
    const std::pair<Contour, FollowerSpec> cams[] = {
        {sixLobe(), armSpec(FollowerType::Roller, 2.0, {60.0, 0.0}, 50.0, ArmSide::Ccw)},
        {sixLobe(), armSpec(FollowerType::Knife, 0.0, {-25.0, -30.0}, 35.0, ArmSide::Cw)},
        {sixLobe(),
         [] {
             FollowerSpec spec;
             spec.type = FollowerType::Roller;
             spec.radius = 2.0;
             spec.offset = 3.0;
             return spec;
         }()},
    };
    for (const auto& [contour, spec] : cams) {
        const FollowerModel m = armModel(contour, spec);
        // Inside arcs (no joint within the differences' reach) of the first lobes.
        for (double deg : {7.3, 21.0, 33.7, 52.1}) {
            const double t0 = degToRad(deg) / omega;
            const auto motion = [&](double t, std::size_t d) {
                return m.liftMotion(m.at(omega * t, omega))[d];
            };
            const double h = 1e-4 / std::abs(omega);
            const auto got = m.liftMotion(m.at(omega * t0, omega));
            for (std::size_t d = 1; d < 4; ++d) {
                const double fd =
                    test::derivative([&](double t) { return motion(t, d - 1); }, t0, h);
                EXPECT_NEAR(got[d], fd, 1e-6 * std::max(1.0, std::abs(fd)))
                    << "derivative " << d << " at " << deg << "°, arm "
                    << (spec.motion == FollowerMotion::Oscillating);
            }
            EXPECT_EQ(got[0], m.lift(m.at(omega * t0, omega)));
        }
    }
}

TEST(FollowerArm, APivotInsideTheCamOrAnArmThatCannotReachItIsRefusedWithItsPlace) {
    const Contour contour = sixLobe();  // r from 20.9 to 29 mm
    const auto refusal = [&](const FollowerSpec& spec) {
        const auto m = FollowerModel::build(contour, spec);
        EXPECT_FALSE(m.ok());
        return m.ok() ? Diagnostic{} : m.errors().front();
    };
    Diagnostic d = refusal(armSpec(FollowerType::Roller, 2.0, {28.0, 0.0}, 10.0, ArmSide::Ccw));
    EXPECT_EQ(d.location, "follower.pivot");
    EXPECT_NE(d.message.find("inside the cam"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("29 mm"), std::string::npos) << d.message;
    d = refusal(armSpec(FollowerType::Roller, 2.0, {60.0, 0.0}, 20.0, ArmSide::Ccw));
    EXPECT_EQ(d.location, "follower.arm_length");
    EXPECT_NE(d.message.find("too short"), std::string::npos) << d.message;
    d = refusal(armSpec(FollowerType::Knife, 0.0, {60.0, 0.0}, 95.0, ArmSide::Cw));
    EXPECT_EQ(d.location, "follower.arm_length");
    EXPECT_NE(d.message.find("too long"), std::string::npos) << d.message;
}

}  // namespace
}  // namespace cam
