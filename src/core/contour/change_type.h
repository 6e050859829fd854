#pragma once
/// @file
/// @brief Another kind of segment through the same two end points (the table's Type column).

#include "project/project.h"

namespace cam {

/// @brief The segment as a `type` through the same window ends, so the contour stays closed:
/// Bézier ↔ Hermite is the same curve exactly (t = 3·handle); a line becomes its ⅓-chord
/// Bézier and a spline a line through its end points; an arc becomes its κ-approximation
/// (handles κ·R, κ = 4/3·tan(θ/4), math.md §4) or the chord line; to an arc, a segment becomes
/// the circle through its two ends and its middle point. The window is kept. Where the ray
/// misses the old curve at a window end, the end point falls back to the unit ray direction,
/// so an invalid row still converts to something drawable.
[[nodiscard]] SegmentSpec withType(const SegmentSpec& segment, SegmentType type);

}  // namespace cam
