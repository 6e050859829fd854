#pragma once
/// @file
/// @brief The contour view's colouring of the profile by contact stress (on demand, View ▸
/// Colour by Contact Stress): where the follower touches the profile over the turn (or,
/// form-closed, the outer flank or second plate while it carries), the stretch drawn thick in
/// the colour of the Hertz stress there, from blue (none) to red (at or above
/// the allowable stress, or the largest stress when the project gives none), with the scale
/// named in a label.

#include <QString>
#include <array>

#include "engine/compute_result.h"

class QCustomPlot;
class QCPCurve;
class QCPItemText;

namespace cam {

class StressOverlay {
public:
    static constexpr int kBands = 12;
    explicit StressOverlay(QCustomPlot* plot);

    /// @brief Draws the result's stress on its profile (or nothing: off, or a result without
    /// a contact stress).
    void show(const ComputeResult* result, bool on);
    /// @brief The stress at the top of the scale (MPa), 0 when nothing is drawn.
    [[nodiscard]] double top() const { return m_top; }
    /// @brief The band a stress falls in (0 … kBands − 1).
    [[nodiscard]] int bandOf(double stressMpa) const;
    [[nodiscard]] QCPCurve* band(int i) const { return m_bands[static_cast<std::size_t>(i)]; }
    [[nodiscard]] QString label() const;

private:
    QCustomPlot* m_plot;
    std::array<QCPCurve*, kBands> m_bands{};
    QCPItemText* m_label;
    double m_top = 0.0;
};

}  // namespace cam
