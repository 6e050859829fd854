#include "forces/forces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/golden_section.h"
#include "common/simd.h"
#include "project/dynamics.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The contact's 1/R' (1/mm): the profile's curvature at the contact plus the follower's; on a
/// groove's outer flank (radius ρ_profile + 2ρ + c, signed as the profile's) the follower's
/// less the flank's, which wraps round the roller where it is convex.
double contactCurvature(const ForceModel& m, double rhoProfile, bool outer) {
    if (!outer) return (std::abs(rhoProfile) < kInf ? 1.0 / rhoProfile : 0.0) + m.followerCurvature;
    const double rho = rhoProfile + m.grooveWidthMm;
    return m.followerCurvature - (std::abs(rho) < kInf ? 1.0 / rho : 0.0);
}

/// The second roller's contact on a conjugate pair's second plate: 1/ρ_plate + 1/ρ₂.
double secondCurvature(const ForceModel& m, double rhoPlate) {
    return (std::abs(rhoPlate) < kInf ? 1.0 / rhoPlate : 0.0) + m.secondFollowerCurvature;
}

}  // namespace

ForceModel ForceModel::of(const DynamicsSpec& d, const FollowerSpec& follower) {
    using K = DynamicsKey;
    ForceModel m;
    m.swinging = follower.motion == FollowerMotion::Oscillating;
    if (m.swinging) {
        m.mass = dynamicsValue(d, K::InertiaKgM2);
        m.rate = dynamicsValue(d, K::SpringRateNmPerRad);
        m.preload = dynamicsValue(d, K::SpringPreloadNm);
        m.external = dynamicsValue(d, K::ExternalMomentNm);
        m.damping = dynamicsValue(d, K::DampingNmsPerRad);
        m.armLength = follower.armLength * 1e-3;
    } else {
        m.mass = dynamicsValue(d, K::MassKg);
        m.rate = dynamicsValue(d, K::SpringRateNPerMm) * 1e3;
        m.preload = dynamicsValue(d, K::SpringPreloadN);
        m.external = dynamicsValue(d, K::ExternalForceN);
        m.damping = dynamicsValue(d, K::DampingNsPerM);
    }
    m.safetyFactor = dynamicsValue(d, K::SpringSafetyFactor);
    m.allowableMpa = d[K::AllowableContactStressMpa];
    const bool given = d[K::ContactWidthMm] && d[K::CamModulusMpa] && d[K::CamPoisson] &&
                       d[K::FollowerModulusMpa] && d[K::FollowerPoisson];
    if (follower.type != FollowerType::Knife && given) {
        m.hasStress = true;
        m.widthMm = *d[K::ContactWidthMm];
        const double nu1 = *d[K::CamPoisson], nu2 = *d[K::FollowerPoisson];
        m.modulusMpa = 1.0 / ((1.0 - nu1 * nu1) / *d[K::CamModulusMpa] +
                              (1.0 - nu2 * nu2) / *d[K::FollowerModulusMpa]);
        m.followerCurvature = followerKind(follower.type).hasRadius ? 1.0 / follower.radius : 0.0;
    }
    if (follower.grooved() && follower.type == FollowerType::Roller) {
        m.grooveWidthMm = 2.0 * follower.radius + follower.grooveClearance;
    }
    m.yoke = SecondRoller::of(follower);
    m.follower = follower;
    if (m.yoke && m.yoke->bellCrank()) m.secondLever = m.yoke->armLengthMm * 1e-3;
    if (m.yoke && m.hasStress) m.secondFollowerCurvature = 1.0 / m.yoke->rollerRadiusMm;
    return m;
}

ForcePoint forceAt(const ForceModel& m, const ForceMotion& motion, double omega) {
    const auto& [lift, d1, d2] = motion.lift;
    ForcePoint f;
    f.load = m.mass * d2 * omega * omega + m.damping * d1 * omega + m.rate * lift + m.preload +
             m.external;
    // A conjugate pair's second roller carries a negative load, at its own pressure angle.
    const bool second = m.conjugate() && f.load < 0.0 && motion.second;
    const double alpha = second ? motion.second->pressureAngle : motion.pressureAngle;
    const double cosAlpha = std::cos(alpha);
    if (m.swinging) {
        f.normal = f.load / ((second ? m.secondLever : m.armLength) * cosAlpha);
        f.lateral = kNaN;
    } else {
        f.normal = f.load / cosAlpha;
        f.lateral = f.normal * std::sin(alpha);
    }
    f.torque = f.load * d1;
    f.power = f.torque * omega;
    f.stress = f.halfWidth = f.shear = kNaN;
    if (m.hasStress && (f.normal >= 0.0 || m.grooved() || second)) {
        // 1/R' = 1/ρ_profile + 1/ρ_f (ρ_profile < 0 where the profile is concave). On a groove's
        // outer flank the roller touches it from the other side: 1/R' = 1/ρ_f − 1/ρ_outer; the
        // second roller of a conjugate pair touches its plate as the first does the first.
        const bool outer = f.normal < 0.0;
        const double curvature = second ? secondCurvature(m, motion.second->rhoPlate)
                                        : contactCurvature(m, motion.rhoProfile, outer);
        const double normal = std::abs(f.normal);
        if (curvature > 0.0) {
            f.stress = std::sqrt(normal * m.modulusMpa * curvature / (kPi * m.widthMm));
            f.halfWidth = std::sqrt(4.0 * normal / (kPi * m.widthMm * m.modulusMpa * curvature));
        } else {
            // Flat on flat (or a roller as wide as its concave arc): no Hertz line contact,
            // the load spreads over the stretch.
            f.stress = 0.0;
            f.halfWidth = kInf;
        }
        f.shear = 0.30 * f.stress;
    }
    return f;
}

ForceMotion forceMotion(const FollowerModel& follower, const FollowerState& state) {
    const std::array<double, 4> l = follower.liftPhi(state);
    const double unit = follower.oscillating() ? kPi / 180.0 : 1e-3;  // deg → rad, mm → m
    ForceMotion motion{{l[0] * unit, l[1] * unit, l[2] * unit},
                       state.pressureAngle,
                       state.rhoProfile,
                       std::nullopt};
    if (const auto yoke = SecondRoller::of(follower.spec())) {
        const ConjugatePoint p = conjugatePointOf(
            state.phi, {state.sPhi[0], state.sPhi[1], state.sPhi[2]}, follower.spec(), *yoke);
        motion.second = ForceMotion::Second{p.pressureAngle, p.rhoPlate};
    }
    return motion;
}

ForceMotion designForceMotion(const MotionDesign& design, const ExactProfile& profile, double phi,
                              bool swinging) {
    const std::array<double, 4> l = design.liftAt(phi);
    const double unit = swinging ? kPi / 180.0 : 1e-3;
    const ProfilePoint p = profile.at(phi);
    return {{l[0] * unit, l[1] * unit, l[2] * unit}, p.pressureAngle, p.rho, std::nullopt};
}

double jumpSpeedAt(const ForceModel& m, const ForceMotion& motion, double omega) {
    const double a = m.mass * motion.lift[2];
    const double b = m.damping * motion.lift[1] * (omega < 0.0 ? -1.0 : 1.0);
    const double c = m.rate * motion.lift[0] + m.preload + m.external;
    if (c < 0.0) return 0.0;
    // The load at speed W is F(W) = a·W² + b·W + c: the first W > 0 where it turns negative.
    // At most three candidates (0, and the two roots): on the stack, as this runs per sample.
    std::array<double, 3> roots{};
    std::size_t count = 0;
    if (c == 0.0) roots[count++] = 0.0;
    if (a == 0.0) {
        if (b != 0.0) roots[count++] = -c / b;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc >= 0.0) {
            const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            if (q != 0.0) {
                roots[count++] = q / a;
                roots[count++] = c / q;
            } else {
                roots[count++] = 0.0;
            }
        }
    }
    std::sort(roots.begin(), roots.begin() + static_cast<std::ptrdiff_t>(count));
    for (std::size_t i = 0; i < count; ++i) {
        const double r = roots[i];
        if (r < 0.0) continue;
        const double slope = 2.0 * a * r + b;
        if (slope < 0.0 || (slope == 0.0 && a < 0.0)) return r;
    }
    return kInf;
}

double preloadNeededAt(const ForceModel& m, const ForceMotion& motion, double omega) {
    const double pull =
        -m.mass * motion.lift[2] * omega * omega - m.damping * motion.lift[1] * omega;
    return m.safetyFactor * pull - m.rate * motion.lift[0] - m.external;
}

namespace {

/// A conjugate pair's second roller at sample k of a turn (φ_k = 2π·k/n in the turning
/// direction): from the first's s and its φ-derivatives v/ω and a/ω².
ConjugatePoint secondOfSample(const FollowerSpec& first, const SecondRoller& yoke,
                              const FollowerTurn& turn, std::size_t k, double omega) {
    const double step = (omega < 0.0 ? -kTwoPi : kTwoPi) / static_cast<double>(turn.size());
    return conjugatePointOf(step * static_cast<double>(k),
                            {turn.s[k], turn.v[k] / omega, turn.a[k] / (omega * omega)}, first,
                            yoke);
}

ForceMotion sampleMotion(const FollowerModel& follower, const FollowerTurn& turn, std::size_t k,
                         double omega) {
    const double q = turn.s[k], v = turn.v[k], a = turn.a[k];
    ForceMotion motion;
    if (follower.oscillating()) {
        const double sign = follower.awaySign();
        motion.lift = {follower.liftOf(q) * kPi / 180.0, sign * v / omega,
                       sign * a / (omega * omega)};
    } else {
        motion.lift = {follower.liftOf(q) * 1e-3, v / omega * 1e-3, a / (omega * omega) * 1e-3};
    }
    motion.pressureAngle = turn.pressureAngle[k];
    motion.rhoProfile = turn.rhoProfile[k];
    if (const auto yoke = SecondRoller::of(follower.spec())) {
        const ConjugatePoint p = secondOfSample(follower.spec(), *yoke, turn, k, omega);
        motion.second = ForceMotion::Second{p.pressureAngle, p.rhoPlate};
    }
    return motion;
}

}  // namespace

void ForceTurn::resize(std::size_t n) {
    for (auto* column : {&load, &normal, &torque, &stress}) column->resize(n);
}

ForcePoint ForceTurn::point(std::size_t k, const ForceModel& model, const FollowerTurn& turn,
                            double omega) const {
    ForcePoint f;
    f.load = load[k];
    f.normal = normal[k];
    f.torque = torque[k];
    f.power = torque[k] * omega;
    f.stress = stress[k];
    f.shear = 0.30 * stress[k];
    double alpha = turn.pressureAngle[k];
    double curvature = 0.0;
    if (model.conjugate() && normal[k] < 0.0) {
        const ConjugatePoint p = secondOfSample(model.follower, *model.yoke, turn, k, omega);
        alpha = p.pressureAngle;
        curvature = secondCurvature(model, p.rhoPlate);
    } else {
        curvature = contactCurvature(model, turn.rhoProfile[k], model.grooved() && normal[k] < 0.0);
    }
    f.lateral = model.swinging ? kNaN : normal[k] * std::sin(alpha);
    f.halfWidth = !std::isfinite(stress[k]) ? kNaN
                  : curvature > 0.0         ? 2.0 * stress[k] / (model.modulusMpa * curvature)
                                            : kInf;
    return f;
}

namespace {

/// The loads, normal forces and torques of n samples: q, q̇, q̈ the follower's coordinate and
/// its time derivatives (mm or rad), lift = sign·(q − q0)·unit, its φ-derivative sign·q̇/ω.
CAMWRIGHT_MULTIVERSION
void loadsOfTurn(const double* __restrict q, const double* __restrict qd,
                 const double* __restrict qdd, const double* __restrict alpha,
                 double* __restrict load, double* __restrict normal, double* __restrict torque,
                 std::size_t n, double m, double c, double k, double constant, double q0,
                 double sign, double unit, double lever, double omega) {
    const double su = sign * unit;
    for (std::size_t i = 0; i < n; ++i) {
        const double f = m * su * qdd[i] + c * su * qd[i] + k * su * (q[i] - q0) + constant;
        load[i] = f;
        normal[i] = f / (lever * std::cos(alpha[i]));
        torque[i] = f * su * qd[i] / omega;
    }
}

/// Hertz p_max of n samples (NaN where the follower has left the cam).
CAMWRIGHT_MULTIVERSION
void stressesOfTurn(const double* __restrict normal, const double* __restrict rhoProfile,
                    double* __restrict stress, std::size_t n, double followerCurvature,
                    double scale) {
    for (std::size_t i = 0; i < n; ++i) {
        const double rho = rhoProfile[i];
        const double curvature = (std::abs(rho) < kInf ? 1.0 / rho : 0.0) + followerCurvature;
        const double p = std::sqrt(std::max(normal[i] * curvature, 0.0) * scale);
        stress[i] = normal[i] >= 0.0 ? p : kNaN;
    }
}

/// The same in a groove: where the normal force is negative, the outer flank's (forceAt).
void grooveStressesOfTurn(const double* normal, const double* rhoProfile, double* stress,
                          std::size_t n, const ForceModel& m) {
    const double scale = m.modulusMpa / (kPi * m.widthMm);
    for (std::size_t i = 0; i < n; ++i) {
        const double curvature = contactCurvature(m, rhoProfile[i], normal[i] < 0.0);
        stress[i] = std::sqrt(std::max(std::abs(normal[i]) * curvature, 0.0) * scale);
    }
}

/// A conjugate pair's turn: where the load is negative the second roller carries it, at its
/// own pressure angle, on the second plate's curvature (forceAt); elsewhere as spring-closed.
void conjugateForcesOfTurn(const ForceModel& m, const FollowerTurn& turn, double omega,
                           ForceTurn& out) {
    const double scale = m.hasStress ? m.modulusMpa / (kPi * m.widthMm) : 0.0;
    for (std::size_t k = 0; k < turn.size(); ++k) {
        if (!(out.load[k] < 0.0)) continue;
        const ConjugatePoint p = secondOfSample(m.follower, *m.yoke, turn, k, omega);
        out.normal[k] = out.load[k] / (m.secondLever * std::cos(p.pressureAngle));
        if (m.hasStress) {
            const double curvature = secondCurvature(m, p.rhoPlate);
            out.stress[k] = std::sqrt(std::max(-out.normal[k] * curvature, 0.0) * scale);
        }
    }
}

}  // namespace

void forcesOfTurn(const ForceModel& model, const FollowerModel& follower, const FollowerTurn& turn,
                  double omega, ForceTurn& out) {
    const std::size_t n = turn.size();
    out.resize(n);
    // lift = sign·(q − q0)·unit: mm → m on a line; on an arm ψ is in rad already.
    const bool arm = follower.oscillating();
    const double sign = follower.awaySign();
    const double unit = arm ? 1.0 : 1e-3;
    // The coordinate at lift 0: liftOf(q0) = 0 (liftOf is affine in q).
    const double slope = follower.liftOf(1.0) - follower.liftOf(0.0);
    const double q0 = -follower.liftOf(0.0) / slope;
    loadsOfTurn(turn.s.data(), turn.v.data(), turn.a.data(), turn.pressureAngle.data(),
                out.load.data(), out.normal.data(), out.torque.data(), n, model.mass, model.damping,
                model.rate, model.preload + model.external, q0, sign, unit,
                arm ? model.armLength : 1.0, omega);
    if (model.hasStress && model.grooved()) {
        grooveStressesOfTurn(out.normal.data(), turn.rhoProfile.data(), out.stress.data(), n,
                             model);
    } else if (model.hasStress) {
        stressesOfTurn(out.normal.data(), turn.rhoProfile.data(), out.stress.data(), n,
                       model.followerCurvature, model.modulusMpa / (kPi * model.widthMm));
    } else {
        std::fill(out.stress.begin(), out.stress.end(), kNaN);
    }
    if (model.conjugate()) conjugateForcesOfTurn(model, turn, omega, out);
}

namespace {

/// A point's stress and (in a groove, on the outer flank) normal force into the summary's
/// extremes, at cam angle `phi`.
void takeStress(ForceSummary& s, const ForceModel& model, const ForcePoint& f, double phi) {
    const bool outer = model.formClosed() && f.normal < 0.0;
    if (outer && (!s.maxNormalSecond || -f.normal > *s.maxNormalSecond)) {
        s.maxNormalSecond = -f.normal;
        s.maxNormalSecondAt = phi;
    }
    if (!std::isfinite(f.stress)) return;
    std::optional<double>& peak = outer ? s.maxStressSecond : s.maxStress;
    std::optional<double>& at = outer ? s.maxStressSecondAt : s.maxStressAt;
    if (!peak || f.stress > *peak) {
        peak = f.stress;
        at = phi;
    }
}

}  // namespace

ForceSummary summarizeForces(const ForceModel& model, const FollowerModel& follower,
                             const FollowerTurn& turn, const ForceTurn& forces, double omega) {
    ForceSummary s;
    const std::size_t n = turn.size();
    if (n == 0 || forces.size() != n) return s;
    const double step = (omega < 0.0 ? -kTwoPi : kTwoPi) / static_cast<double>(n);
    const auto phiOf = [&](std::size_t k) { return step * static_cast<double>(k); };
    s.jumpSpeed = kInf;
    s.minPreload = -kInf;
    double torqueSquares = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const ForcePoint f = forces.point(k, model, turn, omega);
        const ForceMotion motion = sampleMotion(follower, turn, k, omega);
        if (const double w = jumpSpeedAt(model, motion, omega); w < s.jumpSpeed) {
            s.jumpSpeed = w;
            s.jumpSpeedAt = phiOf(k);
        }
        if (const double f0 = preloadNeededAt(model, motion, omega); f0 > s.minPreload) {
            s.minPreload = f0;
            s.minPreloadAt = phiOf(k);
        }
        if (k == 0 || f.normal > s.maxNormal) {
            s.maxNormal = f.normal;
            s.maxNormalAt = phiOf(k);
        }
        if (k == 0 || std::abs(f.torque) > std::abs(s.peakTorque)) {
            s.peakTorque = f.torque;
            s.peakTorqueAt = phiOf(k);
        }
        torqueSquares += f.torque * f.torque;
        takeStress(s, model, f, phiOf(k));
    }
    s.rmsTorque = std::sqrt(torqueSquares / static_cast<double>(n));
    // The joints between samples whose contact changes segment: both sides, by bisection on
    // the segment touched.
    double largest = 0.0;
    for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, std::abs(forces.load[k]));
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        if (turn.segment[k] == turn.segment[next]) continue;
        double a = phiOf(k), b = phiOf(k) + step;
        const std::int32_t left = turn.segment[k];
        for (int i = 0; i < 80 && std::abs(b - a) > 1e-12; ++i) {
            const double mid = 0.5 * (a + b);
            (static_cast<std::int32_t>(follower.at(mid, omega).segment) == left ? a : b) = mid;
        }
        const FollowerState before = follower.at(a, omega), after = follower.at(b, omega);
        ForceJump jump{0.5 * (a + b), forceAt(model, forceMotion(follower, before), omega),
                       forceAt(model, forceMotion(follower, after), omega)};
        if (!(std::abs(jump.after.load - jump.before.load) > 1e-9 * largest)) continue;
        for (const auto* side : {&before, &after}) {
            const ForceMotion motion = forceMotion(follower, *side);
            const ForcePoint f = forceAt(model, motion, omega);
            if (const double w = jumpSpeedAt(model, motion, omega); w < s.jumpSpeed) {
                s.jumpSpeed = w;
                s.jumpSpeedAt = jump.phi;
            }
            if (const double f0 = preloadNeededAt(model, motion, omega); f0 > s.minPreload) {
                s.minPreload = f0;
                s.minPreloadAt = jump.phi;
            }
            if (f.normal > s.maxNormal) {
                s.maxNormal = f.normal;
                s.maxNormalAt = jump.phi;
            }
            if (std::abs(f.torque) > std::abs(s.peakTorque)) {
                s.peakTorque = f.torque;
                s.peakTorqueAt = jump.phi;
            }
            takeStress(s, model, f, jump.phi);
        }
        s.jumps.push_back(jump);
    }
    // The extremes between samples: golden sections a step either side of the best sample, on
    // the follower placed exactly there (an arc table's joints may lie inside: the search then
    // ends at one of their sides, never on a value the turn does not take).
    const auto refineMin = [&](auto&& f, double& value, double& at) {
        const GoldenSection g = goldenSectionMin(
            [&](double phi) { return f(forceMotion(follower, follower.at(phi, omega))); },
            at - std::abs(step), at + std::abs(step),
            [](double lo, double hi, int i) { return i < 80 && hi - lo > 1e-12; });
        for (const auto& [x, fx] : {std::pair{g.x1, g.f1}, std::pair{g.x2, g.f2}}) {
            if (fx < value) {
                value = fx;
                at = x;
            }
        }
    };
    if (std::isfinite(s.jumpSpeed)) {
        refineMin([&](const ForceMotion& m) { return jumpSpeedAt(model, m, omega); }, s.jumpSpeed,
                  s.jumpSpeedAt);
    }
    const auto refineMax = [&](auto&& f, double& value, double& at) {
        double negated = -value;
        refineMin([&](const ForceMotion& m) { return -f(m); }, negated, at);
        value = -negated;
    };
    refineMax([&](const ForceMotion& m) { return preloadNeededAt(model, m, omega); }, s.minPreload,
              s.minPreloadAt);
    refineMax([&](const ForceMotion& m) { return forceAt(model, m, omega).normal; }, s.maxNormal,
              s.maxNormalAt);
    double peak = std::abs(s.peakTorque);
    const double peakAt = s.peakTorqueAt;
    refineMax([&](const ForceMotion& m) { return std::abs(forceAt(model, m, omega).torque); }, peak,
              s.peakTorqueAt);
    if (s.peakTorqueAt != peakAt) {  // found between samples (else a sample's or a joint side's)
        s.peakTorque =
            forceAt(model, forceMotion(follower, follower.at(s.peakTorqueAt, omega)), omega).torque;
    }
    s.peakPower = s.peakTorque * omega;  // P = T·ω: its peak is the torque's
    // Form-closed, each contact's own: a sample of the other one does not count.
    const auto onOuter = [&](const ForcePoint& f) { return model.formClosed() && f.normal < 0.0; };
    if (s.maxStress) {
        double stress = *s.maxStress, at = *s.maxStressAt;
        refineMax(
            [&](const ForceMotion& m) {
                const ForcePoint f = forceAt(model, m, omega);
                return std::isfinite(f.stress) && !onOuter(f) ? f.stress : -kInf;
            },
            stress, at);
        s.maxStress = stress;
        s.maxStressAt = at;
    }
    if (s.maxStressSecond) {
        double stress = *s.maxStressSecond, at = *s.maxStressSecondAt;
        refineMax(
            [&](const ForceMotion& m) {
                const ForcePoint f = forceAt(model, m, omega);
                return std::isfinite(f.stress) && onOuter(f) ? f.stress : -kInf;
            },
            stress, at);
        s.maxStressSecond = stress;
        s.maxStressSecondAt = at;
    }
    if (s.maxNormalSecond) {
        double normal = *s.maxNormalSecond, at = *s.maxNormalSecondAt;
        refineMax([&](const ForceMotion& m) { return -forceAt(model, m, omega).normal; }, normal,
                  at);
        s.maxNormalSecond = normal;
        s.maxNormalSecondAt = at;
    }
    // The runs of samples where the load is negative, a run across the turn's end as one.
    std::size_t k = 0;
    const auto lost = [&](std::size_t i) { return forces.load[i % n] < 0.0; };
    if (lost(0) && lost(n - 1)) {
        while (k < n && lost(k)) ++k;  // that run is closed at the end
    }
    const std::size_t skipped = k;
    while (k < n) {
        if (!lost(k)) {
            ++k;
            continue;
        }
        const std::size_t from = k;
        while (k < n + skipped && lost(k)) ++k;
        s.liftOff.push_back({phiOf(from), phiOf(k - 1)});
    }
    if (skipped == n) {
        s.liftOff = {{0.0, phiOf(n - 1)}};
        return s;
    }
    // Each end where the load crosses 0, bisected between the samples either side of it.
    const auto loadAt = [&](double phi) {
        return forceAt(model, forceMotion(follower, follower.at(phi, omega)), omega).load;
    };
    const auto crossing = [&](double held, double lost) {
        for (int i = 0; i < 80 && std::abs(lost - held) > 1e-12; ++i) {
            const double mid = 0.5 * (held + lost);
            (loadAt(mid) < 0.0 ? lost : held) = mid;
        }
        return lost;
    };
    for (auto& [from, to] : s.liftOff) {
        from = crossing(from - step, from);
        to = crossing(to + step, to);
    }
    return s;
}

}  // namespace cam
