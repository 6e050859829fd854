#include "engine/compute_result.h"

#include <QElapsedTimer>
#include <QFuture>
#include <QScopeGuard>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "engine/background_priority.h"
#include "engine/plot_data_preparer.h"
#include "follower/follower_turn.h"
#include "geometry/planar.h"
#include "timing/timing_job.h"

namespace cam {
namespace {

/// Intervals per segment outline: at most 128 for a few segments, fewer for many, so that the
/// contour view never holds much more than kOutlinePointsTotal points (100,000 segments would
/// otherwise be 16 million points to copy and draw); at least 8 each.
constexpr int kOutlineIntervalsMin = 8;
constexpr int kOutlineIntervalsMax = 128;  // kOutlineIntervalsMin · 2^4
constexpr std::size_t kOutlinePointsTotal = 1u << 18;
/// An interval of an outline is halved while its middle lies farther than this fraction of the
/// contour's size from its chord: 1e-4 of 70 mm is 7 µm, a tenth of a pixel when the contour
/// fills 900 pixels. A 2-pixel line is stroked vertex by vertex (the contour view's largest
/// cost); a fixed 160 intervals a segment gave arcs of 60° ten times the points they need.
constexpr double kOutlineToleranceRelative = 1e-4;

Eigen::Vector2d pointAt(const ContourSegment& s, double phi) {
    return fromPolar(s.evaluate(phi).r, phi);
}

/// Appends the outline of [a, b] without its start: its end, after whatever halving of it the
/// tolerance asks for, up to `depth` times.
void appendOutline(const ContourSegment& s, double a, const Eigen::Vector2d& pa, double b,
                   const Eigen::Vector2d& pb, double tolerance, int depth, QVector<QPointF>& out) {
    const double m = 0.5 * (a + b);
    const Eigen::Vector2d pm = pointAt(s, m);
    const Eigen::Vector2d chord = pb - pa;
    const double length = chord.norm();
    const double off = length > 0.0 ? std::abs(cross(chord, pm - pa)) / length : (pm - pa).norm();
    if (depth > 0 && !(off <= tolerance)) {  // NaN: halved as far as allowed
        appendOutline(s, a, pa, m, pm, tolerance, depth - 1, out);
        appendOutline(s, m, pm, b, pb, tolerance, depth - 1, out);
        return;
    }
    out.append({pb.x(), pb.y()});
}

/// Per segment, its outline for the contour view: ends included, intervals halved where the
/// curve leaves their chord.
std::vector<QVector<QPointF>> outlinesOf(const Contour& c) {
    std::vector<QVector<QPointF>> outlines(c.size());
    const int most = static_cast<int>(
        std::clamp<std::size_t>(kOutlinePointsTotal / std::max<std::size_t>(c.size(), 1),
                                kOutlineIntervalsMin, kOutlineIntervalsMax));
    int depth = 0;
    while ((kOutlineIntervalsMin << (depth + 1)) <= most) ++depth;
    // The contour's size, from its coarsest points.
    double reach = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const ContourSegment& s = c.segment(k);
        for (int i = 0; i <= kOutlineIntervalsMin; ++i) {
            const double r =
                s.evaluate(s.phiStart + (s.phiEnd - s.phiStart) * i / kOutlineIntervalsMin).r;
            if (std::isfinite(r)) reach = std::max(reach, std::abs(r));
        }
    }
    const double tolerance = kOutlineToleranceRelative * 2.0 * reach;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const ContourSegment& s = c.segment(k);
        QVector<QPointF>& out = outlines[k];
        double a = s.phiStart;
        Eigen::Vector2d pa = pointAt(s, a);
        out.append({pa.x(), pa.y()});
        for (int i = 1; i <= kOutlineIntervalsMin; ++i) {
            const double b = s.phiStart + (s.phiEnd - s.phiStart) * i / kOutlineIntervalsMin;
            const Eigen::Vector2d pb = pointAt(s, b);
            appendOutline(s, a, pa, b, pb, tolerance, depth, out);
            a = b;
            pa = pb;
        }
    }
    return outlines;
}

/// A closed path as a polyline: its ends, and arcs every half degree of their sweep.
QVector<QPointF> outlineOf(const ToolPath& path) {
    QVector<QPointF> out;
    for (const PathSegment& piece : path.segments) {
        const int steps =
            piece.kind == PathSegment::Kind::Arc
                ? std::max(2, static_cast<int>(std::ceil(std::abs(piece.sweep) / degToRad(0.5))))
                : 1;
        for (int i = 0; i < steps; ++i) {
            const Eigen::Vector3d p = piece.point(piece.length() * i / steps);
            out.append({p.x(), p.y()});
        }
    }
    if (!out.isEmpty()) out.append(out.front());
    return out;
}

/// The contour view's and the Follower dock's view of a groove.
std::shared_ptr<const GrooveView> grooveViewOf(const GrooveFlanks& flanks,
                                               const FollowerSpec& spec) {
    auto view = std::make_shared<GrooveView>();
    view->flanks = flanks;
    view->lands = grooveLands(flanks, spec.innerLandRadius, spec.outerLandRadius);
    view->outerBends = pathBends(flanks.outer);
    view->outer = outlineOf(flanks.outer);
    view->pitch = outlineOf(flanks.pitch);
    return view;
}

/// What the contour view and the Joints tab need of the contour alone.
struct ContourPart {
    std::vector<JointAnalysis> joints;
    std::vector<QVector<QPointF>> outlines;
};

ContourPart computeContourPart(const Contour* contour, double omega,
                               const std::atomic<bool>* cancel) {
    runInTheBackground();
    ContourPart part;
    part.joints = analyzeJoints(*contour, omega, cancel);
    if (!cancel->load()) part.outlines = outlinesOf(*contour);
    return part;
}

/// The follower the evaluation placed: its design checks and its pressure-angle curve.
struct FollowerPart {
    FollowerAnalysis checks;
    std::vector<double> x, pressureDeg, rhoProfile, rhoPitch;
    std::array<std::vector<double>, 4> motion;
    std::array<PlotRange, 4> motionRanges{};
    std::vector<double> jointX;
    std::vector<std::size_t> jointLeft;
    std::shared_ptr<const ForceCurves> forces;
    std::shared_ptr<const ConjugateView> conjugate;
    Diagnostics conjugateErrors;
};

/// A conjugate pair's second plate, fitted within the project's tolerance (null for another
/// closure, or with `errors` set when it cannot be fitted, or when cancelled).
std::shared_ptr<const ConjugateView> computeConjugate(const Project& project,
                                                      const FollowerModel& model,
                                                      Diagnostics& errors,
                                                      const std::atomic<bool>* cancel) {
    const std::optional<SecondRoller> yoke = SecondRoller::of(project);
    if (!yoke) return nullptr;
    auto view = std::make_shared<ConjugateView>();
    view->yoke = *yoke;
    view->toleranceMm = conjugateTolerance(project);
    auto plate = conjugatePlate(model, *yoke, view->toleranceMm, 7200, cancel);
    if (!plate.ok()) {
        errors = plate.errors();
        return nullptr;
    }
    view->plate = std::move(plate).value();
    view->outline = outlineOf(view->plate.path);
    return view;
}

/// The forces of the project's dynamics: the summary on the project's samples per turn (as
/// the CLI finds it), the curves on the follower curve's `turn`.
std::shared_ptr<const ForceCurves> computeForces(const Project& project, const FollowerModel& model,
                                                 double omega, const FollowerTurn& turn,
                                                 const std::atomic<bool>* cancel) {
    ForceEvaluation evaluation;
    if (!evaluateForces(project, model, omega, evaluation, cancel)) return nullptr;
    auto out = std::make_shared<ForceCurves>();
    out->model = evaluation.model;
    out->summary = std::move(evaluation.summary);
    out->samples = evaluation.turn.size();
    ForceTurn sampled;
    if (evaluation.turn.size() == turn.size()) {
        sampled = std::move(evaluation.forces);
    } else {
        forcesOfTurn(out->model, model, turn, omega, sampled);
    }
    const std::size_t n = turn.size();
    out->curves.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        out->curves.load[k] = sampled.load[k % n];
        out->curves.normal[k] = sampled.normal[k % n];
        out->curves.torque[k] = sampled.torque[k % n];
        out->curves.stress[k] = sampled.stress[k % n];
    }
    if (out->model.hasStress) {
        out->contactX.resize(n + 1);
        out->contactY.resize(n + 1);
        const double period = kTwoPi / std::abs(omega);
        for (std::size_t k = 0; k <= n; ++k) {
            if ((k & 1023) == 0 && cancel->load()) return nullptr;
            const double t = period * static_cast<double>(k % n) / static_cast<double>(n);
            const FollowerState state = model.at(omega * t, omega);
            Eigen::Vector2d c = state.contact;
            if (out->model.formClosed() && out->curves.normal[k] < 0.0) {
                c = out->model.yoke
                        ? conjugatePoint(model, *out->model.yoke, omega * t).plate
                        : Eigen::Vector2d(state.center + model.spec().radius * state.normal);
            }
            out->contactX[k] = c.x();
            out->contactY[k] = c.y();
        }
    }
    return out;
}

FollowerPart computeFollower(const Project* project, const FollowerModel* model, double omega,
                             double period, double phiBegin, PlotAxis axis, bool checks,
                             const std::vector<PhaseSpan>& phases,
                             const std::atomic<bool>* cancel) {
    runInTheBackground();
    FollowerPart part;
    if (checks) {
        part.checks =
            analyzeFollower(*model, omega, phiBegin, kFollowerCheckSamples, nullptr, phases);
        part.conjugate = computeConjugate(*project, *model, part.conjugateErrors, cancel);
    }
    constexpr std::size_t n = ComputeResult::kFollowerCurvePoints;
    FollowerTurn turn;
    if (!sampleFollowerTurn(*model, omega, n, turn, cancel)) return part;
    part.x.resize(n + 1);
    part.pressureDeg.resize(n + 1);
    part.rhoProfile.resize(n + 1);
    part.rhoPitch.resize(n + 1);
    for (auto& curve : part.motion) curve.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const double t = period * static_cast<double>(k) / n;
        part.x[k] = axis == PlotAxis::Angle ? radToDeg(omega * t) : t;
        // The turn's end closes the curve: the angle of its start, one turn on.
        const std::size_t i = k % n;
        part.pressureDeg[k] = radToDeg(turn.pressureAngle[i]);
        part.rhoProfile[k] = turn.rhoProfile[i];
        part.rhoPitch[k] = turn.rhoPitch[i];
        const std::array<double, 4> lift =
            model->liftMotion(turn.s[i], turn.v[i], turn.a[i], turn.j[i]);
        for (std::size_t d = 0; d < 4; ++d) part.motion[d][k] = lift[d];
    }
    for (std::size_t d = 0; d < 4; ++d) {
        const auto [lo, hi] = std::minmax_element(part.motion[d].begin(), part.motion[d].end());
        part.motionRanges[d] = {*lo, *hi};
    }
    // Where the contact passes from one segment to the next: between the two samples.
    for (std::size_t k = 0; k < n; ++k) {
        const std::int32_t from = turn.segment[k], to = turn.segment[(k + 1) % n];
        if (from == to) continue;
        part.jointX.push_back(0.5 * (part.x[k] + part.x[k + 1]));
        // The joint's left segment in the contour's order, whichever way the cam turns.
        part.jointLeft.push_back(static_cast<std::size_t>(omega > 0.0 ? from : to));
    }
    if (project->dynamics) part.forces = computeForces(*project, *model, omega, turn, cancel);
    return part;
}

/// x of sample k of n over the turn (t_k = k·T/n), as the plots show it.
double plotX(std::size_t k, std::size_t n, double omega, double period, PlotAxis axis) {
    const double t = period * static_cast<double>(k) / static_cast<double>(n);
    return axis == PlotAxis::Angle ? radToDeg(omega * t) : t;
}

/// The design's curves (evaluateDesign) on the plots' x axis; null when cancelled.
std::shared_ptr<DesignCurves> computeDesign(const Project& project,
                                            const ProjectEvaluation& evaluation, PlotAxis axis,
                                            const std::atomic<bool>& cancel) {
    auto out = std::make_shared<DesignCurves>();
    constexpr std::size_t n = ComputeResult::kFollowerCurvePoints;
    if (!evaluateDesign(project, evaluation, n, *out, &cancel)) return nullptr;
    const double omega = evaluation.omega, period = evaluation.period;
    if (out->law[0].empty()) return out;  // the design itself has problems
    for (const DesignSegmentSpec& segment : project.design->segments) {
        const double phi = degToRad(segment.toDeg);
        out->jointsX.push_back(axis == PlotAxis::Angle ? radToDeg(omega > 0 ? phi : -phi)
                                                       : phi / std::abs(omega));
    }
    out->x.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) out->x[k] = plotX(k, n, omega, period, axis);
    for (std::size_t d = 0; d < 4; ++d) {
        double lo = out->law[d].front(), hi = lo;
        // The follower's jerk on an arc table spikes at every joint (its acceleration jumps
        // there): the jerk's range is the law's.
        for (const auto* curve : {&out->law[d], d < 3 ? &out->onContour[d] : &out->law[d]}) {
            for (double v : *curve) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        }
        out->yRanges[d] = {lo, hi};
    }
    return out;
}

}  // namespace

Diagnostics ComputeResult::reasonsNotShown() const {
    if (!errors.empty()) return errors;
    Diagnostics reasons;
    if (valid()) return reasons;
    for (const Diagnostic& d : problems) {
        if (d.severity == Severity::Error) reasons.push_back(d);
    }
    return reasons;
}

ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel,
                                const PlotDataPreparer* preparer) {
    QElapsedTimer timer;
    timer.start();
    auto result = std::make_shared<ComputeResult>();
    result->generation = request.generation;
    result->project = request.project;
    result->axis = request.axis;
    const Project& project = *request.project;
    // The one verdict (evaluation.h), as the document and the CLI have it. An invalid project
    // whose contour compiles (joints that do not meet, a follower that cannot ride it) is still
    // drawn while the designer edits; the document reports its problems and nothing exports it.
    ProjectEvaluation evaluation = evaluateProject(project);
    result->status = evaluation.status;
    result->problems = evaluation.problems;
    if (!evaluation.contour) {
        // Nothing to draw but the design's law, if the speed allows (a design waiting for its
        // first synthesis, or one whose contour has problems).
        result->errors = evaluation.status == EvaluationStatus::AwaitsContour
                             ? Diagnostics{contourNeverSynthesised()}
                             : evaluation.problems;
        if (project.design && evaluation.omega != 0.0) {
            auto design = computeDesign(project, evaluation, request.axis, cancel);
            if (!design) return nullptr;
            result->design = std::move(design);
            if (preparer) result->prepared = preparer->prepare(*result, cancel);
        }
        result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
        return result;
    }
    result->contour = std::move(evaluation.contour);
    result->omega = evaluation.omega;
    result->period = evaluation.period;
    if (project.follower) {
        result->follower = evaluation.follower;
        result->followerErrors = evaluation.followerProblems;
        if (evaluation.groove) result->groove = grooveViewOf(*evaluation.groove, *project.follower);
    }
    // The follower's checks and curve need only the contour: on the pool's other core while
    // this thread samples the turn (a swinging arm's pressure-angle curve costs about as much
    // as the kinematics). A first picture leaves its design checks (two to three times that)
    // to refineResult().
    QFuture<FollowerPart> follower;
    const bool checksNow = request.firstPictureBuckets == 0;
    if (result->follower) {
        follower = QtConcurrent::run(computeFollower, &project, result->follower.get(),
                                     result->omega, result->period, result->contour->phiBegin(),
                                     request.axis, checksNow, phasesOf(project), &cancel);
    }
    // So are the analysis and the outlines, on the pool too (the GUI thread waits idle for
    // the first picture: its core is free).
    QFuture<ContourPart> contourPart =
        QtConcurrent::run(computeContourPart, &*result->contour, result->omega, &cancel);
    // Every early return below waits for them: they read the contour this result owns.
    const auto waitForPool = qScopeGuard([&] {
        if (follower.isValid()) follower.waitForFinished();
        contourPart.waitForFinished();
    });
    result->sampleCount = static_cast<std::size_t>(project.samplesPerTurnOrDefault());
    if (!buildPlotCurves(*result->contour, result->omega, result->sampleCount, request.axis,
                         result->curves, cancel, request.firstPictureBuckets)) {
        return nullptr;
    }
    {
        ContourPart part = contourPart.result();
        if (cancel.load()) return nullptr;
        result->joints = std::move(part.joints);
        result->outlines = std::move(part.outlines);
    }
    std::vector<CubicBezier> splines;
    for (const SegmentSpec& spec : project.contour) {
        if (isSpline(spec.type())) splines.push_back(bezierOf(spec));
    }
    if (!splines.empty()) result->pathStudy = studyPath(splines, 100);
    if (cancel.load()) return nullptr;
    if (project.design) {
        // The design's follower on the contour is the evaluation's (a radial knife when the
        // project names none).
        auto design = computeDesign(project, evaluation, request.axis, cancel);
        if (!design) return nullptr;
        result->design = std::move(design);
    }
    if (follower.isValid()) {
        // The follower was computed beside all of the above; it has finished or stops soon.
        FollowerPart part = follower.result();
        if (cancel.load()) return nullptr;
        result->followerChecks = std::move(part.checks);
        result->followerChecksPending = !checksNow;
        result->followerX = std::move(part.x);
        result->followerPressureDeg = std::move(part.pressureDeg);
        result->followerRhoProfile = std::move(part.rhoProfile);
        result->followerRhoPitch = std::move(part.rhoPitch);
        result->followerMotion = std::move(part.motion);
        result->followerMotionRanges = part.motionRanges;
        result->followerJointX = std::move(part.jointX);
        result->followerJointLeft = std::move(part.jointLeft);
        result->forces = std::move(part.forces);
        result->conjugate = std::move(part.conjugate);
        result->conjugateErrors = std::move(part.conjugateErrors);
    }
    if (preparer) {
        result->prepared = preparer->prepare(*result, cancel);
        if (cancel.load()) return nullptr;
    }
    result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return result;
}

ComputeResultPtr refineResult(const ComputeResult& first, const std::atomic<bool>& cancel,
                              const PlotDataPreparer* preparer) {
    if (!first.ok() || first.complete()) return nullptr;
    QElapsedTimer timer;
    timer.start();
    auto result = std::make_shared<ComputeResult>(first);
    // On this thread alone: the window draws the first picture meanwhile on the other core.
    // The checks first, which the Follower dock lists; the finer levels are for zooming in.
    if (first.followerChecksPending) {
        result->followerChecks =
            analyzeFollower(*first.follower, first.omega, first.contour->phiBegin(),
                            kFollowerCheckSamples, &cancel, phasesOf(*first.project));
        if (cancel.load()) return nullptr;
        result->conjugate =
            computeConjugate(*first.project, *first.follower, result->conjugateErrors, &cancel);
        result->followerChecksPending = false;
        if (cancel.load()) return nullptr;
    }
    if (first.curves.partial &&
        !buildPlotCurves(*result->contour, result->omega, result->sampleCount, result->axis,
                         result->curves, cancel)) {
        return nullptr;
    }
    if (preparer && first.curves.partial) {
        result->prepared = preparer->prepare(*result, cancel);
        if (cancel.load()) return nullptr;
    }
    result->computeMs = first.computeMs + static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return result;
}

ComputeResultPtr failedResult(const ComputeRequest& request, const std::string& message) {
    auto result = std::make_shared<ComputeResult>();
    result->generation = request.generation;
    result->project = request.project;
    result->axis = request.axis;
    result->errors = {Diagnostic{"", message}};
    result->problems = result->errors;
    result->status = EvaluationStatus::Failed;
    return result;
}

TimingOutcomePtr computeTiming(const ComputeRequest& request, const Contour& contour,
                               const std::atomic<bool>& cancel) {
    QElapsedTimer timer;
    timer.start();
    auto outcome = std::make_shared<TimingOutcome>();
    outcome->generation = request.generation;
    outcome->plotted = request.plotMethod;
    TimingJob job =
        timingJobFor(*request.project->machining,
                     {TimingMethod::Seed, TimingMethod::ExactStop, TimingMethod::Optimal});
    job.profileMethod = request.plotMethod;
    job.profilePoints = 4000;
    outcome->limits = job.limits;
    const auto timed = timeContour(contour, job, &cancel);
    if (cancel.load()) return nullptr;
    if (!timed.ok()) {
        outcome->errors = timed.errors();
        return outcome;
    }
    outcome->lengthMm = timed.value().path.length();
    for (std::size_t m = 0; m < 3; ++m) {
        const TimingResult& r = timed.value().results[m];
        outcome->timesS[m] = r.timeS;
        outcome->converged[m] = r.converged;
        outcome->convergence[m] = r.convergence;
    }
    outcome->gridPoints = timed.value().results[2].gridPoints;
    outcome->profile = *timed.value().profile;
    outcome->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return outcome;
}

}  // namespace cam
