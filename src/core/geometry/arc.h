#pragma once
/// @file
/// @brief A circular arc seen from the rotation centre: the arc's r(phi) and its derivatives.

#include <Eigen/Core>
#include <cmath>

#include "geometry/polar_derivatives.h"

namespace cam {

/// @brief Which intersection of the ray with the circle the contour follows.
enum class Branch {
    Outer,  ///< far intersection, r = mu + sqrt(D) (seed: r_oben)
    Inner,  ///< near intersection, r = mu - sqrt(D) (seed: r_unten)
};

/// @brief A circle with centre and radius, and the branch the ray takes (math.md §1).
struct Arc {
    Eigen::Vector2d center{0.0, 0.0};
    double radius = 1.0;
    Branch branch = Branch::Outer;

    /// @brief +1 on the outer branch, −1 on the inner.
    [[nodiscard]] double sense() const { return branch == Branch::Outer ? 1.0 : -1.0; }

    /// @brief The arc reduced to the scalars its r(phi) needs, for tight (vectorised) loops.
    struct Kernel {
        double cx = 0.0, cy = 0.0;  ///< centre
        double k = 1.0;             ///< R² - |c|²
        double s = 1.0;             ///< +1 outer, -1 inner

        /// With mu = c·u, D = mu² + k, q = sqrt(D), P = mu·mu', w = mu'² - mu²:
        /// r = mu + s·q, r' = mu' + s·P/q, r'' = -mu + s·(w/q - P²/q³),
        /// r''' = -mu' + s·(-4P/q - 3P·w/q³ + 3P³/q⁵).
        [[nodiscard]] PolarDerivatives operator()(double cosPhi, double sinPhi) const {
            const double mu = cx * cosPhi + cy * sinPhi;
            const double mu1 = cy * cosPhi - cx * sinPhi;
            const double d = mu * mu + k;
            const double q = std::sqrt(d > 0.0 ? d : 0.0);  // D is 0, not -1e-17, at a tangent
            const double p = mu * mu1;
            const double w = mu1 * mu1 - mu * mu;
            const double invQ = 1.0 / q;
            const double invQ2 = invQ * invQ;
            const double pq = p * invQ2;  // P/q²
            return {mu + s * q, mu1 + s * p * invQ, -mu + s * invQ * (w - p * pq),
                    -mu1 + s * p * invQ * (-4.0 - 3.0 * w * invQ2 + 3.0 * pq * pq)};
        }
    };

    [[nodiscard]] Kernel kernel() const {
        return {center.x(), center.y(), radius * radius - center.squaredNorm(),
                branch == Branch::Outer ? 1.0 : -1.0};
    }

    /// @brief r, r', r'', r''' at the ray direction (cos phi, sin phi).
    [[nodiscard]] PolarDerivatives evaluate(double cosPhi, double sinPhi) const {
        return kernel()(cosPhi, sinPhi);
    }

    [[nodiscard]] PolarDerivatives evaluate(double phi) const {
        return evaluate(std::cos(phi), std::sin(phi));
    }

    /// @brief Discriminant D(phi); the ray misses the circle where it is negative.
    [[nodiscard]] double discriminant(double phi) const {
        const double mu = center.x() * std::cos(phi) + center.y() * std::sin(phi);
        return mu * mu - center.squaredNorm() + radius * radius;
    }

    friend bool operator==(const Arc&, const Arc&) = default;
};

}  // namespace cam
