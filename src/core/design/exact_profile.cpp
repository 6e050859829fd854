#include "design/exact_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "common/angles.h"
#include "follower/jet.h"
#include "geometry/planar.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

/// The design's lift at φ as a jet (per radian), in the follower's coordinate: mm, or for an
/// arm the angle swung in radians.
Jet liftJet(const MotionDesign& design, double phi, bool swinging) {
    const std::array<double, 4> l = design.liftAt(phi);
    const double unit = swinging ? kPi / 180.0 : 1.0;
    return {{l[0] * unit, l[1] * unit, l[2] * unit / 2.0, l[3] * unit / 6.0}};
}

Eigen::Vector2d value(const JetVec& v) { return {v.x.c[0], v.y.c[0]}; }
Eigen::Vector2d derivative1(const JetVec& v) { return {v.x.c[1], v.y.c[1]}; }
Eigen::Vector2d derivative2(const JetVec& v) { return {2.0 * v.x.c[2], 2.0 * v.y.c[2]}; }

}  // namespace

Result<ExactProfile> ExactProfile::build(const MotionDesign& design, const FollowerSpec& follower) {
    ExactProfile profile(design, follower);
    const double Rb = design.spec().baseRadius;
    const double rho = contactRadius(follower);
    const double Rp = Rb + rho;  // the pitch curve's base circle
    if (follower.motion == FollowerMotion::Translating) {
        if (follower.type != FollowerType::Flat && !(std::abs(follower.offset) < Rp)) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignBaseRadius},
                                                rho > 0.0
                                                    ? DiagnosticCode::OffsetOutsidePitchBaseCircle
                                                    : DiagnosticCode::OffsetOutsideBaseCircle,
                                                {follower.offset, Rp})};
        }
        profile.m_s0 = follower.type == FollowerType::Flat
                           ? Rb
                           : std::sqrt(Rp * Rp - follower.offset * follower.offset);
        return profile;
    }
    // A swinging arm at lift 0 touches the base circle: |A + L·e(ψ)| = Rp, the arm turned by
    // θ0 from the line pivot → centre, cos θ0 = (a² + L² − Rp²) / (2aL).
    const double a = follower.pivot.norm(), L = follower.armLength;
    const double cosine = (a * a + L * L - Rp * Rp) / (2.0 * a * L);
    if (!(a > Rp) || !(std::abs(cosine) < 1.0)) {
        return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignBaseRadius},
                                            rho > 0.0 ? DiagnosticCode::ArmMissesPitchBaseCircle
                                                      : DiagnosticCode::ArmMissesBaseCircle,
                                            {L, a, Rp})};
    }
    profile.m_theta0 = std::acos(cosine);
    profile.m_beta = std::atan2(-follower.pivot.y(), -follower.pivot.x());
    return profile;
}

ProfilePoint ExactProfile::at(double phi) const {
    const FollowerSpec& f = m_follower;
    const bool swinging = f.motion == FollowerMotion::Oscillating;
    const Jet q = liftJet(m_design, phi, swinging);
    const JetVec u{cosJet(phi), sinJet(phi)}, n = perp(u);
    ProfilePoint p;
    p.phi = phi;
    if (f.type == FollowerType::Flat) {
        // The support function h = Rb + lift: P = h·u + h'·n, P' = (h + h'')·n.
        const double h = m_s0 + q.c[0], h1 = q.c[1], h2 = 2.0 * q.c[2], h3 = 6.0 * q.c[3];
        const Eigen::Vector2d uu = value(u), nn = value(n);
        p.point = h * uu + h1 * nn;
        p.d1 = (h + h2) * nn;
        p.d2 = (h1 + h3) * nn - (h + h2) * uu;
        p.pitch = h * uu;
        p.rho = h + h2;
        return p;
    }
    JetVec C;
    Eigen::Vector2d along, away;
    if (!swinging) {
        const Jet s = q + m_s0;
        C = n * Jet::constant(f.offset) + u * s;
    } else {
        // ψ = β + σθ in the follower frame; the tip X = A + L·e(ψ), turned by φ into the cam.
        const double sigma = f.arm == ArmSide::Cw ? -1.0 : 1.0;
        const Jet psi = Jet::constant(m_beta + sigma * m_theta0) + q * sigma;
        // e(ψ(φ)) as jets: cos and sin of a jet by composition.
        const Jet dpsi = psi - psi.c[0];
        const Jet c0 = cosJet(psi.c[0]), s0 = sinJet(psi.c[0]);
        // cos(ψ0 + δ) with δ a jet without constant term: Taylor in δ up to δ³.
        const Jet d2 = dpsi * dpsi, d3 = d2 * dpsi;
        const double cc = c0.c[0], ss = s0.c[0];
        const Jet cosPsi = Jet::constant(cc) - dpsi * ss - d2 * (cc / 2.0) + d3 * (ss / 6.0);
        const Jet sinPsi = Jet::constant(ss) + dpsi * cc - d2 * (ss / 2.0) - d3 * (cc / 6.0);
        const Jet xf = Jet::constant(f.pivot.x()) + cosPsi * f.armLength;
        const Jet yf = Jet::constant(f.pivot.y()) + sinPsi * f.armLength;
        C = u * xf + n * yf;  // R(φ)·X
        const double theta = phi + psi.c[0];
        along = Eigen::Vector2d(std::cos(theta), std::sin(theta));
        away = sigma * Eigen::Vector2d(-along.y(), along.x());
    }
    const Eigen::Vector2d c0 = value(C), c1 = derivative1(C), c2 = derivative2(C);
    const Eigen::Vector2d c3(6.0 * C.x.c[3], 6.0 * C.y.c[3]);
    const double speed = c1.norm(), speed2 = speed * speed;
    const Eigen::Vector2d normal = Eigen::Vector2d(c1.y(), -c1.x()) / speed;  // out of the cam
    const double curvature = cross(c1, c2) / (speed2 * speed);
    const double curvature1 = cross(c1, c3) / (speed2 * speed) -
                              3.0 * cross(c1, c2) * c1.dot(c2) / (speed2 * speed2 * speed);
    const double rho = contactRadius(f);
    p.pitch = c0;
    p.point = c0 - rho * normal;
    // The inner offset P = C − ρN: P' = (1 − ρκ)·C', P'' = (1 − ρκ)·C'' − ρκ'·C'.
    const double scale = 1.0 - rho * curvature;
    p.d1 = scale * c1;
    p.d2 = scale * c2 - rho * curvature1 * c1;
    p.rho =
        std::abs(curvature) > 0.0 ? 1.0 / curvature - rho : std::numeric_limits<double>::infinity();
    if (!swinging) {
        const double s1 = q.c[1];
        p.pressureAngle = std::atan2(s1 - f.offset, m_s0 + q.c[0]);
    } else {
        const Eigen::Vector2d slide =
            c0.dot(Eigen::Vector2d(-along.y(), along.x())) >= 0.0 ? along : Eigen::Vector2d(-along);
        p.pressureAngle = std::atan2(normal.dot(slide), normal.dot(away));
    }
    return p;
}

std::array<double, 4> ExactProfile::followerCoordinate(double phi) const {
    const bool swinging = m_follower.motion == FollowerMotion::Oscillating;
    const Jet q = liftJet(m_design, phi, swinging);
    if (!swinging) return {m_s0 + q.c[0], q.c[1], 2.0 * q.c[2], 6.0 * q.c[3]};
    const double sigma = m_follower.arm == ArmSide::Cw ? -1.0 : 1.0;
    return {m_beta + sigma * (m_theta0 + q.c[0]), sigma * q.c[1], sigma * 2.0 * q.c[2],
            sigma * 6.0 * q.c[3]};
}

std::vector<ProfileProblem> ExactProfile::problems(bool strictPressureAngle, int samples) const {
    std::vector<ProfileProblem> out;
    const int n = std::max(samples, 64);
    const double h = kTwoPi / n;
    const double rho = contactRadius(m_follower);
    const double limit = degToRad(m_follower.maxPressureAngleOrDefault());
    // Undercut: the profile folds where its tangent turns back, (1 − ρκ) < 0 for a roller
    // (pitch radius below the roller's), h + h'' < 0 for a flat face, never for a knife.
    const auto folds = [&](const ProfilePoint& p) {
        if (m_follower.type == FollowerType::Flat) return p.rho < 0.0;
        if (m_follower.type == FollowerType::Knife) return false;
        return p.rho + rho > 0.0 && p.rho < 0.0;
    };
    const auto steep = [&](const ProfilePoint& p) { return std::abs(p.pressureAngle) > limit; };
    std::vector<ProfilePoint> sampled(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) sampled[static_cast<std::size_t>(i)] = at(i * h);
    // `code` and `args` say what is wrong; the stretch's ends (in degrees) follow as the
    // code's last two arguments.
    const auto ranges = [&](const std::function<bool(const ProfilePoint&)>& bad, const Place& place,
                            DiagnosticCode code, const std::vector<DiagnosticArg>& args,
                            Severity severity) {
        // Stretches of bad samples, their ends bisected to 1e-12 rad.
        const auto edge = [&](double good, double badPhi) {
            for (int it = 0; it < 60 && std::abs(badPhi - good) > 1e-12; ++it) {
                const double mid = 0.5 * (good + badPhi);
                (bad(at(mid)) ? badPhi : good) = mid;
            }
            return badPhi;
        };
        const auto badAt = [&](int i) { return bad(sampled[static_cast<std::size_t>(i)]); };
        int i = 0;
        while (i < n) {
            if (!badAt(i)) {
                ++i;
                continue;
            }
            int j = i;
            while (j + 1 < n && badAt(j + 1)) ++j;
            const double from = i == 0 ? 0.0 : edge((i - 1) * h, i * h);
            const double to = j == n - 1 ? kTwoPi : edge((j + 1) * h, j * h);
            std::vector<DiagnosticArg> coded = args;
            coded.insert(coded.end(), {radToDeg(from), radToDeg(to)});
            out.push_back({from, to, Diagnostic::make(place, code, std::move(coded), severity)});
            i = j + 1;
        }
    };
    if (m_follower.type == FollowerType::Roller) {
        ranges(folds, FieldPlace{Field::FollowerRadius}, DiagnosticCode::UndercutRoller, {rho},
               Severity::Error);
    } else {
        ranges(folds, FieldPlace{Field::Design}, DiagnosticCode::UndercutFlatFace, {},
               Severity::Error);
    }
    if (m_follower.type != FollowerType::Flat) {
        const double limitDeg = m_follower.maxPressureAngleOrDefault();
        ranges(steep, FieldPlace{Field::FollowerMaxPressureAngle},
               DiagnosticCode::PressureAngleExceeded, {limitDeg},
               strictPressureAngle ? Severity::Error : Severity::Info);
    }
    return out;
}

}  // namespace cam
