#include "engine/compute_result.h"

#include <QElapsedTimer>
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
    if (request.project->follower) {
        auto follower = FollowerModel::build(*result->contour, *request.project->follower);
        if (follower.ok()) {
            auto model = std::make_shared<const FollowerModel>(std::move(follower).value());
            if (cancel.load()) return nullptr;
            result->followerChecks =
                analyzeFollower(*model, result->omega, result->contour->phiBegin());
            constexpr std::size_t n = ComputeResult::kFollowerCurvePoints;
            FollowerTurn turn;
            if (!sampleFollowerTurn(*model, result->omega, n, turn, &cancel)) return nullptr;
            result->followerX.resize(n + 1);
            result->followerPressureDeg.resize(n + 1);
            for (std::size_t k = 0; k <= n; ++k) {
                const double t = result->period * static_cast<double>(k) / n;
                const double phi = result->omega * t;
                result->followerX[k] = request.axis == PlotAxis::Angle ? radToDeg(phi) : t;
                // The turn's end closes the curve: the angle of its start, one turn on.
                result->followerPressureDeg[k] = radToDeg(turn.pressureAngle[k % n]);
            }
            result->follower = std::move(model);
        } else {
            result->followerErrors = follower.errors();
        }
        if (cancel.load()) return nullptr;
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
