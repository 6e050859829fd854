#include "contour/fit_windows.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "common/angles.h"
#include "common/golden_section.h"
#include "common/tolerances.h"
#include "geometry/line.h"
#include "geometry/planar.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// Within this, two pieces of one circle or line are the same curve: the rounding of double
/// precision, far below anything typed.
double roundingTolerance(double scale) { return 1e-12 * (1.0 + scale); }

/// Curves that touch or nearly touch (closer than the typing tolerance) meet at the tangent
/// point on the line of centres while the ray through it meets both within half the
/// validator's joint tolerance: the joint then stays smooth (the bundled six-lobe example's
/// circles overlap by 3.4e-8 mm from its ten-digit numbers, and its windows stay as they are).
/// Where the tangent point would leave a gap (a ray that meets the circles at a slant
/// magnifies it: the seed's 8-digit centres leave 1.3e-6 mm from an overlap of 6e-7 mm),
/// overlapping curves meet at their true intersections and curves that miss are moved.
using TouchCheck = std::function<bool(const Vec&)>;

double extent(const SegmentShape& shape) {
    if (const Arc* a = std::get_if<Arc>(&shape)) return a->center.norm() + a->radius;
    if (const Line* l = std::get_if<Line>(&shape)) return std::max(l->from.norm(), l->to.norm());
    return 0.0;
}

/// What joining the later segment to the earlier one needs.
struct Meeting {
    enum Kind {
        Cross,  ///< they intersect at `points`
        Touch,  ///< they touch at points[0]
        Same,   ///< one circle or one line: any boundary will do
        Near,   ///< they miss by `miss` <= the typing tolerance; `moved` is the later one moved
        Miss,   ///< they miss by `miss`, more than the typing tolerance
    } kind = Miss;
    std::vector<Vec> points;
    double miss = 0.0;
    SegmentShape moved;
    bool madeSame = false;  ///< Near: `moved` is the earlier segment's curve

    static Meeting at(Kind kind, std::vector<Vec> points = {}) {
        Meeting m;
        m.kind = kind;
        m.points = std::move(points);
        return m;
    }
};

Meeting missBy(double gap, std::optional<SegmentShape> moved, bool madeSame = false) {
    Meeting m;
    m.miss = gap;
    if (moved && gap <= kTypingToleranceMm) {
        m.kind = Meeting::Near;
        m.moved = std::move(*moved);
        m.madeSame = madeSame;
    }
    return m;
}

Meeting arcs(const Arc& a, const Arc& b, double boundaryDeg, double rt, const TouchCheck& holds) {
    const Vec d = b.center - a.center;
    const double dist = d.norm();
    const double dr = std::abs(b.radius - a.radius);
    if (a.branch == b.branch && dist + dr <= kTypingToleranceMm) {
        // Two pieces of one circle (a notch split at 0°): the second becomes the first's,
        // unless they already meet at the boundary.
        if (dist + dr <= rt || holds(fromPolar(1.0, degToRad(boundaryDeg)))) {
            return Meeting::at(Meeting::Same);
        }
        return missBy(dist + dr, Arc{a.center, a.radius, b.branch}, true);
    }
    if (dist <= rt) {
        // Concentric: they meet nowhere, or everywhere on the other branch (no boundary). The
        // smaller circle moves along the boundary ray until it touches the larger one there.
        const Vec u = fromPolar(1.0, degToRad(boundaryDeg));
        return missBy(dr,
                      Arc{b.center + (a.radius > b.radius ? u : Vec(-u)) * dr, b.radius, b.branch});
    }
    const Vec e = d / dist;
    const double external = dist - (a.radius + b.radius);  // > 0: apart
    const double internal = dr - dist;                     // > 0: one inside the other
    const double along = (dist * dist + a.radius * a.radius - b.radius * b.radius) / (2.0 * dist);
    const Vec base = a.center + along * e;
    if (std::min(std::abs(external), std::abs(internal)) <= kTypingToleranceMm && holds(base)) {
        return Meeting::at(Meeting::Touch, {base});
    }
    if (external < 0.0 && internal < 0.0) {
        const double h = std::sqrt(std::max(a.radius * a.radius - along * along, 0.0));
        return Meeting::at(Meeting::Cross, {base + h * perp(e), base - h * perp(e)});
    }
    // The smallest change of b that makes them touch: its centre onto the circle of centres
    // at distance R_a + R_b (or |R_a − R_b|) about a's, along the line of centres.
    const double gap = external > 0.0 ? external : internal;
    const Vec shift = external > 0.0 ? Vec(-gap * e) : Vec(gap * e);
    return missBy(gap, Arc{b.center + shift, b.radius, b.branch});
}

/// The line `line` and the circle `arc`; `lineIsLater` says which of them may move.
Meeting lineArc(const Line& line, const Arc& arc, bool lineIsLater, const TouchCheck& holds) {
    const Vec u = (line.to - line.from).normalized();
    const Vec w = line.from - arc.center;
    const double p = u.dot(w);
    const Vec foot = line.from - p * u;
    const Vec toFoot = foot - arc.center;
    const double dist = toFoot.norm();
    const double gap = dist - arc.radius;
    if (std::abs(gap) <= kTypingToleranceMm && holds(foot)) {
        return Meeting::at(Meeting::Touch, {foot});
    }
    if (gap < 0.0) {
        const double s = std::sqrt(std::max(arc.radius * arc.radius - dist * dist, 0.0));
        return Meeting::at(Meeting::Cross, {foot + s * u, foot - s * u});
    }
    const Vec shift = toFoot / dist * gap;  // moves the circle onto the line
    if (lineIsLater) return missBy(gap, Line{line.from - shift, line.to - shift});
    return missBy(gap, Arc{arc.center + shift, arc.radius, arc.branch});
}

Meeting lines(const Line& a, const Line& b, double rt) {
    const Vec u = (a.to - a.from).normalized();
    const auto offLine = [&](const Vec& p) { return cross(u, p - a.from); };
    const double off = std::max(std::abs(offLine(b.from)), std::abs(offLine(b.to)));
    if (off <= rt) return Meeting::at(Meeting::Same);
    if (off <= kTypingToleranceMm) {
        // Two pieces of one line: the second's ends onto the first's line.
        return missBy(off, Line{b.from - offLine(b.from) * perp(u), b.to - offLine(b.to) * perp(u)},
                      true);
    }
    const Vec u1 = a.to - a.from, u2 = b.to - b.from;
    const double c = cross(u1, u2);
    if (std::abs(c) <= 1e-12 * u1.norm() * u2.norm()) return missBy(off, std::nullopt);
    const double t = cross(b.from - a.from, u2) / c;
    return Meeting::at(Meeting::Cross, {a.from + t * u1});
}

Meeting meet(const SegmentSpec& left, const SegmentSpec& right) {
    const double rt = roundingTolerance(std::max(extent(left.shape), extent(right.shape)));
    const Arc* la = left.as<Arc>();
    const Arc* ra = right.as<Arc>();
    const Line* ll = left.as<Line>();
    const Line* rl = right.as<Line>();
    const TouchCheck holds = [&](const Vec& p) {
        const double phi = polarDeg(p);
        const double gap = (pointOnSegment(left, phi) - pointOnSegment(right, phi)).norm();
        return gap <= 0.5 * kJointToleranceMm;
    };
    if (la && ra) return arcs(*la, *ra, left.phiEndDeg, rt, holds);
    if (la) return lineArc(*rl, *la, true, holds);
    if (ra) return lineArc(*ll, *ra, false, holds);
    return lines(*ll, *rl, rt);
}

/// To first order, `moving` touches `fixed` after it changes by (Δc, ΔR) with
/// gap + a·Δc + b·ΔR = 0 (|a| = 1, |b| = 1): outside each other or one inside the other,
/// whichever is nearer.
struct Touching {
    Vec a;
    double b;
    double gap;
};

Touching touching(const Arc& fixed, const Arc& moving) {
    const Vec d = moving.center - fixed.center;
    const double dist = d.norm();
    const Vec e = dist > 0.0 ? Vec(d / dist) : Vec(1.0, 0.0);
    const double external = dist - (fixed.radius + moving.radius);
    const double internal = std::abs(fixed.radius - moving.radius) - dist;
    if (std::abs(external) <= std::abs(internal)) return {e, -1.0, external};
    return {-e, moving.radius >= fixed.radius ? 1.0 : -1.0, internal};
}

/// The smallest change of `moving` — least |Δc| + |ΔR|, the farthest any point of the circle
/// moves — that makes it touch both `first` and `second`; none when the two lines of centres
/// are parallel. A circle that misses both its neighbours by g (a radius typed short) then
/// changes its radius by g rather than moving its centre by many times g (the lines of centres
/// of the six-lobe cam meet at 167°).
std::optional<Arc> touchingBoth(const Arc& first, const Arc& moving, const Arc& second) {
    Arc m = moving;
    for (int newton = 0; newton < 3; ++newton) {  // the gaps are nearly linear over 1e-5 mm
        const Touching t1 = touching(first, m);
        const Touching t2 = touching(second, m);
        const double det = cross(t1.a, t2.a);
        if (std::abs(det) < 1e-3) return std::nullopt;
        // a1·Δc = r1, a2·Δc = r2, by Cramer's rule.
        const auto solve = [&](double r1, double r2) {
            return Vec((r1 * t2.a.y() - r2 * t1.a.y()) / det,
                       (t1.a.x() * r2 - t2.a.x() * r1) / det);
        };
        // With ΔR = t: Δc = p + q·t; minimise the convex |p + q·t| + |t| over |t| <= |p|
        // (t = 0 already gives |p|) by golden section.
        const Vec p = solve(-t1.gap, -t2.gap);
        const Vec q = solve(-t1.b, -t2.b);
        const auto cost = [&](double t) { return (p + q * t).norm() + std::abs(t); };
        const GoldenSection g = goldenSectionMin(
            cost, -p.norm(), p.norm(),
            [](double lo, double hi, int step) { return step < 200 && hi - lo > 0.0; });
        const double mid = 0.5 * (g.lo + g.hi);
        const double t = cost(0.0) <= cost(mid) ? 0.0 : mid;
        m.center += p + q * t;
        m.radius += t;
    }
    return m;
}

double moveDistance(const SegmentShape& before, const SegmentShape& after) {
    if (const Arc* a = std::get_if<Arc>(&before)) {
        const Arc* b = std::get_if<Arc>(&after);
        if (!b) internalError("fitWindows: a circle became another kind of segment");
        return (b->center - a->center).norm() + std::abs(b->radius - a->radius);
    }
    const Line* a = std::get_if<Line>(&before);
    const Line* b = std::get_if<Line>(&after);
    if (!a || !b) return 0.0;  // splines are never moved
    return std::max((b->from - a->from).norm(), (b->to - a->to).norm());
}

bool isSplineJoint(const SegmentSpec& left, const SegmentSpec& right) {
    return isSpline(left.type()) || isSpline(right.type());
}

/// The later circle of joint k moved by `m` along the line of centres would open its other
/// joint (or leave it open): the smallest change that closes both instead, if there is one.
std::optional<Arc> touchingOtherJointToo(const std::vector<SegmentSpec>& contour, std::size_t k,
                                         const Meeting& m) {
    const std::size_t n = contour.size();
    const std::size_t j = (k + 1) % n;
    const std::size_t next = (j + 1) % n;
    const Arc* first = contour[k].as<Arc>();
    const Arc* moving = contour[j].as<Arc>();
    const Arc* second = contour[next].as<Arc>();
    if (m.madeSame || next == k || !first || !moving || !second) return std::nullopt;
    SegmentSpec trial = contour[j];
    trial.shape = m.moved;
    const Meeting other = meet(trial, contour[next]);
    if (other.kind != Meeting::Near && other.kind != Meeting::Miss) return std::nullopt;
    if (other.madeSame) return std::nullopt;  // two pieces of one circle: no tangency to keep
    const Meeting now = meet(contour[j], contour[next]);
    if (now.kind == Meeting::Same || (now.kind == Meeting::Near && now.madeSame)) {
        return std::nullopt;
    }
    return touchingBoth(*first, *moving, *second);
}

/// Rounds of moves before the joints must have settled: a move opens at most the moved
/// segment's other joint, and a chain of moves ends at the first joint that overlaps.
constexpr int kMaxRounds = 8;

Diagnostic moveNote(const SegmentMove& m) {
    const auto k = static_cast<double>(m.neighbour);
    if (const Arc* after = std::get_if<Arc>(&m.after)) {
        const Arc& before = std::get<Arc>(m.before);
        if (m.tookNeighboursCurve) {
            return Diagnostic::make(
                SegmentPlace{m.segment, SegmentPart::Whole}, DiagnosticCode::WindowsCircleMadeSame,
                {k, m.distanceMm, after->center.x(), after->center.y(), after->radius},
                Severity::Info);
        }
        if (m.alsoNeighbour) {
            return Diagnostic::make(SegmentPlace{m.segment, SegmentPart::Whole},
                                    DiagnosticCode::WindowsCircleResized,
                                    {m.distanceMm, before.center.x(), before.center.y(),
                                     before.radius, after->center.x(), after->center.y(),
                                     after->radius, k, static_cast<double>(*m.alsoNeighbour)},
                                    Severity::Info);
        }
        return Diagnostic::make(SegmentPlace{m.segment, SegmentPart::Center},
                                DiagnosticCode::WindowsCircleMoved,
                                {m.distanceMm, before.center.x(), before.center.y(),
                                 after->center.x(), after->center.y(), k},
                                Severity::Info);
    }
    return Diagnostic::make(SegmentPlace{m.segment, SegmentPart::Whole},
                            DiagnosticCode::WindowsLineMoved, {m.distanceMm, k}, Severity::Info);
}

}  // namespace

double FittedWindows::largestMoveMm() const {
    double largest = 0.0;
    for (const SegmentMove& m : moves) largest = std::max(largest, m.distanceMm);
    return largest;
}

Result<FittedWindows> fitWindows(const std::vector<SegmentSpec>& contour) {
    const std::size_t n = contour.size();
    if (n < 2) return FittedWindows{contour, {}, {}, {}};
    std::vector<SegmentSpec> moved = contour;
    // Per segment, why it moved last: the neighbour it was made to meet, the one after it that
    // it was made to touch too, or that it took the neighbour's curve.
    std::vector<std::size_t> movedFor(n, 0);
    std::vector<std::optional<std::size_t>> alsoFor(n);
    std::vector<bool> madeSame(n, false);
    // Which segments moved: a shape compared with itself is not the test, since a NaN in a
    // segment (which validation then reports) makes it unequal to itself.
    std::vector<bool> changed(n, false);
    // Gauss–Seidel over the joints: each closes its gap by moving its later segment, which the
    // next joint then sees. The last joint moves the first segment, so a second round checks
    // the first joint again.
    for (int round = 0; round < kMaxRounds; ++round) {
        bool any = false;
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t j = (k + 1) % n;
            if (isSplineJoint(moved[k], moved[j])) continue;
            Meeting m = meet(moved[k], moved[j]);
            if (m.kind != Meeting::Near) continue;
            std::optional<std::size_t> also;
            if (const auto both = touchingOtherJointToo(moved, k, m);
                both && moveDistance(contour[j].shape, *both) <= kTypingToleranceMm) {
                m.moved = *both;
                also = (j + 1) % n;
            }
            const double total = moveDistance(contour[j].shape, m.moved);
            if (total > kTypingToleranceMm) {
                return Diagnostics{Diagnostic::make(JointPlace{k, j},
                                                    DiagnosticCode::WindowsMoveTooLarge,
                                                    {static_cast<double>(j), total})};
            }
            moved[j].shape = std::move(m.moved);
            changed[j] = true;
            movedFor[j] = k;
            alsoFor[j] = also;
            madeSame[j] = m.madeSame;
            any = true;
        }
        if (!any) break;
    }

    FittedWindows fitted;
    fitted.joints.resize(n);
    std::vector<Vec> points(n);
    Diagnostics errors;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = (k + 1) % n;
        const SegmentSpec& left = moved[k];
        const SegmentSpec& right = moved[j];
        const double current = left.phiEndDeg;
        const auto angleOf = [current](const Vec& p) {
            return current + wrapDeg(polarDeg(p) - current);
        };
        if (isSplineJoint(left, right)) {
            // A spline's end points are fixed by its control points: the joint is there.
            points[k] = isSpline(left.type()) ? endPointsOf(left).second : endPointsOf(right).first;
            fitted.joints[k] = {angleOf(points[k]), JointMeeting::SplineEnd};
            continue;
        }
        const Meeting m = meet(left, right);
        switch (m.kind) {
            case Meeting::Same:
                points[k] = pointOnSegment(left, current);
                fitted.joints[k] = {current, JointMeeting::SameCurve};
                continue;
            case Meeting::Near:
                errors.push_back(Diagnostic::make(JointPlace{k, j},
                                                  DiagnosticCode::WindowsMovesDoNotSettle,
                                                  {m.miss, static_cast<double>(kMaxRounds)}));
                continue;
            case Meeting::Miss:
                errors.push_back(Diagnostic::make(
                    JointPlace{k, j}, DiagnosticCode::WindowsSegmentsDoNotMeet, {m.miss}));
                continue;
            case Meeting::Cross:
            case Meeting::Touch:
                break;
        }
        std::optional<double> best;
        for (const Vec& p : m.points) {
            if (p.norm() < 1e-9) continue;  // at the rotation centre: no ray angle
            const double angle = angleOf(p);
            if (!best || std::abs(angle - current) < std::abs(*best - current)) {
                best = angle;
                points[k] = p;
            }
        }
        if (!best) {
            errors.push_back(Diagnostic::make(JointPlace{k, j},
                                              DiagnosticCode::WindowsSegmentsDoNotMeet, {0.0}));
            continue;
        }
        fitted.joints[k] = {
            *best, m.kind == Meeting::Touch ? JointMeeting::Tangent : JointMeeting::Crossing};
    }
    if (!errors.empty()) return errors;

    for (std::size_t k = 0; k < n; ++k) {
        const double angle = fitted.joints[k].angleDeg;
        SegmentSpec& left = moved[k];
        SegmentSpec& right = moved[(k + 1) % n];
        if (k + 1 < n) {
            left.phiEndDeg = angle;
            right.phiStartDeg = angle;
        } else {  // the wrap-around joint: the first window starts there, the last ends a turn on
            right.phiStartDeg =
                angle - 360.0 * std::round((angle - contour[0].phiStartDeg) / 360.0);
            left.phiEndDeg = right.phiStartDeg + 360.0;
        }
    }
    for (std::size_t j = 0; j < n; ++j) {
        if (changed[j]) {
            SegmentMove m{j,
                          movedFor[j],
                          alsoFor[j],
                          madeSame[j],
                          contour[j].shape,
                          moved[j].shape,
                          moveDistance(contour[j].shape, moved[j].shape)};
            fitted.notes.push_back(moveNote(m));
            fitted.moves.push_back(std::move(m));
        }
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (auto* line = moved[k].as<Line>()) line->to = points[k];
        if (auto* line = moved[(k + 1) % n].as<Line>()) line->from = points[k];
    }
    fitted.contour = std::move(moved);
    return fitted;
}

}  // namespace cam
