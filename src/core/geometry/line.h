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

    /// @brief The line reduced to the scalars its r(phi) needs, for tight (vectorised) loops.
    struct Kernel {
        double nx = 1.0, ny = 0.0;  ///< unit normal n
        double d = 1.0;             ///< n·from >= 0

        /// With c = n·u, c' = n·u', t = c'/c: r = d/c, r' = -r·t, r'' = r·(2t² + 1),
        /// r''' = -r·t·(5 + 6t²).
        [[nodiscard]] PolarDerivatives operator()(double cosPhi, double sinPhi) const {
            const double c = nx * cosPhi + ny * sinPhi;
            const double c1 = ny * cosPhi - nx * sinPhi;
            const double r = d / c;
            const double t = c1 / c;
            return {r, -r * t, r * (2.0 * t * t + 1.0), -r * t * (5.0 + 6.0 * t * t)};
        }
    };

    [[nodiscard]] Kernel kernel() const {
        const Eigen::Vector2d n = normal();
        return {n.x(), n.y(), n.dot(from)};
    }

    /// @brief r, r', r'', r''' at the ray direction (cos phi, sin phi).
    [[nodiscard]] PolarDerivatives evaluate(double cosPhi, double sinPhi) const {
        return kernel()(cosPhi, sinPhi);
    }

    [[nodiscard]] PolarDerivatives evaluate(double phi) const {
        return evaluate(std::cos(phi), std::sin(phi));
    }

    friend bool operator==(const Line&, const Line&) = default;
};

}  // namespace cam
