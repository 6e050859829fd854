#include "views/contour_snapping.h"

namespace cam {

double GridStep::multiple(double n) const {
    const double scale = std::pow(10.0, std::abs(exponent));
    return exponent >= 0 ? n * mantissa * scale : n * mantissa / scale;
}

GridStep gridStepFor(double minimumMm) {
    if (!(minimumMm > 0.0) || !std::isfinite(minimumMm)) return {};
    const int exponent = static_cast<int>(std::floor(std::log10(minimumMm)));
    for (double mantissa : {1.0, 2.0, 5.0}) {
        const GridStep step{mantissa, exponent};
        if (step.value() >= minimumMm) return step;
    }
    return {1.0, exponent + 1};
}

Snapped snapPoint(const Eigen::Vector2d& pointMm, std::span<const Eigen::Vector2d> candidates,
                  double toleranceMm, const GridStep& grid, Qt::KeyboardModifiers modifiers,
                  const std::optional<Eigen::Vector2d>& origin) {
    Snapped out;
    out.point = pointMm;
    if (!(modifiers & Qt::AltModifier)) {
        double best = toleranceMm;
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const double d = (candidates[i] - pointMm).norm();
            if (std::isfinite(d) && d <= best) {
                best = d;
                out.candidate = static_cast<int>(i);
            }
        }
        if (out.candidate >= 0) {
            out.point = candidates[static_cast<std::size_t>(out.candidate)];
            out.target = SnapTarget::Point;
        } else {
            out.point = {grid.round(pointMm.x()), grid.round(pointMm.y())};
            out.target = SnapTarget::Grid;
        }
    }
    if (origin && (modifiers & Qt::ShiftModifier)) {
        // Keep the axis along which the mouse moved less.
        out.keptAxis =
            std::abs(pointMm.x() - origin->x()) >= std::abs(pointMm.y() - origin->y()) ? 1 : 0;
        out.point[out.keptAxis] = (*origin)[out.keptAxis];
    }
    return out;
}

double snapLength(double lengthMm, const GridStep& grid, Qt::KeyboardModifiers modifiers) {
    return modifiers & Qt::AltModifier ? lengthMm : grid.round(lengthMm);
}

}  // namespace cam
