#pragma once
/// @file
/// @brief A straight segment seen from the rotation centre: the line's r(phi) and derivatives.

#include <Eigen/Core>
#include <cmath>

#include "geometry/polar_derivatives.h"

namespace cam {

/// @brief The line through `from` and `to` (math.md §1): r = d / (n·u).
struct Line {
    Eigen::Vector2d from{0.0, 0.0};
    Eigen::Vector2d to{1.0, 0.0};

    /// @brief Unit normal n of the line, oriented so that d = n·from >= 0.
    [[nodiscard]] Eigen::Vector2d normal() const {
        const Eigen::Vector2d dir = to - from;
        Eigen::Vector2d n(-dir.y(), dir.x());
        n.normalize();
        return n.dot(from) < 0.0 ? Eigen::Vector2d(-n) : n;
    }

    /// @brief Distance from the rotation centre to the line.
    [[nodiscard]] double distance() const { return normal().dot(from); }

    /// @brief r, r', r'', r''' at the ray direction (cos phi, sin phi), given n and d.
    ///
    /// With c = n·u, c' = n·u': r = d/c, r' = -d·c'/c², r'' = d·(2c'² + c²)/c³,
    /// r''' = -d·c'·(5c² + 6c'²)/c⁴.
    [[nodiscard]] static PolarDerivatives evaluate(const Eigen::Vector2d& n, double d,
                                                   double cosPhi, double sinPhi) {
        const double c = n.x() * cosPhi + n.y() * sinPhi;
        const double c1 = n.y() * cosPhi - n.x() * sinPhi;
        const double inv = 1.0 / c;
        const double r = d * inv;
        const double t = c1 * inv;  // c'/c
        return {r, -r * t, r * (2.0 * t * t + 1.0), -r * t * (5.0 + 6.0 * t * t)};
    }

    [[nodiscard]] PolarDerivatives evaluate(double phi) const {
        return evaluate(normal(), distance(), std::cos(phi), std::sin(phi));
    }
};

}  // namespace cam
