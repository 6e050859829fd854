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
#include "common/translate_marker.h"
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

/// A point's two coordinates as a diagnostic's arguments, to six digits: enough to tell the
/// user which point is meant. Components below 1e-12 of the point's size are round-off
/// (cos 90° = 6e-17) and shown as 0.
std::vector<DiagnosticArg> pointArgs(const Vec& p) {
    const double tiny = 1e-12 * std::max(std::abs(p.x()), std::abs(p.y()));
    auto component = [&](double v) {
        return std::strtod(sixDigits(std::abs(v) <= tiny ? 0.0 : v).c_str(), nullptr);
    };
    return {component(p.x()), component(p.y())};
}

/// The number sixDigits() shows.
double shown(double v) { return std::strtod(sixDigits(v).c_str(), nullptr); }

/// Arguments one after another: {a, b} + {c}.
std::vector<DiagnosticArg> joined(std::vector<DiagnosticArg> head,
                                  const std::vector<DiagnosticArg>& tail) {
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
}

DiagnosticArg segmentArg(std::size_t index) { return static_cast<double>(index); }

/// The segment's type as a term of the diagnostic catalogue: "a line".
const char* typeName(SegmentType type) {
    switch (type) {
        case SegmentType::Arc:
            return CAM_TRANSLATE_NOOP("Diagnostic", "an arc");
        case SegmentType::Line:
            return CAM_TRANSLATE_NOOP("Diagnostic", "a line");
        case SegmentType::Bezier:
            return CAM_TRANSLATE_NOOP("Diagnostic", "a Bézier spline");
        case SegmentType::Hermite:
            return CAM_TRANSLATE_NOOP("Diagnostic", "a Hermite spline");
    }
    return CAM_TRANSLATE_NOOP("Diagnostic", "a segment");
}

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
    bool window = false;  ///< dropped only for its windows
    DiagnosticCode code = DiagnosticCode::Unspecified;
    std::vector<DiagnosticArg> args;
};

/// The arguments that name a tangent ("the outer tangent from (1, 2) on contour[3] to (4, 5)
/// on contour[6]"): which one it is, the point on A, left, the point on B, right.
std::vector<DiagnosticArg> tangentArgs(const CircleTangent& t, const Joint& k) {
    std::vector<DiagnosticArg> args{t.kind == TangentKind::Outer
                                        ? CAM_TRANSLATE_NOOP("Diagnostic", "the outer tangent")
                                        : CAM_TRANSLATE_NOOP("Diagnostic", "the inner tangent")};
    args = joined(std::move(args), pointArgs(t.onA));
    args.push_back(segmentArg(k.left));
    args = joined(std::move(args), pointArgs(t.onB));
    args.push_back(segmentArg(k.right));
    return args;
}

/// The tangent t dropped because it touches the arc of `index` on the wrong side.
Dropped wrongSide(const CircleTangent& t, const Joint& k, const Arc& arc, std::size_t index) {
    // On the outer branch (sense > 0) it touches the near side, on the inner the far one.
    return {
        false,
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
        return Dropped{true, DiagnosticCode::TangentEmptiesLeft,
                       joined(tangentArgs(t, k), {a.phiStartDeg})};
    }
    SegmentSpec line{Line{t.onA, t.onB}};
    const auto [start, end] = lineWindowDeg(line, aEnd);
    // Bit-equal joints keep the chain contiguous; the line's own window is tied to its ends.
    line.phiStartDeg = aEnd;
    line.phiEndDeg = aEnd + (end - start);
    const double bStart = line.phiEndDeg - k.shift;
    if (!(bStart < b.phiEndDeg)) {
        return Dropped{true, DiagnosticCode::TangentReversesRight,
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
        return Diagnostic::make(JointPlace{k.left, k.right}, DiagnosticCode::TangentSameCircle);
    }
    const bool aInside = a.radius < b.radius;
    const std::size_t inner = aInside ? k.left : k.right;
    const std::size_t outer = aInside ? k.right : k.left;
    return Diagnostic::make(JointPlace{k.left, k.right}, DiagnosticCode::TangentCircleInside,
                            {segmentArg(inner), segmentArg(outer)});
}

/// A code with its arguments: where the arc-through-a-point construction stops.
struct Refusal {
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
            return Refusal{DiagnosticCode::ArcRowNotCircle, {segmentArg(row)}};
        }
        end.point = pointOnSegment(s, s.phiEndDeg);
        if (!finite(end.point)) {
            return Refusal{DiagnosticCode::ArcRayMissesEnd, {s.phiEndDeg, segmentArg(row)}};
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
        return Refusal{DiagnosticCode::ArcNoEndDirection, {segmentArg(row)}};
    }
    end.travel /= length;
    if (!(cross(end.point, end.travel) > 0.0)) {
        return Refusal{DiagnosticCode::ArcEndClockwise,
                       joined({segmentArg(row)}, pointArgs(end.point))};
    }
    return end;
}

/// Moves the start of `next` to the angle startDeg (the arc's end) and, for a line or spline,
/// its start point to P. Why not if its window would be empty or reversed.
std::optional<Refusal> moveStart(SegmentSpec& next, std::size_t index, double startDeg,
                                 const Vec& p) {
    if (!(startDeg < next.phiEndDeg)) {
        return Refusal{DiagnosticCode::ArcEndsAfterNext,
                       {startDeg, next.phiEndDeg, segmentArg(index)}};
    }
    if (next.as<Arc>()) {
        next.phiStartDeg = startDeg;
        return std::nullopt;
    }
    if (auto* line = next.as<Line>()) {
        line->from = p;
        if ((line->to - p).norm() <= kJointToleranceMm) {
            return Refusal{DiagnosticCode::ArcPointIsNextEnd, {segmentArg(index)}};
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
        return Refusal{DiagnosticCode::ArcNextClockwise,
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
    if (auto problem =
            jointIndexProblem(n, joint, CAM_TRANSLATE_NOOP("Diagnostic", "a tangent line"))) {
        return Diagnostics{*problem};
    }
    Joint k;
    k.left = (joint + n - 1) % n;
    k.right = joint;
    k.a = &contour[k.left];
    k.b = &contour[k.right];
    k.shift = joint == 0 ? 360.0 : 0.0;
    auto fail = [&](DiagnosticCode code, std::vector<DiagnosticArg> args = {}) {
        return Diagnostics{Diagnostic::make(JointPlace{k.left, k.right}, code, std::move(args))};
    };
    for (std::size_t i : {k.left, k.right}) {
        const SegmentSpec& s = contour[i];
        if (!s.as<Arc>()) {
            return fail(DiagnosticCode::TangentNeedsArcs,
                        {segmentArg(i), std::string(typeName(s.type()))});
        }
        if (!isCircle(*s.as<Arc>())) {
            return fail(DiagnosticCode::TangentNotCircle, {segmentArg(i)});
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
            dropped.push_back({false, DiagnosticCode::TangentTouch, pointArgs(t.onA)});
            continue;
        }
        // (a) The polar angle grows from t_A to t_B.
        if (!(cross(t.onA, dir) > 0.0)) {
            dropped.push_back({false, DiagnosticCode::TangentClockwise, tangentArgs(t, k)});
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
        if (d.window) return fail(d.code, d.args);
    }
    Diagnostics reasons;
    for (const Dropped& d : dropped) reasons.push_back(Diagnostic::make({}, d.code, d.args));
    return Diagnostics{
        Diagnostic::make(JointPlace{k.left, k.right}, DiagnosticCode::TangentNoneFits)
            .because(std::move(reasons))};
}

Result<ArcThroughPointResult> arcThroughPoint(const std::vector<SegmentSpec>& contour,
                                              std::size_t row, Eigen::Vector2d point) {
    const std::size_t n = contour.size();
    if (n == 0) {
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::Contour}, DiagnosticCode::ArcNoSegment)};
    }
    if (row >= n) {
        return Diagnostics{Diagnostic::make(FieldPlace{Field::Contour},
                                            DiagnosticCode::ArcNoSuchRow,
                                            {segmentArg(row), static_cast<double>(n - 1)})};
    }
    const std::size_t next = (row + 1) % n;
    auto fail = [&](Refusal refusal) {
        return Diagnostics{
            Diagnostic::make(JointPlace{row, next}, refusal.code, std::move(refusal.args))};
    };
    const SegmentSpec& s = contour[row];
    if (n == 1 && !s.as<Arc>()) {
        return fail({DiagnosticCode::ArcSingleNotCircle,
                     {segmentArg(row), std::string(typeName(s.type()))}});
    }
    const auto end = rowEnd(s, row);
    if (const auto* refusal = std::get_if<Refusal>(&end)) return fail(*refusal);
    const Vec t = std::get<RowEnd>(end).point;
    const Vec travel = std::get<RowEnd>(end).travel;
    const Vec& p = point;

    if (!finite(p)) {
        return fail({DiagnosticCode::ArcPointNotFinite, pointArgs(p)});
    }
    if (p.norm() <= kJointToleranceMm) {
        return fail({DiagnosticCode::ArcPointAtCentre, {}});
    }
    const Vec w = p - t;
    if (w.norm() <= kJointToleranceMm) {
        return fail({DiagnosticCode::ArcPointIsEnd, joined(pointArgs(t), {segmentArg(row)})});
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
        return fail({DiagnosticCode::ArcPointOnTangent, {}});
    }
    if (radius < kMinLengthMm) {
        return fail({DiagnosticCode::ArcRadiusTooSmall, {radius, kMinLengthMm}});
    }
    // s > 0: centre on the left, the arc turns counter-clockwise about it: outer.
    const double sense = sc > 0.0 ? 1.0 : -1.0;
    // The circle's centre and radius, as the messages name it.
    const std::vector<DiagnosticArg> circleArgs = joined(pointArgs(center), {shown(radius)});
    const bool outer = sense > 0.0;
    if (!onBranch(t, center, sense)) {  // guarded by cross(T, t) > 0 up to rounding
        return fail({outer ? DiagnosticCode::ArcEndOffOuter : DiagnosticCode::ArcEndOffInner,
                     joined({segmentArg(row)}, circleArgs)});
    }
    if (!onBranch(p, center, sense)) {
        // The outer branch (sense > 0) leaves on the far side, so the point is on the near one.
        return fail({outer ? DiagnosticCode::ArcPointOnNearSide : DiagnosticCode::ArcPointOnFarSide,
                     joined(circleArgs, {segmentArg(row)})});
    }
    const double sweep = sweepRad(t - center, p - center, sense);
    if (!arcSweepOnBranch(center, radius, t, sweep, sense)) {
        return fail({outer ? DiagnosticCode::ArcRunsBackNear : DiagnosticCode::ArcRunsBackFar,
                     joined({segmentArg(row)}, circleArgs)});
    }
    const double startDeg = s.phiEndDeg;
    const double endDeg = startDeg + mod360(polarDeg(p) - startDeg);
    if (!(endDeg > startDeg)) {
        return fail({DiagnosticCode::ArcPointOnEndRay, {startDeg, segmentArg(row)}});
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
