#pragma once
/// @file
/// @brief A 3D tool path of straight lines and circular arcs (arcs lie in a plane z = const).

#include <Eigen/Core>
#include <atomic>
#include <string>
#include <vector>

#include "common/diagnostic.h"
#include "contour/contour.h"

namespace cam {

/// @brief One piece of a tool path, parameterised by arc length s in [0, length()].
struct PathSegment {
    enum class Kind { Line, Arc };
    Kind kind = Kind::Line;
    Eigen::Vector3d start{0, 0, 0};
    Eigen::Vector3d end{0, 0, 0};
    // Arc only: centre in the XY plane, radius, polar angle of `start` about the centre, and
    // the signed sweep (rad, + counter-clockwise).
    Eigen::Vector2d center{0, 0};
    double radius = 0.0;
    double startAngle = 0.0;
    double sweep = 0.0;

    static PathSegment line(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
    /// @brief Arc at height z around `center`, from polar angle `startAngle` (rad, about the
    /// centre) through the signed `sweep`.
    static PathSegment arc(const Eigen::Vector2d& center, double radius, double startAngle,
                           double sweep, double z);

    [[nodiscard]] double length() const;
    [[nodiscard]] Eigen::Vector3d point(double s) const;
    /// @brief Unit tangent q'(s).
    [[nodiscard]] Eigen::Vector3d tangent(double s) const;
    /// @brief q''(s): zero on lines, the curvature vector (towards the centre, 1/R) on arcs.
    [[nodiscard]] Eigen::Vector3d curvature(double s) const;
};

struct ToolPath {
    std::vector<PathSegment> segments;
    [[nodiscard]] double length() const;
};

/// @brief One point of a point list: position (mm) and the DXF bulge of the move to the next
/// point (tan of a quarter of the included angle, + counter-clockwise; 0 = straight).
struct PathPoint {
    Eigen::Vector3d position{0, 0, 0};
    double bulge = 0.0;
};

/// @brief Coordinates of a point list, and every point of its arcs, are at most this, mm.
inline constexpr double kMaxPathCoordinateMm = 1e6;

/// @brief A bulge of at most this magnitude makes a straight segment: such an arc turns from its
/// chord by at most 2e-9 rad at its ends (a hundredth of the tangent tolerance,
/// kTangentToleranceDeg) and bulges out by at most 5e-10 of the chord's length. (Taken as an
/// arc, a bulge of 1e-300 would put the centre 1e300 chord lengths away.)
inline constexpr double kStraightBulge = 1e-9;

/// @brief Lines and arcs through the points. Errors are located as `point[k]` (a point
/// repeated, an arc whose end points are at different heights, a non-finite value, a
/// coordinate beyond kMaxPathCoordinateMm, an arc reaching beyond it).
[[nodiscard]] Result<ToolPath> toolPathFromPoints(const std::vector<PathPoint>& points);

/// @brief How closely a spline segment's tangent arcs (biarcs) follow it in a tool path, mm.
inline constexpr double kSplineToleranceMm = 1e-4;

/// @brief The path of the tool centre that mills the contour from outside: every segment of the
/// contour offset outwards by `toolRadius` (arcs stay arcs, lines stay lines; a spline becomes
/// tangent arc pairs within kSplineToleranceMm), joined at corners by an arc around the corner
/// (convex) or trimmed to the offsets' intersection (concave). A radius that makes an offset
/// degenerate, or so large that a concave corner would trim a segment's offset beyond its ends,
/// is an error naming the segment (`contour[k]`). If `cancel` is given it is polled per segment
/// and per biarc; a cancelled computation returns the error {"", "cancelled"}.
[[nodiscard]] Result<ToolPath> toolPathFromContour(const Contour& contour, double toolRadius,
                                                   const std::atomic<bool>* cancel = nullptr);

/// @brief Marks a piece of a ContourOffset that follows no segment: the arc that rolls the tool
/// around a convex corner.
inline constexpr std::size_t kCornerPiece = static_cast<std::size_t>(-1);

/// @brief A contour offset, and for each of its pieces the contour segment it follows.
struct ContourOffset {
    ToolPath path;
    std::vector<std::size_t> origin;  ///< per piece of `path`: segment index, or kCornerPiece
};

/// @brief toolPathFromContour with the spline tolerance given (mm, > 0) and each piece's origin.
/// With toolRadius 0 it is the profile itself: one line or arc per line or arc segment (exact),
/// tangent arc pairs within `splineToleranceMm` for a spline.
[[nodiscard]] Result<ContourOffset> offsetContour(const Contour& contour, double toolRadius,
                                                  double splineToleranceMm,
                                                  const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
