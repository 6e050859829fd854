#pragma once
/// @file
/// @brief A grooved (form-closed) cam's flanks (issue 32, project-format.md `closure: groove`):
/// a roller of radius ρ runs in a groove milled into the disc. The contour table is the inner
/// flank; the roller centre runs on the pitch curve, the inner flank offset outwards by ρ; the
/// outer flank is the pitch curve offset outwards by ρ + the clearance c, i.e. the inner flank
/// offset by 2ρ + c. Offsets of arcs are arcs about the same centres and offsets of lines are
/// lines (math.md §7), so both flanks of an arc table are exact arc tables; a spline's offset is
/// followed by tangent arcs within kSplineToleranceMm.

#include <optional>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief A groove's size: the roller's radius ρ and its clearance c between the flanks, mm.
struct GrooveSize {
    double rollerRadiusMm = 0.0;
    double clearanceMm = 0.0;
    /// The groove's width 2ρ + c, mm.
    [[nodiscard]] double width() const { return 2.0 * rollerRadiusMm + clearanceMm; }
    /// The groove of a grooved roller follower; none for any other.
    [[nodiscard]] static std::optional<GrooveSize> of(const FollowerSpec& follower) {
        if (!follower.grooved() || follower.type != FollowerType::Roller) return std::nullopt;
        return GrooveSize{follower.radius, follower.grooveClearance};
    }
};

/// @brief The project's groove: its follower's, when that runs in one.
[[nodiscard]] inline std::optional<GrooveSize> grooveOf(const Project& project) {
    return project.follower ? GrooveSize::of(*project.follower) : std::nullopt;
}

/// @brief The pitch curve (the roller centre's path) and the outer flank of a groove, closed
/// paths of lines and arcs at z = 0 in the cam frame, in the contour's order.
struct GrooveFlanks {
    ToolPath inner;  ///< the contour itself (exact lines and arcs, tangent arcs for splines)
    ToolPath pitch;
    ToolPath outer;
};

/// @brief grooveFlanks for `size` when there is one (a drawing of a grooved cam); none, and no
/// error, without.
[[nodiscard]] Result<std::optional<GrooveFlanks>> grooveFlanksIf(
    const Contour& contour, const std::optional<GrooveSize>& size, double splineToleranceMm);

/// @brief The point of a closed path nearest to the cam centre or farthest from it: its
/// distance (mm), the point, and its polar angle in the cam frame (rad, in [0, 2π)).
struct RadialExtreme {
    double radius = 0.0;
    Eigen::Vector2d point{0.0, 0.0};
    double phi = 0.0;
};

/// @brief The exact nearest and farthest points of `path` (lines and arcs) from the origin:
/// on each piece its ends, the foot of the perpendicular on a line, and on an arc the two
/// points on the line through its centre and the origin, where they lie within the sweep.
[[nodiscard]] RadialExtreme nearestToCentre(const ToolPath& path);
[[nodiscard]] RadialExtreme farthestFromCentre(const ToolPath& path);

/// @brief The tightest bends of a closed path of lines and arcs running counter-clockwise round
/// the cam (as offsetContour makes them): the smallest radius of an arc bending round the cam
/// centre's side (convex, counter-clockwise about its own centre) and of one bending away
/// (concave), each at its middle; none where no arc bends that way. Exact on an arc cam's
/// flanks; a spline's flank is its tangent arcs'.
struct PathBends {
    std::optional<RadialExtreme> minConvex, minConcave;  ///< `radius`: the arc's radius
};
[[nodiscard]] PathBends pathBends(const ToolPath& path);

/// @brief The groove's lands (project-format.md `inner_land_radius_mm`, `outer_land_radius_mm`):
/// where the inner flank comes nearest the bore and the outer flank nearest the rim, and
/// whether each keeps its land (unchecked, and true, when the project gives no radius).
struct GrooveLands {
    RadialExtreme innerMost, outerMost;
    std::optional<double> innerLand, outerLand;
    [[nodiscard]] bool innerKept() const { return !innerLand || innerMost.radius >= *innerLand; }
    [[nodiscard]] bool outerKept() const { return !outerLand || outerMost.radius <= *outerLand; }
};

[[nodiscard]] GrooveLands grooveLands(const GrooveFlanks& flanks,
                                      std::optional<double> innerLandRadius,
                                      std::optional<double> outerLandRadius);

/// @brief The groove for a roller of radius `rollerRadius` (> 0) with `clearance` (≥ 0) on
/// `contour`, its inner flank. A concave stretch of the pitch curve tighter than the roller
/// radius + the clearance would undercut the outer flank: an error naming the segment
/// (GrooveOuterFlankUndercut, with the roller radius, the clearance and the stretch's radius on
/// the inner flank); a radius or clearance that is not finite, or out of range, is an error
/// (`follower.radius`, `follower.groove_clearance_mm`).
[[nodiscard]] Result<GrooveFlanks> grooveFlanks(const Contour& contour, double rollerRadius,
                                                double clearance,
                                                double splineToleranceMm = kSplineToleranceMm);

/// @brief The roller pressed against the outer flank (where the load turns it over to the other
/// side of the groove) runs with its centre on the outer flank offset inwards by ρ, which is the
/// inner flank offset outwards by ρ + c: the path of a roller of radius ρ + c on the contour.
/// This is that roller, spring-closed, to place with FollowerModel::build.
[[nodiscard]] FollowerSpec outerFlankRoller(const FollowerSpec& grooved);

/// @brief The follower on the outer flank from `wide`, outerFlankRoller's state at the same
/// angle: the same centre and motion, the contact moved across the roller to the outer flank
/// (ρ from the centre, away from the inner flank), the normal out of the outer flank's material
/// (towards the cam centre's side), the same pressure angle (the line of force is the same),
/// and the outer flank's radius of curvature, signed as the inner flank's (positive where it
/// bends round the cam centre, where the roller touches it from inside): ρ_inner + 2ρ + c.
[[nodiscard]] FollowerState onOuterFlank(const FollowerState& wide, double rollerRadius,
                                         double clearance);

}  // namespace cam
