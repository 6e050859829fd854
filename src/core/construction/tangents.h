#pragma once
/// @file
/// @brief Construction help: the common tangents of two circles, a tangent line inserted
/// between two arcs of the contour, and a tangent arc through a point (math.md §1, §5).
///
/// Like the fillets these operations take a contour and return a new one with the windows
/// written for the user: they repair a rough sketch (arcs whose windows do not meet yet) into
/// a tangent-continuous (G1) chain. They check only what they change; the app validates the
/// result like any edit.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "geometry/arc.h"
#include "project/project.h"

namespace cam {

/// @brief Which common tangent of two circles: an outer (external) one has both circles on
/// the same side of it, an inner (crossing) one passes between them.
enum class TangentKind { Outer, Inner };

/// @brief A line tangent to two circles a and b, given by the points where it touches them.
struct CircleTangent {
    Eigen::Vector2d onA{0.0, 0.0};  ///< tangent point on circle a, mm
    Eigen::Vector2d onB{0.0, 0.0};  ///< tangent point on circle b, mm
    TangentKind kind = TangentKind::Outer;
};

/// @brief The common tangent lines of the circles of a and b (their branches play no part).
///
/// With d = |c_b − c_a| and e = (c_b − c_a)/d, let m be the unit normal of the tangent at a's
/// tangent point, t_a = c_a + R_a·m. An outer tangent has t_b = c_b + R_b·m and
/// m·e = (R_a − R_b)/d; an inner one has t_b = c_b − R_b·m and m·e = (R_a + R_b)/d; in both
/// m = (m·e)·e ± h·perp(e), h = sqrt(1 − (m·e)²). (On the axis e = (0, 1) this is the
/// textbook t_i = c_i + R_i·(±cos θ, sin θ), sin θ = (R_a ∓ R_b)/d.)
///
/// Order: the outer tangents, then the inner ones; of each pair first the one touching a on
/// the left of the line c_a → c_b (+h), then the one on the right. The cases:
/// - disjoint circles (d > R_a + R_b): four;
/// - circles touching from outside (d = R_a + R_b): the two outer ones and one inner one, the
///   tangent at the contact point (onA = onB);
/// - intersecting circles (|R_a − R_b| < d < R_a + R_b): the two outer ones;
/// - touching from inside (d = |R_a − R_b|): one outer, at the contact point (onA = onB);
/// - one circle inside the other, concentric circles (also the same circle twice), or a radius
///   that is not a finite number > 0: none.
/// "Touching" means equal within 1e-12 of the largest of d, R_a, R_b. Nothing returned is NaN.
[[nodiscard]] std::vector<CircleTangent> circleTangentLines(const Arc& a, const Arc& b);

/// @brief One way to join two arcs by a tangent line: the contour with the line inserted.
struct TangentLineChoice {
    /// The new contour, one segment longer: the line sits between contour[K-1] and contour[K],
    /// i.e. at index K, or at the end when K = 0 (so the first segment stays first), exactly as
    /// a fillet (FilletResult) is inserted.
    std::vector<SegmentSpec> contour;
    std::size_t lineIndex = 0;                ///< where the line is in `contour`
    Eigen::Vector2d tangentPoint1{0.0, 0.0};  ///< where it leaves contour[K-1] (its `from`), mm
    Eigen::Vector2d tangentPoint2{0.0, 0.0};  ///< where it enters contour[K] (its `to`), mm
    TangentKind kind = TangentKind::Outer;    ///< which common tangent of the two circles
};

/// @brief The tangent lines that fit at one joint, in the order of circleTangentLines.
struct TangentLineChoices {
    std::vector<TangentLineChoice> choices;  ///< never empty in a successful Result
};

/// @brief Insert a straight line tangent to both arcs at joint K (between A = contour[K-1]
/// and B = contour[K]; K = 0 is the joint between the last and the first segment), so that
/// the contour runs A → line → B tangent-continuously (G1) and counter-clockwise.
///
/// Of the common tangents of the two circles (circleTangentLines) a line from t_A (on A) to
/// t_B (on B) is kept when (a) the polar angle grows along it, cross(t_A, t_B − t_A) > 0;
/// (b) it runs in A's direction of travel at t_A and B's at t_B (the tangent ±perp(p − c) of
/// an arc whose polar angle grows: +perp on an outer branch, −perp on an inner one); and
/// (c) t_A lies on A's branch and t_B on B's (the ray from the origin through the point meets
/// the circle there on the side the arc follows: p·(p − c) > 0 on the outer branch, < 0 on
/// the inner one). Given (a), (b) and (c) say the same, and they leave at most one of the four
/// tangents: the branches fix on which side of the line each circle lies (an outer arc's
/// circle on the left, as the origin; an inner arc's on the right), and just one common
/// tangent has the circles on those sides. `choices` is a list all the same, so that a caller
/// need not change should a future rule admit several.
///
/// Windows, in degrees, written for the caller: A's end moves to the polar angle of t_A, taken
/// within one turn after A's start (the only one that can leave A a window; for a contour
/// whose windows are contiguous and cover one turn it is the representative nearest A's
/// current end whenever that one gives a valid contour); the line's window follows from its
/// end points (lineWindowDeg), starting bit-equal at A's new end; B's start moves to the
/// line's end (at K = 0 to the line's end − 360, so that the windows still cover one turn).
/// The tangent points need not lie in A's or B's old windows: the windows of a sketch may be
/// rough. Nothing else of the contour is changed, and the result is not validated here (a
/// sketch validates only once all its joints are joined): the app validates it like any edit.
///
/// Errors, located "contour[K-1]/contour[K]" (as data: A's phi_end and B's phi_start), except
/// a contour of fewer than two segments or a joint out of range ("contour"): a neighbour is
/// not an arc (or not a circle: radius not a finite number > 0, centre not finite); no common
/// tangent fits, with the reason: both arcs lie on the same circle (they meet tangentially
/// already), one circle lies inside the other, the circles touch (the arcs can meet at the
/// contact point without a line), or for each tangent why it was dropped (it runs clockwise
/// around the rotation centre; it touches A or B on the other side of its circle than the
/// arc's branch); a new window would be empty or reversed (A's end would reach its start, or
/// B's start would pass its end), with both angles.
[[nodiscard]] Result<TangentLineChoices> tangentLineJoint(const std::vector<SegmentSpec>& contour,
                                                          std::size_t joint);

/// @brief A contour with a tangent arc through a point added after one row.
struct ArcThroughPointResult {
    /// The new contour, one segment longer: the arc sits right after contour[row], at index
    /// row + 1 (at the end when row is the last one).
    std::vector<SegmentSpec> contour;
    std::size_t arcIndex = 0;          ///< row + 1
    Eigen::Vector2d center{0.0, 0.0};  ///< of the new arc, mm
    double radius = 0.0;               ///< of the new arc, mm
};

/// @brief Append to contour[row] an arc that starts at its end point T, tangent to it there
/// (G1, the same direction of travel), and ends at `point` P (mm).
///
/// T is the row's end: for an arc the point on its branch at phi_end (pointOnSegment), for a
/// line `to`, for a spline (Bézier or Hermite) its end point P3. The direction of travel t
/// there is the arc's (branch-signed) tangent, to − from, or P3 − P2 (P3 − P1, then P3 − P0
/// where the handles vanish); the polar angle must grow along it, cross(T, t) > 0. With the
/// left normal n = perp(t) the centre is c = T + s·n, s = |P − T|² / (2·n·(P − T)) (the point
/// of the normal as far from P as from T), the radius |s|. For s > 0 the arc turns left
/// (counter-clockwise about c): branch "outer"; for s < 0 right: "inner". The branch at T is
/// then right by construction; P must lie on it too, and every point of the arc from T to P,
/// so that the follower ray meets it exactly once in its window.
///
/// Windows, in degrees: the arc's runs from contour[row].phiEndDeg (bit-equal) to the polar
/// angle of P, taken within one turn after the start. The next segment's start moves to the
/// arc's end; after the last row the next segment is contour[0], whose start moves to the
/// arc's end − 360, so that the first segment stays first and the windows still cover one
/// turn (as tangentLineJoint and the fillets do at K = 0). An arc next keeps its circle, so
/// the joint at P stays open unless that circle passes through P (tangentLineJoint can then
/// join the two arcs); a line or spline next has its window tied to its end points, so its
/// start point moves to P (a spline keeps its start tangent: a Bézier's P1 moves with P0) and
/// the joint closes.
///
/// Errors, located "contour[row]/contour[row+1]" (the joint the arc goes into; row + 1 wraps to
/// 0), except an empty contour or a row out of range ("contour"): the row's end point cannot
/// be found (an arc whose ray misses its circle at phi_end, a curve without direction there) or
/// it runs clockwise there; the point is not finite, is the rotation centre or T itself; the
/// point is on the tangent ("the point is on the tangent: use a line"; also when the radius or
/// the centre would exceed 1e6 mm, the largest length a project holds) or the radius would be
/// below 1e-6 mm; P lies on the other branch of the circle than T; the arc would pass over to
/// the other branch between T and P (P lies behind T as seen from the rotation centre); the
/// arc's window or the next segment's would be empty or reversed (P's polar angle lies beyond
/// the next segment's end), or the moved start point would reverse a line or spline next; a
/// single-segment contour whose segment is not an arc.
[[nodiscard]] Result<ArcThroughPointResult> arcThroughPoint(const std::vector<SegmentSpec>& contour,
                                                            std::size_t row, Eigen::Vector2d point);

}  // namespace cam
