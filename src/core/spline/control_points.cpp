#include "spline/control_points.h"

#include <cmath>
#include <tuple>

#include "common/angles.h"
#include "project/validate.h"

namespace cam {
namespace {

/// Sets end k's handle to `handle`: a Bézier's P1 or P2, a Hermite's t0 = 3·handle or
/// t1 = −3·handle; the window follows the end points.
SegmentSpec withHandle(const SegmentSpec& s, int k, const Eigen::Vector2d& handle) {
    SegmentSpec r = s;
    if (CubicBezier* b = r.as<CubicBezier>()) {
        b->p[k == 0 ? 1 : 2] = b->p[k == 0 ? 0 : 3] + handle;
    } else if (HermiteCurve* h = r.as<HermiteCurve>()) {
        (k == 0 ? h->t0 : h->t1) = (k == 0 ? 3.0 : -3.0) * handle;
    }
    return r;
}

}  // namespace

Eigen::Vector2d splineHandle(const SegmentSpec& s, int k) {
    const CubicBezier b = bezierOf(s);
    return k == 0 ? Eigen::Vector2d(b.p[1] - b.p[0]) : Eigen::Vector2d(b.p[2] - b.p[3]);
}

Eigen::Vector2d splineHandleDirection(const SegmentSpec& s, int k) {
    const Eigen::Vector2d h = splineHandle(s, k);
    if (h.norm() > 0.0) return h.normalized();
    const CubicBezier b = bezierOf(s);
    const Eigen::Vector2d chord =
        k == 0 ? Eigen::Vector2d(b.p[3] - b.p[0]) : Eigen::Vector2d(b.p[0] - b.p[3]);
    return chord.norm() > 0.0 ? chord.normalized() : Eigen::Vector2d(1.0, 0.0);
}

SegmentSpec withControlPoint(const SegmentSpec& s, int k, int axis, double v) {
    SegmentSpec r = s;
    if (CubicBezier* b = r.as<CubicBezier>()) {
        if (k == 0 || k == 3) {
            const int handle = k == 0 ? 1 : 2;
            const double offset = b->p[handle][axis] - b->p[k][axis];
            b->p[handle][axis] = v + offset;  // the handle moves with its end
        }
        b->p[k][axis] = v;
    } else if (HermiteCurve* h = r.as<HermiteCurve>()) {
        Eigen::Vector2d* fields[4] = {&h->p0, &h->t0, &h->p3, &h->t1};
        (*fields[k])[axis] = v;
    }
    std::tie(r.phiStartDeg, r.phiEndDeg) = lineWindowDeg(r, r.phiStartDeg);
    return r;
}

SegmentSpec withHandleLength(const SegmentSpec& s, int k, double length) {
    return withHandle(s, k, length * splineHandleDirection(s, k));
}

SegmentSpec withHandleAngle(const SegmentSpec& s, int k, double angleDeg) {
    const double length = splineHandle(s, k).norm();
    const double a = degToRad(angleDeg);
    return withHandle(s, k, length * Eigen::Vector2d(std::cos(a), std::sin(a)));
}

}  // namespace cam
