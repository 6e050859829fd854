// A conjugate yoke's second plate (closure/conjugate.h), checked against closed forms: on an
// eccentric disc of radius R about c, a roller on a line at offset e sits at
// s(φ) = u·c + √((R + ρ)² − (e − n·c)²); the second roller, D behind it on the same line, at
// (s − D)·u + e·n. The fitted second plate must hold that roller, at every angle, within the
// tolerance; and a roller placed by contact on the second plate (the follower machinery, the
// line turned half a turn) must stand D from the first.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "closure/conjugate.h"
#include "common/angles.h"
#include "core/follower_geometry.h"
#include "evaluation/evaluation.h"
#include "evaluation/force_evaluation.h"

namespace cam {
namespace {

struct Disc {
    Eigen::Vector2d c{6.0, -2.0};
    double R = 25.0, rho = 4.0, e = 3.0;
};

FollowerModel firstRoller(const Disc& d) {
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = d.rho;
    spec.offset = d.e;
    return FollowerModel::build(test::disc(d.c, d.R), spec).value();
}

double sOf(const Disc& d, double phi) {
    const Eigen::Vector2d u = test::unit(phi), n = test::normalOf(phi);
    const double side = d.e - n.dot(d.c);
    return u.dot(d.c) + std::sqrt((d.R + d.rho) * (d.R + d.rho) - side * side);
}

TEST(Conjugate, TheSecondRollerOfAYokeOnAnEccentricDiscIsHeldWithinTheTolerance) {
    const Disc d;
    const SecondRoller yoke{80.0, 5.0};
    const double tolerance = 1e-3;
    const FollowerModel first = firstRoller(d);
    // The second roller's centre: the closed form.
    for (double deg = 0.0; deg < 360.0; deg += 7.7) {
        const double phi = degToRad(deg);
        const Eigen::Vector2d expected =
            (sOf(d, phi) - yoke.distanceMm) * test::unit(phi) + d.e * test::normalOf(phi);
        EXPECT_NEAR((conjugatePoint(first, yoke, phi).centre - expected).norm(), 0.0, 1e-10) << deg;
    }
    const auto plate = conjugatePlate(first, yoke, tolerance);
    ASSERT_TRUE(plate.ok()) << plate.errors().front().text();
    const ConjugatePlate& p = plate.value();
    EXPECT_GT(p.fit.arcs.size(), 4u);
    EXPECT_LE(p.maxPlay, tolerance);
    EXPECT_GE(p.minPlay, -tolerance);
    // Independently of the plate's own measure: every closed-form centre, densely, is the
    // roller's radius from the arcs to the tolerance, and each arc's ends meet the next.
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) {
        const double phi = kTwoPi * k / 20000;
        const Eigen::Vector2d centre =
            (sOf(d, phi) - yoke.distanceMm) * test::unit(phi) + d.e * test::normalOf(phi);
        double distance = 1e300;
        for (const FittedArc& arc : p.fit.arcs) {
            distance = std::min(distance, distanceToArc(arc, centre));
        }
        worst = std::max(worst, std::abs(distance - yoke.rollerRadiusMm));
    }
    EXPECT_LE(worst, tolerance);
    // Not zero by construction: the arcs do deviate, by a part of the tolerance.
    EXPECT_GT(worst, tolerance / 100);
    ::testing::Test::RecordProperty("worst_mm", std::to_string(worst));
    for (std::size_t k = 0; k < p.fit.arcs.size(); ++k) {
        const auto& next = p.fit.arcs[(k + 1) % p.fit.arcs.size()];
        EXPECT_NEAR((p.fit.arcs[k].to - next.from).norm(), 0.0, 1e-9) << k;
    }
}

TEST(Conjugate, TheSecondPlatesChecksMeanWhatTheySayAtTheCamAngle) {
    // The second roller's pressure angle from the closed-form centre path alone: its tangent by
    // central differences, the contact normal that tangent turned clockwise (the path runs
    // counter-clockwise round the cam), measured from −u.
    const Disc d;
    const SecondRoller yoke{80.0, 5.0};
    const FollowerModel first = firstRoller(d);
    const auto centre = [&](double phi) {
        return Eigen::Vector2d((sOf(d, phi) - yoke.distanceMm) * test::unit(phi) +
                               d.e * test::normalOf(phi));
    };
    const auto pressure = [&](double phi) {
        const double h = 1e-5;
        const Eigen::Vector2d t = (centre(phi + h) - centre(phi - h)).normalized();
        const Eigen::Vector2d normal(t.y(), -t.x()), towards = -test::unit(phi);
        return std::atan2(towards.x() * normal.y() - towards.y() * normal.x(), towards.dot(normal));
    };
    double largest = 0.0, largestAt = 0.0;
    for (int k = 0; k < 36000; ++k) {
        const double phi = kTwoPi * k / 36000;
        const double a = pressure(phi);
        EXPECT_NEAR(conjugatePoint(first, yoke, phi).pressureAngle, a, 1e-8) << k;
        if (std::abs(a) > std::abs(largest)) {
            largest = a;
            largestAt = phi;
        }
    }
    const auto plate = conjugatePlate(first, yoke, 1e-3);
    ASSERT_TRUE(plate.ok());
    const ConjugatePlate& p = plate.value();
    // Sampled every 0.05° against every 0.01°: the peak is flat, its value agrees closely.
    EXPECT_NEAR(p.maxPressureAngle, largest, 1e-6);
    EXPECT_NEAR(p.maxPressureAt, largestAt, degToRad(0.05));
    // A disc's second plate bends round its centre everywhere: convex arcs only. The tightest
    // one's `phi` is a cam angle and `point` where the roller touches the plate then: the
    // closed-form centre at that angle is the roller's radius from it, and it lies on that arc
    // to the tolerance (its polar angle lies about half a turn from the cam angle).
    ASSERT_TRUE(p.bends.minConvex);
    EXPECT_FALSE(p.bends.minConcave);
    const RadialExtreme& tight = *p.bends.minConvex;
    double smallest = 1e300;
    for (const FittedArc& arc : p.fit.arcs) smallest = std::min(smallest, arc.radius);
    EXPECT_EQ(tight.radius, smallest);
    EXPECT_NEAR((centre(tight.phi) - tight.point).norm(), yoke.rollerRadiusMm, 1e-9);
    const auto on = std::find_if(p.fit.arcs.begin(), p.fit.arcs.end(),
                                 [&](const FittedArc& arc) { return arc.radius == smallest; });
    EXPECT_LE(std::abs((tight.point - on->center).norm() - smallest), 1e-3);
    EXPECT_GT(
        std::abs(std::remainder(std::atan2(tight.point.y(), tight.point.x()) - tight.phi, kTwoPi)),
        degToRad(90.0));
}

TEST(Conjugate, ARollerPlacedByContactOnTheSecondPlateStandsTheYokesLengthBehind) {
    // The second plate as a contour, a roller on it running on the same line turned half a
    // turn (its line's direction −u, its offset −e): placed by contact alone, it stands at
    // s₂(φ + π) = D − s(φ) to the fit's tolerance.
    const Disc d;
    const SecondRoller yoke{80.0, 5.0};
    const double tolerance = 1e-4;
    const auto plate = conjugatePlate(firstRoller(d), yoke, tolerance);
    ASSERT_TRUE(plate.ok()) << plate.errors().front().text();
    Project second;
    second.contour = plate.value().contour;
    const auto contour = Contour::build(second);
    ASSERT_TRUE(contour.ok()) << contour.errors().front().text();
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = yoke.rollerRadiusMm;
    spec.offset = -d.e;
    const auto roller = FollowerModel::build(contour.value(), spec);
    ASSERT_TRUE(roller.ok()) << roller.errors().front().text();
    double worst = 0.0;
    for (int k = 0; k < 3600; ++k) {
        const double phi = kTwoPi * k / 3600;
        const double s2 = roller.value().at(phi + kPi, 1.0).s;
        worst = std::max(worst, std::abs(sOf(d, phi) + s2 - yoke.distanceMm));
    }
    // The contact moves along the normal, not the line: by at most the play over cos α.
    EXPECT_LE(worst, 2 * tolerance);
    ::testing::Test::RecordProperty("worst_mm", std::to_string(worst));
}

TEST(Conjugate, WhatCannotBeMadeIsRefusedAtItsKey) {
    const Disc d;
    const FollowerModel first = firstRoller(d);
    // Too short: the second roller would stand in front of the cam centre.
    const auto shortYoke = conjugatePlate(first, {20.0, 5.0}, 1e-3);
    ASSERT_FALSE(shortYoke.ok());
    EXPECT_EQ(shortYoke.errors().front().location, "follower.conjugate_distance_mm");
    EXPECT_EQ(shortYoke.errors().front().code, DiagnosticCode::ConjugateRollerNotBeyondCentre);
    const auto noRadius = conjugatePlate(first, {80.0, 0.0}, 1e-3);
    ASSERT_FALSE(noRadius.ok());
    EXPECT_EQ(noRadius.errors().front().location, "follower.conjugate_radius_mm");
    // A knife has no second roller.
    FollowerSpec knife;
    const auto plain = FollowerModel::build(test::disc(d.c, d.R), knife).value();
    const auto refused = conjugatePlate(plain, {80.0, 5.0}, 1e-3);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.errors().front().code, DiagnosticCode::ConjugateNeedsRoller);
}

TEST(ConjugateForces, TheSecondRollerCarriesWhereTheClosedFormsLoadTurnsNegative) {
    // The yoke on the eccentric disc, driven by inertia alone: the load m·s''·ω² turns negative
    // where s'' does (found on the closed form alone), and the second roller then carries it on
    // the second plate — at its own pressure angle and on the plate's curvature, both taken
    // from the closed-form centre path (s − D)·u + e·n by finite differences.
    const Disc d;
    const double mass = 0.5, omega = 20.0, b = 10.0, E = 210000.0, nu = 0.3;
    const SecondRoller yoke{80.0, 5.0};
    Project p;
    p.motion = {SpeedUnit::OmegaRadS, omega};
    p.contour.push_back(SegmentSpec{Arc{d.c, d.R, Branch::Outer}, 0.0, 360.0});
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = d.rho;
    spec.offset = d.e;
    spec.closure = Closure::Conjugate;
    spec.conjugateDistance = yoke.distanceMm;
    spec.conjugateRadius = yoke.rollerRadiusMm;
    p.follower = spec;
    DynamicsSpec dyn;
    dyn[DynamicsKey::MassKg] = mass;
    dyn[DynamicsKey::ContactWidthMm] = b;
    dyn[DynamicsKey::CamModulusMpa] = E;
    dyn[DynamicsKey::CamPoisson] = nu;
    dyn[DynamicsKey::FollowerModulusMpa] = E;
    dyn[DynamicsKey::FollowerPoisson] = nu;
    p.dynamics = dyn;
    const ProjectEvaluation e = evaluateProject(p);
    ASSERT_EQ(e.status, EvaluationStatus::Computed);
    ForceEvaluation forces;
    ASSERT_TRUE(evaluateForces(p, *e.follower, e.omega, forces));
    ASSERT_TRUE(forces.model.conjugate());

    const double h = 1e-3;
    const auto d2 = [h](auto&& f, double x) {
        return (-f(x - 2 * h) + 16 * f(x - h) - 30 * f(x) + 16 * f(x + h) - f(x + 2 * h)) /
               (12 * h * h);
    };
    const auto d1 = [h](auto&& f, double x) {
        return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h)) / (12 * h);
    };
    const auto s = [&](double phi) { return sOf(d, phi); };
    const auto s2 = [&](double phi) { return d2(s, phi); };
    // The sign changes of s'', by bisection on the closed form.
    std::vector<double> roots;
    for (int k = 0; k < 3600; ++k) {
        double a = kTwoPi * k / 3600, c = kTwoPi * (k + 1) / 3600;
        if ((s2(a) < 0) == (s2(c) < 0)) continue;
        const bool negativeAtA = s2(a) < 0;
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + c);
            ((s2(m) < 0) == negativeAtA ? a : c) = m;
        }
        roots.push_back(0.5 * (a + c));
    }
    ASSERT_EQ(roots.size(), 2u);
    const ForceSummary& summary = forces.summary;
    ASSERT_EQ(summary.liftOff.size(), 1u);
    for (const double end : summary.liftOff[0]) {
        double nearest = 1e300;
        for (const double r : roots)
            nearest = std::min(nearest, std::abs(std::remainder(r - end, kTwoPi)));
        EXPECT_LT(nearest, 1e-7) << end;
    }
    // The second roller's normal force and stress over the turn, densely, against the summary.
    const double eStar = 1.0 / (2 * (1 - nu * nu) / E);
    double normalPeak = 0.0, stressPeak = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const double phi = kTwoPi * k / 100000;
        const double load = mass * s2(phi) * 1e-3 * omega * omega;
        if (load >= 0) continue;
        const auto x = [&](double t) {
            return (s(t) - yoke.distanceMm) * std::cos(t) - d.e * std::sin(t);
        };
        const auto y = [&](double t) {
            return (s(t) - yoke.distanceMm) * std::sin(t) + d.e * std::cos(t);
        };
        const Eigen::Vector2d p1(d1(x, phi), d1(y, phi)), p2(d2(x, phi), d2(y, phi));
        const double kappa = (p1.x() * p2.y() - p1.y() * p2.x()) / std::pow(p1.norm(), 3);
        const double rhoPlate = 1 / kappa - yoke.rollerRadiusMm;
        const Eigen::Vector2d outward(p1.y() / p1.norm(), -p1.x() / p1.norm());
        const Eigen::Vector2d towards = -test::unit(phi);
        const double cosAlpha = towards.dot(outward);
        const double normal = -load / cosAlpha;
        const double p =
            std::sqrt(normal * eStar * (1 / rhoPlate + 1 / yoke.rollerRadiusMm) / (kPi * b));
        normalPeak = std::max(normalPeak, normal);
        stressPeak = std::max(stressPeak, p);
    }
    ASSERT_TRUE(summary.maxNormalSecond && summary.maxStressSecond);
    EXPECT_NEAR(*summary.maxNormalSecond, normalPeak, 1e-6 * normalPeak);
    EXPECT_NEAR(*summary.maxStressSecond, stressPeak, 1e-6 * stressPeak);
    // The torque does not care which roller pushes: F·λ' throughout.
    for (std::size_t k = 0; k < forces.turn.size(); k += 97) {
        const double phi =
            kTwoPi * static_cast<double>(k) / static_cast<double>(forces.turn.size());
        const double load = mass * s2(phi) * 1e-3 * omega * omega;
        EXPECT_NEAR(forces.forces.torque[k], load * d1(s, phi) * 1e-3, 1e-7) << k;
    }
}

// A bell crank on the eccentric disc: the first arm (pivot (70, 0) in the follower frame, 60 mm,
// counter-clockwise of the line to the centre) carries a 4 mm roller on the disc; the second
// arm, 60 mm on the same pivot turned by β = −48°, a 5 mm roller. In the cam frame the pivot is
// Q(φ) = R(φ)·q; the first roller's centre is where the circle of radius R + ρ about c meets
// the circle of radius L about Q, on the arm's side — a closed form, without the follower
// machinery; the second roller's centre Q + L₂·(cos(θ + β), sin(θ + β)), θ the first arm's
// direction.
struct Crank {
    Disc d;
    Eigen::Vector2d q{70.0, 0.0};
    double L = 60.0, L2 = 60.0, beta = degToRad(-48.0), rho2 = 5.0;

    [[nodiscard]] Eigen::Vector2d pivot(double phi) const {
        return q.x() * test::unit(phi) + q.y() * test::normalOf(phi);
    }
    [[nodiscard]] Eigen::Vector2d first(double phi) const {
        const Eigen::Vector2d Q = pivot(phi), w = Q - d.c;
        const double dist = w.norm(), r1 = d.R + d.rho;
        const double a = (r1 * r1 - L * L + dist * dist) / (2 * dist);
        const double h = std::sqrt(r1 * r1 - a * a);
        const Eigen::Vector2d base = d.c + a * w / dist, across(-w.y() / dist, w.x() / dist);
        for (const double side : {1.0, -1.0}) {
            const Eigen::Vector2d c1 = base + side * h * across;
            const Eigen::Vector2d arm = c1 - Q;
            if (-Q.x() * arm.y() + Q.y() * arm.x() > 0) return c1;  // ccw of Q → centre
        }
        return {NAN, NAN};
    }
    [[nodiscard]] Eigen::Vector2d second(double phi) const {
        const Eigen::Vector2d Q = pivot(phi), arm = first(phi) - Q;
        const double theta = std::atan2(arm.y(), arm.x()) + beta;
        return Q + L2 * Eigen::Vector2d(std::cos(theta), std::sin(theta));
    }
    [[nodiscard]] FollowerSpec spec() const {
        FollowerSpec f;
        f.type = FollowerType::Roller;
        f.radius = d.rho;
        f.motion = FollowerMotion::Oscillating;
        f.pivot = q;
        f.armLength = L;
        f.arm = ArmSide::Ccw;
        f.closure = Closure::Conjugate;
        f.conjugateAngleDeg = radToDeg(beta);
        f.conjugateArmLength = L2;
        f.conjugateRadius = rho2;
        return f;
    }
};

TEST(ConjugateBellCrank, TheSecondArmsRollerIsHeldWhereTheClosedFormPutsIt) {
    const Crank k;
    const FollowerModel first = FollowerModel::build(test::disc(k.d.c, k.d.R), k.spec()).value();
    const std::optional<SecondRoller> crank = SecondRoller::of(k.spec());
    ASSERT_TRUE(crank && crank->bellCrank());
    for (double deg = 0.0; deg < 360.0; deg += 7.7) {
        const double phi = degToRad(deg);
        ASSERT_NEAR((first.at(phi, 1.0).center - k.first(phi)).norm(), 0.0, 1e-9) << deg;
        EXPECT_NEAR((conjugatePoint(first, *crank, phi).centre - k.second(phi)).norm(), 0.0, 1e-9)
            << deg;
    }
    ASSERT_TRUE(conjugateProblems(first, *crank).empty());
    const double tolerance = 1e-3;
    const auto plate = conjugatePlate(first, *crank, tolerance);
    ASSERT_TRUE(plate.ok()) << plate.errors().front().text();
    const ConjugatePlate& p = plate.value();
    EXPECT_LE(p.maxPlay, tolerance);
    EXPECT_GE(p.minPlay, -tolerance);
    // Every closed-form centre is the roller's radius from the arcs, to the tolerance.
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const Eigen::Vector2d centre = k.second(kTwoPi * i / 20000);
        double distance = 1e300;
        for (const FittedArc& arc : p.fit.arcs) {
            distance = std::min(distance, distanceToArc(arc, centre));
        }
        worst = std::max(worst, std::abs(distance - k.rho2));
    }
    EXPECT_LE(worst, tolerance);
    EXPECT_GT(worst, tolerance / 100);
    // The pressure angle at the second roller: from the way its centre moves when it leaves its
    // plate — across the second arm, against the first roller's way away from its cam (the
    // crank turns both) — to the normal of the closed-form path, turned clockwise.
    for (double deg = 3.0; deg < 360.0; deg += 11.0) {
        const double phi = degToRad(deg), h = 1e-5;
        const Eigen::Vector2d t = (k.second(phi + h) - k.second(phi - h)).normalized();
        const Eigen::Vector2d normal(t.y(), -t.x());
        const Eigen::Vector2d arm = k.second(phi) - k.pivot(phi);
        const Eigen::Vector2d leaving = -Eigen::Vector2d(-arm.y(), arm.x()).normalized();
        // Leaving the plate is leaving along its normal: the two agree within 90°.
        EXPECT_GT(leaving.dot(normal), 0.0) << deg;
        const double expected =
            std::atan2(leaving.x() * normal.y() - leaving.y() * normal.x(), leaving.dot(normal));
        EXPECT_NEAR(conjugatePoint(first, *crank, phi).pressureAngle, expected, 1e-8) << deg;
    }
}

TEST(ConjugateBellCrank, ARollerPlacedByContactOnTheSecondPlateSwingsWithTheFirstArm) {
    // The second plate as a contour, a swinging roller on it from the same pivot with the
    // second arm (clockwise of the line to the centre, as the mirrored crank lies): placed by
    // contact alone, its centre is where the crank carries the second roller, to the fit's
    // tolerance over the cosine of its pressure angle.
    const Crank k;
    const double tolerance = 1e-4;
    const FollowerModel first = FollowerModel::build(test::disc(k.d.c, k.d.R), k.spec()).value();
    const auto plate = conjugatePlate(first, *SecondRoller::of(k.spec()), tolerance);
    ASSERT_TRUE(plate.ok()) << plate.errors().front().text();
    const auto contour = plateContour(plate.value());
    ASSERT_TRUE(contour.ok()) << contour.errors().front().text();
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = k.rho2;
    spec.motion = FollowerMotion::Oscillating;
    spec.pivot = k.q;
    spec.armLength = k.L2;
    spec.arm = ArmSide::Cw;
    const auto roller = FollowerModel::build(contour.value(), spec);
    ASSERT_TRUE(roller.ok()) << roller.errors().front().text();
    double worst = 0.0;
    for (int i = 0; i < 3600; ++i) {
        const double phi = kTwoPi * i / 3600;
        worst = std::max(worst, (roller.value().at(phi, 1.0).center - k.second(phi)).norm());
    }
    EXPECT_LE(worst, 3 * tolerance);
    ::testing::Test::RecordProperty("worst_mm", std::to_string(worst));
}

TEST(ConjugateBellCrank, ASecondArmThatSwingsAcrossTheCentreIsRefusedAtItsAngle) {
    // A second arm as long as the pivot is far, pointing at the cam centre: as the crank
    // swings, its roller crosses the centre back and forth and runs round it no way a plate
    // could make it. (Any roller off the centre turns round it with the frame: a second arm
    // pointing away from the cam makes a large ring of a plate, which is a cam.)
    Crank k;
    k.L2 = 70.0;
    k.rho2 = 2.0;
    k.beta = -std::acos((70.0 * 70.0 + 60.0 * 60.0 - 29.0 * 29.0) / (2 * 70.0 * 60.0));
    const FollowerModel first = FollowerModel::build(test::disc(k.d.c, k.d.R), k.spec()).value();
    const Diagnostics problems = conjugateProblems(first, *SecondRoller::of(k.spec()));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.front().location, "follower.conjugate_angle_deg");
    EXPECT_EQ(problems.front().code, DiagnosticCode::ConjugatePlateNotRoundCentre);
}

TEST(ConjugateBellCrank, ANegativeMomentIsCarriedByTheSecondArmsRoller) {
    // The crank driven by its inertia alone: the moment I·ψ''·ω² turns negative where ψ'' does,
    // and the second roller then takes |M| / (L₂·cos α₂) — ψ and α₂ from the closed form.
    const Crank k;
    const double inertia = 2e-3, omega = 15.0;
    Project p;
    p.motion = {SpeedUnit::OmegaRadS, omega};
    p.contour.push_back(SegmentSpec{Arc{k.d.c, k.d.R, Branch::Outer}, 0.0, 360.0});
    p.follower = k.spec();
    DynamicsSpec dyn;
    dyn[DynamicsKey::InertiaKgM2] = inertia;
    p.dynamics = dyn;
    const ProjectEvaluation e = evaluateProject(p);
    ASSERT_EQ(e.status, EvaluationStatus::Computed)
        << (e.problems.empty() ? "" : e.problems.front().text());
    ForceEvaluation forces;
    ASSERT_TRUE(evaluateForces(p, *e.follower, e.omega, forces));
    const auto psi = [&](double phi) {
        const Eigen::Vector2d arm = k.first(phi) - k.pivot(phi);
        return std::remainder(std::atan2(arm.y(), arm.x()) - phi, kTwoPi);
    };
    const double h = 1e-3;
    const auto psi2 = [&](double phi) {
        return (-psi(phi - 2 * h) + 16 * psi(phi - h) - 30 * psi(phi) + 16 * psi(phi + h) -
                psi(phi + 2 * h)) /
               (12 * h * h);
    };
    double peak = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const double phi = kTwoPi * i / 100000;
        const double moment = inertia * psi2(phi) * omega * omega;
        if (moment >= 0) continue;
        const double g = 1e-5;
        const Eigen::Vector2d t = (k.second(phi + g) - k.second(phi - g)).normalized();
        const Eigen::Vector2d normal(t.y(), -t.x()), arm = k.second(phi) - k.pivot(phi);
        const Eigen::Vector2d leaving = -Eigen::Vector2d(-arm.y(), arm.x()).normalized();
        peak = std::max(peak, -moment / (k.L2 * 1e-3 * leaving.dot(normal)));
    }
    ASSERT_GT(peak, 0.0);
    ASSERT_TRUE(forces.summary.maxNormalSecond);
    EXPECT_NEAR(*forces.summary.maxNormalSecond, peak, 1e-6 * peak);
    EXPECT_FALSE(forces.summary.liftOff.empty());
}

}  // namespace
}  // namespace cam
