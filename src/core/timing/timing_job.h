#pragma once
/// @file
/// @brief The machining-time pipeline in one place: the tool path (from the contour, or given),
/// then the methods asked for on it, and for plots one method's profile. The CLI's `timing` and
/// the app's Machining panel both run it.

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "project/project.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief What to compute.
struct TimingJob {
    double toolRadiusMm = 0.0;  ///< offset of the tool path from the contour (timeContour only)
    MachineLimits limits;
    std::vector<TimingMethod> methods;  ///< one result per method, in this order
    /// Also the feed and axis-acceleration profile of this method, on about profilePoints points.
    std::optional<TimingMethod> profileMethod;
    std::size_t profilePoints = 4000;
    /// Where the seed step came from, for its errors: `machining.step` (a project's), `--step`.
    Field stepField = Field::MachiningStep;
};

/// @brief The job a project's `machining` section describes: its tool radius and its limits.
[[nodiscard]] TimingJob timingJobFor(const MachiningSpec& machining,
                                     std::vector<TimingMethod> methods);

/// @brief What a job gives.
struct TimedPath {
    ToolPath path;
    std::vector<TimingResult> results;     ///< per requested method, in the job's order
    std::optional<TimingProfile> profile;  ///< when the job asked for one
};

/// @brief The contour's tool path (toolPathFromContour with the job's tool radius), then the
/// job on it. Errors: the tool path's, located `contour[k]`; the limits', located as
/// machiningTime does (`accel[i]`, `feed`, …); a seed step too small for the path (more than
/// kMaxSeedSteps steps), located at `stepField`, before any work; or {"", "cancelled"} once
/// `cancel` is set, which every step polls.
[[nodiscard]] Result<TimedPath> timeContour(const Contour& contour, const TimingJob& job,
                                            const std::atomic<bool>* cancel = nullptr);

/// @brief The job on a given tool path (a point list, a spline's biarcs); the tool radius is
/// not used. Errors as timeContour's, without the tool path's.
[[nodiscard]] Result<TimedPath> timePath(ToolPath path, const TimingJob& job,
                                         const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
