#pragma once
/// @file
/// @brief Splines as tool paths: each Bézier piece replaced by tangent-continuous arc pairs
/// (biarcs) within a tolerance, so the machining-time planner sees lines and arcs only.

#include <atomic>
#include <vector>

#include "geometry/bezier.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief Arcs (and lines where straight) following the Bézier within `toleranceMm`, tangent to
/// it at both ends and to each other (G1), at height z. Pieces are halved until each biarc fits.
/// If `cancel` is set while it works, it stops early and returns what it has (incomplete: the
/// caller, which polls the same flag, discards it).
[[nodiscard]] std::vector<PathSegment> biarcsOf(const CubicBezier& curve, double toleranceMm,
                                                double z = 0.0,
                                                const std::atomic<bool>* cancel = nullptr);

/// @brief An open tool path through a spline: the biarcs of all its pieces.
[[nodiscard]] ToolPath toolPathFromSpline(const std::vector<CubicBezier>& pieces,
                                          double toleranceMm, double z = 0.0);

/// @brief Largest distance from the curve (sampled densely) to the segments: how well they fit.
[[nodiscard]] double fitError(const CubicBezier& curve, const std::vector<PathSegment>& segments);

}  // namespace cam
