#include "toolpath/tool_path.h"
#include "geometry/planar.h"

#include <cmath>
#include <limits>
#include <optional>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "common/cancel.h"
#include "project/validate.h"
#include "toolpath/biarc.h"

namespace cam {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

Vec2 xy(const Vec3& v) { return v.head<2>(); }

}  // namespace

PathSegment PathSegment::line(const Vec3& a, const Vec3& b) {
    PathSegment s;
    s.kind = Kind::Line;
    s.start = a;
    s.end = b;
    return s;
}

PathSegment PathSegment::arc(const Vec2& center, double radius, double startAngle, double sweep,
                             double z) {
    PathSegment s;
    s.kind = Kind::Arc;
    s.center = center;
    s.radius = radius;
    s.startAngle = startAngle;
    s.sweep = sweep;
    s.start = Vec3(center.x() + radius * std::cos(startAngle),
                   center.y() + radius * std::sin(startAngle), z);
    const double endAngle = startAngle + sweep;
    s.end =
        Vec3(center.x() + radius * std::cos(endAngle), center.y() + radius * std::sin(endAngle), z);
    return s;
}

double PathSegment::length() const {
    return kind == Kind::Line ? (end - start).norm() : std::abs(sweep) * radius;
}

Vec3 PathSegment::point(double s) const {
    if (kind == Kind::Line) return start + (end - start).normalized() * s;
    const double theta = startAngle + std::copysign(s / radius, sweep);
    return {center.x() + radius * std::cos(theta), center.y() + radius * std::sin(theta),
            start.z()};
}

Vec3 PathSegment::tangent(double s) const {
    if (kind == Kind::Line) return (end - start).normalized();
    const double sign = sweep >= 0 ? 1.0 : -1.0;
    const double theta = startAngle + sign * s / radius;
    return {-sign * std::sin(theta), sign * std::cos(theta), 0.0};
}

Vec3 PathSegment::curvature(double s) const {
    if (kind == Kind::Line) return Vec3::Zero();
    const double theta = startAngle + std::copysign(s / radius, sweep);
    return {-std::cos(theta) / radius, -std::sin(theta) / radius, 0.0};
}

double ToolPath::length() const {
    double total = 0.0;
    for (const PathSegment& s : segments) total += s.length();
    return total;
}

namespace {

constexpr double kUnlimitedReach = std::numeric_limits<double>::infinity();

/// The largest coordinate magnitude on the arc around `center` of `radius` that starts in the
/// direction `from` (from the centre) and sweeps `sweep`: its end points and the extremes of the
/// circle (at 0°, 90°, 180°, 270°) that it passes.
double arcReach(const Vec2& center, double radius, const Vec2& from, double sweep) {
    const double start = std::atan2(from.y(), from.x());
    double reach = 0.0;
    auto take = [&](double angle) {
        const Vec2 p = center + radius * Vec2(std::cos(angle), std::sin(angle));
        // A circle too large for a double (bulge 1.7e308) has no finite point: it reaches "inf".
        const double far = p.allFinite() ? p.cwiseAbs().maxCoeff() : kUnlimitedReach;
        reach = std::max(reach, far);
    };
    take(start);
    take(start + sweep);
    for (int q = 0; q < 4; ++q) {
        const double extreme = q * kPi / 2.0;
        // How far along the sweep's direction the extreme lies from the start, in [0, 2π).
        double along = std::remainder(sweep >= 0 ? extreme - start : start - extreme, kTwoPi);
        if (along < 0) along += kTwoPi;
        if (along <= std::abs(sweep)) take(extreme);
    }
    return reach;
}

}  // namespace

Result<ToolPath> toolPathFromPoints(const std::vector<PathPoint>& points) {
    Diagnostics errors;
    auto at = [](std::size_t k) { return FieldPlace{Field::Point, static_cast<int>(k)}; };
    for (std::size_t k = 0; k < points.size(); ++k) {
        const PathPoint& p = points[k];
        if (!p.position.allFinite() || !std::isfinite(p.bulge) ||
            p.position.cwiseAbs().maxCoeff() > kMaxPathCoordinateMm) {
            errors.push_back(Diagnostic::make(at(k), DiagnosticCode::PathPointInvalid));
        }
    }
    if (points.size() < 2) {
        errors.push_back(
            Diagnostic::make(FieldPlace{Field::Points}, DiagnosticCode::PathTooFewPoints));
    }
    if (!errors.empty()) return errors;

    ToolPath path;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const Vec3& a = points[k].position;
        const Vec3& b = points[k + 1].position;
        if ((b - a).norm() < 1e-9) {
            errors.push_back(Diagnostic::make(at(k + 1), DiagnosticCode::PathPointRepeated));
            continue;
        }
        const double bulge = points[k].bulge;
        if (std::abs(bulge) <= kStraightBulge) {
            path.segments.push_back(PathSegment::line(a, b));
            continue;
        }
        if (std::abs(b.z() - a.z()) > 1e-9) {
            errors.push_back(Diagnostic::make(at(k), DiagnosticCode::PathArcChangesHeight,
                                              {bulge, a.z(), b.z()}));
            continue;
        }
        const Vec2 chord = xy(b) - xy(a);
        const double c = chord.norm();
        if (c < 1e-9) {
            errors.push_back(Diagnostic::make(at(k + 1), DiagnosticCode::PathArcNoChord));
            continue;
        }
        // DXF bulge b = tan(θ/4): the centre sits (c/4)·(1/b − b) to the left of the chord and
        // the radius is (c/4)·(1/|b| + |b|) (written so that neither b² nor 1/b² overflows).
        const double theta = 4.0 * std::atan(bulge);
        const Vec2 left(-chord.y() / c, chord.x() / c);
        const double offset = (c / 4.0) / bulge - (c / 4.0) * bulge;
        const double radius = (c / 4.0) / std::abs(bulge) + (c / 4.0) * std::abs(bulge);
        const Vec2 center = (xy(a) + xy(b)) / 2.0 + left * offset;
        // The arc stays where the points may be: a large bulge on a long chord is a circle of
        // huge radius (bulge 1e9 on a 10 mm chord: 2.5e9 mm), with a length and times to match.
        const double reach = arcReach(center, radius, (xy(a) - center), theta);
        if (!(reach <= kMaxPathCoordinateMm)) {
            errors.push_back(Diagnostic::make(at(k), DiagnosticCode::PathArcTooFar,
                                              {bulge, reach, kMaxPathCoordinateMm}));
            continue;
        }
        const Vec2 ra = xy(a) - center;
        path.segments.push_back(
            PathSegment::arc(center, radius, std::atan2(ra.y(), ra.x()), theta, a.z()));
        // Exactly the given points, not their recomputation from a far centre.
        path.segments.back().start = a;
        path.segments.back().end = b;
    }
    if (!errors.empty()) return errors;
    return path;
}

namespace {

/// Contour point, tangent dP/dφ and the outward normal (right of the counter-clockwise
/// direction of travel) at φ on segment k.
struct ContourFrame {
    Vec2 point;
    Vec2 tangent;  // unit
    Vec2 normal;   // unit, outwards
};

ContourFrame frameAt(const ContourSegment& seg, double phi) {
    const PolarDerivatives d = seg.evaluate(phi);
    const Vec2 u(std::cos(phi), std::sin(phi)), u1(-std::sin(phi), std::cos(phi));
    const Vec2 t = (d.dr * u + d.r * u1).normalized();
    return {d.r * u, t, Vec2(t.y(), -t.x())};
}

double sweepFrom(const Vec2& from, const Vec2& to, double direction) {
    double sweep = std::atan2(cross(from, to), from.dot(to));  // (-π, π]
    if (direction > 0 && sweep <= 1e-15) sweep += kTwoPi;
    if (direction < 0 && sweep >= -1e-15) sweep -= kTwoPi;
    return sweep;
}

/// Intersections of two path segments' full curves (lines, circles) in the XY plane.
std::vector<Vec2> intersections(const PathSegment& p, const PathSegment& q) {
    auto lineLine = [](const PathSegment& a, const PathSegment& b) -> std::vector<Vec2> {
        const Vec2 u = xy(a.end - a.start), v = xy(b.end - b.start);
        const double den = cross(u, v);
        if (std::abs(den) < 1e-15 * u.norm() * v.norm()) return {};
        const double t = cross(xy(b.start - a.start), v) / den;
        return {xy(a.start) + t * u};
    };
    auto lineCircle = [](const PathSegment& l, const Vec2& c, double r) -> std::vector<Vec2> {
        const Vec2 u = xy(l.end - l.start).normalized();
        const Vec2 w = xy(l.start) - c;
        const double b = u.dot(w), disc = b * b - (w.squaredNorm() - r * r);
        if (disc < 0) return {};
        return {xy(l.start) + (-b + std::sqrt(disc)) * u, xy(l.start) + (-b - std::sqrt(disc)) * u};
    };
    auto circleCircle = [](const Vec2& c1, double r1, const Vec2& c2,
                           double r2) -> std::vector<Vec2> {
        const double d = (c2 - c1).norm();
        if (d < 1e-12) return {};
        const double a = (d * d + r1 * r1 - r2 * r2) / (2 * d), h2 = r1 * r1 - a * a;
        if (h2 < 0) return {};
        const Vec2 e = (c2 - c1) / d, base = c1 + a * e, n(-e.y(), e.x());
        return {base + std::sqrt(h2) * n, base - std::sqrt(h2) * n};
    };
    using K = PathSegment::Kind;
    if (p.kind == K::Line && q.kind == K::Line) return lineLine(p, q);
    if (p.kind == K::Line) return lineCircle(p, q.center, q.radius);
    if (q.kind == K::Line) return lineCircle(q, p.center, p.radius);
    return circleCircle(p.center, p.radius, q.center, q.radius);
}

void moveEnd(PathSegment& s, const Vec2& p) {
    if (s.kind == PathSegment::Kind::Line) {
        s.end = Vec3(p.x(), p.y(), s.end.z());
        return;
    }
    const Vec2 from(std::cos(s.startAngle), std::sin(s.startAngle));
    s = PathSegment::arc(s.center, s.radius, s.startAngle,
                         sweepFrom(from, (p - s.center).normalized(), s.sweep), s.start.z());
}

void moveStart(PathSegment& s, const Vec2& p) {
    if (s.kind == PathSegment::Kind::Line) {
        s.start = Vec3(p.x(), p.y(), s.start.z());
        return;
    }
    const double endAngle = s.startAngle + s.sweep;
    const Vec2 to(std::cos(endAngle), std::sin(endAngle));
    const Vec2 from = (p - s.center).normalized();
    s = PathSegment::arc(s.center, s.radius, std::atan2(from.y(), from.x()),
                         sweepFrom(from, to, s.sweep), s.start.z());
}

/// The piece offset outwards (to the right of travel) by rho: lines shift, arcs change radius
/// (turning left the centre is on the left, so the radius grows). Empty if it vanishes.
std::optional<PathSegment> offsetPiece(const PathSegment& s, double rho) {
    if (s.kind == PathSegment::Kind::Line) {
        const Vec2 d = xy(s.end - s.start).normalized();
        const Vec3 shift(rho * d.y(), -rho * d.x(), 0.0);
        return PathSegment::line(s.start + shift, s.end + shift);
    }
    const double radius = s.radius + (s.sweep >= 0 ? rho : -rho);
    if (radius <= 1e-9) return std::nullopt;
    return PathSegment::arc(s.center, radius, s.startAngle, s.sweep, s.start.z());
}

/// Where p lies along `piece`: its distance from the start along the piece, mm (on an arc,
/// measured in the sweep's direction, in [0, 2πR)).
double distanceAlong(const PathSegment& piece, const Vec2& p) {
    if (piece.kind == PathSegment::Kind::Line) {
        return (p - xy(piece.start)).dot(xy(piece.end - piece.start).normalized());
    }
    const Vec2 from(std::cos(piece.startAngle), std::sin(piece.startAngle));
    const Vec2 to = (p - piece.center).normalized();
    double angle = std::atan2(cross(from, to), from.dot(to));  // (-π, π]
    if (piece.sweep < 0) angle = -angle;
    if (angle < 0) angle += kTwoPi;
    return angle * piece.radius;
}

/// Whether p (on the piece's line or circle) lies within the piece, to 1e-9 of its length.
bool liesOn(const PathSegment& piece, const Vec2& p) {
    const double length = piece.length();
    const double eps = 1e-9 * std::max(1.0, length);
    double a = distanceAlong(piece, p);
    if (piece.kind == PathSegment::Kind::Arc && a > kTwoPi * piece.radius - eps) {
        a -= kTwoPi * piece.radius;  // a hair before the start
    }
    return a >= -eps && a <= length + eps;
}

/// Trimming at a concave corner may only shorten a piece within its own extent and direction.
/// An arc whose sweep changed sign, wrapped or grew, or a line that runs backwards or past its
/// ends, is what a tool too large for the piece gives: the trims of its two ends cross.
bool trimmedWithin(const PathSegment& original, const PathSegment& trimmed) {
    const double length = original.length();
    const double eps = 1e-9 * std::max(1.0, length);
    double a = distanceAlong(original, xy(trimmed.start));
    double b = distanceAlong(original, xy(trimmed.end));
    if (original.kind == PathSegment::Kind::Arc) {
        // A point a hair before the start reads as almost a full turn; a hair after the end of
        // an almost full arc as almost zero.
        const double turn = kTwoPi * original.radius;
        if (a > turn - eps) a -= turn;
        if (b < eps && length > turn - eps) b += turn;
    }
    const bool sameSense =
        original.kind == PathSegment::Kind::Line || (trimmed.sweep > 0) == (original.sweep > 0);
    return sameSense && a >= -eps && b <= length + eps && b - a >= 1e-9 &&
           std::abs((b - a) - trimmed.length()) <= eps;
}

}  // namespace

Result<ToolPath> toolPathFromContour(const Contour& contour, double toolRadius,
                                     const std::atomic<bool>* cancel) {
    auto offset = offsetContour(contour, toolRadius, kSplineToleranceMm, cancel);
    if (!offset.ok()) return offset.errors();
    return std::move(offset.value().path);
}

Result<ContourOffset> offsetContour(const Contour& contour, double toolRadius,
                                    double splineToleranceMm, const std::atomic<bool>* cancel) {
    Diagnostics errors;
    const std::size_t n = contour.size();
    // Per contour segment, its offset pieces (one, or a spline's biarcs).
    std::vector<std::vector<PathSegment>> offset(n);
    std::vector<ContourFrame> starts, ends;
    for (std::size_t k = 0; k < n; ++k) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        const ContourSegment& seg = contour.segment(k);
        const ContourFrame a = frameAt(seg, seg.phiStart), b = frameAt(seg, seg.phiEnd);
        starts.push_back(a);
        ends.push_back(b);
        if (isSpline(seg.type)) {
            // Tangent arc pairs within 0.1 µm: lines and arcs for the planner, G1 throughout.
            for (const PathSegment& piece :
                 biarcsOf(CubicBezier{seg.bezierKernel.p}, splineToleranceMm, 0.0, cancel)) {
                const auto shifted = offsetPiece(piece, toolRadius);
                if (!shifted) {
                    errors.push_back(Diagnostic::make(SegmentPlace{k},
                                                      DiagnosticCode::ToolAboveCurveRadius,
                                                      {toolRadius, piece.radius}));
                    break;
                }
                offset[k].push_back(*shifted);
            }
            continue;
        }
        if (seg.type == SegmentType::Line) {
            offset[k].push_back(
                PathSegment::line(Vec3(a.point.x() + toolRadius * a.normal.x(),
                                       a.point.y() + toolRadius * a.normal.y(), 0),
                                  Vec3(b.point.x() + toolRadius * b.normal.x(),
                                       b.point.y() + toolRadius * b.normal.y(), 0)));
            continue;
        }
        const Vec2 c = seg.arc.center;
        const double r = seg.arc.radius;
        const Vec2 wa = (a.point - c) / r, wb = (b.point - c) / r;
        // Convex where the circle bulges outwards (normal away from its centre): the offset
        // circle grows; on a concave arc it shrinks and vanishes at the tool radius.
        const double convex = wa.dot(a.normal) >= 0 ? 1.0 : -1.0;
        const double radius = r + convex * toolRadius;
        if (radius <= 1e-9) {
            errors.push_back(Diagnostic::make(
                SegmentPlace{k}, DiagnosticCode::ToolNotBelowArcRadius, {toolRadius, r}));
            continue;
        }
        const double direction = cross(wa, a.tangent) >= 0 ? 1.0 : -1.0;
        const bool fullTurn = n == 1;
        const double sweep = fullTurn ? direction * kTwoPi : sweepFrom(wa, wb, direction);
        offset[k].push_back(PathSegment::arc(c, radius, std::atan2(wa.y(), wa.x()), sweep, 0.0));
    }
    // Biarcs stop early when cancelled: never hand out a path built from them.
    if (cancelRequested(cancel)) return cancelledDiagnostics();
    if (!errors.empty()) return errors;
    ContourOffset result;
    ToolPath& path = result.path;
    if (toolRadius == 0.0 || n == 1) {
        for (std::size_t k = 0; k < n; ++k) {
            path.segments.insert(path.segments.end(), offset[k].begin(), offset[k].end());
            result.origin.insert(result.origin.end(), offset[k].size(), k);
        }
        return result;
    }

    std::vector<std::vector<PathSegment>> joined = offset;
    std::vector<std::optional<PathSegment>> cornerArcs(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        const std::size_t next = (k + 1) % n;
        const ContourFrame& left = ends[k];
        const ContourFrame& right = starts[next];
        const double turn =
            std::atan2(cross(left.tangent, right.tangent), left.tangent.dot(right.tangent));
        // Tangent joint: the offsets meet (within the contour's own precision). Treating a break
        // of 1e-8 rad as a corner would intersect two nearly tangent offsets, which moves the
        // joint by sqrt(2Rδ) and tilts both tangents.
        if (std::abs(turn) <= degToRad(kTangentToleranceDeg)) continue;
        if (turn > 0) {
            // Convex corner: the tool rolls around the corner point.
            const Vec2 na = left.normal;
            cornerArcs[k] =
                PathSegment::arc(left.point, toolRadius, std::atan2(na.y(), na.x()), turn, 0.0);
            continue;
        }
        // Concave corner: both offsets overshoot; cut them where they cross, nearest the corner.
        const Vec2 guess = left.point + toolRadius * (left.normal + right.normal).normalized();
        auto nearest = [&](const PathSegment& a, const PathSegment& b, bool onBoth) {
            std::optional<Vec2> best;
            for (const Vec2& p : intersections(a, b)) {
                if (onBoth && !(liesOn(a, p) && liesOn(b, p))) continue;
                if (!best || (p - guess).norm() < (*best - guess).norm()) best = p;
            }
            return best;
        };
        // A spline's offset is many short arcs: the crossing may lie pieces away from the corner.
        // The pair that drops the fewest pieces and crosses on both wins; with none, the last
        // and first pieces are cut where their curves cross (trimmedWithin judges that below).
        std::vector<PathSegment>& before = joined[k];
        std::vector<PathSegment>& after = joined[next];
        std::size_t keepBefore = before.size() - 1, keepAfter = 0;
        std::optional<Vec2> best;
        for (std::size_t dropped = 0; !best && dropped + 1 < before.size() + after.size();
             ++dropped) {
            for (std::size_t fromBefore = 0; !best && fromBefore <= dropped; ++fromBefore) {
                const std::size_t fromAfter = dropped - fromBefore;
                if (fromBefore >= before.size() || fromAfter >= after.size()) continue;
                best = nearest(before[before.size() - 1 - fromBefore], after[fromAfter], true);
                if (best) {
                    keepBefore = before.size() - 1 - fromBefore;
                    keepAfter = fromAfter;
                }
            }
        }
        if (!best) best = nearest(before.back(), after.front(), false);
        if (!best) {
            errors.push_back(
                Diagnostic::make(JointPlace{k, next}, DiagnosticCode::OffsetCornerUnmet));
            continue;
        }
        before.resize(keepBefore + 1);
        offset[k].resize(keepBefore + 1);
        after.erase(after.begin(), after.begin() + static_cast<std::ptrdiff_t>(keepAfter));
        offset[next].erase(offset[next].begin(),
                           offset[next].begin() + static_cast<std::ptrdiff_t>(keepAfter));
        moveEnd(before.back(), *best);
        moveStart(after.front(), *best);
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        for (std::size_t i = 0; i < joined[k].size(); ++i) {
            if (!trimmedWithin(offset[k][i], joined[k][i])) {
                errors.push_back(Diagnostic::make(SegmentPlace{k}, DiagnosticCode::ToolTrimsSegment,
                                                  {toolRadius}));
                break;
            }
        }
    }
    if (!errors.empty()) return errors;
    for (std::size_t k = 0; k < n; ++k) {
        path.segments.insert(path.segments.end(), joined[k].begin(), joined[k].end());
        result.origin.insert(result.origin.end(), joined[k].size(), k);
        if (cornerArcs[k]) {
            path.segments.push_back(*cornerArcs[k]);
            result.origin.push_back(kCornerPiece);
        }
    }
    return result;
}

}  // namespace cam
