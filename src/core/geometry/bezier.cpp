#include "geometry/bezier.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/planar.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// A truncated Taylor series c0 + c1·h + c2·h² + c3·h³.
using Series = std::array<double, 4>;

Series mul(const Series& a, const Series& b) {
    Series r{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; i + j < 4; ++j) r[i + j] += a[i] * b[j];
    }
    return r;
}
Series add(const Series& a, const Series& b, double kb = 1.0) {
    return {a[0] + kb * b[0], a[1] + kb * b[1], a[2] + kb * b[2], a[3] + kb * b[3]};
}

/// Power-basis coefficients A0..A3 of B(s) = A0 + A1 s + A2 s² + A3 s³.
std::array<Vec, 4> powerBasis(const std::array<Vec, 4>& p) {
    return {p[0], 3.0 * (p[1] - p[0]), 3.0 * (p[2] - 2.0 * p[1] + p[0]),
            p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0]};
}

/// Real roots of the polynomial c0 + c1 s + c2 s² + c3 s³ in [lo, hi]: split at the roots of
/// its derivative so each piece is monotone, then bisect (robust for any coefficients).
std::vector<double> rootsIn(const std::array<double, 4>& c, double lo, double hi) {
    auto f = [&](double s) { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); };
    std::vector<double> cuts{lo};
    // f' = c1 + 2 c2 s + 3 c3 s²
    const double a = 3.0 * c[3], b = 2.0 * c[2], q = c[1];
    if (std::abs(a) > 1e-300) {
        const double disc = b * b - 4.0 * a * q;
        if (disc > 0) {
            const double r = std::sqrt(disc);
            for (double x : {(-b - r) / (2 * a), (-b + r) / (2 * a)}) {
                if (x > lo && x < hi) cuts.push_back(x);
            }
        }
    } else if (std::abs(b) > 1e-300) {
        const double x = -q / b;
        if (x > lo && x < hi) cuts.push_back(x);
    }
    cuts.push_back(hi);
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> roots;
    const double scale = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        double x0 = cuts[i], x1 = cuts[i + 1];
        double f0 = f(x0), f1 = f(x1);
        if (std::abs(f0) <= 1e-14 * scale) {
            if (roots.empty() || std::abs(roots.back() - x0) > 1e-12) roots.push_back(x0);
            continue;
        }
        if (std::abs(f1) <= 1e-14 * scale) continue;  // counted as the next piece's start
        if ((f0 < 0) == (f1 < 0)) continue;
        for (int it = 0; it < 200 && x1 - x0 > 1e-15; ++it) {
            const double m = 0.5 * (x0 + x1);
            const double fm = f(m);
            if ((fm < 0) == (f0 < 0)) {
                x0 = m;
                f0 = fm;
            } else {
                x1 = m;
            }
        }
        roots.push_back(0.5 * (x0 + x1));
    }
    if (std::abs(f(hi)) <= 1e-14 * scale &&
        (roots.empty() || std::abs(roots.back() - hi) > 1e-12)) {
        roots.push_back(hi);
    }
    return roots;
}

}  // namespace

CubicBezier CubicBezier::fromHermite(const Vec& p0, const Vec& t0, const Vec& p3, const Vec& t1) {
    return {{p0, p0 + t0 / 3.0, p3 - t1 / 3.0, p3}};
}

std::array<Vec, 2> CubicBezier::hermiteTangents() const {
    return {3.0 * (p[1] - p[0]), 3.0 * (p[3] - p[2])};
}

Vec CubicBezier::point(double s) const {
    const double t = 1.0 - s;
    return t * t * t * p[0] + 3.0 * t * t * s * p[1] + 3.0 * t * s * s * p[2] + s * s * s * p[3];
}

Vec CubicBezier::derivative(double s, int order) const {
    const auto a = powerBasis(p);
    switch (order) {
        case 0:
            return point(s);
        case 1:
            return a[1] + 2.0 * s * a[2] + 3.0 * s * s * a[3];
        case 2:
            return 2.0 * a[2] + 6.0 * s * a[3];
        case 3:
            return 6.0 * a[3];
        default:
            return Vec::Zero();
    }
}

std::vector<double> CubicBezier::rayParameters(double c, double s) const {
    const Vec u(c, s);
    const auto a = powerBasis(p);
    // u × B(s) = 0 is a cubic in s; keep the roots in front of the origin (u·B > 0).
    const std::array<double, 4> coeff{cross(u, a[0]), cross(u, a[1]), cross(u, a[2]),
                                      cross(u, a[3])};
    std::vector<double> out;
    for (double root : rootsIn(coeff, -1e-12, 1.0 + 1e-12)) {
        const double clamped = std::clamp(root, 0.0, 1.0);
        if (u.dot(point(clamped)) > 0.0) out.push_back(clamped);
    }
    return out;
}

PolarDerivatives CubicBezier::polarAt(double s0, double c, double sn) const {
    // Taylor series in h = φ − φ0 of u(φ) and of B(s(φ)); s(φ) = s0 + s1 h + s2 h² + s3 h³ is
    // found order by order from u × B = 0 (each order is linear in its new coefficient, with
    // factor u0 × B'(s0)); then r = u·B. Exact to rounding — implicit differentiation by series.
    const Series ux{c, -sn, -c / 2.0, sn / 6.0};
    const Series uy{sn, c, -sn / 2.0, -c / 6.0};
    const Vec b0 = point(s0), b1 = derivative(s0, 1), b2 = derivative(s0, 2),
              b3 = derivative(s0, 3);
    const double fs = cross(Vec(c, sn), b1);
    Series ds{0.0, 0.0, 0.0, 0.0};  // s(φ) − s0
    auto curve = [&](const Series& d) {
        const Series d2 = mul(d, d), d3 = mul(d2, d);
        Series bx{b0.x(), 0, 0, 0}, by{b0.y(), 0, 0, 0};
        bx = add(add(add(bx, d, b1.x()), d2, b2.x() / 2.0), d3, b3.x() / 6.0);
        by = add(add(add(by, d, b1.y()), d2, b2.y() / 2.0), d3, b3.y() / 6.0);
        return std::pair{bx, by};
    };
    for (int k = 1; k <= 3; ++k) {
        const auto [bx, by] = curve(ds);
        const Series f = add(mul(ux, by), mul(uy, bx), -1.0);
        ds[k] = -f[k] / fs;
    }
    const auto [bx, by] = curve(ds);
    const Series r = add(mul(ux, bx), mul(uy, by));
    return {r[0], r[1], 2.0 * r[2], 6.0 * r[3]};
}

PolarDerivatives CubicBezier::evaluate(double c, double sn, std::optional<double> hint) const {
    const std::vector<double> hits = rayParameters(c, sn);
    if (hits.empty()) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan, nan};
    }
    double s = hits.front();
    if (hint) {
        for (double h : hits) {
            if (std::abs(h - *hint) < std::abs(s - *hint)) s = h;
        }
    }
    return polarAt(s, c, sn);
}

PolarDerivatives CubicBezier::evaluate(double phi) const {
    return evaluate(std::cos(phi), std::sin(phi));
}

}  // namespace cam
