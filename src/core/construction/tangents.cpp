#include "construction/tangents.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "common/angles.h"
#include "common/tolerances.h"
#include "geometry/line.h"
#include "geometry/planar.h"
#include "project/validate.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// Circles closer to touching than this (relative to their size) touch.
constexpr double kTouchRel = 1e-12;

bool finite(const Vec& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

bool isCircle(const Arc& arc) {
    return finite(arc.center) && std::isfinite(arc.radius) && arc.radius > 0.0;
}

/// +1 on the outer branch, -1 on the inner: as phi grows the far intersection moves
/// counter-clockwise about the centre and the near one clockwise.

/// Which intersection of the ray through p (a point of the circle) p is: with r = |p| and
/// r = mu ± sqrt(D) (math.md §1), p·(p − c) = r² − r·mu = ±r·sqrt(D). So the sign of
/// p·(p − c) is the branch p lies on: the same test as comparing |p| with the branch's r on
/// that ray, without its rounding near the tangent ray.
bool onBranch(const Vec& p, const Vec& center, double sense) {
    return sense * p.dot(p - center) > 0.0;
}

/// Six significant digits: enough to tell the user which point is meant.
std::string sixDigits(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v == 0.0 ? 0.0 : v);  // no "-0"
    return buffer;
}

/// Components below 1e-12 of the point's size are round-off (cos 90° = 6e-17) and shown as 0.
std::string pointText(const Vec& p) {
    const double tiny = 1e-12 * std::max(std::abs(p.x()), std::abs(p.y()));
    auto component = [&](double v) { return sixDigits(std::abs(v) <= tiny ? 0.0 : v); };
    // Appended piece by piece: "(" + std::string trips GCC 12's -Wrestrict false positive.
    std::string text = "(";
    text += component(p.x());
    text += ", ";
    text += component(p.y());
    text += ")";
    return text;
}

/// The two numbers pointText shows, as numbers (for a diagnostic's arguments).
std::vector<DiagnosticArg> pointArgs(const Vec& p) {
    const double tiny = 1e-12 * std::max(std::abs(p.x()), std::abs(p.y()));
    auto component = [&](double v) {
        return std::strtod(sixDigits(std::abs(v) <= tiny ? 0.0 : v).c_str(), nullptr);
    };
    return {component(p.x()), component(p.y())};
}

/// The number sixDigits() shows.
double shown(double v) { return std::strtod(sixDigits(v).c_str(), nullptr); }

std::string deg(double value) { return formatNumber(value) + "°"; }

/// Arguments one after another: {a, b} + {c}.
std::vector<DiagnosticArg> joined(std::vector<DiagnosticArg> head,
                                  const std::vector<DiagnosticArg>& tail) {
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
}

DiagnosticArg segmentArg(std::size_t index) { return static_cast<double>(index); }

const char* typeName(SegmentType type) {
    switch (type) {
        case SegmentType::Arc:
            return "an arc";
        case SegmentType::Line:
            return "a line";
        case SegmentType::Bezier:
            return "a Bézier spline";
        case SegmentType::Hermite:
            return "a Hermite spline";
    }
    return "a segment";
}

const char* branchName(double sense) { return sense > 0.0 ? "outer" : "inner"; }

/// "far" or "near" side of a circle as seen from the rotation centre.
const char* sideName(double sense) { return sense > 0.0 ? "far" : "near"; }

// ---- tangent line at a joint ----

/// The joint K and what the candidates are checked against.
struct Joint {
    std::size_t left = 0, right = 0;
    const SegmentSpec* a = nullptr;
    const SegmentSpec* b = nullptr;
    double shift = 0.0;  ///< 360 at the wrap-around joint K = 0, else 0
};

/// A candidate that was dropped, and why (for the message when none is left).
struct Dropped {
    std::string reason;
    bool window = false;  ///< dropped only for its windows
    DiagnosticCode code = DiagnosticCode::Unspecified;
    std::vector<DiagnosticArg> args;
};

std::string tangentName(const CircleTangent& t, const Joint& k) {
    return std::string(t.kind == TangentKind::Outer ? "the outer" : "the inner") +
           " tangent from " + pointText(t.onA) + " on " + segmentLocation(k.left) + " to " +
           pointText(t.onB) + " on " + segmentLocation(k.right);
}

/// tangentName's arguments: "outer" or "inner", the point on A, left, the point on B, right.
std::vector<DiagnosticArg> tangentArgs(const CircleTangent& t, const Joint& k) {
    std::vector<DiagnosticArg> args{std::string(t.kind == TangentKind::Outer ? "outer" : "inner")};
    args = joined(std::move(args), pointArgs(t.onA));
    args.push_back(segmentArg(k.left));
    args = joined(std::move(args), pointArgs(t.onB));
    args.push_back(segmentArg(k.right));
    return args;
}

std::string branchReason(const Arc& arc, std::size_t index) {
    const double sense = arc.sense();
    return "touches " + segmentLocation(index) + " on the " + sideName(-sense) +
           " side of its circle, but the arc follows the " + sideName(sense) + " side (" +
           branchName(sense) + " branch)";
}

/// The tangent t dropped because it touches the arc of `index` on the wrong side.
Dropped wrongSide(const CircleTangent& t, const Joint& k, const Arc& arc, std::size_t index) {
    // On the outer branch (sense > 0) it touches the near side, on the inner the far one.
    return {
        tangentName(t, k) + " " + branchReason(arc, index), false,
        arc.sense() > 0.0 ? DiagnosticCode::TangentOnNearSide : DiagnosticCode::TangentOnFarSide,
        joined(tangentArgs(t, k), {segmentArg(index)})};
}

/// The contour with the line of tangent `t` inserted, or why the windows do not allow it.
std::variant<TangentLineChoice, Dropped> buildChoice(const std::vector<SegmentSpec>& contour,
                                                     std::size_t joint, const Joint& k,
                                                     const CircleTangent& t) {
    const SegmentSpec& a = *k.a;
    const SegmentSpec& b = *k.b;
    // Within one turn after A's start: no other representative can leave A a window.
    const double aEnd = a.phiStartDeg + mod360(polarDeg(t.onA) - a.phiStartDeg);
    if (!(aEnd > a.phiStartDeg)) {
        return Dropped{
            "with " + tangentName(t, k) + " the window of " + segmentLocation(k.left) +
                " would be empty: its end would move onto its start " + deg(a.phiStartDeg),
            true, DiagnosticCode::TangentEmptiesLeft, joined(tangentArgs(t, k), {a.phiStartDeg})};
    }
    SegmentSpec line{Line{t.onA, t.onB}};
    const auto [start, end] = lineWindowDeg(line, aEnd);
    // Bit-equal joints keep the chain contiguous; the line's own window is tied to its ends.
    line.phiStartDeg = aEnd;
    line.phiEndDeg = aEnd + (end - start);
    const double bStart = line.phiEndDeg - k.shift;
    if (!(bStart < b.phiEndDeg)) {
        return Dropped{"with " + tangentName(t, k) + " the window of " + segmentLocation(k.right) +
                           " would be empty or reversed: its start would move to " + deg(bStart) +
                           ", not before its end " + deg(b.phiEndDeg),
                       true, DiagnosticCode::TangentReversesRight,
                       joined(tangentArgs(t, k), {bStart, b.phiEndDeg})};
    }
    std::vector<SegmentSpec> out = contour;
    out[k.left].phiEndDeg = aEnd;
    out[k.right].phiStartDeg = bStart;
    // At K = 0 the line goes last: its window ends a turn after the first one starts.
    const std::size_t at = joint == 0 ? out.size() : joint;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), line);
    return TangentLineChoice{std::move(out), at, t.onA, t.onB, t.kind};
}

/// Why the circles have no common tangent at all (circleTangentLines returned none).
Diagnostic noTangentReason(const Arc& a, const Arc& b, const Joint& k) {
    const double d = (b.center - a.center).norm();
    const double scale = std::max({d, a.radius, b.radius});
    if (d <= kTouchRel * scale && std::abs(a.radius - b.radius) <= kTouchRel * scale) {
        return Diagnostic::atJoint(k.left, k.right,
                                   "both arcs lie on the same circle, so they already meet "
                                   "tangentially: no line fits between them")
            .coded(DiagnosticCode::TangentSameCircle, {});
    }
    const bool aInside = a.radius < b.radius;
    const std::size_t inner = aInside ? k.left : k.right;
    const std::size_t outer = aInside ? k.right : k.left;
    return Diagnostic::atJoint(k.left, k.right,
                               "the circle of " + segmentLocation(inner) + " lies inside that of " +
                                   segmentLocation(outer) +
                                   ", so the two circles have no common tangent")
        .coded(DiagnosticCode::TangentCircleInside, {segmentArg(inner), segmentArg(outer)});
}

/// A message with its code: where the arc-through-a-point construction stops.
struct Refusal {
    std::string message;
    DiagnosticCode code = DiagnosticCode::Unspecified;
    std::vector<DiagnosticArg> args;
};

// ---- arc through a point ----

/// The end point of a row and its unit direction of travel there.
struct RowEnd {
    Vec point{0.0, 0.0};
    Vec travel{0.0, 0.0};
};

/// Where the row ends and which way it runs there; why not if that is not defined.
std::variant<RowEnd, Refusal> rowEnd(const SegmentSpec& s, std::size_t row) {
    RowEnd end;
    if (const auto* arc = s.as<Arc>()) {
        if (!isCircle(*arc)) {
            return Refusal{segmentLocation(row) + " is not a circle",
                           DiagnosticCode::ArcRowNotCircle,
                           {segmentArg(row)}};
        }
        end.point = pointOnSegment(s, s.phiEndDeg);
        if (!finite(end.point)) {
            return Refusal{"the follower ray at the end " + deg(s.phiEndDeg) + " of " +
                               segmentLocation(row) + " misses its circle, so it has no end point",
                           DiagnosticCode::ArcRayMissesEnd,
                           {s.phiEndDeg, segmentArg(row)}};
        }
        end.travel = arc->sense() * perp(end.point - arc->center);
    } else if (const auto* line = s.as<Line>()) {
        end.point = line->to;
        end.travel = line->to - line->from;
    } else {
        const CubicBezier bez = bezierOf(s);
        end.point = bez.p[3];
        // Where the end handle vanishes the curve leaves P3 along P3 − P1 (then P3 − P0).
        const double scale = std::max({bez.p[0].norm(), bez.p[3].norm(), 1.0});
        for (int i = 2; i >= 0; --i) {
            end.travel = bez.p[3] - bez.p[static_cast<std::size_t>(i)];
            if (end.travel.norm() > 1e-12 * scale) break;
        }
    }
    const double length = end.travel.norm();
    if (!finite(end.point) || !(length > 0.0) || !std::isfinite(length)) {
        return Refusal{segmentLocation(row) + " has no direction at its end point",
                       DiagnosticCode::ArcNoEndDirection,
                       {segmentArg(row)}};
    }
    end.travel /= length;
    if (!(cross(end.point, end.travel) > 0.0)) {
        return Refusal{
            segmentLocation(row) + " does not run counter-clockwise around the rotation " +
                "centre at its end point " + pointText(end.point) +
                " (its polar angle does not grow there)",
            DiagnosticCode::ArcEndClockwise, joined({segmentArg(row)}, pointArgs(end.point))};
    }
    return end;
}

/// Moves the start of `next` to the angle startDeg (the arc's end) and, for a line or spline,
/// its start point to P. Why not if its window would be empty or reversed.
std::optional<Refusal> moveStart(SegmentSpec& next, std::size_t index, double startDeg,
                                 const Vec& p) {
    if (!(startDeg < next.phiEndDeg)) {
        return Refusal{"the arc would end at " + deg(startDeg) +
                           " (the polar angle of the point), not before the end " +
                           deg(next.phiEndDeg) + " of " + segmentLocation(index) +
                           ", whose window would be empty or reversed",
                       DiagnosticCode::ArcEndsAfterNext,
                       {startDeg, next.phiEndDeg, segmentArg(index)}};
    }
    if (next.as<Arc>()) {
        next.phiStartDeg = startDeg;
        return std::nullopt;
    }
    if (auto* line = next.as<Line>()) {
        line->from = p;
        if ((line->to - p).norm() <= kJointToleranceMm) {
            return Refusal{"the point is the end point of " + segmentLocation(index) +
                               ", which would have no length left",
                           DiagnosticCode::ArcPointIsNextEnd,
                           {segmentArg(index)}};
        }
    } else if (auto* bez = next.as<CubicBezier>()) {
        const Vec offset = p - bez->p[0];
        bez->p[0] += offset;
        bez->p[1] += offset;
    } else {
        next.as<HermiteCurve>()->p0 = p;
    }
    // Its window must stay the polar angles of its end points: the sweep from P to its end.
    const auto [start, end] = lineWindowDeg(next, startDeg);
    const double width = next.phiEndDeg - startDeg;
    if (!(end > start) || std::abs((end - start) - width) > kLineWindowToleranceDeg) {
        return Refusal{"with its start point moved to the point, " + segmentLocation(index) +
                           " would no longer run counter-clockwise from " + deg(startDeg) +
                           " to its end " + deg(next.phiEndDeg),
                       DiagnosticCode::ArcNextClockwise,
                       {segmentArg(index), startDeg, next.phiEndDeg}};
    }
    next.phiStartDeg = startDeg;
    return std::nullopt;
}

}  // namespace

std::vector<CircleTangent> circleTangentLines(const Arc& a, const Arc& b) {
    std::vector<CircleTangent> out;
    if (!isCircle(a) || !isCircle(b)) return out;
    const Vec delta = b.center - a.center;
    const double d = delta.norm();
    const double scale = std::max({d, a.radius, b.radius});
    if (!std::isfinite(d) || d <= kTouchRel * scale) return out;  // concentric: none, or all
    const Vec e = delta / d;
    // One pair: m·e = q/d with q = R_a − R_b (outer, t_b = c_b + R_b·m) or R_a + R_b (inner,
    // t_b = c_b − R_b·m). h² = 1 − (q/d)² = (d − |q|)(d + |q|)/d², computed from the gap so
    // that it is exact near touching.
    auto pair = [&](double q, double signB, TangentKind kind) {
        const double gap = d - std::abs(q);
        if (gap < -kTouchRel * scale)
            return;  // one circle inside the other (outer), or they
                     // overlap (inner)
        if (gap <= kTouchRel * scale) {
            // Touching: the two tangents of the pair are the one at the contact point.
            const Vec m = q >= 0.0 ? e : Vec(-e);
            const Vec contact =
                0.5 * ((a.center + a.radius * m) + (b.center + signB * b.radius * m));
            out.push_back({contact, contact, kind});
            return;
        }
        const double k = q / d;
        const double h = std::sqrt(gap * (d + std::abs(q))) / d;
        for (double side : {1.0, -1.0}) {
            const Vec m = k * e + side * h * perp(e);
            out.push_back({a.center + a.radius * m, b.center + signB * b.radius * m, kind});
        }
    };
    pair(a.radius - b.radius, 1.0, TangentKind::Outer);
    pair(a.radius + b.radius, -1.0, TangentKind::Inner);
    return out;
}

Result<TangentLineChoices> tangentLineJoint(const std::vector<SegmentSpec>& contour,
                                            std::size_t joint) {
    const std::size_t n = contour.size();
    if (auto problem = jointIndexProblem(n, joint, "tangent line")) return Diagnostics{*problem};
    Joint k;
    k.left = (joint + n - 1) % n;
    k.right = joint;
    k.a = &contour[k.left];
    k.b = &contour[k.right];
    k.shift = joint == 0 ? 360.0 : 0.0;
    auto fail = [&](std::string message, DiagnosticCode code, std::vector<DiagnosticArg> args) {
        return Diagnostics{
            Diagnostic::atJoint(k.left, k.right, std::move(message)).coded(code, std::move(args))};
    };
    for (std::size_t i : {k.left, k.right}) {
        const SegmentSpec& s = contour[i];
        if (!s.as<Arc>()) {
            return fail(std::string("a tangent line joins two arcs; ") + segmentLocation(i) +
                            " is " + typeName(s.type()),
                        DiagnosticCode::TangentNeedsArcs,
                        {segmentArg(i), std::string(typeName(s.type()))});
        }
        if (!isCircle(*s.as<Arc>())) {
            return fail(segmentLocation(i) +
                            " is not a circle (its radius must be a finite number > 0, its "
                            "centre finite)",
                        DiagnosticCode::TangentNotCircle, {segmentArg(i)});
        }
    }
    const Arc& arcA = *k.a->as<Arc>();
    const Arc& arcB = *k.b->as<Arc>();
    const std::vector<CircleTangent> tangents = circleTangentLines(arcA, arcB);
    if (tangents.empty()) return Diagnostics{noTangentReason(arcA, arcB, k)};

    TangentLineChoices result;
    std::vector<Dropped> dropped;
    for (const CircleTangent& t : tangents) {
        const Vec dir = t.onB - t.onA;
        if (dir.norm() <= kJointToleranceMm) {
            dropped.push_back({"the circles touch at " + pointText(t.onA) +
                                   ": the arcs can meet there directly, without a line",
                               false, DiagnosticCode::TangentTouch, pointArgs(t.onA)});
            continue;
        }
        // (a) The polar angle grows from t_A to t_B.
        if (!(cross(t.onA, dir) > 0.0)) {
            dropped.push_back({tangentName(t, k) +
                                   " runs clockwise around the rotation centre (its polar "
                                   "angle would not grow from " +
                                   segmentLocation(k.left) + " to " + segmentLocation(k.right) +
                                   ")",
                               false, DiagnosticCode::TangentClockwise, tangentArgs(t, k)});
            continue;
        }
        // (b) The line runs as the arcs travel there, and (c) its ends are on the arcs'
        // branches. With (a) the two are the same condition; both are checked for clarity.
        const double senseA = arcA.sense(), senseB = arcB.sense();
        const bool travelA = dir.dot(senseA * perp(t.onA - arcA.center)) > 0.0;
        const bool travelB = dir.dot(senseB * perp(t.onB - arcB.center)) > 0.0;
        const bool branchA = onBranch(t.onA, arcA.center, senseA);
        const bool branchB = onBranch(t.onB, arcB.center, senseB);
        if (!(travelA && branchA)) {
            dropped.push_back(wrongSide(t, k, arcA, k.left));
            continue;
        }
        if (!(travelB && branchB)) {
            dropped.push_back(wrongSide(t, k, arcB, k.right));
            continue;
        }
        auto built = buildChoice(contour, joint, k, t);
        if (auto* choice = std::get_if<TangentLineChoice>(&built)) {
            result.choices.push_back(std::move(*choice));
        } else {
            dropped.push_back(std::get<Dropped>(std::move(built)));
        }
    }
    if (!result.choices.empty()) return result;
    // A tangent that fits but for its windows says most; otherwise every tangent's reason.
    for (const Dropped& d : dropped) {
        if (d.window) return fail(d.reason, d.code, d.args);
    }
    std::string message = "no tangent line fits: ";
    std::vector<Diagnostic> reasons;
    for (std::size_t i = 0; i < dropped.size(); ++i) {
        message += (i ? "; " : "") + dropped[i].reason;
        reasons.push_back(
            Diagnostic("", dropped[i].reason).coded(dropped[i].code, dropped[i].args));
    }
    Diagnostics none = fail(std::move(message), DiagnosticCode::TangentNoneFits, {});
    none.front().reasons = std::move(reasons);
    return none;
}

Result<ArcThroughPointResult> arcThroughPoint(const std::vector<SegmentSpec>& contour,
                                              std::size_t row, Eigen::Vector2d point) {
    const std::size_t n = contour.size();
    if (n == 0) {
        return Diagnostics{Diagnostic("contour", "has no segment to continue")
                               .coded(DiagnosticCode::ArcNoSegment, {})};
    }
    if (row >= n) {
        return Diagnostics{Diagnostic("contour", "there is no " + segmentLocation(row) +
                                                     ": rows are 0 .. " + std::to_string(n - 1))
                               .coded(DiagnosticCode::ArcNoSuchRow,
                                      {segmentArg(row), static_cast<double>(n - 1)})};
    }
    const std::size_t next = (row + 1) % n;
    auto fail = [&](Refusal refusal) {
        return Diagnostics{Diagnostic::atJoint(row, next, std::move(refusal.message))
                               .coded(refusal.code, std::move(refusal.args))};
    };
    const SegmentSpec& s = contour[row];
    if (n == 1 && !s.as<Arc>()) {
        return fail({"a contour of one segment must be a circle; " + segmentLocation(row) + " is " +
                         typeName(s.type()),
                     DiagnosticCode::ArcSingleNotCircle,
                     {segmentArg(row), std::string(typeName(s.type()))}});
    }
    const auto end = rowEnd(s, row);
    if (const auto* refusal = std::get_if<Refusal>(&end)) return fail(*refusal);
    const Vec t = std::get<RowEnd>(end).point;
    const Vec travel = std::get<RowEnd>(end).travel;
    const Vec& p = point;

    if (!finite(p)) {
        return fail({"the point must be finite (got " + pointText(p) + ")",
                     DiagnosticCode::ArcPointNotFinite, pointArgs(p)});
    }
    if (p.norm() <= kJointToleranceMm) {
        return fail({"the point is the rotation centre, which no arc of the contour can reach",
                     DiagnosticCode::ArcPointAtCentre,
                     {}});
    }
    const Vec w = p - t;
    if (w.norm() <= kJointToleranceMm) {
        return fail({"the point is the end point " + pointText(t) + " of " + segmentLocation(row) +
                         ": an arc needs a second point",
                     DiagnosticCode::ArcPointIsEnd, joined(pointArgs(t), {segmentArg(row)})});
    }
    // The centre c = T + s·n on the normal is as far from P as from T:
    // |T − P + s·n|² = s²  <=>  |P − T|² = 2·s·n·(P − T).
    const Vec normal = perp(travel);
    const double q = normal.dot(w);
    const double sc = w.squaredNorm() / (2.0 * q);
    const Vec center = t + sc * normal;
    const double radius = std::abs(sc);
    if (!(std::abs(q) > 1e-12 * w.norm()) || !(radius <= kMaxLengthMm) ||
        !(std::abs(center.x()) <= kMaxLengthMm && std::abs(center.y()) <= kMaxLengthMm)) {
        return fail(
            {"the point is on the tangent: use a line (an arc through it would need a "
             "radius or centre beyond 1e6 mm, the largest length a project holds)",
             DiagnosticCode::ArcPointOnTangent,
             {}});
    }
    if (radius < kMinLengthMm) {
        return fail({"the arc's radius would be " + formatNumber(radius) + " mm, below " +
                         formatNumber(kMinLengthMm) + " mm, the smallest a project holds",
                     DiagnosticCode::ArcRadiusTooSmall,
                     {radius, kMinLengthMm}});
    }
    // s > 0: centre on the left, the arc turns counter-clockwise about it: outer.
    const double sense = sc > 0.0 ? 1.0 : -1.0;
    const std::string circle =
        "the circle (centre " + pointText(center) + ", radius " + sixDigits(radius) + " mm)";
    const std::vector<DiagnosticArg> circleArgs = joined(pointArgs(center), {shown(radius)});
    const bool outer = sense > 0.0;
    if (!onBranch(t, center, sense)) {  // guarded by cross(T, t) > 0 up to rounding
        return fail({"the end point of " + segmentLocation(row) + " is not on the " +
                         branchName(sense) + " branch of " + circle,
                     outer ? DiagnosticCode::ArcEndOffOuter : DiagnosticCode::ArcEndOffInner,
                     joined({segmentArg(row)}, circleArgs)});
    }
    if (!onBranch(p, center, sense)) {
        // The outer branch (sense > 0) leaves on the far side, so the point is on the near one.
        return fail({"the point lies on the " + std::string(sideName(-sense)) + " side of " +
                         circle + " as seen from the rotation centre, but the arc leaves " +
                         segmentLocation(row) + " on its " + sideName(sense) + " side (" +
                         branchName(sense) +
                         " branch): the follower ray would not meet the arc at the point",
                     outer ? DiagnosticCode::ArcPointOnNearSide : DiagnosticCode::ArcPointOnFarSide,
                     joined(circleArgs, {segmentArg(row)})});
    }
    const double sweep = sweepRad(t - center, p - center, sense);
    if (!arcSweepOnBranch(center, radius, t, sweep, sense)) {
        return fail({"the point lies behind the end point of " + segmentLocation(row) +
                         " as seen from the rotation centre: the arc along " + circle +
                         " would pass to its " + sideName(-sense) +
                         " side and run back before reaching it",
                     outer ? DiagnosticCode::ArcRunsBackNear : DiagnosticCode::ArcRunsBackFar,
                     joined({segmentArg(row)}, circleArgs)});
    }
    const double startDeg = s.phiEndDeg;
    const double endDeg = startDeg + mod360(polarDeg(p) - startDeg);
    if (!(endDeg > startDeg)) {
        return fail({"the point lies on the follower ray at the end " + deg(startDeg) + " of " +
                         segmentLocation(row) + ": the arc's window would be empty",
                     DiagnosticCode::ArcPointOnEndRay,
                     {startDeg, segmentArg(row)}});
    }

    std::vector<SegmentSpec> out = contour;
    // After the last row the next segment is the first one: its start moves a turn back.
    const double shift = row + 1 == n ? 360.0 : 0.0;
    if (auto refusal = moveStart(out[next], next, endDeg - shift, p)) return fail(*refusal);
    SegmentSpec arc{Arc{center, radius, sense > 0.0 ? Branch::Outer : Branch::Inner}};
    arc.phiStartDeg = startDeg;
    arc.phiEndDeg = endDeg;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(row + 1), arc);
    return ArcThroughPointResult{std::move(out), row + 1, center, radius};
}

}  // namespace cam
