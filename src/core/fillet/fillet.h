#pragma once
/// @file
/// @brief Switch arcs (fillets): round a corner of the contour by an arc tangent to both
/// neighbours (math.md §5, seed 002).

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief rho_min = V² / (vae · ACv): the smallest switch radius for speed V [mm/s] at the
/// joint, vector acceleration ACv [mm/s²] and admissible acceleration error vae (dimensionless)
/// (math.md §5, seed 002). NaN unless accel > 0 and admissibleError > 0.
[[nodiscard]] double minimumSwitchRadius(double speed, double accel, double admissibleError);

/// @brief The radii a fillet at one joint may have: minRadius <= rho < maxRadius.
///
/// minRadius is always kMinLengthMm (1e-6 mm), the smallest radius a project holds: geometry
/// sets no lower bound (the speed does, see minimumSwitchRadius). maxRadius is where the first
/// condition fails as rho grows from minRadius: a tangent point reaches the far end of its
/// segment, no circle of that radius touches both neighbours inside the corner any more, or the
/// follower ray would meet the fillet twice. It is at most 1e6 mm, the largest length a project
/// holds.
struct FilletRange {
    double minRadius = kMinLengthMm;
    double maxRadius = 0.0;
};

/// @brief A contour with one corner rounded.
struct FilletResult {
    /// The new contour, one segment longer: the fillet arc sits between contour[K-1] and
    /// contour[K], i.e. at index K, or at the end when K = 0 (so the first segment stays first).
    std::vector<SegmentSpec> contour;
    Eigen::Vector2d center{0.0, 0.0};         ///< centre of the fillet arc
    double radius = 0.0;                      ///< its radius, the rho asked for
    Eigen::Vector2d tangentPoint1{0.0, 0.0};  ///< where it touches contour[K-1]
    Eigen::Vector2d tangentPoint2{0.0, 0.0};  ///< where it touches contour[K]
};

/// @brief Replace the corner at joint K (between contour[K-1] and contour[K]; K = 0 is the joint
/// between the last and the first segment) by an arc of radius rho tangent to both neighbours.
///
/// The neighbours are arcs or lines (line–line, line–arc, arc–line, arc–arc). The fillet lies
/// inside the corner: at a convex corner (the contour turns left, it runs counter-clockwise
/// around the origin) its centre is on the material side and it cuts material away; at a
/// concave corner (turning right) its centre is outside and it fills the notch. Both tangent
/// points lie inside the current windows of their segments. The trimmed neighbours get new
/// windows (lines: the tangent point becomes `to`/`from`, the window follows from
/// lineWindowDeg; arcs: the window boundary moves to the tangent point's polar angle). The new
/// arc's window runs from the polar angle of tangent point 1 to that of tangent point 2; its
/// branch is "outer" at a convex corner (it runs counter-clockwise about its centre, so the
/// ray meets its far side) and "inner" at a concave one. The arc holds nothing but its circle
/// and window; switching its type to a line in the table joins its window ends, the chamfer.
///
/// Errors, located "contour[K-1]/contour[K]": the contour does not validate (its own
/// diagnostics follow), a neighbour is neither an arc nor a line, the joint is already tangent
/// (G1: there is no corner), or rho is not in the feasible range; the message then states both
/// the requested radius and the range, e.g. "radius 25 mm is too large: only radii below 20 mm
/// fit (the tangent point would leave contour[0])".
[[nodiscard]] Result<FilletResult> filletJoint(const std::vector<SegmentSpec>& contour,
                                               std::size_t joint, double rho);

/// @brief The feasible radii at joint K (see FilletRange), found by a scan in rho and
/// bisection to ~1e-13 relative (the scan starts at minRadius: radii below it that fit, or a
/// gap below it, do not count). The same errors as filletJoint, and one when no radius of at
/// least minRadius fits, so a range always has minRadius < maxRadius.
[[nodiscard]] Result<FilletRange> filletRange(const std::vector<SegmentSpec>& contour,
                                              std::size_t joint);

}  // namespace cam
