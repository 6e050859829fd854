#pragma once
/// @file
/// @brief A grooved (form-closed) cam's flanks (issue 32, project-format.md `closure: groove`):
/// a roller of radius ρ runs in a groove milled into the disc. The contour table is the inner
/// flank; the roller centre runs on the pitch curve, the inner flank offset outwards by ρ; the
/// outer flank is the pitch curve offset outwards by ρ + the clearance c, i.e. the inner flank
/// offset by 2ρ + c. Offsets of arcs are arcs about the same centres and offsets of lines are
/// lines (math.md §7), so both flanks of an arc table are exact arc tables; a spline's offset is
/// followed by tangent arcs within kSplineToleranceMm.

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief The pitch curve (the roller centre's path) and the outer flank of a groove, closed
/// paths of lines and arcs at z = 0 in the cam frame, in the contour's order.
struct GrooveFlanks {
    ToolPath pitch;
    ToolPath outer;
};

/// @brief The groove for a roller of radius `rollerRadius` (> 0) with `clearance` (≥ 0) on
/// `contour`, its inner flank. A concave stretch of the pitch curve tighter than the roller
/// radius + the clearance would undercut the outer flank: an error naming the segment
/// (GrooveOuterFlankUndercut, with the roller radius, the clearance and the stretch's radius on
/// the inner flank); a radius or clearance that is not finite, or out of range, is an error
/// (`follower.radius`, `follower.groove_clearance_mm`).
[[nodiscard]] Result<GrooveFlanks> grooveFlanks(const Contour& contour, double rollerRadius,
                                                double clearance);

}  // namespace cam
