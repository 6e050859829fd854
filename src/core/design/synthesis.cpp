#include "design/synthesis.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "contour/contour.h"
#include "design/arc_fit.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"

namespace cam {
namespace {

/// The polar angle of x unwrapped to lie at or after `after` by less than a turn.
double polarAfter(const Eigen::Vector2d& x, double after) {
    double angle = std::atan2(x.y(), x.x());
    angle = after + std::fmod(angle - after + 4.0 * kTwoPi, kTwoPi);
    return angle;
}

/// The arcs as contour segments with polar windows (degrees) rising from the first joint's
/// angle through one turn; each arc takes the branch of the ray that holds its midpoint.
std::vector<SegmentSpec> contourOf(const std::vector<FittedArc>& arcs) {
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

}  // namespace

Result<Synthesis> synthesize(const Project& project, std::optional<double> tolerance,
                             bool strictPressureAngle, const std::atomic<bool>* cancel) {
    if (!project.design) {
        return Diagnostics{
            Diagnostic{"design", "the project has no design to synthesise a contour from"}.coded(
                DiagnosticCode::NoDesign, {})};
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

    auto fit = fitArcs(
        [&](double phi) {
            const ProfilePoint p = profile.at(phi);
            return CurveSample{p.point, p.d1};
        },
        0.0, spec.tolerance, cancel);
    if (!fit.ok()) return fit.errors();
    result.contour = contourOf(fit.value().arcs);
    result.report.segments = result.contour.size();
    result.report.maxDeviationMm = fit.value().maxDeviation;

    // The price of arcs: the follower placed by contact on the arc table (not by the fit's
    // arithmetic) against the motion the design asks for.
    Project made = project;
    made.contour = result.contour;
    auto contour = Contour::build(made);
    if (!contour.ok()) {
        Diagnostics why{
            Diagnostic{"design", "the synthesised arc table is not a valid contour"}.coded(
                DiagnosticCode::SynthesisedContourInvalid, {})};
        for (const Diagnostic& d : contour.errors()) why.push_back(d);
        return why;
    }
    auto placed = FollowerModel::build(contour.value(), follower);
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
