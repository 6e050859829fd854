#pragma once
/// @file
/// @brief Small plane-vector helpers shared by the geometric modules.

#include <Eigen/Core>

namespace cam {

/// @brief z of the cross product a × b: positive when b lies counter-clockwise of a.
[[nodiscard]] inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// @brief v turned a quarter turn counter-clockwise.
[[nodiscard]] inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

}  // namespace cam
