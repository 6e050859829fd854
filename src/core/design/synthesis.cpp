#include "design/synthesis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "common/angles.h"
#include "common/diagnostic_catalogue.h"
#include "contour/contour.h"
#include "design/arc_fit.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

/// The polar angle of x unwrapped to lie at or after `after` by less than a turn.
double polarAfter(const Eigen::Vector2d& x, double after) {
    double angle = std::atan2(x.y(), x.x());
    angle = after + std::fmod(angle - after + 4.0 * kTwoPi, kTwoPi);
    return angle;
}

/// Where the exact profile lies farthest from the centre (mm), over the fit's own density of
/// cam angles.
double profileExtent(const ExactProfile& profile) {
    constexpr int kAngles = 1 << 14;
    double extent = 0.0;
    for (int k = 0; k < kAngles; ++k) {
        extent = std::max(extent, profile.at(kTwoPi * k / kAngles).point.norm());
    }
    return extent;
}

/// The distance from x to the contour as the engine evaluates it (r(φ) of its segments, math.md
/// §1): Newton's method on the polar angle φ of the nearest contour point p(φ) = r(φ)·u(φ), from
/// the polar angle of x, where (p − x)·p' = 0.
double distanceToContour(const Contour& contour, const Eigen::Vector2d& x) {
    double phi = std::atan2(x.y(), x.x());
    const auto at = [&](double angle, Eigen::Vector2d& p, Eigen::Vector2d& p1,
                        Eigen::Vector2d& p2) {
        const PolarDerivatives d = contour.evaluate(angle);
        const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), n(-u.y(), u.x());
        p = d.r * u;
        p1 = d.dr * u + d.r * n;
        p2 = (d.d2r - d.r) * u + 2.0 * d.dr * n;
    };
    Eigen::Vector2d p, p1, p2;
    for (int it = 0; it < 8; ++it) {
        at(phi, p, p1, p2);
        const Eigen::Vector2d e = p - x;
        const double slope = p1.squaredNorm() + e.dot(p2);
        if (!(slope > 0.0)) break;
        const double step = e.dot(p1) / slope;
        phi -= step;
        if (std::abs(step) <= 1e-16 * (1.0 + std::abs(phi))) break;
    }
    at(phi, p, p1, p2);
    return (p - x).norm();
}

struct Measured {
    double deviation = 0.0;  ///< mm
    double atPhi = 0.0;      ///< the cam angle of the exact profile point farthest away, rad
    std::size_t points = 0;
};

/// How far the contour lies from the exact profile, measured apart from the fit: the exact
/// profile at 2^14 cam angles offset from the fit's samples and the points it checks, and at 32
/// within every arc's stretch (the deviation over an arc is a bulge or two, so 32 points find its
/// largest within about half a percent), each point's distance to the contour by
/// distanceToContour. Empty when cancelled.
std::optional<Measured> measureDeviation(const ExactProfile& profile, const Contour& contour,
                                         const std::vector<FittedArc>& arcs,
                                         const std::atomic<bool>* cancel) {
    Measured m;
    const auto measure = [&](double phi) {
        const double d = distanceToContour(contour, profile.at(phi).point);
        ++m.points;
        // A NaN counts as the worst: never as "within".
        if (!(d <= m.deviation)) {
            m.deviation = std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
            m.atPhi = phi;
        }
    };
    constexpr std::size_t kUniform = std::size_t{1} << 14;
    for (std::size_t k = 0; k < kUniform; ++k) {
        if (k % 4096 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return {};
        measure(kTwoPi * (static_cast<double>(k) + 0.382) / static_cast<double>(kUniform));
    }
    constexpr int kPerArc = 32;
    for (std::size_t k = 0; k < arcs.size(); ++k) {
        if (k % 128 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return {};
        const double t0 = arcs[k].t0;
        // The first arc may hold the end of the turn and its start.
        const double t1 = arcs[k].t1 >= t0 ? arcs[k].t1 : arcs[k].t1 + kTwoPi;
        for (int q = 0; q < kPerArc; ++q) measure(t0 + (t1 - t0) * (q + 0.5) / kPerArc);
    }
    return m;
}

/// How often the fit is made again with a smaller target when the measured contour strays
/// beyond the tolerance.
constexpr int kRefits = 3;

}  // namespace

std::vector<SegmentSpec> contourOfArcs(const std::vector<FittedArc>& arcs) {
    std::vector<SegmentSpec> out;
    const double begin = std::atan2(arcs.front().from.y(), arcs.front().from.x());
    double start = begin;
    for (std::size_t k = 0; k < arcs.size(); ++k) {
        const FittedArc& a = arcs[k];
        // The last window closes the turn exactly.
        const double end = k + 1 == arcs.size() ? begin + kTwoPi : polarAfter(a.to, start);
        SegmentSpec s;
        if (a.straight) {
            s.shape = Line{a.from, a.to};
        } else {
            const double half = a.sweep / 2.0;
            const Eigen::Vector2d r = a.from - a.center;
            const Eigen::Vector2d mid =
                a.center + Eigen::Vector2d(std::cos(half) * r.x() - std::sin(half) * r.y(),
                                           std::sin(half) * r.x() + std::cos(half) * r.y());
            const Eigen::Vector2d u = mid.normalized();
            const double mu = a.center.dot(u);
            const double root =
                std::sqrt(std::max(0.0, mu * mu - (a.center.squaredNorm() - a.radius * a.radius)));
            const bool outer = std::abs(mu + root - mid.norm()) <= std::abs(mu - root - mid.norm());
            s.shape = Arc{a.center, a.radius, outer ? Branch::Outer : Branch::Inner};
        }
        s.phiStartDeg = radToDeg(start);
        s.phiEndDeg = radToDeg(end);
        out.push_back(s);
        start = end;
    }
    out.back().phiEndDeg = out.front().phiStartDeg + 360.0;
    return out;
}

Diagnostics placeArcTableProblems(const Diagnostics& problems, const std::vector<FittedArc>& arcs,
                                  const MotionDesign& motion) {
    const Diagnostic& first = problems.front();
    std::optional<std::size_t> arc;
    if (const std::vector<SegmentPlace> fields = first.segmentFields(); !fields.empty()) {
        arc = fields.front().segment;
    } else {
        const std::string_view signature = diagnosticCodeSignature(first.code);
        for (std::size_t i = 0; i < signature.size() && i < first.args.size(); ++i) {
            if (signature[i] == 'k' && std::holds_alternative<double>(first.args[i])) {
                arc = static_cast<std::size_t>(std::get<double>(first.args[i]));
                break;
            }
        }
    }
    Diagnostics out;
    if (arc && *arc < arcs.size()) {
        const FittedArc& a = arcs[*arc];
        const double t1 = a.t1 >= a.t0 ? a.t1 : a.t1 + kTwoPi;  // the first may wrap the turn
        const double fromDeg = radToDeg(a.t0), toDeg = radToDeg(t1);
        const std::size_t segment = motion.segmentAt(0.5 * (a.t0 + t1));
        out.push_back(Diagnostic::make(DesignSegmentPlace{segment},
                                       DiagnosticCode::SynthesisedArcInvalid,
                                       {static_cast<double>(*arc), fromDeg, toDeg})
                          .because({first}));
    } else {
        out.push_back(
            Diagnostic::make(FieldPlace{Field::Design}, DiagnosticCode::SynthesisedContourInvalid)
                .because({first}));
    }
    out.insert(out.end(), problems.begin() + 1, problems.end());
    return out;
}

// Why 16 ε · extent (ε = 2^-52, the spacing of doubles relative to 1; an ulp of the extent is
// between ε/2 and ε times it). The reported deviation is a distance between two points of size
// up to the extent, each computed in double precision: the exact profile's point (cos and sin
// of the cam angle, the lift's jets, the roller's offset along the normal: a few roundings of
// the extent's size), the contour's r(φ) (μ ± √(μ² + R² − |c|²) for an arc about the centre:
// about three more) and the difference of the two. Together they are off by up to about
// 4 ε · extent; a fit asked for 3e-14 mm on the 50 mm roller cam of resources/examples fails on
// exactly this noise (2.7 ε · 50 mm). A tolerance of 16 ε · extent keeps that error below a
// quarter of what is asked, so a deviation measured within the tolerance means one; below it a
// measured "within" would be rounding, not geometry. For 50 mm that is 1.8e-13 mm (1e-12 mm is
// certified, 1e-13 mm is not). An arc of large radius R rounds more (ε · R): the fit does not
// make arcs whose R exceeds tolerance / (16 ε) (arc_fit.cpp), and the measurement would show it.
double certifiableTolerance(double extentMm) {
    return kCertifiableEpsilons * std::numeric_limits<double>::epsilon() * extentMm;
}

Result<Synthesis> synthesize(const Project& project, std::optional<double> tolerance,
                             bool strictPressureAngle, const std::atomic<bool>* cancel) {
    if (!project.design) {
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::Design}, DiagnosticCode::NoDesign, {})};
    }
    DesignSpec spec = *project.design;
    if (tolerance) spec.tolerance = *tolerance;
    auto motion = MotionDesign::build(spec);
    if (!motion.ok()) return motion.errors();
    const FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    auto exact = ExactProfile::build(motion.value(), follower);
    if (!exact.ok()) return exact.errors();
    const ExactProfile& profile = exact.value();
    Synthesis result;
    result.report.notes = motion.value().jumps();
    Diagnostics refusals;
    const bool strict = strictPressureAngle || spec.strictPressureAngle;
    for (const ProfileProblem& problem : profile.problems(strict)) {
        if (problem.what.severity == Severity::Error) {
            refusals.push_back(problem.what);
        } else {
            result.report.notes.push_back(problem.what);
        }
    }
    if (!refusals.empty()) return refusals;

    const double extent = profileExtent(profile);
    const double limit = certifiableTolerance(extent);
    if (!(spec.tolerance >= limit)) {
        return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignTolerance},
                                            DiagnosticCode::ToleranceBelowPrecision,
                                            {spec.tolerance, limit, extent})};
    }

    // The fit keeps its biarcs within its target at the points it checks; between them the
    // arcs may stray a little further. So the contour is measured apart from the fit, and when
    // that measurement exceeds the tolerance the fit is made again with a smaller target.
    // A roller must fit into every concave arc (the validator's rule): the exact profile's
    // concave radius exceeds the roller's by its pitch curve's, so only a stray arc would not.
    const double rollerRadius = contactRadius(follower);
    Project made = project;
    std::optional<Contour> built;
    std::vector<FittedArc> arcs;
    Measured measured;
    double target = spec.tolerance;
    for (int round = 0;; ++round) {
        auto fit = fitArcs(
            [&](double phi) {
                const ProfilePoint p = profile.at(phi);
                return CurveSample{p.point, p.d1};
            },
            0.0, target, cancel, rollerRadius);
        if (!fit.ok()) return fit.errors();
        arcs = std::move(fit).value().arcs;
        made.contour = contourOfArcs(arcs);
        auto contour = Contour::build(made);
        if (!contour.ok()) return placeArcTableProblems(contour.errors(), arcs, motion.value());
        built = std::move(contour).value();
        const std::optional<Measured> m = measureDeviation(profile, *built, arcs, cancel);
        if (!m) return Diagnostics{};
        measured = *m;
        if (measured.deviation <= spec.tolerance) break;
        if (round == kRefits) {
            const double atDeg = radToDeg(measured.atPhi);
            return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignTolerance},
                                                DiagnosticCode::ToleranceNotReached,
                                                {spec.tolerance, measured.deviation, atDeg})};
        }
        // Aim as far below the tolerance as the last fit strayed above it, and a little more.
        target *= std::max(0.9 * spec.tolerance / measured.deviation, 0.25);
    }
    result.contour = made.contour;
    result.report.segments = result.contour.size();
    result.report.maxDeviationMm = measured.deviation;
    result.report.measuredPoints = measured.points;

    // The price of arcs: the follower placed by contact on the arc table (not by the fit's
    // arithmetic) against the motion the design asks for.
    auto placed = FollowerModel::build(*built, follower);
    if (!placed.ok()) return placed.errors();
    const double omega = project.motion.omegaRadS();
    const bool swinging = follower.motion == FollowerMotion::Oscillating;
    const double unit = swinging ? 180.0 / kPi : 1.0;
    // 7201 angles: none of them a whole degree, where a design's own acceleration may jump.
    constexpr std::size_t kAngles = 7201;
    FollowerTurn turn;
    if (!sampleFollowerTurn(placed.value(), omega, kAngles, turn, cancel)) return Diagnostics{};
    const double dt = kTwoPi / std::abs(omega) / static_cast<double>(kAngles);
    for (std::size_t k = 0; k < kAngles; ++k) {
        const double phi = omega * (static_cast<double>(k) * dt);
        const std::array<double, 4> q = profile.followerCoordinate(phi);
        SynthesisReport& r = result.report;
        r.maxLiftError = std::max(r.maxLiftError, std::abs(turn.s[k] - q[0]) * unit);
        r.maxVelocityError =
            std::max(r.maxVelocityError, std::abs(turn.v[k] - omega * q[1]) * unit);
        r.maxAccelerationError =
            std::max(r.maxAccelerationError, std::abs(turn.a[k] - omega * omega * q[2]) * unit);
    }
    result.report.checkedAngles = kAngles;
    return result;
}

}  // namespace cam
