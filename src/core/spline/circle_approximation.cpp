#include "spline/circle_approximation.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "geometry/planar.h"
#include "project/validate.h"

namespace cam {

CubicBezier bezierArc(const Eigen::Vector2d& c, double R, double a0, double sweep) {
    const double a1 = a0 + sweep;
    const double k = 4.0 / 3.0 * std::tan(sweep / 4.0) * R;
    const Eigen::Vector2d u0(std::cos(a0), std::sin(a0)), u1(std::cos(a1), std::sin(a1));
    const Eigen::Vector2d t0(-u0.y(), u0.x()), t1(-u1.y(), u1.x());
    return {{c + R * u0, c + R * u0 + k * t0, c + R * u1 - k * t1, c + R * u1}};
}

double bezierArcRadialError(double sweep) {
    // Sampled finely: the error is a smooth function of s with two equal peaks.
    const CubicBezier b = bezierArc(Eigen::Vector2d::Zero(), 1.0, 0.0, sweep);
    double worst = 0.0;
    constexpr int kSamples = 2000;
    for (int i = 0; i <= kSamples; ++i) {
        worst = std::max(worst, std::abs(b.point(static_cast<double>(i) / kSamples).norm() - 1.0));
    }
    return worst;
}

ArcApproximation approximateArc(const Eigen::Vector2d& center, double radius, double a0,
                                double sweep, double maxErrorMm) {
    ArcApproximation out;
    int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (kPi / 2))));
    while (n < 4096 && bezierArcRadialError(sweep / n) * radius > maxErrorMm) ++n;
    for (int i = 0; i < n; ++i) {
        out.pieces.push_back(bezierArc(center, radius, a0 + sweep * i / n, sweep / n));
    }
    out.radialErrorMm = bezierArcRadialError(sweep / n) * radius;
    const CubicBezier& b = out.pieces.front();
    out.speedRatio = b.derivative(0.0, 1).norm() / b.derivative(0.5, 1).norm();
    return out;
}

Result<std::vector<SegmentSpec>> approximateArcSegment(const std::vector<SegmentSpec>& contour,
                                                       std::size_t k, double maxErrorMm,
                                                       ArcApproximation* report) {
    if (k >= contour.size()) {
        return Diagnostics{Diagnostic::make(SegmentPlace{k}, DiagnosticCode::NoSuchSegment)};
    }
    const SegmentSpec& s = contour[k];
    const Arc* arc = s.as<Arc>();
    if (!arc) {
        return Diagnostics{
            Diagnostic::make(SegmentPlace{k, SegmentPart::Type}, DiagnosticCode::NotAnArc)};
    }
    if (!(maxErrorMm > 0) || !std::isfinite(maxErrorMm)) {
        return Diagnostics{Diagnostic::make(FieldPlace{Field::ApproximationError},
                                            DiagnosticCode::RadialErrorNotPositive)};
    }
    // The arc's piece inside the window, about its own centre, in the direction of travel.
    const Eigen::Vector2d p0 = pointOnSegment(s, s.phiStartDeg) - arc->center;
    const Eigen::Vector2d p1 = pointOnSegment(s, s.phiEndDeg) - arc->center;
    // An arc its window's rays miss (the contour is invalid there) has no piece to replace.
    // (Where a ray misses, r(φ) is the foot of the perpendicular: finite, but not on the arc.)
    const auto meets = [&](double phiDeg, const Eigen::Vector2d& p) {
        return arc->discriminant(degToRad(phiDeg)) >= 0.0 && p.allFinite();
    };
    if (!meets(s.phiStartDeg, p0)) {
        return Diagnostics{Diagnostic::make(SegmentPlace{k, SegmentPart::PhiStart},
                                            DiagnosticCode::ApproximationStartMissesArc)};
    }
    if (!meets(s.phiEndDeg, p1)) {
        return Diagnostics{Diagnostic::make(SegmentPlace{k, SegmentPart::PhiEnd},
                                            DiagnosticCode::ApproximationEndMissesArc)};
    }
    // Direction of travel about the arc's centre: that of the contour's tangent dP/dφ.
    const double phi0 = degToRad(s.phiStartDeg);
    const PolarDerivatives d0 = arc->evaluate(phi0);
    const Eigen::Vector2d u(std::cos(phi0), std::sin(phi0)), u1(-u.y(), u.x());
    const Eigen::Vector2d travel = d0.dr * u + d0.r * u1;
    const double direction = cross(p0, travel) >= 0 ? 1.0 : -1.0;
    double sweep = std::atan2(cross(p0, p1), p0.dot(p1));
    if (direction > 0 && sweep <= 0) sweep += kTwoPi;
    if (direction < 0 && sweep >= 0) sweep -= kTwoPi;
    const ArcApproximation approx =
        approximateArc(arc->center, arc->radius, std::atan2(p0.y(), p0.x()), sweep, maxErrorMm);
    if (report) *report = approx;

    std::vector<SegmentSpec> out(contour.begin(), contour.begin() + static_cast<long>(k));
    double previousEnd = s.phiStartDeg;
    for (std::size_t i = 0; i < approx.pieces.size(); ++i) {
        SegmentSpec piece{approx.pieces[i]};
        // The first and last piece keep the arc's exact window ends (the joints).
        std::tie(piece.phiStartDeg, piece.phiEndDeg) = lineWindowDeg(piece, previousEnd);
        if (i == 0) piece.phiStartDeg = s.phiStartDeg;
        if (i + 1 == approx.pieces.size()) piece.phiEndDeg = s.phiEndDeg;
        if (i > 0) piece.phiStartDeg = previousEnd;
        previousEnd = piece.phiEndDeg;
        out.push_back(piece);
    }
    out.insert(out.end(), contour.begin() + static_cast<long>(k) + 1, contour.end());
    return out;
}

}  // namespace cam
