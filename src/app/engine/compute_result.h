#pragma once
/// @file
/// @brief What the compute engine hands back: immutable, shared, ready to draw.

#include <qcustomplot.h>

#include <QSharedPointer>
#include <array>
#include <memory>
#include <optional>

#include "analysis/analysis.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "kinematics/kinematics.h"
#include "project/project.h"
#include "spline/path_study.h"
#include "timing/machining_time.h"

namespace cam {

/// @brief The x axis of the kinematics plots.
enum class PlotAxis { Angle, Time };

/// @brief The curves of the kinematics plots, in this order.
enum class Curve { VR, VPhi, V, AR, APhi, A, JR, JPhi, J, Count };

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
    Diagnostics errors;  ///< non-empty: the project could not be computed
    std::optional<Contour> contour;
    double omega = 0.0;   ///< rad/s
    double period = 0.0;  ///< s
    SampledTurn turn;
    ContourAnalysis analysis;
    /// Per segment, its outline for the contour view (x, y in mm), ends included.
    std::vector<QVector<QPointF>> outlines;
    /// Plot data over angle (deg) or time (s), with NaN gaps where the segment changes so a
    /// jump shows as a jump.
    std::array<QSharedPointer<QCPGraphDataContainer>, static_cast<int>(Curve::Count)> curves;
    /// The same curves reduced to the minimum and maximum of each of kEnvelopeBuckets buckets
    /// (per segment run, so joints still break the line): what a plot of the whole turn draws.
    std::array<QSharedPointer<QCPGraphDataContainer>, static_cast<int>(Curve::Count)> envelopes;
    static constexpr int kEnvelopeBuckets = 4096;
    /// y range of each plot (velocity, acceleration, jerk) over all of its curves.
    std::array<QCPRange, 3> plotRanges;
    /// x range of the plotted turn.
    QCPRange xRange;
    double computeMs = 0.0;
    /// The path study of the contour's spline segments, in contour order (empty: none).
    PathStudy pathStudy;

    [[nodiscard]] bool ok() const { return errors.empty() && contour.has_value(); }
};

using ComputeResultPtr = std::shared_ptr<const ComputeResult>;

/// @brief The machining times of one request: computed after its kinematics, reported apart so
/// the plots never wait for them.
struct TimingOutcome {
    std::uint64_t generation = 0;
    Diagnostics errors;  ///< non-empty: no tool path (e.g. the tool is wider than a notch)
    std::array<double, 3> timesS{};  ///< seed, exact stop, optimal
    std::size_t gridPoints = 0;      ///< of the optimal plan
    double lengthMm = 0.0;
    TimingMethod plotted = TimingMethod::Optimal;
    MachineLimits limits;
    /// Feed (mm/s) and per-axis acceleration (mm/s²) over the path length (mm).
    QSharedPointer<QCPGraphDataContainer> feed;
    std::array<QSharedPointer<QCPGraphDataContainer>, 3> accel;
    double computeMs = 0.0;
};
using TimingOutcomePtr = std::shared_ptr<const TimingOutcome>;

/// @brief Tool path, the three times and the profile of the plotted method. Null if cancelled.
TimingOutcomePtr computeTiming(const ComputeRequest& request, const Contour& contour,
                               const std::atomic<bool>& cancel);

/// @brief Does the whole computation for one request; polls `cancel`. Returns null if cancelled.
ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel);

}  // namespace cam

Q_DECLARE_METATYPE(cam::ComputeResultPtr)
Q_DECLARE_METATYPE(cam::TimingOutcomePtr)
