#include "contour/change_type.h"

#include <cmath>

#include "common/angles.h"
#include "geometry/planar.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// The curve's point on the ray at phiDeg, or the unit ray direction where the ray misses it.
Vec pointOrDirection(const SegmentSpec& s, double phiDeg) {
    const Vec p = pointOnSegment(s, phiDeg);
    if (p.allFinite()) return p;
    const double phi = degToRad(phiDeg);
    return {std::cos(phi), std::sin(phi)};
}

/// The arc through a and b that passes through (or, on a straight chord, bulges away from the
/// rotation centre like) the middle point m.
Arc arcThrough(const Vec& a, const Vec& m, const Vec& b) {
    Vec center;
    if (const auto c = circumcenter(a, m, b)) {
        center = *c;
    } else {
        // Collinear: a gentle arc of radius = chord whose centre lies towards the origin.
        const Vec mid = (a + b) / 2.0;
        const double chord = (b - a).norm();
        Vec n = perp(b - a).normalized();
        if (n.dot(mid) > 0) n = -n;
        center = mid + n * (chord * std::sqrt(3.0) / 2.0);
    }
    const double radius = (a - center).norm();
    // The branch whose ray hit at m's angle lies nearest to m's side of the circle.
    const Vec target = m.allFinite() ? m : (a + b) / 2.0;
    const double phi = std::atan2(target.y(), target.x());
    Arc arc{center, radius, Branch::Outer};
    const double outer = arc.evaluate(phi).r;
    arc.branch = Branch::Inner;
    const double inner = arc.evaluate(phi).r;
    const double want = target.norm();
    arc.branch = std::abs(outer - want) <= std::abs(inner - want) || !std::isfinite(inner)
                     ? Branch::Outer
                     : Branch::Inner;
    return arc;
}

/// κ-approximation of the arc between the same end points (math.md §4).
CubicBezier kappaBezier(const Arc& arc, const Vec& from, const Vec& to) {
    const Vec a = from - arc.center, c = to - arc.center;
    const double sweep = std::atan2(cross(a, c), a.dot(c));
    const double kappa = 4.0 / 3.0 * std::tan(sweep / 4.0);
    return {{from, from + kappa * perp(a), to - kappa * perp(c), to}};
}

}  // namespace

SegmentSpec withType(const SegmentSpec& s, SegmentType type) {
    if (type == s.type()) return s;
    const Vec from = pointOrDirection(s, s.phiStartDeg);
    const Vec to = pointOrDirection(s, s.phiEndDeg);
    SegmentSpec out = s;
    switch (type) {
        case SegmentType::Arc:
            out.shape =
                arcThrough(from, pointOnSegment(s, (s.phiStartDeg + s.phiEndDeg) / 2.0), to);
            break;
        case SegmentType::Line:
            out.shape = Line{from, to};
            break;
        case SegmentType::Bezier:
        case SegmentType::Hermite: {
            CubicBezier b;
            if (isSpline(s.type())) {
                b = bezierOf(s);  // Bézier ↔ Hermite: the same curve, exactly
            } else if (const auto* arc = s.as<Arc>()) {
                b = kappaBezier(*arc, from, to);
            } else {
                const Vec third = (to - from) / 3.0;  // the same straight line
                b = {{from, from + third, to - third, to}};
            }
            if (type == SegmentType::Bezier) {
                out.shape = b;
            } else {
                out.shape = HermiteCurve::of(b);
            }
            break;
        }
    }
    return out;
}

}  // namespace cam
