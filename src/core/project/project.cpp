#include "project/project.h"

#include "common/angles.h"
#include "common/diagnostic.h"
#include "geometry/planar.h"

#include <cmath>

namespace cam {

CubicBezier bezierOf(const SegmentSpec& s) {
    if (const auto* h = s.as<HermiteCurve>()) return h->bezier();
    const auto* b = s.as<CubicBezier>();
    if (!b) internalError("bezierOf() of a segment that is no spline");
    return *b;
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> endPointsOf(const SegmentSpec& s) {
    if (const auto* line = s.as<Line>()) return {line->from, line->to};
    const CubicBezier b = bezierOf(s);
    return {b.p[0], b.p[3]};
}

PolarDerivatives polarOfSegment(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    if (const auto* arc = s.as<Arc>()) return arc->evaluate(phi);
    if (const auto* line = s.as<Line>()) return line->evaluate(phi);
    const double hint =
        std::abs(phiDeg - s.phiStartDeg) < std::abs(phiDeg - s.phiEndDeg) ? 0.0 : 1.0;
    return bezierOf(s).evaluate(std::cos(phi), std::sin(phi), hint);
}

Eigen::Vector2d pointOnSegment(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    return fromPolar(polarOfSegment(s, phiDeg).r, phi);
}

double UnitsSpec::angleFactor() const { return angle == AngleUnit::Rad ? 180.0 / kPi : 1.0; }

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
