#pragma once
/// @file
/// @brief Small plane-vector helpers shared by the geometric modules.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>

#include "common/angles.h"

namespace cam {

/// @brief z of the cross product a × b: positive when b lies counter-clockwise of a.
[[nodiscard]] inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// @brief v turned a quarter turn counter-clockwise.
[[nodiscard]] inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

/// @brief The point at distance r from the origin on the ray at angle phi (rad).
[[nodiscard]] inline Eigen::Vector2d fromPolar(double r, double phi) {
    return {r * std::cos(phi), r * std::sin(phi)};
}

/// @brief The polar angle of p, degrees in (−180, 180].
[[nodiscard]] inline double polarDeg(const Eigen::Vector2d& p) {
    return radToDeg(std::atan2(p.y(), p.x()));
}

/// @brief The angle from direction a to direction b turning in `sense` (+1 counter-clockwise,
/// −1 clockwise), in [0, 2π).
[[nodiscard]] inline double sweepRad(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                     double sense) {
    const double t = std::atan2(sense * cross(a, b), a.dot(b));
    return t < 0.0 ? t + kTwoPi : t;
}

/// @brief v turned by `angle` (rad) counter-clockwise.
[[nodiscard]] inline Eigen::Vector2d rotate(const Eigen::Vector2d& v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

/// @brief Whether every point p = o + rho·e of the arc about o that leaves t1 turning `sense`
/// by `sweep` (rad) lies on the branch `sense` of the ray from the origin (+1 the far
/// intersection, −1 the near one), i.e. the ray's angle grows along the whole arc and meets it
/// once: sense·p·(p − o) = sense·rho·(rho + o·e) > 0. o·e is a cosine in e, so its minimum over
/// the swept directions is at an end or at e = −sense·ô, if that is swept.
[[nodiscard]] inline bool arcSweepOnBranch(const Eigen::Vector2d& o, double rho,
                                           const Eigen::Vector2d& t1, double sweep, double sense) {
    auto g = [&](const Eigen::Vector2d& e) { return sense * (rho + o.dot(e)); };
    const Eigen::Vector2d e1 = (t1 - o) / rho;
    const Eigen::Vector2d e2 = rotate(e1, sense * sweep);
    double worst = std::min(g(e1), g(e2));
    if (o.norm() > 0.0) {
        const Eigen::Vector2d extreme = -sense * o.normalized();
        if (sweepRad(e1, extreme, sense) < sweep) worst = std::min(worst, g(extreme));
    }
    return worst > 0.0;
}

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
