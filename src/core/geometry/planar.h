#pragma once
/// @file
/// @brief Small plane-vector helpers shared by the geometric modules.

#include <Eigen/Core>
#include <cmath>
#include <optional>

namespace cam {

/// @brief z of the cross product a × b: positive when b lies counter-clockwise of a.
[[nodiscard]] inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// @brief v turned a quarter turn counter-clockwise.
[[nodiscard]] inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

/// @brief Centre of the circle through a, b and c; none when they are (nearly) collinear.
[[nodiscard]] inline std::optional<Eigen::Vector2d> circumcenter(const Eigen::Vector2d& a,
                                                                 const Eigen::Vector2d& b,
                                                                 const Eigen::Vector2d& c) {
    const Eigen::Vector2d ab = b - a, bc = c - b;
    if (std::abs(cross(ab, bc)) <= 1e-12 * ab.norm() * bc.norm()) return std::nullopt;
    const double d =
        2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const double a2 = a.squaredNorm(), b2 = b.squaredNorm(), c2 = c.squaredNorm();
    return Eigen::Vector2d(
        (a2 * (b.y() - c.y()) + b2 * (c.y() - a.y()) + c2 * (a.y() - b.y())) / d,
        (a2 * (c.x() - b.x()) + b2 * (a.x() - c.x()) + c2 * (b.x() - a.x())) / d);
}

}  // namespace cam
