#include "engine/compute_result.h"

#include <QElapsedTimer>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "timing/timing_job.h"

namespace cam {
namespace {

constexpr int kOutlinePointsPerSegment = 160;

void buildOutlines(ComputeResult& r) {
    const Contour& c = *r.contour;
    r.outlines.resize(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) {
        const ContourSegment& s = c.segment(k);
        QVector<QPointF>& out = r.outlines[k];
        out.reserve(kOutlinePointsPerSegment + 1);
        for (int i = 0; i <= kOutlinePointsPerSegment; ++i) {
            const double phi = s.phiStart + (s.phiEnd - s.phiStart) * i / kOutlinePointsPerSegment;
            const double rr = s.evaluate(phi).r;
            out.append({rr * std::cos(phi), rr * std::sin(phi)});
        }
    }
}

void buildCurves(ComputeResult& r) {
    const SampledTurn& t = r.turn;
    const std::vector<double>* sources[] = {&t.vR, &t.vPhi, &t.v,    &t.aR, &t.aPhi,
                                            &t.a,  &t.jR,   &t.jPhi, &t.j};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const bool angle = r.axis == PlotAxis::Angle;
    const std::size_t n = t.size();
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) x[k] = angle ? radToDeg(t.phi[k]) : t.t[k];
    const bool ascending = !angle || r.omega > 0.0;
    r.xRange = QCPRange(std::min(x.front(), x.back()), std::max(x.front(), x.back()));
    const std::size_t bucket = std::max<std::size_t>(1, n / ComputeResult::kEnvelopeBuckets);

    for (int c = 0; c < static_cast<int>(Curve::Count); ++c) {
        const std::vector<double>& y = *sources[c];
        QVector<QCPGraphData> full, envelope;
        full.reserve(static_cast<int>(n + r.contour->size() + 1));
        envelope.reserve(static_cast<int>(2 * (n / bucket) + 2 * r.contour->size() + 4));
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        std::size_t runStart = 0;
        for (std::size_t k = 0; k <= n; ++k) {
            const bool runEnds = k == n || (k > 0 && t.segment[k] != t.segment[k - 1]);
            if (runEnds && k > runStart) {
                if (runStart > 0) envelope.append({x[runStart], nan});
                // Min and max of each bucket of this run, in x order.
                for (std::size_t b = runStart; b < k; b += bucket) {
                    const std::size_t e = std::min(k, b + bucket);
                    std::size_t iMin = b, iMax = b;
                    for (std::size_t i = b; i < e; ++i) {
                        if (y[i] < y[iMin]) iMin = i;
                        if (y[i] > y[iMax]) iMax = i;
                    }
                    const std::size_t first = std::min(iMin, iMax), second = std::max(iMin, iMax);
                    envelope.append({x[first], y[first]});
                    if (second != first) envelope.append({x[second], y[second]});
                }
                runStart = k;
            }
            if (k == n) break;
            if (k > 0 && t.segment[k] != t.segment[k - 1]) full.append({x[k], nan});
            full.append({x[k], y[k]});
            lo = std::min(lo, y[k]);
            hi = std::max(hi, y[k]);
        }
        auto fullContainer = QSharedPointer<QCPGraphDataContainer>::create();
        fullContainer->set(full, ascending);
        auto envelopeContainer = QSharedPointer<QCPGraphDataContainer>::create();
        envelopeContainer->set(envelope, ascending);
        r.curves[static_cast<std::size_t>(c)] = fullContainer;
        r.envelopes[static_cast<std::size_t>(c)] = envelopeContainer;
        QCPRange& range = r.plotRanges[static_cast<std::size_t>(c / 3)];
        range = c % 3 == 0 ? QCPRange(lo, hi)
                           : QCPRange(std::min(range.lower, lo), std::max(range.upper, hi));
    }
}

}  // namespace

ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel) {
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
    const auto n = static_cast<std::size_t>(request.project->samplesPerTurnOrDefault());
    if (!sampleTurn(*result->contour, result->omega, n, result->turn, &cancel)) return nullptr;
    if (cancel.load()) return nullptr;
    result->analysis = analyzeContour(*result->contour, result->omega);
    buildOutlines(*result);
    std::vector<CubicBezier> splines;
    for (const SegmentSpec& spec : request.project->contour) {
        if (isSpline(spec.type())) splines.push_back(bezierOf(spec));
    }
    if (!splines.empty()) result->pathStudy = studyPath(splines, 100);
    if (cancel.load()) return nullptr;
    buildCurves(*result);
    result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
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
    for (std::size_t m = 0; m < 3; ++m) outcome->timesS[m] = timed.value().results[m].timeS;
    outcome->gridPoints = timed.value().results[2].gridPoints;
    const TimingProfile& profile = *timed.value().profile;
    QVector<QCPGraphData> feed;
    std::array<QVector<QCPGraphData>, 3> accel;
    for (std::size_t k = 0; k < profile.s.size(); ++k) {
        feed.append({profile.s[k], profile.speed[k]});
        for (int i = 0; i < 3; ++i) {
            accel[static_cast<std::size_t>(i)].append({profile.s[k], profile.accel[k][i]});
        }
    }
    outcome->feed = QSharedPointer<QCPGraphDataContainer>::create();
    outcome->feed->set(feed, true);
    for (std::size_t i = 0; i < 3; ++i) {
        outcome->accel[i] = QSharedPointer<QCPGraphDataContainer>::create();
        outcome->accel[i]->set(accel[i], true);
    }
    outcome->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return outcome;
}

}  // namespace cam
