#pragma once
/// @file
/// @brief Where a dragged or picked point of the contour view lands: the grid step for a zoom,
/// and snapping to points, to the grid or to one axis. Pure functions in mm: the view turns
/// pixels into mm and gathers the points (see ContourEditTool::snap()).

#include <Qt>

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <span>

namespace cam {

/// @brief A grid step of mantissa × 10^exponent mm, the mantissa 1, 2 or 5.
struct GridStep {
    double mantissa = 1.0;
    int exponent = 0;
    [[nodiscard]] double value() const { return multiple(1.0); }
    /// @brief n steps: the double nearest the decimal n·mantissa·10^exponent (0.3, not
    /// 0.30000000000000004).
    [[nodiscard]] double multiple(double n) const;
    /// @brief The multiple of the step nearest v.
    [[nodiscard]] double round(double v) const { return multiple(std::round(v / value())); }
};

/// @brief The smallest 1-2-5 step of at least `minimumMm` (1 mm when that is not a positive
/// finite number).
[[nodiscard]] GridStep gridStepFor(double minimumMm);

/// @brief What a point snapped to.
enum class SnapTarget {
    Nothing,  ///< Alt: placed freely
    Point,    ///< one of the candidate points
    Grid,     ///< the nearest grid point
};

struct Snapped {
    Eigen::Vector2d point{0.0, 0.0};  ///< mm
    SnapTarget target = SnapTarget::Nothing;
    int candidate = -1;  ///< with SnapTarget::Point: its index among the candidates
    /// @brief Shift: the axis kept at the origin's value (0: x, 1: y), else -1.
    int keptAxis = -1;
};

/// @brief Where a point at `pointMm` lands. Without modifiers: on the nearest candidate within
/// `toleranceMm` (at equal distances the later one), else on the nearest point of `grid`.
/// Alt: nowhere but where it is. Shift with an `origin` (where a drag began), after that: the
/// axis along which `pointMm` lies nearer the origin keeps the origin's value, bit for bit.
[[nodiscard]] Snapped snapPoint(const Eigen::Vector2d& pointMm,
                                std::span<const Eigen::Vector2d> candidates, double toleranceMm,
                                const GridStep& grid, Qt::KeyboardModifiers modifiers,
                                const std::optional<Eigen::Vector2d>& origin = std::nullopt);

/// @brief A dragged length (an arc's radius) on the grid; Alt: as it is.
[[nodiscard]] double snapLength(double lengthMm, const GridStep& grid,
                                Qt::KeyboardModifiers modifiers);

}  // namespace cam
