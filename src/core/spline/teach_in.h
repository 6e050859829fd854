#pragma once
/// @file
/// @brief A cascaded cubic Bézier spline through teach-in points, with automatic handles
/// (math.md §4; the seed's "Kurve 1/2/3").

#include <Eigen/Core>
#include <vector>

#include "common/diagnostic.h"
#include "geometry/bezier.h"
#include "project/project.h"

namespace cam {

/// @brief How the handles at each knot are placed.
enum class HandleRule {
    /// Parallel to the chord joining the midpoints of the two adjacent legs; total length that
    /// chord, split in the ratio of the legs.
    Chord,
    /// Tangent to the circle through the knot and its two neighbours; each handle a third of
    /// its leg.
    Circumcircle,
    /// Direction as Circumcircle; length κ·R from the opening angle of the leg on that circle
    /// (κ = 4/3·tan(θ/4)), so points on a circle give that circle.
    Oval,
};

/// @brief One Bézier per leg (n legs for n closed points, n − 1 open). Handles point along the
/// direction of travel at every knot, whichever way the points turn, so no leg loops back;
/// `bulge` scales every handle's length. At the ends of an open spline the handle follows its
/// leg. Knots must be distinct (consecutive ones at least 1e-9 mm apart).
[[nodiscard]] Result<std::vector<CubicBezier>> splineThroughPoints(
    const std::vector<Eigen::Vector2d>& knots, bool closed, HandleRule rule, double bulge = 1.0);

/// @brief A closed contour of Bézier segments through the points (counter-clockwise around the
/// rotation centre), with windows from the knots' polar angles; validated.
[[nodiscard]] Result<std::vector<SegmentSpec>> contourThroughPoints(
    const std::vector<Eigen::Vector2d>& knots, HandleRule rule, double bulge = 1.0);

}  // namespace cam
