#pragma once
/// @file
/// @brief Velocity, acceleration and jerk over one turn, stacked on one shared angle/time axis,
/// with the cursor and the joints where the radial acceleration jumps.

#include <QWidget>
#include <array>

#include "engine/compute_result.h"

class QCustomPlot;
class QCPItemStraightLine;

namespace cam {

class KinematicsPlots : public QWidget {
    Q_OBJECT
public:
    explicit KinematicsPlots(QWidget* parent = nullptr);

    void setResult(const ComputeResultPtr& result);
    /// @brief Moves the cursor line to x (degrees or seconds, as the axis shows).
    void setCursorX(double x);
    void resetZoom();
    [[nodiscard]] QCustomPlot* plot(int i) const { return m_plots[static_cast<std::size_t>(i)]; }

signals:
    /// The mouse points at x (degrees or seconds, as the axis shows).
    void cursorMoved(double x);

private:
    void rebuildJointMarkers();
    /// Whole turn in view: draw the envelopes; zoomed in: the full-resolution curves.
    void chooseResolution();
    void fitY();

    std::array<QCustomPlot*, 3> m_plots{};
    std::array<QCPItemStraightLine*, 3> m_cursors{};
    std::vector<QCPItemStraightLine*> m_jointMarkers;
    ComputeResultPtr m_result;
    PlotAxis m_axis = PlotAxis::Angle;
    bool m_fitted = false;
    bool m_showingEnvelope = false;
};

}  // namespace cam
