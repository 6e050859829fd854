#pragma once
/// @file
/// @brief "Fit windows": move every window boundary to where the neighbouring segments meet,
/// and make neighbours that miss each other by a typing slip meet.

#include <cstddef>
#include <optional>
#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief How two neighbours meet at a fitted joint.
enum class JointMeeting {
    Crossing,   ///< at one of their intersections (the one nearest the boundary as it was)
    Tangent,    ///< they touch (within the rounding of double precision): at the tangent point
    SameCurve,  ///< two pieces of one circle or line: the boundary stays where it was
    SplineEnd,  ///< a spline's end point, which its control points fix
};

/// @brief Joint k: where contour[k] ends and contour[(k + 1) % n] begins.
struct FittedJoint {
    double angleDeg = 0.0;
    JointMeeting meeting = JointMeeting::Crossing;
};

/// @brief A segment Fit Windows moved so that it meets the segment before it.
struct SegmentMove {
    std::size_t segment = 0;    ///< the segment moved: the later of its joint
    std::size_t neighbour = 0;  ///< the segment it was made to meet
    /// The segment after it, which it was made to touch too: the move along the line of centres
    /// would have opened that joint, so centre and radius changed by the least for both.
    std::optional<std::size_t> alsoNeighbour;
    /// It is a second piece of the neighbour's circle or line and took that curve.
    bool tookNeighboursCurve = false;
    SegmentShape before;  ///< its curve as given
    SegmentShape after;   ///< its curve moved (a line's ends before they are fitted)
    /// How far any point of it moved: |Δcentre| + |Δradius| for an arc, the larger move of
    /// an end point for a line. At most kTypingToleranceMm.
    double distanceMm = 0.0;
};

struct FittedWindows {
    std::vector<SegmentSpec> contour;
    std::vector<FittedJoint> joints;  ///< one per segment (none for a single segment)
    std::vector<SegmentMove> moves;   ///< in the order of the segments; empty: none moved
    /// One note (Severity::Info) per move, at the moved segment: what moved, how far, where to.
    Diagnostics notes;

    /// @brief The largest SegmentMove::distanceMm (0 when nothing moved).
    [[nodiscard]] double largestMoveMm() const;
};

/// @brief The contour with each boundary set to where its two neighbours meet: at their
/// tangent point when they touch; when they cross, at the intersection nearest the current
/// boundary angle (circles that overlap by a rounding amount cross at two points close to where
/// they would touch). Neighbours that miss each other by at most kTypingToleranceMm
/// (common/tolerances.h) are first made to meet by the smallest change of the later segment:
/// a circle's centre moves along the line of centres (along the normal to a line) by the gap,
/// a second piece of one circle or line takes the first piece's curve, a line moves across its
/// direction. A move can open the later segment's other joint, which is then closed in turn;
/// no segment moves by more than kTypingToleranceMm in all. Lines get their end points at the
/// joints. Splines are not moved: a joint next to one is at the spline's end point.
///
/// Errors, at the joint: the neighbours miss each other by more than kTypingToleranceMm (the
/// message gives by how much), making them meet would move a segment too far, or the moves do
/// not settle.
[[nodiscard]] Result<FittedWindows> fitWindows(const std::vector<SegmentSpec>& contour);

}  // namespace cam
