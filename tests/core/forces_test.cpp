// The forces of math.md §9 (forces/forces.h) against references written here:
// - the eccentric disc (a circle of R 30 about (5, 0), roller 8, radial): its pitch curve is the
//   circle of 38 about (5, 0), so s = 5 cos φ + √(38² − 25 sin² φ) with s' and s'' by hand;
//   the load, normal force, torque and Hertz stress from those in the textbook's arrangement
//   p = √(F_n (1/R1 + 1/R2) / (π b ((1 − ν1²)/E1 + (1 − ν2²)/E2))), and math.md's printed
//   values;
// - the jump speed by sweeping the speed until the load turns negative somewhere, no roots;
// - the least preload by its definition: with it the margin is never below 0 and touches 0;
// - the textbook exercise of math.md §9 (cycloidal rise, 1000 rpm) on its motion law;
// - a flat face on the same disc: its position is the circle's support function 30 + 5 cos φ,
//   α = 0, the torque by the power balance, Hertz with R' = 30 and two materials;
// - a roller on a swinging arm on the same disc: the arm's angle by the circle–circle
//   intersection, its derivatives by 7-point central differences, the moment of §9, the
//   normal force from the moment about the pivot, the torque by the power balance.

#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "contour/contour.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "forces/forces.h"
#include "io/project_json.h"
#include "project/dynamics.h"
#include "steel_dynamics.h"

namespace cam {
namespace {

constexpr double kRpm = 300.0;
constexpr double kOmega = kRpm * kTwoPi / 60.0;

/// s, s', s'' (mm, per rad) of the roller's centre on the eccentric disc.
std::array<double, 3> discLift(double phi) {
    const double sn = std::sin(phi), cs = std::cos(phi);
    const double d = std::sqrt(38.0 * 38.0 - 25.0 * sn * sn);
    return {5.0 * cs + d, -5.0 * sn - 25.0 * sn * cs / d,
            -5.0 * cs - 25.0 * std::cos(2.0 * phi) / d - 625.0 * sn * sn * cs * cs / (d * d * d)};
}

Project discProject() {
    Project p;
    p.motion = {SpeedUnit::Rpm, kRpm};
    SegmentSpec s;
    s.shape = Arc{Eigen::Vector2d(5.0, 0.0), 30.0, Branch::Outer};
    s.phiStartDeg = 0.0;
    s.phiEndDeg = 360.0;
    p.contour = {s};
    FollowerSpec f;
    f.type = FollowerType::Roller;
    f.radius = 8.0;
    p.follower = f;
    p.dynamics = test::steelOnSteelDynamics();
    return p;
}

/// The disc's dynamics for a swinging arm: the translating follower's keys out, the arm's in
/// (I = 0.002 kg·m², kt = 5 N·m/rad, M0 = 1.5 N·m, the damping ct and the external moment).
DynamicsSpec armDynamics(DynamicsSpec d, double damping, double externalMoment) {
    using K = DynamicsKey;
    for (K key :
         {K::MassKg, K::SpringRateNPerMm, K::SpringPreloadN, K::ExternalForceN, K::DampingNsPerM}) {
        d[key].reset();
    }
    d[K::InertiaKgM2] = 0.002;
    d[K::SpringRateNmPerRad] = 5.0;
    d[K::SpringPreloadNm] = 1.5;
    d[K::ExternalMomentNm] = externalMoment;
    d[K::DampingNmsPerRad] = damping;
    return d;
}

struct Disc {
    Project project = discProject();
    Contour contour = Contour::build(project).value();
    FollowerModel follower = FollowerModel::build(contour, *project.follower).value();
    ForceModel model = ForceModel::of(*project.dynamics, *project.follower);
};

/// The load by math.md §9 from the closed form (N), at speed w (rad/s).
double discLoad(double phi, double w, double preload = 20.0) {
    const auto [s, s1, s2] = discLift(phi);
    return 0.5 * s2 * 1e-3 * w * w + 10.0 * s1 * 1e-3 * w + 2000.0 * (s - 33.0) * 1e-3 + preload +
           5.0;
}

TEST(Forces, TheEccentricDiscAt17DegreesIsTheClosedForm) {
    Disc disc;
    const double phi = degToRad(17.0);
    const ForcePoint f =
        forceAt(disc.model, forceMotion(disc.follower, disc.follower.at(phi, kOmega)), kOmega);
    const auto [s, s1, s2] = discLift(phi);
    const double load = discLoad(phi, kOmega);
    const double alpha = std::atan(s1 / s);  // radial: tan α = s'/s
    const double normal = load / std::cos(alpha);
    EXPECT_NEAR(f.load, load, 1e-9);
    EXPECT_NEAR(f.normal, normal, 1e-9);
    EXPECT_NEAR(f.lateral, normal * std::sin(alpha), 1e-9);
    EXPECT_NEAR(f.torque, load * s1 * 1e-3, 1e-12);
    EXPECT_NEAR(f.power, load * s1 * 1e-3 * kOmega, 1e-10);
    const double soft = 2.0 * (1.0 - 0.09) / 210000.0;  // (1 − ν1²)/E1 + (1 − ν2²)/E2
    const double stress = std::sqrt(normal * (1.0 / 30.0 + 1.0 / 8.0) / (kPi * 12.0 * soft));
    EXPECT_NEAR(f.stress, stress, 1e-9);
    const double radius = 1.0 / (1.0 / 30.0 + 1.0 / 8.0);
    EXPECT_NEAR(f.halfWidth, std::sqrt(4.0 * normal * radius * soft / (kPi * 12.0)), 1e-12);
    EXPECT_NEAR(f.shear, 0.30 * stress, 1e-9);
    // math.md §9's printed values.
    EXPECT_NEAR(f.load, 41.36032, 5e-6);
    EXPECT_NEAR(f.normal, 41.39096, 5e-6);
    EXPECT_NEAR(f.torque, -0.0680766, 5e-8);
    EXPECT_NEAR(f.stress, 141.6274, 5e-5);
}

/// The speed (rad/s) above which the load on the disc turns negative somewhere, by sweeping
/// the speed: the smallest load over 20,000 angles, in steps of 1 rpm, then bisection.
double sweptJumpSpeed() {
    const auto smallestLoad = [](double w) {
        double least = 1e300;
        for (int i = 0; i < 20000; ++i) least = std::min(least, discLoad(kTwoPi * i / 20000, w));
        // Around the smallest, finer: the minimum is a smooth valley.
        return least;
    };
    double lo = 0.0, hi = 0.0;
    for (double rpm = 1.0;; rpm += 1.0) {
        if (smallestLoad(rpm * kTwoPi / 60.0) < 0.0) {
            hi = rpm * kTwoPi / 60.0;
            lo = hi - kTwoPi / 60.0;
            break;
        }
    }
    while (hi - lo > 1e-9) {
        const double mid = 0.5 * (lo + hi);
        (smallestLoad(mid) < 0.0 ? hi : lo) = mid;
    }
    return hi;
}

TEST(Forces, TheJumpSpeedIsWhereASweptSpeedFirstLiftsTheRoller) {
    Disc disc;
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(disc.follower, kOmega, 3600, turn));
    ForceTurn forces;
    forcesOfTurn(disc.model, disc.follower, turn, kOmega, forces);
    const ForceSummary s = summarizeForces(disc.model, disc.follower, turn, forces, kOmega);
    // The sweep samples 20,000 angles: its valley bottom is within a few 1e-4 rpm of the
    // refined one. (math.md prints 1197.46 rpm: the smallest over whole degrees, at 8°; the
    // valley's bottom is at 8.34°, 1197.4486 rpm.)
    const double swept = sweptJumpSpeed() * 60.0 / kTwoPi;
    EXPECT_NEAR(s.jumpSpeed * 60.0 / kTwoPi, swept, 2e-3);
    EXPECT_NEAR(s.jumpSpeed * 60.0 / kTwoPi, 1197.4486, 1e-3);
    EXPECT_NEAR(radToDeg(s.jumpSpeedAt), 8.34, 0.01);
    // At 300 rpm the spring holds it everywhere.
    EXPECT_TRUE(s.liftOff.empty());
    // The peaks against the closed form on a dense grid.
    double maxNormal = 0.0, peakTorque = 0.0, squares = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double phi = kTwoPi * i / n;
        const auto [sv, s1, s2] = discLift(phi);
        const double load = discLoad(phi, kOmega);
        maxNormal = std::max(maxNormal, load / std::cos(std::atan(s1 / sv)));
        const double torque = load * s1 * 1e-3;
        if (std::abs(torque) > std::abs(peakTorque)) peakTorque = torque;
        squares += torque * torque;
    }
    EXPECT_NEAR(s.maxNormal, maxNormal, 1e-6);
    EXPECT_NEAR(s.peakTorque, peakTorque, 1e-8);
    EXPECT_NEAR(s.peakPower, peakTorque * kOmega, 1e-6);
    EXPECT_NEAR(s.rmsTorque, std::sqrt(squares / n), 1e-6);  // a periodic mean: 3600 suffice
}

TEST(Forces, TheLeastPreloadJustKeepsTheMarginAtZero) {
    Disc disc;
    // A faster cam, and a safety factor: the spring must hold 1.5 times the pull.
    const double w = 1500.0 * kTwoPi / 60.0;
    disc.project.dynamics->values[static_cast<std::size_t>(DynamicsKey::SpringSafetyFactor)] = 1.5;
    disc.model = ForceModel::of(*disc.project.dynamics, *disc.project.follower);
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(disc.follower, w, 3600, turn));
    ForceTurn forces;
    forcesOfTurn(disc.model, disc.follower, turn, w, forces);
    const ForceSummary s = summarizeForces(disc.model, disc.follower, turn, forces, w);
    // The definition: k·lift + F0 + Fe ≥ n·(−m·s̈ − c·ṡ) everywhere, with equality somewhere.
    const auto margin = [&](double preload) {
        double least = 1e300;
        for (int i = 0; i < 200000; ++i) {
            const double phi = kTwoPi * i / 200000;
            const auto [sv, s1, s2] = discLift(phi);
            const double pull = -0.5 * s2 * 1e-3 * w * w - 10.0 * s1 * 1e-3 * w;
            least = std::min(least, 2000.0 * (sv - 33.0) * 1e-3 + preload + 5.0 - 1.5 * pull);
        }
        return least;
    };
    EXPECT_GT(s.minPreload, 20.0);  // the project's 20 N is not enough at this speed
    EXPECT_NEAR(margin(s.minPreload), 0.0, 1e-6);
    EXPECT_LT(margin(s.minPreload - 1e-3), 0.0);
    // And at this speed without that preload the roller leaves the cam near the top.
    ASSERT_FALSE(s.liftOff.empty());
    for (const auto& [from, to] : s.liftOff) {
        for (double phi = from; phi <= to; phi += 1e-3) EXPECT_LT(discLoad(phi, w), 1e-6);
        // Its ends are where the closed form's load crosses 0.
        EXPECT_LT(discLoad(from, w), 0.0);
        EXPECT_GE(discLoad(from - 1e-9, w), 0.0);
        EXPECT_LT(discLoad(to, w), 0.0);
        EXPECT_GE(discLoad(to + 1e-9, w), 0.0);
    }
}

TEST(Forces, TheTextbookFollowerLeavesTheCamAt100Degrees) {
    // math.md §9: a cycloidal rise of 10 mm over 120°, 1000 rpm, 1.8 kg, 15 N/mm with 2.5 mm
    // initial compression (37.5 N). At 100° of the rise the inertia pulls harder than the
    // spring pushes: −61.69 N.
    DesignSpec spec;
    spec.baseRadius = 40.0;
    spec.segments = {{MotionLawType::Cycloidal, 120.0, 10.0},
                     {MotionLawType::Dwell, 180.0, 10.0},
                     {MotionLawType::Cycloidal, 300.0, 0.0},
                     {MotionLawType::Dwell, 360.0, 0.0}};
    const MotionDesign design = MotionDesign::build(spec).value();
    DynamicsSpec d;
    d[DynamicsKey::MassKg] = 1.8;
    d[DynamicsKey::SpringRateNPerMm] = 15.0;
    d[DynamicsKey::SpringPreloadN] = 15.0 * 2.5;
    const ForceModel model = ForceModel::of(d, FollowerSpec{});
    const double omega = 1000.0 * kTwoPi / 60.0;
    const auto lift = design.liftAt(degToRad(100.0));  // mm, per rad
    ForceMotion motion;
    motion.lift = {lift[0] * 1e-3, lift[1] * 1e-3, lift[2] * 1e-3};
    // The cycloid by hand: s = h(x − sin 2πx / 2π), s̈ = 2πh ω² sin(2πx) / β².
    const double x = 100.0 / 120.0, beta = degToRad(120.0);
    EXPECT_NEAR(lift[0], 10.0 * (x - std::sin(kTwoPi * x) / kTwoPi), 1e-12);
    EXPECT_NEAR(lift[0], 9.7117, 5e-5);
    const double accel = kTwoPi * 0.010 * omega * omega * std::sin(kTwoPi * x) / (beta * beta);
    EXPECT_NEAR(accel, -136.035, 5e-4);
    const ForcePoint f = forceAt(model, motion, omega);
    EXPECT_NEAR(f.load, 1.8 * accel + 15000.0 * lift[0] * 1e-3 + 37.5, 1e-9);
    EXPECT_NEAR(f.load, -61.69, 5e-3);
    EXPECT_TRUE(std::isnan(f.stress));  // a knife edge has no contact stress
    EXPECT_EQ(jumpSpeedAt(model, motion, omega) < omega, true);
    // The same from the design and its exact profile (the forces of the law itself): a radial
    // knife on a base circle of 40 mm, tan α = s' / (Rb + s).
    const ExactProfile profile = ExactProfile::build(design, FollowerSpec{}).value();
    const ForceMotion law = designForceMotion(design, profile, degToRad(100.0), false);
    const ForcePoint g = forceAt(model, law, omega);
    EXPECT_NEAR(g.load, f.load, 1e-12);
    const double alpha = std::atan(lift[1] / (40.0 + lift[0]));
    EXPECT_NEAR(law.pressureAngle, alpha, 1e-12);
    EXPECT_NEAR(g.normal, g.load / std::cos(alpha), 1e-9);
    EXPECT_NEAR(g.torque, g.load * lift[1] * 1e-3, 1e-12);
}

TEST(Forces, JumpSpeedRootsCoverEveryCase) {
    ForceModel m;
    m.mass = 1.0;
    m.rate = 0.0;
    m.damping = 0.0;
    ForceMotion motion;
    // No pull anywhere (s'' ≥ 0) and a positive load: no speed lifts it.
    m.preload = 10.0;
    motion.lift = {0.0, 0.0, 0.5};
    EXPECT_EQ(jumpSpeedAt(m, motion, 1.0), std::numeric_limits<double>::infinity());
    // s'' < 0 without damping: W = √(F0 / (m·|s''|)).
    motion.lift = {0.0, 0.0, -0.5};
    EXPECT_NEAR(jumpSpeedAt(m, motion, 1.0), std::sqrt(10.0 / 0.5), 1e-12);
    // Pulled off at rest already.
    m.preload = -1.0;
    EXPECT_EQ(jumpSpeedAt(m, motion, 1.0), 0.0);
    // Damping alone against a falling follower (s' < 0, ω > 0): W = F0 / (c·|s'|).
    m.preload = 10.0;
    m.damping = 4.0;
    motion.lift = {0.0, -0.5, 0.0};
    EXPECT_NEAR(jumpSpeedAt(m, motion, 1.0), 5.0, 1e-12);
    // Turning the other way the damping pushes: no lift-off.
    EXPECT_EQ(jumpSpeedAt(m, motion, -1.0), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// Every sample of the batch path against forceAt on the follower placed at that angle.
void expectBatchIsForceAt(const FollowerModel& follower, const ForceModel& model, double omega) {
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(follower, omega, 720, turn));
    ForceTurn forces;
    forcesOfTurn(model, follower, turn, omega, forces);
    ASSERT_EQ(forces.size(), 720U);
    const auto close = [](double a, double b) {
        if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
        return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
    };
    for (std::size_t k = 0; k < forces.size(); ++k) {
        const double phi = omega / std::abs(omega) * kTwoPi * static_cast<double>(k) / 720.0;
        const ForcePoint f = forces.point(k, model, turn, omega);
        const ForcePoint g = forceAt(model, forceMotion(follower, follower.at(phi, omega)), omega);
        EXPECT_PRED2(close, f.load, g.load) << k;
        EXPECT_PRED2(close, f.normal, g.normal) << k;
        EXPECT_PRED2(close, f.lateral, g.lateral) << k;
        EXPECT_PRED2(close, f.torque, g.torque) << k;
        EXPECT_PRED2(close, f.power, g.power) << k;
        EXPECT_PRED2(close, f.stress, g.stress) << k;
        EXPECT_PRED2(close, f.halfWidth, g.halfWidth) << k;
        EXPECT_PRED2(close, f.shear, g.shear) << k;
    }
}

TEST(Forces, TheBatchPathIsForceAtOnALineAndOnAnArm) {
    Disc disc;
    expectBatchIsForceAt(disc.follower, disc.model, kOmega);
    expectBatchIsForceAt(disc.follower, disc.model, -kOmega);  // turning clockwise
    // The same disc under a roller on a swinging arm, with its arm's keys.
    FollowerSpec arm = *disc.project.follower;
    arm.motion = FollowerMotion::Oscillating;
    arm.pivot = Eigen::Vector2d(90.0, 0.0);
    arm.armLength = 70.0;
    const FollowerModel swinging = FollowerModel::build(disc.contour, arm).value();
    const DynamicsSpec d = armDynamics(*disc.project.dynamics, 0.01, 0.0);
    const ForceModel model = ForceModel::of(d, arm);
    ASSERT_TRUE(model.swinging);
    expectBatchIsForceAt(swinging, model, kOmega);
    // The arm's moment by hand at one angle: M = I·λ̈ + ct·λ̇ + kt·λ + M0, λ in rad.
    const FollowerState st = swinging.at(1.0, kOmega);
    const auto l = swinging.liftPhi(st);  // degrees, per rad
    const double rad = kPi / 180.0;
    const double moment =
        0.002 * l[2] * rad * kOmega * kOmega + 0.01 * l[1] * rad * kOmega + 5.0 * l[0] * rad + 1.5;
    const ForcePoint f = forceAt(model, forceMotion(swinging, st), kOmega);
    EXPECT_NEAR(f.load, moment, 1e-12);
    EXPECT_NEAR(f.normal, moment / (0.070 * std::cos(st.pressureAngle)), 1e-9);
    EXPECT_TRUE(std::isnan(f.lateral));
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(Forces, AnArcTablesJointsMakeTheForceJumpAndBothSidesAreReported) {
    // The bundled synthesised roller cam: tangent arcs, so s'' (and the inertia force) jumps
    // at every joint the roller passes. Each reported side must be the limit of the load from
    // that side: extrapolated here from four angles 1e-4 rad apart on each side.
    auto project =
        loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/synthesised-cycloidal-roller.cam.json");
    ASSERT_TRUE(project.ok());
    const Contour contour = Contour::build(project.value()).value();
    const FollowerModel follower = FollowerModel::build(contour, *project.value().follower).value();
    DynamicsSpec d;
    d[DynamicsKey::MassKg] = 1.2;
    d[DynamicsKey::SpringRateNPerMm] = 5.0;
    d[DynamicsKey::SpringPreloadN] = 30.0;
    const ForceModel model = ForceModel::of(d, *project.value().follower);
    const double omega = project.value().motion.omegaRadS();
    FollowerTurn turn;
    ASSERT_TRUE(sampleFollowerTurn(follower, omega, 3600, turn));
    ForceTurn forces;
    forcesOfTurn(model, follower, turn, omega, forces);
    const ForceSummary s = summarizeForces(model, follower, turn, forces, omega);
    ASSERT_GT(s.jumps.size(), 10U);
    const double h = 1e-4;
    const auto load = [&](double phi) {
        return forceAt(model, forceMotion(follower, follower.at(phi, omega)), omega).load;
    };
    // Cubic extrapolation to x = 0 from x = −h, −2h, −3h, −4h: 4f(−h) − 6f(−2h) + 4f(−3h) − f(−4h).
    const auto fromLeft = [&](double phi) {
        return 4.0 * load(phi - h) - 6.0 * load(phi - 2 * h) + 4.0 * load(phi - 3 * h) -
               load(phi - 4 * h);
    };
    const auto fromRight = [&](double phi) {
        return 4.0 * load(phi + h) - 6.0 * load(phi + 2 * h) + 4.0 * load(phi + 3 * h) -
               load(phi + 4 * h);
    };
    double biggest = 0.0;
    for (const ForceJump& j : s.jumps) {
        const double scale = std::max(1.0, std::abs(j.before.load));
        EXPECT_NEAR(j.before.load, fromLeft(j.phi), 1e-6 * scale) << radToDeg(j.phi);
        EXPECT_NEAR(j.after.load, fromRight(j.phi), 1e-6 * scale) << radToDeg(j.phi);
        biggest = std::max(biggest, std::abs(j.after.load - j.before.load));
        EXPECT_GE(s.maxNormal, std::max(j.before.normal, j.after.normal));
    }
    EXPECT_GT(biggest, 1e-3);  // a real jump, not rounding
}

TEST(Forces, AFlatFaceOnTheEccentricDiscIsItsSupportFunction) {
    // Reference: the face's position is the support function of the circle of R 30 about
    // (5, 0) in the direction u = (cos φ, sin φ) of its line, h = 30 + 5 cos φ, so by hand
    // λ = h − min h = 5 (1 + cos φ), λ' = −5 sin φ, λ'' = −5 cos φ (mm); the load of math.md
    // §9 from them; α = 0, so F_n = F; the torque from the power balance T·ω = F·λ̇; the Hertz
    // stress of a flat on the circle (R' = R) as p = √(F_n / (π b R (1/E*))) with two different
    // materials. Nothing of the model's placement (support pieces) or of forceAt is used.
    Disc disc;
    FollowerSpec flat;
    flat.type = FollowerType::Flat;
    const FollowerModel follower = FollowerModel::build(disc.contour, flat).value();
    DynamicsSpec d = *disc.project.dynamics;
    d[DynamicsKey::FollowerModulusMpa] = 120000.0;  // a cast-iron face on the steel disc
    d[DynamicsKey::FollowerPoisson] = 0.25;
    const ForceModel model = ForceModel::of(d, flat);
    const double soft = (1.0 - 0.3 * 0.3) / 210000.0 + (1.0 - 0.25 * 0.25) / 120000.0;  // 1/E*
    EXPECT_NEAR(follower.minS(), 25.0, 1e-12);
    // Exact but for rounding: a few ulps of the largest term (about 40 N).
    const auto near = [](double value, double expected) {
        return std::abs(value - expected) <= 1e-12 * std::max(1.0, std::abs(expected));
    };
    for (const double w : {kOmega, -kOmega}) {
        for (const double deg : {17.0, 100.0, 250.0}) {
            const double phi = degToRad(deg), cs = std::cos(phi), sn = std::sin(phi);
            const FollowerState st = follower.at(phi, w);
            // The convention first: the face is at h along u and touches the circle at C + R·u.
            EXPECT_NEAR(st.s, 30.0 + 5.0 * cs, 1e-12) << deg;
            EXPECT_NEAR((st.contact - Eigen::Vector2d(5.0 + 30.0 * cs, 30.0 * sn)).norm(), 0.0,
                        1e-12)
                << deg;
            const double lift = 5.0e-3 * (1.0 + cs), lift1 = -5.0e-3 * sn, lift2 = -5.0e-3 * cs;
            const double load = 0.5 * w * w * lift2 + 10.0 * w * lift1 + 2000.0 * lift + 25.0;
            const double torque = load * lift1;
            const double stress = std::sqrt(load / (kPi * 12.0 * 30.0 * soft));
            const ForcePoint f = forceAt(model, forceMotion(follower, st), w);
            EXPECT_PRED2(near, f.load, load) << deg << ' ' << w;
            EXPECT_PRED2(near, f.normal, load) << deg << ' ' << w;
            EXPECT_PRED2(near, f.lateral, 0.0) << deg << ' ' << w;
            EXPECT_PRED2(near, f.torque, torque) << deg << ' ' << w;
            EXPECT_PRED2(near, f.power, torque * w) << deg << ' ' << w;
            EXPECT_PRED2(near, f.stress, stress) << deg << ' ' << w;
            EXPECT_PRED2(near, f.halfWidth, std::sqrt(4.0 * 30.0 * load * soft / (12.0 * kPi)))
                << deg << ' ' << w;
            EXPECT_PRED2(near, f.shear, 0.30 * stress) << deg << ' ' << w;
        }
    }
}

/// A roller of 8 on an arm of 70 about the pivot (80, 40) (follower frame) on the eccentric
/// disc, in closed form: with the pivot turned by φ, P = 89.44·(cos(φ + φ0), sin(φ + φ0)), the
/// centre X = P + L·(cos Θ, sin Θ) on the pitch circle |X − C| = 38 about C = (5, 0); with
/// D = P − C, D·(cos Θ, sin Θ) = (38² − |D|² − L²) / (2L) = K, so Θ = δ ∓ acos(K / |D|), δ the
/// direction of D. Between the two roots the arm's circle is inside the pitch circle; the
/// contact is the root past which swinging away (ψ growing for "ccw", σ = +1; falling for "cw")
/// leaves it: Θ = δ − σ·acos(K / |D|). θ = σ·(Θ − φ − β), β the direction pivot → cam centre.
struct EccentricArm {
    Eigen::Vector2d pivot, centre;
    double theta = 0.0;  ///< rad, growing away from the cam
};

constexpr double kArmLength = 70.0;
constexpr double kArmPivotX = 80.0, kArmPivotY = 40.0;

EccentricArm eccentricArm(double phi, double sigma) {
    const double cs = std::cos(phi), sn = std::sin(phi);
    EccentricArm a;
    a.pivot = Eigen::Vector2d(cs * kArmPivotX - sn * kArmPivotY, sn * kArmPivotX + cs * kArmPivotY);
    const Eigen::Vector2d D = a.pivot - Eigen::Vector2d(5.0, 0.0);
    const double K = (38.0 * 38.0 - D.squaredNorm() - kArmLength * kArmLength) / (2.0 * kArmLength);
    const double big = std::atan2(D.y(), D.x()) - sigma * std::acos(K / D.norm());
    a.centre = a.pivot + kArmLength * Eigen::Vector2d(std::cos(big), std::sin(big));
    const double beta = std::atan2(-kArmPivotY, -kArmPivotX);
    a.theta = std::remainder(sigma * (big - phi - beta), kTwoPi);
    return a;
}

TEST(Forces, ARollerOnASwingingArmOnTheEccentricDiscIsTheClosedForm) {
    // Reference: the arm's angle θ(φ) of eccentricArm (circle–circle, no jets), λ = θ − min θ
    // (the smallest by golden sections on the closed form), λ' and λ'' by 7-point central
    // differences of θ with h = 0.01 (truncation h⁶·θ⁽⁷⁾/140 and h⁶·θ⁽⁸⁾/560, below 1e-13 here;
    // rounding a few 1e-15/h², up to 3e-11 in λ'': hence 1e-9 on λ'' and 1e-8 relative on the
    // forces, which a 1e-6 error in λ'' already fails); the moment of math.md §9, the torque from
    // the power balance T·ω = M·λ̇, the normal force from the moment about the pivot, N = M / |(X −
    // P) × n| with n = (X − C)/|X − C| (no pressure angle), the stress with 1/R' = 1/30 + 1/8. Both
    // arm sides and both turning directions.
    Disc disc;
    const DynamicsSpec d = armDynamics(*disc.project.dynamics, 0.05, 0.3);
    const double soft = 2.0 * (1.0 - 0.09) / 210000.0;  // 1/E*
    const double h = 0.01;
    for (const ArmSide side : {ArmSide::Ccw, ArmSide::Cw}) {
        FollowerSpec spec = *disc.project.follower;  // the roller of 8
        spec.motion = FollowerMotion::Oscillating;
        spec.pivot = Eigen::Vector2d(kArmPivotX, kArmPivotY);
        spec.armLength = kArmLength;
        spec.arm = side;
        const double sigma = side == ArmSide::Ccw ? 1.0 : -1.0;
        const FollowerModel follower = FollowerModel::build(disc.contour, spec).value();
        const ForceModel model = ForceModel::of(d, spec);
        const auto theta = [&](double phi) { return eccentricArm(phi, sigma).theta; };
        // The smallest θ: the best of 3600 samples, then golden sections round it.
        double at = 0.0;
        for (int i = 1; i < 3600; ++i) {
            if (theta(kTwoPi * i / 3600) < theta(at)) at = kTwoPi * i / 3600;
        }
        double lo = at - kTwoPi / 3600, hi = at + kTwoPi / 3600;
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        while (hi - lo > 1e-12) {
            const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            if (theta(x1) < theta(x2)) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        const double least = theta(0.5 * (lo + hi));
        for (const double w : {kOmega, -kOmega}) {
            for (const double deg : {17.0, 100.0, 250.0}) {
                const double phi = degToRad(deg);
                const EccentricArm arm = eccentricArm(phi, sigma);
                const FollowerState st = follower.at(phi, w);
                // The branch: the model's roller centre is the closed form's.
                EXPECT_NEAR((st.center - arm.centre).norm(), 0.0, 1e-9) << deg;
                const auto t = [&](int k) { return theta(phi + k * h); };
                const double lift = arm.theta - least;
                const double lift1 =
                    (-t(-3) + 9.0 * t(-2) - 45.0 * t(-1) + 45.0 * t(1) - 9.0 * t(2) + t(3)) /
                    (60.0 * h);
                const double lift2 = (2.0 * t(-3) - 27.0 * t(-2) + 270.0 * t(-1) - 490.0 * t(0) +
                                      270.0 * t(1) - 27.0 * t(2) + 2.0 * t(3)) /
                                     (180.0 * h * h);
                const ForceMotion motion = forceMotion(follower, st);
                EXPECT_NEAR(motion.lift[0], lift, 1e-12) << deg;
                EXPECT_NEAR(motion.lift[1], lift1, 1e-11) << deg;
                EXPECT_NEAR(motion.lift[2], lift2, 1e-9) << deg;
                const double moment =
                    0.002 * w * w * lift2 + 0.05 * w * lift1 + 5.0 * lift + 1.5 + 0.3;  // N·m
                const Eigen::Vector2d n = (arm.centre - Eigen::Vector2d(5.0, 0.0)).normalized();
                const Eigen::Vector2d lever = (arm.centre - arm.pivot) * 1e-3;  // m
                const double normal = moment / std::abs(lever.x() * n.y() - lever.y() * n.x());
                const double stress =
                    std::sqrt(normal * (1.0 / 30.0 + 1.0 / 8.0) / (kPi * 12.0 * soft));
                const ForcePoint f = forceAt(model, motion, w);
                EXPECT_NEAR(f.load, moment, 1e-8 * std::abs(moment)) << deg << ' ' << w;
                EXPECT_NEAR(f.normal, normal, 1e-8 * normal) << deg << ' ' << w;
                EXPECT_TRUE(std::isnan(f.lateral));
                EXPECT_NEAR(f.torque, moment * lift1, 1e-8 * std::abs(moment * lift1))
                    << deg << ' ' << w;
                EXPECT_NEAR(f.power, moment * lift1 * w, 1e-8 * std::abs(moment * lift1 * w))
                    << deg << ' ' << w;
                EXPECT_NEAR(f.stress, stress, 1e-8 * stress) << deg << ' ' << w;
            }
        }
    }
}

}  // namespace
}  // namespace cam
