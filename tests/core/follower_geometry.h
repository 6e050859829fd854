#pragma once
// Plane geometry for checking followers without the follower's own formulas: profile points
// through r(φ) of math.md §1, the distance from a point to the profile by brute force, and
// central differences.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/test_projects.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam::test {

/// A disc: one whole circle of radius R about c (an eccentric circle when c is not 0).
inline Contour disc(const Eigen::Vector2d& c, double R) {
    Project p;
    p.contour.push_back(SegmentSpec{Arc{c, R, Branch::Outer}, 0.0, 360.0});
    return Contour::build(p).value();
}

inline Eigen::Vector2d unit(double phi) { return {std::cos(phi), std::sin(phi)}; }
inline Eigen::Vector2d normalOf(double phi) { return {-std::sin(phi), std::cos(phi)}; }

/// The profile point on the ray at φ: r(φ)·u, through the contour's polar formulas.
inline Eigen::Vector2d profilePoint(const Contour& contour, double phi) {
    return contour.evaluate(phi).r * unit(phi);
}

/// The distance from x to the profile: the nearest of 5 000 points on it, refined by golden
/// sections along the polar angle within two samples either side.
inline double distanceToProfile(const Contour& contour, const Eigen::Vector2d& x) {
    constexpr int n = 5000;
    double best = 1e300, bestPhi = 0.0;
    for (int i = 0; i < n; ++i) {
        const double phi = contour.phiBegin() + kTwoPi * i / n;
        const double d = (profilePoint(contour, phi) - x).norm();
        if (d < best) {
            best = d;
            bestPhi = phi;
        }
    }
    double lo = bestPhi - 2 * kTwoPi / n, hi = bestPhi + 2 * kTwoPi / n;
    const auto f = [&](double phi) { return (profilePoint(contour, phi) - x).norm(); };
    constexpr double g = 0.6180339887498949;
    for (int it = 0; it < 100; ++it) {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (f(a) < f(b)) {
            hi = b;
        } else {
            lo = a;
        }
    }
    return std::min(best, f(0.5 * (lo + hi)));
}

/// Central differences of order 4: f'(x) with error O(h⁴).
template <class F>
inline double derivative(F f, double x, double h) {
    return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h)) / (12 * h);
}

}  // namespace cam::test
