#include "project/project.h"

#include "common/angles.h"
#include "geometry/line.h"

#include <cmath>

namespace cam {

CubicBezier bezierOf(const SegmentSpec& s) {
    if (s.type == SegmentType::Hermite) {
        return CubicBezier::fromHermite(s.controls[0], s.controls[1], s.controls[2], s.controls[3]);
    }
    return CubicBezier{s.controls};
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> endPointsOf(const SegmentSpec& s) {
    if (s.type == SegmentType::Line) return {s.from, s.to};
    const CubicBezier b = bezierOf(s);
    return {b.p[0], b.p[3]};
}

Eigen::Vector2d pointOnSegment(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    double r = 0.0;
    if (s.type == SegmentType::Arc) {
        r = Arc{s.center, s.radius, s.branch}.evaluate(phi).r;
    } else if (s.type == SegmentType::Line) {
        r = Line{s.from, s.to}.evaluate(phi).r;
    } else {
        const double hint =
            std::abs(phiDeg - s.phiStartDeg) < std::abs(phiDeg - s.phiEndDeg) ? 0.0 : 1.0;
        r = bezierOf(s).evaluate(std::cos(phi), std::sin(phi), hint).r;
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

double MotionSpec::omegaRadS() const {
    switch (unit) {
        case SpeedUnit::OmegaRadS:
            return value;
        case SpeedUnit::Rpm:
            return value * kTwoPi / 60.0;
        case SpeedUnit::PeriodS:
            return kTwoPi / value;
    }
    return 0.0;
}

}  // namespace cam
