#pragma once
/// @file
/// @brief Editing a spline segment's control points by value: an end point, or an end's handle
/// by length and angle (the seed's way). Each edit returns the changed segment, its window
/// following the end points; a Bézier's handle moves with its end.

#include <Eigen/Core>

#include "project/project.h"

namespace cam {

/// @brief End k's handle (k = 0: P0→P1, k = 1: P3→P2), mm. A Hermite's are t0/3 and −t1/3.
[[nodiscard]] Eigen::Vector2d splineHandle(const SegmentSpec& s, int k);

/// @brief The direction of end k's handle; along the chord towards the other end when the
/// handle has no length.
[[nodiscard]] Eigen::Vector2d splineHandleDirection(const SegmentSpec& s, int k);

/// @brief Point k's coordinate `axis` (0 x, 1 y) set to v: a Bézier's P0…P3, a Hermite's p0,
/// t0, p3, t1. Moving an end point moves its handle with it (the handle keeps its length and
/// angle, as a Hermite end keeps its tangent). Requires a spline.
[[nodiscard]] SegmentSpec withControlPoint(const SegmentSpec& s, int k, int axis, double v);

/// @brief End k's handle given this length (mm), its direction kept.
[[nodiscard]] SegmentSpec withHandleLength(const SegmentSpec& s, int k, double length);

/// @brief End k's handle turned to this angle (degrees from +x), its length kept.
[[nodiscard]] SegmentSpec withHandleAngle(const SegmentSpec& s, int k, double angleDeg);

}  // namespace cam
