#include "project/project.h"

#include "common/angles.h"

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
