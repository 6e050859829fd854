#pragma once
/// @file
/// @brief The radius r (the lift plot), velocity, acceleration and jerk over one turn, stacked
/// on one shared angle/time axis, with the cursor and the joints where the radial acceleration
/// jumps.

#include <QWidget>
#include <array>

#include "engine/compute_result.h"

class QCustomPlot;
class QCPItemStraightLine;
class QCPLayer;

namespace cam {

class StaleLabel;

struct KinematicsPlotData;

class KinematicsPlots : public QWidget {
    Q_OBJECT
public:
    explicit KinematicsPlots(QWidget* parent = nullptr);

    /// @brief Shows a result. One that could not be computed leaves the last curves in place,
    /// greyed, under a label that says why (see staleReason()).
    void setResult(const ComputeResultPtr& result);
    /// @brief Moves the cursor line to x (degrees or seconds, as the axis shows). Redraws only
    /// the cursor's own buffered layer.
    void setCursorX(double x);
    void resetZoom();
    /// @brief Velocity (0), acceleration (1), jerk (2) and the lift plot r (kLiftPlot, drawn on
    /// top).
    [[nodiscard]] QCustomPlot* plot(int i) const { return m_plots[static_cast<std::size_t>(i)]; }
    static constexpr int kPlotCount = 4;
    static constexpr int kLiftPlot = 3;
    /// @brief Why the curves shown are out of date; empty when they are the current project's.
    [[nodiscard]] QString staleReason() const;
    /// @brief The level of the result's curves the graphs draw now.
    [[nodiscard]] std::size_t shownLevel() const { return m_level; }
    /// @brief Whether the plots overlay a motion design's law and the follower on the contour
    /// (graphs kCurvesPerPlot and kCurvesPerPlot + 1 of each plot).
    [[nodiscard]] bool showsDesign() const;
    static constexpr int kCurvesPerPlot = 3;

signals:
    /// The mouse points at x (degrees or seconds, as the axis shows).
    void cursorMoved(double x);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuildJointMarkers();
    /// Draws the coarsest level whose buckets are at most a pixel wide at the current zoom.
    void chooseResolution(bool force = false);
    void fitY();
    void showDesign();
    void setStale(const QString& reason);

    std::array<QCustomPlot*, kPlotCount> m_plots{};
    std::array<QCPItemStraightLine*, kPlotCount> m_cursors{};
    std::vector<QCPItemStraightLine*> m_jointMarkers;
    StaleLabel* m_staleLabel = nullptr;
    ComputeResultPtr m_result;  ///< the result drawn (the last one that could be computed)
    std::shared_ptr<const KinematicsPlotData> m_data;
    PlotAxis m_axis = PlotAxis::Angle;
    PlotRange m_xRange;
    bool m_fitted = false;
    std::size_t m_level = static_cast<std::size_t>(-1);
    std::size_t m_levelBucket = 0;  ///< samples per bucket of the level drawn
};

}  // namespace cam
