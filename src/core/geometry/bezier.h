#pragma once
/// @file
/// @brief A cubic Bézier segment seen from the rotation centre: where the follower ray meets it,
/// and r(phi) with exact derivatives by implicit differentiation (math.md §1, §4).

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "geometry/polar_derivatives.h"

namespace cam {

/// @brief B(s) = Σ b_i(s)·P_i, s in [0, 1].
struct CubicBezier {
    std::array<Eigen::Vector2d, 4> p{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                     Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};

    /// @brief The same curve from Hermite data: end points and tangent offsets (derivatives at
    /// s = 0 and 1, relative to their own end point): P1 = p0 + t0/3, P2 = p3 − t1/3.
    static CubicBezier fromHermite(const Eigen::Vector2d& p0, const Eigen::Vector2d& t0,
                                   const Eigen::Vector2d& p3, const Eigen::Vector2d& t1);
    /// @brief Hermite tangents of this curve: t0 = 3(P1 − P0), t1 = 3(P3 − P2).
    [[nodiscard]] std::array<Eigen::Vector2d, 2> hermiteTangents() const;

    friend bool operator==(const CubicBezier&, const CubicBezier&) = default;

    /// @brief B, B', B'', B''' at s.
    [[nodiscard]] Eigen::Vector2d point(double s) const;
    [[nodiscard]] Eigen::Vector2d derivative(double s, int order) const;

    /// @brief Parameters s in [0, 1] (with a tolerance of 1e-12 at the ends) where the ray at
    /// direction (cos phi, sin phi) from the origin meets the curve in front of the origin.
    [[nodiscard]] std::vector<double> rayParameters(double cosPhi, double sinPhi) const;

    /// @brief r, r', r'', r''' where the ray meets the curve at parameter s (a ray parameter).
    [[nodiscard]] PolarDerivatives polarAt(double s, double cosPhi, double sinPhi) const;

    /// @brief r and its derivatives at the ray direction; NaN if the ray misses the curve.
    /// With several hits, the one nearest `hint` (a parameter) if given, else the first.
    [[nodiscard]] PolarDerivatives evaluate(double cosPhi, double sinPhi,
                                            std::optional<double> hint = std::nullopt) const;
    [[nodiscard]] PolarDerivatives evaluate(double phi) const;

    /// @brief The contour's kernel for tight loops (same interface as Arc::Kernel).
    struct Kernel {
        std::array<Eigen::Vector2d, 4> p{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                         Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
        [[nodiscard]] PolarDerivatives operator()(double cosPhi, double sinPhi,
                                                  std::optional<double> hint = {}) const {
            return CubicBezier{p}.evaluate(cosPhi, sinPhi, hint);
        }
    };
    [[nodiscard]] Kernel kernel() const { return {p}; }
};

/// @brief A cubic given the Hermite way, as a file holds it: end points p0, p3 and tangent
/// offsets t0, t1 (the curve's derivative at s = 0 and 1). The same curve as the Bézier with
/// P1 = p0 + t0/3, P2 = p3 − t1/3.
struct HermiteCurve {
    Eigen::Vector2d p0{0.0, 0.0};
    Eigen::Vector2d t0{0.0, 0.0};
    Eigen::Vector2d p3{0.0, 0.0};
    Eigen::Vector2d t1{0.0, 0.0};

    [[nodiscard]] CubicBezier bezier() const { return CubicBezier::fromHermite(p0, t0, p3, t1); }
    /// @brief The Hermite data of a Bézier (exact: t0 = 3(P1 − P0), t1 = 3(P3 − P2)).
    [[nodiscard]] static HermiteCurve of(const CubicBezier& b) {
        const auto t = b.hermiteTangents();
        return {b.p[0], t[0], b.p[3], t[1]};
    }

    friend bool operator==(const HermiteCurve&, const HermiteCurve&) = default;
};

}  // namespace cam
