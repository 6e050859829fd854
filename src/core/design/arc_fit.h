#pragma once
/// @file
/// @brief A closed smooth curve fitted by tangent-continuous (G1) circular arcs within a normal
/// deviation (math.md §8, "arc fitting"): biarcs between points of the curve, each as long as
/// the tolerance allows, the junction of each placed where the deviation is smallest.

#include <Eigen/Core>
#include <atomic>
#include <cstddef>
#include <functional>
#include <vector>

#include "common/diagnostic.h"

namespace cam {

/// @brief A point of the curve and its derivative by the curve's parameter.
struct CurveSample {
    Eigen::Vector2d point{0.0, 0.0};
    Eigen::Vector2d tangent{1.0, 0.0};  ///< d point / dt (need not be unit)
};

/// @brief One arc of the fit, from `from` to `to`, turning by `sweep` (rad, + counter-clockwise)
/// about `center`; a straight piece when `straight` (center and radius then mean nothing).
struct FittedArc {
    Eigen::Vector2d from{0.0, 0.0}, to{0.0, 0.0};
    Eigen::Vector2d center{0.0, 0.0};
    double radius = 0.0;
    double sweep = 0.0;
    bool straight = false;
    double t0 = 0.0, t1 = 0.0;  ///< the stretch of the curve's parameter it stands for
};

struct ArcFit {
    std::vector<FittedArc> arcs;  ///< in the curve's order, closed: the last ends at the first
    /// The largest of the bounds on the distance from the curve to the biarcs the fit took (mm):
    /// their distance at the points it checked plus what it can grow between them (arc_fit.cpp,
    /// boundedDeviation). The fit's own figure: synthesize measures the contour apart from it.
    double maxDeviation = 0.0;
};

/// @brief Fits the closed curve t ↦ curve(t), t over [t0, t0 + 2π) (the end meets the start
/// with the same tangent direction), by G1 arcs whose distance from the curve is at most
/// `tolerance` everywhere: checked at 2^14 samples of the curve and, where that does not settle
/// a biarc, at three points between each two, with a bound on what the distance can do between
/// the points checked; where one interval of the sampling is not fine enough, it is halved (up
/// to 2^-24 of it). No arc whose centre lies beyond kMaxLengthMm or whose radius is so large
/// that its rounding would matter to the tolerance, and no arc turning clockwise (concave on a
/// curve that runs counter-clockwise) of radius `minConcaveRadius` or less. Returns no value when
/// cancelled; an error located "design.tolerance" (ToleranceCannotBeMet, with the parameter in
/// degrees) when even the finest pieces do not come within the tolerance (a corner or a cusp).
[[nodiscard]] Result<ArcFit> fitArcs(const std::function<CurveSample(double)>& curve, double t0,
                                     double tolerance, const std::atomic<bool>* cancel = nullptr,
                                     double minConcaveRadius = 0.0);

/// @brief The distance from x to one fitted arc (to its nearer end beyond its span).
[[nodiscard]] double distanceToArc(const FittedArc& arc, const Eigen::Vector2d& x);

}  // namespace cam
