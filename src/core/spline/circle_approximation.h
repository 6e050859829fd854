#pragma once
/// @file
/// @brief Circular arcs as cubic Béziers: handles of length κ·R, κ = 4/3·tan(θ/4) (math.md §4).

#include <Eigen/Core>
#include <vector>

#include "common/diagnostic.h"
#include "geometry/bezier.h"
#include "project/project.h"

namespace cam {

/// @brief The single Bézier for the arc of radius R about `center` from angle a0 through the
/// signed sweep θ (|θ| <= π/2 keeps it accurate).
[[nodiscard]] CubicBezier bezierArc(const Eigen::Vector2d& center, double radius, double a0,
                                    double sweep);

/// @brief Largest |distance from the centre − R| / R along one κ-Bézier of opening θ.
[[nodiscard]] double bezierArcRadialError(double sweep);

struct ArcApproximation {
    std::vector<CubicBezier> pieces;
    double radialErrorMm = 0.0;  ///< achieved, largest over the pieces
    /// |B'| at the ends over |B'| in the middle of a piece (1 = uniform speed in s).
    double speedRatio = 1.0;
};

/// @brief The fewest equal pieces whose radial error is at most `maxErrorMm`.
[[nodiscard]] ArcApproximation approximateArc(const Eigen::Vector2d& center, double radius,
                                              double a0, double sweep, double maxErrorMm);

/// @brief contour[k] (an arc) replaced by Bézier segments within `maxErrorMm`; the end points
/// and so the joints are exact. Errors name the segment.
[[nodiscard]] Result<std::vector<SegmentSpec>> approximateArcSegment(
    const std::vector<SegmentSpec>& contour, std::size_t k, double maxErrorMm,
    ArcApproximation* report = nullptr);

}  // namespace cam
