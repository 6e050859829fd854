#include "engine/compute_result.h"

#include <QElapsedTimer>
#include <cmath>
#include <limits>

#include "common/angles.h"

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
    for (int c = 0; c < static_cast<int>(Curve::Count); ++c) {
        QVector<QCPGraphData> data;
        data.reserve(static_cast<int>(t.size() + r.contour->size() + 1));
        const std::vector<double>& y = *sources[c];
        for (std::size_t k = 0; k < t.size(); ++k) {
            const double x = angle ? radToDeg(t.phi[k]) : t.t[k];
            if (k > 0 && t.segment[k] != t.segment[k - 1]) {
                data.append({x, nan});  // break the line at a joint
            }
            data.append({x, y[k]});
        }
        auto container = QSharedPointer<QCPGraphDataContainer>::create();
        container->set(data, !angle || r.omega > 0.0);
        r.curves[static_cast<std::size_t>(c)] = container;
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
    auto contour = Contour::build(*request.project);
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
    if (cancel.load()) return nullptr;
    buildCurves(*result);
    result->computeMs = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return result;
}

}  // namespace cam
