#pragma once
/// @file
/// @brief What the compute engine hands back: immutable, shared, plain data (no plotting
/// library types). What a view needs beyond that it prepares itself in the worker thread,
/// through a PlotDataPreparer (plot_data_preparer.h).

#include <QMetaType>
#include <QPointF>
#include <QVector>
#include <array>
#include <atomic>
#include <memory>
#include <optional>

#include "analysis/analysis.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "engine/plot_levels.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "kinematics/kinematics.h"
#include "project/project.h"
#include "spline/path_study.h"
#include "timing/machining_time.h"

namespace cam {

class PlotDataPreparer;

/// @brief Opaque data a view derived from a result in the worker thread, ready to draw (for
/// instance the plotting library's containers). The engine only carries it.
class PreparedPlotData {
public:
    virtual ~PreparedPlotData() = default;
};
using PreparedPlotDataPtr = std::shared_ptr<const PreparedPlotData>;

struct ComputeRequest {
    std::uint64_t generation = 0;
    std::shared_ptr<const Project> project;
    PlotAxis axis = PlotAxis::Angle;
    bool timing = false;  ///< also compute the machining times (when the panel is shown)
    TimingMethod plotMethod = TimingMethod::Optimal;
};

/// @brief One finished computation. Never modified after it leaves the worker.
struct ComputeResult {
    std::uint64_t generation = 0;
    std::shared_ptr<const Project> project;
    PlotAxis axis = PlotAxis::Angle;
    /// Non-empty: nothing was computed — the project has problems, or the computation failed
    /// (`failed`); the views mark what they still show as out of date.
    Diagnostics errors;
    bool failed = false;  ///< the computation itself failed (e.g. out of memory)
    std::optional<Contour> contour;
    double omega = 0.0;           ///< rad/s
    double period = 0.0;          ///< s
    std::size_t sampleCount = 0;  ///< samples per turn that were computed (in chunks)
    ContourAnalysis analysis;
    /// Per segment, its outline for the contour view (x, y in mm), ends included.
    std::vector<QVector<QPointF>> outlines;
    /// The kinematics curves over angle or time at several resolutions, with their ranges.
    PlotCurves curves;
    double computeMs = 0.0;
    /// The path study of the contour's spline segments, in contour order (empty: none).
    PathStudy pathStudy;
    /// The project's follower on the contour (null when the project names none, or when it
    /// cannot ride this contour: then followerErrors says why), and its design checks.
    std::shared_ptr<const FollowerModel> follower;
    Diagnostics followerErrors;
    FollowerAnalysis followerChecks;
    /// The pressure angle (deg) over the turn at kFollowerCurvePoints + 1 equal time steps, on
    /// the plots' x axis (degrees or seconds, as `curves`).
    std::vector<double> followerX, followerPressureDeg;
    static constexpr std::size_t kFollowerCurvePoints = 3600;
    /// What the views' preparer made of this result (null without a preparer).
    PreparedPlotDataPtr prepared;

    [[nodiscard]] bool ok() const { return errors.empty() && contour.has_value(); }
};

using ComputeResultPtr = std::shared_ptr<const ComputeResult>;

/// @brief The machining times of one request: computed after its kinematics, reported apart so
/// the plots never wait for them.
struct TimingOutcome {
    std::uint64_t generation = 0;
    Diagnostics errors;  ///< non-empty: no tool path (e.g. the tool is wider than a notch)
    std::array<double, 3> timesS{};  ///< seed, exact stop, optimal
    /// Per method: whether the planner's refinement reached its tolerance (the seed always
    /// does), and the estimated relative error of its time (TimingResult).
    std::array<bool, 3> converged{true, true, true};
    std::array<double, 3> convergence{};
    std::size_t gridPoints = 0;  ///< of the optimal plan
    double lengthMm = 0.0;
    TimingMethod plotted = TimingMethod::Optimal;
    MachineLimits limits;
    /// Feed (mm/s) and per-axis acceleration (mm/s²) over the path length (mm).
    TimingProfile profile;
    double computeMs = 0.0;
    /// What the views' preparer made of this outcome (null without a preparer).
    PreparedPlotDataPtr prepared;
};
using TimingOutcomePtr = std::shared_ptr<const TimingOutcome>;

/// @brief Tool path, the three times and the profile of the plotted method. Null if cancelled.
TimingOutcomePtr computeTiming(const ComputeRequest& request, const Contour& contour,
                               const std::atomic<bool>& cancel);

/// @brief Does the whole computation for one request; polls `cancel`. Returns null if
/// cancelled. With a preparer, its data for the views is made here too (in the caller's
/// thread, the worker's).
ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel,
                                const PlotDataPreparer* preparer = nullptr);

/// @brief A result that says the computation failed and why (the message is shown as is).
ComputeResultPtr failedResult(const ComputeRequest& request, const std::string& message);

}  // namespace cam

Q_DECLARE_METATYPE(cam::ComputeResultPtr)
Q_DECLARE_METATYPE(cam::TimingOutcomePtr)
