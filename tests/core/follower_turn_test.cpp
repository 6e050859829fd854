// A whole turn of the follower at once (sampleFollowerTurn, the batch path of plots, CSV and the
// benchmark): on an eccentric disc against the closed form, and on every reference cam, each
// follower and both senses of turning against FollowerModel::at() at every sample angle — at()
// is checked against closed forms, plane geometry and the 50-digit contact reference in
// follower_test.cpp and cli/follower_cli_test.cpp.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <string>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/follower_geometry.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "test_support.h"

namespace cam {
namespace {

using test::load;
using test::normalOf;
using test::relClose;
using test::unit;

FollowerSpec spec(FollowerType type, double offset, double radius) {
    FollowerSpec s;
    s.type = type;
    s.offset = offset;
    s.radius = radius;
    return s;
}

FollowerModel build(const Contour& contour, const FollowerSpec& s) {
    auto m = FollowerModel::build(contour, s);
    EXPECT_TRUE(m.ok());
    return std::move(m).value();
}

/// φ of sample k, as sampleTurn() places it.
double phiOf(double omega, std::size_t n, std::size_t k) {
    const double dt = kTwoPi / std::abs(omega) / static_cast<double>(n);
    return omega * (static_cast<double>(k) * dt);
}

/// Relative to the radius, or to 1 mm for radii near 0 (a roller round a sharp corner rides a
/// circle of its own radius: the profile's radius there is 0 to rounding).
bool radiusClose(double batch, double exact, double tolerance) {
    if (std::isinf(exact) || std::isinf(batch)) return batch == exact;
    return std::abs(batch - exact) <= tolerance * std::max(std::abs(exact), 1.0);
}

/// Every sample of the batch against at() at the same angle. s and v are continuous through
/// every joint and must agree everywhere; a, j, the pressure angle and the radii must agree too,
/// except where the sample sits on a joint and the batch took the contact on the other side of
/// it (cos/sin by the block table differ from std::cos in the last bits): then they must equal
/// at() a hair before or after the joint. Such samples are counted and must be rare.
void expectSameAsAt(const FollowerModel& m, double omega, std::size_t n, const std::string& what,
                    std::size_t allowedJoints) {
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(m, omega, n, turn));
    ASSERT_EQ(turn.size(), n);
    std::vector<FollowerState> exact(n);
    double sScale = 1.0, vScale = 1e-9, aScale = 1e-9, jScale = 1e-9;
    for (std::size_t k = 0; k < n; ++k) {
        exact[k] = m.at(phiOf(omega, n, k), omega);
        sScale = std::max(sScale, std::abs(exact[k].s));
        vScale = std::max(vScale, std::abs(exact[k].v));
        aScale = std::max(aScale, std::abs(exact[k].a));
        jScale = std::max(jScale, std::abs(exact[k].j));
    }
    const auto matches = [&](std::size_t k, const FollowerState& st, double looseness) {
        return std::abs(turn.a[k] - st.a) <= 1e-10 * looseness * aScale &&
               std::abs(turn.j[k] - st.j) <= 1e-9 * looseness * jScale &&
               std::abs(turn.pressureAngle[k] - st.pressureAngle) <= 1e-12 * looseness &&
               radiusClose(turn.rhoPitch[k], st.rhoPitch, 1e-9 * looseness) &&
               radiusClose(turn.rhoProfile[k], st.rhoProfile, 1e-9 * looseness);
    };
    std::size_t joints = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const FollowerState& st = exact[k];
        ASSERT_NEAR(turn.s[k], st.s, 1e-12 * sScale) << what << " k=" << k;
        ASSERT_NEAR(turn.v[k], st.v, 1e-10 * vScale) << what << " k=" << k;
        if (matches(k, st, 1.0)) {
            EXPECT_EQ(turn.segment[k], static_cast<std::int32_t>(st.segment)) << what << " k=" << k;
            continue;
        }
        ++joints;
        const double phi = phiOf(omega, n, k), h = 1e-9;
        const bool before = matches(k, m.at(phi - h, omega), 1e5);
        const bool after = matches(k, m.at(phi + h, omega), 1e5);
        EXPECT_TRUE(before || after)
            << what << " k=" << k << " phi=" << radToDeg(phi) << "°: a " << turn.a[k] << " vs "
            << st.a << ", j " << turn.j[k] << " vs " << st.j << ", pressure "
            << turn.pressureAngle[k] << " vs " << st.pressureAngle << ", rho " << turn.rhoPitch[k]
            << " vs " << st.rhoPitch << ", " << turn.rhoProfile[k] << " vs " << st.rhoProfile;
    }
    EXPECT_LE(joints, allowedJoints) << what;
}

TEST(FollowerTurn, OnAnEccentricDiscEverySampleIsTheClosedForm) {
    // Roller of 4 mm with offset −7 mm on a circle of 25 mm about (−6, 4): the centre rides the
    // circle of 29 mm, s = c·u + √(29² − (e − c·n)²); the pressure angle is the angle of that
    // circle's radius to u; both radii are constant.
    const Eigen::Vector2d c(-6.0, 4.0);
    const double R = 25.0, rho = 4.0, e = -7.0, Rp = R + rho;
    const Contour contour = test::disc(c, R);
    for (const double omega : {3.0, -2.0}) {
        const FollowerModel m = build(contour, spec(FollowerType::Roller, e, rho));
        constexpr std::size_t n = 5000;
        FollowerTurn turn;
        ASSERT_TRUE(sampleFollowerTurn(m, omega, n, turn));
        for (std::size_t k = 0; k < n; ++k) {
            const double phi = phiOf(omega, n, k);
            const double a = c.dot(unit(phi)), b = c.dot(normalOf(phi));
            const double s = a + std::sqrt(Rp * Rp - (e - b) * (e - b));
            ASSERT_NEAR(turn.s[k], s, 1e-12) << k;
            const Eigen::Vector2d centre = e * normalOf(phi) + s * unit(phi);
            const Eigen::Vector2d nu = (centre - c).normalized();
            EXPECT_NEAR(turn.pressureAngle[k],
                        std::atan2(-nu.dot(normalOf(phi)), nu.dot(unit(phi))), 1e-12)
                << k;
            EXPECT_TRUE(relClose(turn.rhoPitch[k], Rp, 1e-9)) << k << " " << turn.rhoPitch[k];
            EXPECT_TRUE(relClose(turn.rhoProfile[k], R, 1e-9)) << k;
            EXPECT_EQ(turn.segment[k], 0);
        }
        // A flat face: the support function h = c·u + R, h'' = −c·u, ρ = h + h'' = R.
        const FollowerModel flat = build(contour, spec(FollowerType::Flat, 0.0, 0.0));
        ASSERT_TRUE(sampleFollowerTurn(flat, omega, n, turn));
        for (std::size_t k = 0; k < n; ++k) {
            const double phi = phiOf(omega, n, k);
            ASSERT_NEAR(turn.s[k], c.dot(unit(phi)) + R, 1e-12) << k;
            EXPECT_NEAR(turn.v[k], omega * c.dot(normalOf(phi)), 1e-12) << k;
            EXPECT_NEAR(turn.a[k], -omega * omega * c.dot(unit(phi)), 1e-11) << k;
            EXPECT_EQ(turn.pressureAngle[k], 0.0);
            EXPECT_NEAR(turn.rhoProfile[k], R, 1e-11) << k;
        }
    }
}

TEST(FollowerTurn, EveryFollowerOnEveryReferenceCamIsWhatAtGivesAtThatAngle) {
    struct Case {
        std::string file;
        FollowerType type;
        double offset, radius;
    };
    // Arcs only, arcs with lines (straight stretches: infinite radii), hollows a roller or a
    // face bridges, and cams with splines (their bins go through at()).
    const std::vector<Case> cases{
        {"six-lobe-arc-cam.cam.json", FollowerType::Roller, 3.0, 2.0},
        {"six-lobe-arc-cam.cam.json", FollowerType::Knife, -4.0, 0.0},
        {"six-lobe-arc-cam.cam.json", FollowerType::Flat, 0.0, 0.0},
        {"reference/d-flat.cam.json", FollowerType::Roller, 2.0, 3.0},
        {"reference/d-flat.cam.json", FollowerType::Knife, 1.5, 0.0},
        {"reference/d-flat.cam.json", FollowerType::Flat, 0.0, 0.0},
        {"reference/notch-flat.cam.json", FollowerType::Roller, -1.0, 1.0},
        {"reference/notch-flat.cam.json", FollowerType::Flat, 0.0, 0.0},
        {"reference/pear-tangent.cam.json", FollowerType::Roller, 5.0, 4.0},
        {"reference/five-lobe.cam.json", FollowerType::Knife, 2.0, 0.0},
        {"reference/rounded-triangle.cam.json", FollowerType::Flat, 0.0, 0.0},
        {"reference/eccentric-split.cam.json", FollowerType::Roller, 0.0, 1.5},
        {"reference/spline-mix.cam.json", FollowerType::Roller, -2.5, 1.5},
        {"reference/spline-offset.cam.json", FollowerType::Flat, 0.0, 0.0},
    };
    for (const Case& c : cases) {
        const std::string path =
            c.file.starts_with("reference/") ? test::dataPath(c.file) : test::examplePath(c.file);
        const Contour contour = load(path);
        const FollowerModel m = build(contour, spec(c.type, c.offset, c.radius));
        const std::string what = c.file + " type " + std::to_string(static_cast<int>(c.type));
        // 3600 samples land on the joints of cams laid out in whole degrees; 4099 do not.
        expectSameAsAt(m, 2.5, 3600, what + " n=3600", 2 * contour.size() + 4);
        expectSameAsAt(m, -1.75, 4099, what + " n=4099 cw", 4);
    }
}

TEST(FollowerTurn, ASwingingArmAndAFewSamplesGoThroughAt) {
    const Contour contour = test::sixLobe();
    FollowerSpec arm = spec(FollowerType::Roller, 0.0, 2.0);
    arm.motion = FollowerMotion::Oscillating;
    arm.pivot = {60.0, 0.0};
    arm.armLength = 50.0;
    const FollowerModel m = build(contour, arm);
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(m, 4.0, 997, turn));
    for (std::size_t k = 0; k < 997; ++k) {
        const FollowerState st = m.at(phiOf(4.0, 997, k), 4.0);
        ASSERT_EQ(turn.s[k], st.s) << k;  // the same call: bit for bit
        ASSERT_EQ(turn.pressureAngle[k], st.pressureAngle) << k;
    }
    // Fewer samples than bins: every run is one sample long.
    const FollowerModel roller = build(contour, spec(FollowerType::Roller, 3.0, 2.0));
    expectSameAsAt(roller, 1.0, 7, "7 samples", 0);
    expectSameAsAt(roller, -1.0, 1, "1 sample", 0);
}

TEST(FollowerTurn, CancelStopsIt) {
    const Contour contour = test::sixLobe();
    const FollowerModel m = build(contour, spec(FollowerType::Roller, 3.0, 2.0));
    FollowerTurn turn;
    std::atomic<bool> cancel{true};
    EXPECT_FALSE(sampleFollowerTurn(m, 1.0, 100000, turn, &cancel));
    cancel = false;
    EXPECT_TRUE(sampleFollowerTurn(m, 1.0, 100000, turn, &cancel));
}

}  // namespace
}  // namespace cam
