#include "views/plot_data.h"

namespace cam {
namespace {

QSharedPointer<QCPGraphDataContainer> containerOf(const std::vector<PlotPoint>& points) {
    QVector<QCPGraphData> data;
    data.reserve(static_cast<qsizetype>(points.size()));
    for (const PlotPoint& p : points) data.emplaceBack(p.x, p.y);
    auto container = QSharedPointer<QCPGraphDataContainer>::create();
    container->set(data, true);  // the engine made them ascending in x
    return container;
}

/// y over x, sorted by x (at a negative speed x runs from 0 down to −360°).
QSharedPointer<QCPGraphDataContainer> containerOf(const std::vector<double>& x,
                                                  const std::vector<double>& y) {
    QVector<QCPGraphData> data;
    data.reserve(static_cast<qsizetype>(x.size()));
    for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) data.emplaceBack(x[k], y[k]);
    auto container = QSharedPointer<QCPGraphDataContainer>::create();
    container->set(data, x.size() < 2 || x.front() <= x.back());
    return container;
}

}  // namespace

std::shared_ptr<const KinematicsPlotData> makeKinematicsPlotData(const ComputeResult& result,
                                                                 const std::atomic<bool>* cancel) {
    auto data = std::make_shared<KinematicsPlotData>();
    for (const PlotLevel& level : result.curves.levels) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return nullptr;
        auto& containers = data->levels.emplace_back();
        for (std::size_t c = 0; c < kCurveCount; ++c) containers[c] = containerOf(level.curves[c]);
    }
    if (const auto& design = result.design; design && !design->x.empty()) {
        for (std::size_t d = 0; d < 4; ++d) {
            data->designLaw[d] = containerOf(design->x, design->law[d]);
            if (!design->onContour[d].empty()) {
                data->designOnContour[d] = containerOf(design->x, design->onContour[d]);
            }
        }
    }
    if (!result.followerMotion[0].empty()) {
        for (std::size_t d = 0; d < 4; ++d) {
            data->followerMotion[d] = containerOf(result.followerX, result.followerMotion[d]);
        }
    }
    return data;
}

std::shared_ptr<const MachiningPlotData> makeMachiningPlotData(const TimingOutcome& outcome) {
    auto data = std::make_shared<MachiningPlotData>();
    const TimingProfile& profile = outcome.profile;
    QVector<QCPGraphData> feed;
    std::array<QVector<QCPGraphData>, 3> accel;
    for (std::size_t k = 0; k < profile.s.size(); ++k) {
        feed.append({profile.s[k], profile.speed[k]});
        for (int i = 0; i < 3; ++i) {
            accel[static_cast<std::size_t>(i)].append({profile.s[k], profile.accel[k][i]});
        }
    }
    data->feed = QSharedPointer<QCPGraphDataContainer>::create();
    data->feed->set(feed, true);
    for (std::size_t i = 0; i < 3; ++i) {
        data->accel[i] = QSharedPointer<QCPGraphDataContainer>::create();
        data->accel[i]->set(accel[i], true);
    }
    return data;
}

}  // namespace cam
