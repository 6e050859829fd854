#pragma once
/// @file
/// @brief Design from motion (math.md §8): the project's design and follower → the exact
/// profile → an arc table within the tolerance, and what the arcs cost the motion.

#include <atomic>
#include <cstddef>
#include <optional>
#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

struct SynthesisReport {
    std::size_t segments = 0;
    double maxDeviationMm = 0.0;  ///< the arc table's largest distance from the exact profile
    /// The follower placed by contact on the arc table against the design, over the turn: its
    /// coordinate (mm, or degrees on an arm), velocity (mm/s or °/s) and acceleration (mm/s² or
    /// °/s²) at the project's speed. The arc table is only C1: the acceleration jumps at joints.
    double maxLiftError = 0.0;
    double maxVelocityError = 0.0;
    double maxAccelerationError = 0.0;
    std::size_t checkedAngles = 0;
    Diagnostics notes;  ///< velocity/acceleration jumps of the design, pressure angle beyond limit
};

struct Synthesis {
    std::vector<SegmentSpec> contour;
    SynthesisReport report;
};

/// @brief The arc table for `project`'s design and follower (a knife on the radial line when it
/// names none) within `tolerance` (the design's when not given). Errors, located: no design,
/// an invalid design, a base circle the follower cannot reach, undercut (with its angles), a
/// pressure angle beyond the limit when `strictPressureAngle` or the design asks for it
/// (DesignSpec::strictPressureAngle). Empty errors: cancelled.
[[nodiscard]] Result<Synthesis> synthesize(const Project& project,
                                           std::optional<double> tolerance = std::nullopt,
                                           bool strictPressureAngle = false,
                                           const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
