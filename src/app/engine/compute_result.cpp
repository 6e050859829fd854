#include "engine/compute_result.h"

#include <QElapsedTimer>
#include <QFuture>
#include <QScopeGuard>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "engine/plot_data_preparer.h"
#include "follower/follower_turn.h"
#include "timing/timing_job.h"

namespace cam {
namespace {

/// Points per segment outline: 160 intervals for a few segments, fewer for many, so that the
/// contour view never holds much more than kOutlinePointsTotal points (100,000 segments would
/// otherwise be 16 million points to copy and draw); at least 8 intervals each.
constexpr int kOutlineIntervalsPerSegment = 160;
constexpr int kOutlineIntervalsMin = 8;
constexpr std::size_t kOutlinePointsTotal = 1u << 18;

void buildOutlines(ComputeResult& r) {
    const Contour& c = *r.contour;
    r.outlines.resize(c.size());
    const int intervals = static_cast<int>(
        std::clamp<std::size_t>(kOutlinePointsTotal / std::max<std::size_t>(c.size(), 1),
                                kOutlineIntervalsMin, kOutlineIntervalsPerSegment));
    for (std::size_t k = 0; k < c.size(); ++k) {
        const ContourSegment& s = c.segment(k);
        QVector<QPointF>& out = r.outlines[k];
        out.reserve(intervals + 1);
        for (int i = 0; i <= intervals; ++i) {
            const double phi = s.phiStart + (s.phiEnd - s.phiStart) * i / intervals;
            const double rr = s.evaluate(phi).r;
            out.append({rr * std::cos(phi), rr * std::sin(phi)});
        }
    }
}

/// The follower on the contour: placed, its design checks and its pressure-angle curve.
struct FollowerPart {
    std::shared_ptr<const FollowerModel> model;
    Diagnostics errors;
    FollowerAnalysis checks;
    std::vector<double> x, pressureDeg;
};

FollowerPart computeFollower(const Contour* contour, const FollowerSpec& spec, double omega,
                             double period, PlotAxis axis, const std::atomic<bool>* cancel) {
    FollowerPart part;
    auto follower = FollowerModel::build(*contour, spec);
    if (!follower.ok()) {
        part.errors = follower.errors();
        return part;
    }
    auto model = std::make_shared<const FollowerModel>(std::move(follower).value());
    if (cancel->load()) return part;
    part.checks = analyzeFollower(*model, omega, contour->phiBegin());
    constexpr std::size_t n = ComputeResult::kFollowerCurvePoints;
    FollowerTurn turn;
    if (!sampleFollowerTurn(*model, omega, n, turn, cancel)) return part;
    part.x.resize(n + 1);
    part.pressureDeg.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const double t = period * static_cast<double>(k) / n;
        part.x[k] = axis == PlotAxis::Angle ? radToDeg(omega * t) : t;
        // The turn's end closes the curve: the angle of its start, one turn on.
        part.pressureDeg[k] = radToDeg(turn.pressureAngle[k % n]);
    }
    part.model = std::move(model);
    return part;
}

}  // namespace

ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel,
                                const PlotDataPreparer* preparer) {
    QElapsedTimer timer;
    timer.start();
    auto result = std::make_shared<ComputeResult>();
    result->generation = request.generation;
    result->project = request.project;
    result->axis = request.axis;
    // Joints that do not meet are drawn (r jumps there) rather than blanking the plots while
    // the designer edits; the document still reports them and refuses to save.
    auto contour = Contour::build(*request.project, ValidationOptions{.checkJoints = false});
    if (!contour.ok()) {
        result->errors = contour.errors();
        result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
        return result;
    }
    result->contour = std::move(contour).value();
    result->omega = request.project->motion.omegaRadS();
    result->period = kTwoPi / std::abs(result->omega);
    // The follower needs only the contour: on the pool's other core while this thread samples
    // the turn (a swinging arm's design checks cost about as much as the kinematics).
    QFuture<FollowerPart> follower;
    if (request.project->follower) {
        follower = QtConcurrent::run(computeFollower, &*result->contour, *request.project->follower,
                                     result->omega, result->period, request.axis, &cancel);
    }
    // Every early return below waits for it: it reads the contour this result owns.
    const auto waitForFollower = qScopeGuard([&] {
        if (follower.isValid()) follower.waitForFinished();
    });
    result->sampleCount = static_cast<std::size_t>(request.project->samplesPerTurnOrDefault());
    if (!buildPlotCurves(*result->contour, result->omega, result->sampleCount, request.axis,
                         result->curves, cancel)) {
        return nullptr;
    }
    result->analysis = analyzeContour(*result->contour, result->omega, &cancel);
    if (cancel.load()) return nullptr;
    buildOutlines(*result);
    std::vector<CubicBezier> splines;
    for (const SegmentSpec& spec : request.project->contour) {
        if (isSpline(spec.type())) splines.push_back(bezierOf(spec));
    }
    if (!splines.empty()) result->pathStudy = studyPath(splines, 100);
    if (cancel.load()) return nullptr;
    if (follower.isValid()) {
        // The follower was computed beside all of the above; it has finished or stops soon.
        FollowerPart part = follower.result();
        if (cancel.load()) return nullptr;
        result->follower = std::move(part.model);
        result->followerErrors = std::move(part.errors);
        result->followerChecks = std::move(part.checks);
        result->followerX = std::move(part.x);
        result->followerPressureDeg = std::move(part.pressureDeg);
    }
    if (preparer) {
        result->prepared = preparer->prepare(*result, cancel);
        if (cancel.load()) return nullptr;
    }
    result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return result;
}

ComputeResultPtr failedResult(const ComputeRequest& request, const std::string& message) {
    auto result = std::make_shared<ComputeResult>();
    result->generation = request.generation;
    result->project = request.project;
    result->axis = request.axis;
    result->errors = {Diagnostic{"", message}};
    result->failed = true;
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
