#pragma once
/// @file
/// @brief The motion over one turn, stacked on one shared angle/time axis, with the cursor and
/// the joints where the acceleration jumps: the follower's lift, velocity, acceleration and
/// jerk (an arm's in degrees) when the project names a follower that rides the cam, else (or
/// when View ▸ Polar Kinematics is chosen) the profile's radius r and its polar velocity,
/// acceleration and jerk along the ray.

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
    /// @brief Shows the polar r, v, a, j even when the project names a follower (View ▸ Polar
    /// Kinematics); false: the follower's motion whenever there is one.
    void setPolarChosen(bool polar);
    /// @brief Whether the plots show the follower's lift, velocity, acceleration and jerk.
    [[nodiscard]] bool showsFollower() const { return m_follower; }
    /// @brief The top plot's quantity, without unit: "Lift", "Arm angle", or "Radius r".
    [[nodiscard]] QString liftTitle() const;
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
    /// The graph of each plot that draws the follower's quantity.
    static constexpr int kFollowerGraph = kCurvesPerPlot + 2;

signals:
    /// The mouse points at x (degrees or seconds, as the axis shows).
    void cursorMoved(double x);
    /// The plots switched between the follower's motion and the polar kinematics.
    void followerShownChanged(bool follower);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuildJointMarkers();
    /// Draws the coarsest level whose buckets are at most a pixel wide at the current zoom.
    void chooseResolution(bool force = false);
    void fitY();
    void showDesign();
    /// Shows the follower's motion or the polar kinematics, as the result and the choice ask.
    void chooseQuantities();
    void showFollower();
    /// Puts each legend's entries in one order: the quantities, then the design's.
    void orderLegends();
    /// The y axis titles of the quantities shown.
    void applyTitles();
    /// The follower's quantity in plot `plot`'s legend.
    static QString motionName(int plot, bool swinging);
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
    bool m_polarChosen = false;
    bool m_follower = false;  ///< the follower's motion is shown
    bool m_swinging = false;  ///< and it is an arm's (degrees)
    std::size_t m_level = static_cast<std::size_t>(-1);
    std::size_t m_levelBucket = 0;  ///< samples per bucket of the level drawn
};

}  // namespace cam
