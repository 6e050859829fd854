// Followers placed by contact (math.md §7), checked without the follower's own formulas: on an
// eccentric circle against its closed form and plane geometry; on the six-lobe cam and on spline
// cams by the distance from the roller centre to the profile (sampled through r(φ), refined),
// by the support function taken as a maximum over the profile, by the knife at e = 0 equalling
// r(φ) of math.md §1, and by finite differences of s for its derivatives.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/test_projects.h"
#include "follower/follower.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

Contour load(const std::string& path) {
    auto p = loadProjectFile(path);
    EXPECT_TRUE(p.ok()) << path;
    return Contour::build(p.value()).value();
}

Contour sixLobe() { return load(test::examplePath("six-lobe-arc-cam.cam.json")); }

FollowerModel model(const Contour& contour, FollowerType type, double offset, double radius) {
    FollowerSpec spec;
    spec.type = type;
    spec.offset = offset;
    spec.radius = radius;
    auto m = FollowerModel::build(contour, spec);
    EXPECT_TRUE(m.ok());
    return std::move(m).value();
}

Eigen::Vector2d unit(double phi) { return {std::cos(phi), std::sin(phi)}; }
Eigen::Vector2d normalOf(double phi) { return {-std::sin(phi), std::cos(phi)}; }

/// The profile point on the ray at φ: r(φ)·u, through the contour's polar formulas.
Eigen::Vector2d profilePoint(const Contour& contour, double phi) {
    return contour.evaluate(phi).r * unit(phi);
}

/// The distance from x to the profile: the nearest of 20 000 points on it, refined by golden
/// sections along the polar angle.
double distanceToProfile(const Contour& contour, const Eigen::Vector2d& x) {
    constexpr int n = 20000;
    double best = 1e300, bestPhi = 0.0;
    for (int i = 0; i < n; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * i / n;
        const double d = (profilePoint(contour, phi) - x).norm();
        if (d < best) {
            best = d;
            bestPhi = phi;
        }
    }
    double lo = bestPhi - kTwoPi / n, hi = bestPhi + kTwoPi / n;
    const auto f = [&](double phi) { return (profilePoint(contour, phi) - x).norm(); };
    constexpr double g = 0.6180339887498949;
    for (int it = 0; it < 100; ++it) {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (f(a) < f(b)) {
            hi = b;
        } else {
            lo = a;
        }
    }
    return std::min(best, f(0.5 * (lo + hi)));
}

/// Central differences of order 4: f'(x) with error O(h⁴).
template <class F>
double derivative(F f, double x, double h) {
    return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h)) / (12 * h);
}

TEST(FollowerOnACircle, KnifeWithOffsetIsTheOuterCrossingOfItsLine) {
    // A circle of radius 20 about (8, 3): s(φ) = c·u + √(R² − (e − c·n)²).
    const Eigen::Vector2d c(8.0, 3.0);
    const double R = 20.0, e = 5.0;
    Project p;
    p.contour.push_back(SegmentSpec{Arc{c, R, Branch::Outer}, 0.0, 360.0});
    const Contour contour = Contour::build(p).value();
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
    Project p;
    p.contour.push_back(SegmentSpec{Arc{c, R, Branch::Outer}, 0.0, 360.0});
    const Contour contour = Contour::build(p).value();
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
    Project p;
    p.contour.push_back(SegmentSpec{Arc{c, R, Branch::Outer}, 0.0, 360.0});
    const Contour contour = Contour::build(p).value();
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
void checkRoller(const Contour& contour, double e, double rho, const char* name) {
    const FollowerModel m = model(contour, FollowerType::Roller, e, rho);
    const auto s = [&](double phi) { return m.at(phi, 1.0).s; };
    const auto s1 = [&](double phi) { return m.at(phi, 1.0).sPhi[1]; };
    const auto s2 = [&](double phi) { return m.at(phi, 1.0).sPhi[2]; };
    int checked = 0;
    for (int i = 0; i < 90; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * (i + 0.41) / 90;
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
    EXPECT_GT(checked, 60) << name;
}

TEST(FollowerRoller, KeepsItsRadiusFromTheSixLobeCam) {
    checkRoller(sixLobe(), 3.0, 2.0, "six-lobe");
}

TEST(FollowerRoller, KeepsItsRadiusFromSplineCams) {
    checkRoller(load(test::dataPath("reference/spline-mix.cam.json")), -2.5, 1.5, "spline-mix");
    checkRoller(load(test::dataPath("reference/spline-offset.cam.json")), 1.0, 2.0,
                "spline-offset");
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
