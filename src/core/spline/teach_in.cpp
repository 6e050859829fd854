#include "spline/teach_in.h"

#include <cmath>
#include <limits>

#include "geometry/planar.h"
#include "project/validate.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// Unit tangent at knot b of the circle through a, b, c, oriented along the travel a → c;
/// the travel direction itself when the three are collinear.
Vec circumTangent(const Vec& a, const Vec& b, const Vec& c, double* radius) {
    const Vec ac = c - a;
    const std::optional<Vec> center = circumcenter(a, b, c);
    if (!center) {
        *radius = std::numeric_limits<double>::infinity();
        return ac.normalized();
    }
    *radius = (b - *center).norm();
    // The tangent at b is perpendicular to the radius.
    const Vec t = perp(b - *center).normalized();
    return t.dot(ac) >= 0 ? t : Vec(-t);  // along the travel: no parasitic loop
}

/// Handle length on a leg of chord c on a circle of radius R (κ rule); c/3 on a straight line.
double ovalLength(double chord, double radius) {
    if (!std::isfinite(radius) || chord >= 2.0 * radius) return chord / 3.0;
    const double theta = 2.0 * std::asin(chord / (2.0 * radius));
    return 4.0 / 3.0 * std::tan(theta / 4.0) * radius;
}

}  // namespace

Result<std::vector<CubicBezier>> splineThroughPoints(const std::vector<Vec>& k, bool closed,
                                                     HandleRule rule, double bulge) {
    const std::size_t n = k.size();
    if (n < (closed ? 3u : 2u)) {
        if (closed) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::Points},
                                                DiagnosticCode::ClosedSplineTooFewPoints)};
        }
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::Points}, DiagnosticCode::SplineTooFewPoints)};
    }
    if (!(bulge > 0) || !std::isfinite(bulge)) {
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::Bulge}, DiagnosticCode::BulgeNotPositive, {bulge})};
    }
    const std::size_t legs = closed ? n : n - 1;
    for (std::size_t i = 0; i < legs; ++i) {
        if ((k[(i + 1) % n] - k[i]).norm() < 1e-9) {
            return Diagnostics{
                Diagnostic::make(FieldPlace{Field::Point, static_cast<int>((i + 1) % n)},
                                 DiagnosticCode::PathPointRepeated)};
        }
    }
    // Per knot: unit direction and the lengths of its incoming and outgoing handles.
    std::vector<Vec> dir(n);
    std::vector<double> in(n, 0.0), out(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const bool end = !closed && (i == 0 || i + 1 == n);
        if (end) {
            const Vec leg = i == 0 ? Vec(k[1] - k[0]) : Vec(k[n - 1] - k[n - 2]);
            dir[i] = leg.normalized();
            out[i] = in[i] = leg.norm() / 3.0;
            continue;
        }
        const Vec& a = k[(i + n - 1) % n];
        const Vec& b = k[i];
        const Vec& c = k[(i + 1) % n];
        const double la = (b - a).norm(), lc = (c - b).norm();
        if (rule == HandleRule::Chord) {
            const Vec chord = (c - a) / 2.0;  // between the midpoints of the two legs
            dir[i] = chord.normalized();
            in[i] = chord.norm() * la / (la + lc);
            out[i] = chord.norm() * lc / (la + lc);
            continue;
        }
        double radius = 0.0;
        dir[i] = circumTangent(a, b, c, &radius);
        if (rule == HandleRule::Circumcircle) {
            in[i] = la / 3.0;
            out[i] = lc / 3.0;
        } else {
            in[i] = ovalLength(la, radius);
            out[i] = ovalLength(lc, radius);
        }
    }
    std::vector<CubicBezier> spline;
    for (std::size_t i = 0; i < legs; ++i) {
        const std::size_t j = (i + 1) % n;
        spline.push_back(CubicBezier{
            {k[i], k[i] + bulge * out[i] * dir[i], k[j] - bulge * in[j] * dir[j], k[j]}});
    }
    return spline;
}

Result<std::vector<SegmentSpec>> contourThroughPoints(const std::vector<Vec>& knots,
                                                      HandleRule rule, double bulge) {
    auto spline = splineThroughPoints(knots, true, rule, bulge);
    if (!spline.ok()) return spline.errors();
    std::vector<SegmentSpec> contour;
    double previousEnd = 0.0;
    for (std::size_t i = 0; i < spline.value().size(); ++i) {
        SegmentSpec s{spline.value()[i]};
        std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, i == 0 ? 0.0 : previousEnd);
        if (i > 0) s.phiStartDeg = previousEnd;  // exactly contiguous
        previousEnd = s.phiEndDeg;
        contour.push_back(s);
    }
    // The last window ends exactly one turn after the first begins.
    contour.back().phiEndDeg = contour.front().phiStartDeg + 360.0;
    Project p;
    p.contour = contour;
    Diagnostics problems = validateProject(p);
    if (!problems.empty()) return problems;
    return contour;
}

}  // namespace cam
