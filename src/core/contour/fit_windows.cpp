#include "contour/fit_windows.h"

#include <cmath>
#include <optional>

#include "common/angles.h"
#include "geometry/line.h"
#include "geometry/planar.h"
#include "project/validate.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// Circles (or a circle and a line) closer than this count as touching: their tangent point
/// is used. Far below anything a designer types, above the rounding of ten-digit data.
double touchTolerance(double scale) { return 1e-6 * (1.0 + scale); }

std::vector<Vec> circleCircle(const Vec& c1, double r1, const Vec& c2, double r2) {
    const Vec d = c2 - c1;
    const double dist = d.norm();
    if (dist < 1e-12) return {};  // concentric: no isolated meeting point
    const Vec e = d / dist;
    const double a = (dist * dist + r1 * r1 - r2 * r2) / (2.0 * dist);
    const double h2 = r1 * r1 - a * a;
    const Vec base = c1 + a * e;
    // Nearly touching circles mean "tangent": an overlap of 1e-8 mm would otherwise split the
    // tangent point into two intersections sqrt(2Rδ) ≈ 4e-4 mm apart.
    const double gap = std::min(std::abs(dist - (r1 + r2)), std::abs(dist - std::abs(r1 - r2)));
    if (gap <= touchTolerance(std::max(r1, r2))) return {base};
    if (h2 < 0.0) return {};
    const double h = std::sqrt(h2);
    return {base + h * perp(e), base - h * perp(e)};
}

std::vector<Vec> lineCircle(const Vec& a, const Vec& b, const Vec& c, double r) {
    const Vec u = (b - a).normalized();
    const Vec w = a - c;
    const double p = u.dot(w);
    const double disc = p * p - (w.squaredNorm() - r * r);
    const Vec foot = a - p * u;
    if (std::abs((foot - c).norm() - r) <= touchTolerance(r)) return {foot};  // tangent
    if (disc < 0.0) return {};
    const double s = std::sqrt(disc);
    return {a + (-p + s) * u, a + (-p - s) * u};
}

std::vector<Vec> lineLine(const Vec& a1, const Vec& b1, const Vec& a2, const Vec& b2) {
    const Vec u1 = b1 - a1, u2 = b2 - a2;
    const double cross = u1.x() * u2.y() - u1.y() * u2.x();
    if (std::abs(cross) <= 1e-12 * u1.norm() * u2.norm()) return {};
    const Vec w = a2 - a1;
    const double t = (w.x() * u2.y() - w.y() * u2.x()) / cross;
    return {a1 + t * u1};
}

/// Two pieces of one circle or one line: any angle is a valid boundary.
bool sameCurve(const SegmentSpec& s, const SegmentSpec& t) {
    if (s.type() != t.type()) return false;
    if (const auto* a = s.as<Arc>()) {
        const Arc& b = *t.as<Arc>();
        return (a->center - b.center).norm() <= touchTolerance(a->radius) &&
               std::abs(a->radius - b.radius) <= touchTolerance(a->radius) && a->branch == b.branch;
    }
    const Line& a = *s.as<Line>();
    const Line& b = *t.as<Line>();
    const Vec u = (a.to - a.from).normalized();
    auto offLine = [&](const Vec& p) { return std::abs(cross(u, p - a.from)); };
    const double scale = std::max(a.from.norm(), a.to.norm());
    return offLine(b.from) <= touchTolerance(scale) && offLine(b.to) <= touchTolerance(scale);
}

std::vector<Vec> meetingPoints(const SegmentSpec& s, const SegmentSpec& t) {
    const Arc* sArc = s.as<Arc>();
    const Arc* tArc = t.as<Arc>();
    const Line* sLine = s.as<Line>();
    const Line* tLine = t.as<Line>();
    if (sArc && tArc) return circleCircle(sArc->center, sArc->radius, tArc->center, tArc->radius);
    if (sArc) return lineCircle(tLine->from, tLine->to, sArc->center, sArc->radius);
    if (tArc) return lineCircle(sLine->from, sLine->to, tArc->center, tArc->radius);
    return lineLine(sLine->from, sLine->to, tLine->from, tLine->to);
}

}  // namespace

Result<std::vector<SegmentSpec>> fitWindows(const std::vector<SegmentSpec>& contour) {
    const std::size_t n = contour.size();
    if (n < 2) return contour;
    std::vector<SegmentSpec> out = contour;
    Diagnostics errors;
    struct Joint {
        double angleDeg;
        Vec point;
    };
    std::vector<std::optional<Joint>> joints(n);  // joint k: end of k, start of k+1
    for (std::size_t k = 0; k < n; ++k) {
        const SegmentSpec& left = contour[k];
        const SegmentSpec& right = contour[(k + 1) % n];
        const double current = left.phiEndDeg;
        std::optional<Joint> best;
        if (isSpline(left.type()) || isSpline(right.type())) {
            // A spline's end points are fixed by its control points: the joint is there.
            const Vec p =
                isSpline(left.type()) ? endPointsOf(left).second : endPointsOf(right).first;
            const double angle = current + wrapDeg(radToDeg(std::atan2(p.y(), p.x())) - current);
            joints[k] = Joint{angle, p};
            continue;
        }
        if (sameCurve(left, right)) {
            joints[k] = Joint{current, pointOnSegment(left, current)};
            continue;
        }
        for (const Vec& p : meetingPoints(left, right)) {
            if (p.norm() < 1e-9) continue;  // at the rotation centre: no ray angle
            const double angle = current + wrapDeg(radToDeg(std::atan2(p.y(), p.x())) - current);
            if (!best || std::abs(angle - current) < std::abs(best->angleDeg - current)) {
                best = Joint{angle, p};
            }
        }
        if (!best) {
            errors.push_back(Diagnostic::make(JointPlace{k, (k + 1) % n},
                                              DiagnosticCode::WindowsSegmentsDoNotMeet));
        }
        joints[k] = best;
    }
    if (!errors.empty()) return errors;

    for (std::size_t k = 0; k < n; ++k) {
        const Joint& j = *joints[k];
        SegmentSpec& left = out[k];
        SegmentSpec& right = out[(k + 1) % n];
        if (k + 1 < n) {
            left.phiEndDeg = j.angleDeg;
            right.phiStartDeg = j.angleDeg;
        } else {  // the wrap-around joint: the first window starts there, the last ends a turn on
            right.phiStartDeg =
                j.angleDeg - 360.0 * std::round((j.angleDeg - contour[0].phiStartDeg) / 360.0);
            left.phiEndDeg = right.phiStartDeg + 360.0;
        }
        if (auto* line = left.as<Line>()) line->to = j.point;
        if (auto* line = right.as<Line>()) line->from = j.point;
    }
    return out;
}

}  // namespace cam
