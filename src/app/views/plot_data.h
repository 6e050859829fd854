#pragma once
/// @file
/// @brief The views' side of the engine's PlotDataPreparer: QCustomPlot containers made from a
/// result in the worker thread, so that the GUI thread only hands them to the graphs.

#include <qcustomplot.h>

#include <array>
#include <vector>

#include "engine/plot_data_preparer.h"

namespace cam {

/// @brief The kinematics curves of a result as graph containers, level for level and curve
/// for curve as in ComputeResult::curves.
struct KinematicsPlotData : PreparedPlotData {
    std::vector<std::array<QSharedPointer<QCPGraphDataContainer>, kCurveCount>> levels;
    /// The motion design (ComputeResult::design): lift, velocity, acceleration and jerk of the
    /// law and of the follower on the contour (null where the result has none).
    std::array<QSharedPointer<QCPGraphDataContainer>, 4> designLaw, designOnContour;
    /// The follower's lift, velocity, acceleration and jerk (ComputeResult::followerMotion;
    /// null without a follower).
    std::array<QSharedPointer<QCPGraphDataContainer>, 4> followerMotion;
};

/// @brief Feed and per-axis accelerations of a machining-time outcome.
struct MachiningPlotData : PreparedPlotData {
    QSharedPointer<QCPGraphDataContainer> feed;
    std::array<QSharedPointer<QCPGraphDataContainer>, 3> accel;
};

/// @brief Makes the containers (any thread). Null if cancelled.
std::shared_ptr<const KinematicsPlotData> makeKinematicsPlotData(const ComputeResult& result,
                                                                 const std::atomic<bool>* cancel);
std::shared_ptr<const MachiningPlotData> makeMachiningPlotData(const TimingOutcome& outcome);

/// @brief What the main window installs in the engine.
class QcpPlotDataPreparer : public PlotDataPreparer {
public:
    [[nodiscard]] PreparedPlotDataPtr prepare(const ComputeResult& result,
                                              const std::atomic<bool>& cancel) const override {
        return makeKinematicsPlotData(result, &cancel);
    }
    [[nodiscard]] PreparedPlotDataPtr prepareTiming(const TimingOutcome& outcome) const override {
        return makeMachiningPlotData(outcome);
    }
};

}  // namespace cam
