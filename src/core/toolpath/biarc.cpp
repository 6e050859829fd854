#include "toolpath/biarc.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/cancel.h"
#include "geometry/planar.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// The arc that leaves `a` along unit tangent `t` and passes through `b` (a line if straight).
PathSegment arcThrough(const Vec& a, const Vec& t, const Vec& b, double z) {
    const Vec n(-t.y(), t.x());  // left normal
    const Vec ab = b - a;
    const double k = n.dot(ab);
    if (std::abs(k) < 1e-12 * ab.squaredNorm() + 1e-300) {
        return PathSegment::line({a.x(), a.y(), z}, {b.x(), b.y(), z});
    }
    const double signedRadius = ab.squaredNorm() / (2.0 * k);  // > 0: turns left
    const Vec center = a + signedRadius * n;
    const Vec ra = a - center, rb = b - center;
    double sweep = std::atan2(cross(ra, rb), ra.dot(rb));
    if (signedRadius > 0 && sweep < 0) sweep += kTwoPi;
    if (signedRadius < 0 && sweep > 0) sweep -= kTwoPi;
    PathSegment s =
        PathSegment::arc(center, std::abs(signedRadius), std::atan2(ra.y(), ra.x()), sweep, z);
    s.end = {b.x(), b.y(), z};
    return s;
}

/// Distance from p to a path segment (in the XY plane).
double distanceTo(const PathSegment& s, const Vec& p) {
    const Vec a = s.start.head<2>(), b = s.end.head<2>();
    if (s.kind == PathSegment::Kind::Line) {
        const Vec ab = b - a;
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        return (a + t * ab - p).norm();
    }
    const Vec rp = p - s.center;
    double rel = std::atan2(rp.y(), rp.x()) - s.startAngle;  // angle from the start, along sweep
    rel = std::remainder(rel, kTwoPi);
    if (s.sweep < 0) rel = -rel;
    if (rel < 0) rel += kTwoPi;
    if (rel <= std::abs(s.sweep)) return std::abs(rp.norm() - s.radius);
    return std::min((p - a).norm(), (p - b).norm());
}

/// The equal-distance biarc between a (tangent ta) and b (tangent tb).
std::vector<PathSegment> biarc(const Vec& a, const Vec& ta, const Vec& b, const Vec& tb, double z) {
    const Vec v = b - a, t = ta + tb;
    const double denom = 2.0 * (1.0 - ta.dot(tb));
    double d = 0.0;
    if (std::abs(denom) < 1e-12) {
        const double vt = v.dot(t);
        d = std::abs(vt) > 1e-300 ? v.squaredNorm() / (2.0 * vt) : v.norm() / 2.0;
    } else {
        const double vt = v.dot(t);
        d = (-vt + std::sqrt(vt * vt + denom * v.squaredNorm())) / denom;
    }
    const Vec junction = (a + d * ta + b - d * tb) / 2.0;
    PathSegment first = arcThrough(a, ta, junction, z);
    // The second arc is the first run backwards from b: build it from b along −tb, then reverse.
    PathSegment back = arcThrough(b, -tb, junction, z);
    PathSegment second = back;
    if (back.kind == PathSegment::Kind::Line) {
        second = PathSegment::line({junction.x(), junction.y(), z}, {b.x(), b.y(), z});
    } else {
        second = PathSegment::arc(back.center, back.radius, back.startAngle + back.sweep,
                                  -back.sweep, z);
        second.start = {junction.x(), junction.y(), z};
        second.end = {b.x(), b.y(), z};
    }
    return {first, second};
}

void fit(const CubicBezier& c, double tol, double z, int depth, std::vector<PathSegment>& out,
         const std::atomic<bool>* cancel) {
    if (cancelRequested(cancel)) return;
    const Vec ta = c.derivative(0.0, 1).normalized(), tb = c.derivative(1.0, 1).normalized();
    std::vector<PathSegment> pair = biarc(c.p[0], ta, c.p[3], tb, z);
    if (depth >= 24 || fitError(c, pair) <= tol) {
        out.insert(out.end(), pair.begin(), pair.end());
        return;
    }
    // de Casteljau at s = 1/2.
    const Vec p01 = (c.p[0] + c.p[1]) / 2, p12 = (c.p[1] + c.p[2]) / 2, p23 = (c.p[2] + c.p[3]) / 2;
    const Vec p012 = (p01 + p12) / 2, p123 = (p12 + p23) / 2, mid = (p012 + p123) / 2;
    fit(CubicBezier{{c.p[0], p01, p012, mid}}, tol, z, depth + 1, out, cancel);
    fit(CubicBezier{{mid, p123, p23, c.p[3]}}, tol, z, depth + 1, out, cancel);
}

}  // namespace

double fitError(const CubicBezier& curve, const std::vector<PathSegment>& segments) {
    double worst = 0.0;
    for (int i = 0; i <= 64; ++i) {
        const Vec p = curve.point(i / 64.0);
        double best = std::numeric_limits<double>::infinity();
        for (const PathSegment& s : segments) best = std::min(best, distanceTo(s, p));
        worst = std::max(worst, best);
    }
    return worst;
}

std::vector<PathSegment> biarcsOf(const CubicBezier& curve, double toleranceMm, double z,
                                  const std::atomic<bool>* cancel) {
    std::vector<PathSegment> out;
    fit(curve, toleranceMm, z, 0, out, cancel);
    return out;
}

ToolPath toolPathFromSpline(const std::vector<CubicBezier>& pieces, double toleranceMm, double z) {
    ToolPath path;
    for (const CubicBezier& b : pieces) {
        const auto arcs = biarcsOf(b, toleranceMm, z);
        path.segments.insert(path.segments.end(), arcs.begin(), arcs.end());
    }
    return path;
}

}  // namespace cam
