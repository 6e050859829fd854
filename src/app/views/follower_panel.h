#pragma once
/// @file
/// @brief The follower (type, motion, radius, offset, pivot, arm, pressure-angle limit, its
/// closure: spring, groove with clearance and lands, or conjugate plates with the second
/// roller's distance and radius; every edit an undo command) and its design checks over the
/// turn (math.md §7): the largest pressure angles against the limit, the ranges beyond it, the
/// smallest radii of curvature, the flat face's width, every stretch the follower cannot reach,
/// a groove's outer flank and lands, a second plate's play, pressure angle and bends. Clicking
/// a check goes to its angle.

#include <QWidget>
#include <array>
#include <functional>
#include <optional>

#include "engine/compute_result.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QCPItemStraightLine;
class QCustomPlot;

namespace cam {

class CheckList;
class TurningPicture;
class NumberSpinBox;
class ProjectDocument;

class FollowerPanel : public QWidget {
    Q_OBJECT
public:
    explicit FollowerPanel(ProjectDocument* document, QWidget* parent = nullptr);

    /// @brief Shows the pressure-angle curve and the design checks of a result (the last one
    /// computed); a first picture's checks come later, through showChecks().
    void setResult(const ComputeResultPtr& result);
    /// @brief Shows the design checks of a result (its curve is shown already).
    void showChecks(const ComputeResultPtr& result);
    /// @brief The checks as shown, one line each (for tests and copying).
    [[nodiscard]] QStringList checkLines() const;
    /// @brief How many checks fail (beyond the limit, cannot reach, cannot ride).
    [[nodiscard]] int problemCount() const;
    /// @brief The pressure angle over the turn, on the kinematics plots' x axis, with the limit
    /// drawn and the stretches beyond it in red.
    [[nodiscard]] QCustomPlot* pressurePlot() const { return m_pressurePlot; }
    /// @brief The radii of curvature over the turn, clipped at ±curvatureClip().
    [[nodiscard]] QCustomPlot* curvaturePlot() const { return m_curvaturePlot; }
    /// @brief Where the curvature plot clips: twice the cam's largest radius (mm).
    [[nodiscard]] double curvatureClip() const { return m_curvatureClip; }
    /// @brief The plots over the turn, which share the kinematics plots' x axis.
    [[nodiscard]] std::array<QCustomPlot*, 2> turnPlots() const {
        return {m_pressurePlot, m_curvaturePlot};
    }
    /// @brief Moves the plot's cursor line to x (degrees or seconds).
    void setCursorX(double x);

signals:
    /// A check was clicked: go to this cam angle (rad).
    void anglePicked(double phi);

private:
    /// The groove's lines of the checks: its width, the outer flank's tightest bends, the lands.
    void addGrooveChecks(const GrooveView& groove, const FollowerSpec& spec);
    /// The second plate's lines: how well it holds the second roller, its pressure angle and
    /// its tightest arcs; or why it cannot be fitted.
    void addConjugateChecks(const ComputeResult& result, double limit);
    void add(const QString& text, std::optional<double> phi, bool problem);
    void showCurvature(const ComputeResultPtr& result);
    void refresh();
    void edit(const std::function<void(FollowerSpec&)>& change);
    /// Turns the cam the other way: the speed's sign (a period, which has none, becomes rpm).
    void turnRound(bool clockwise);

    ProjectDocument* m_document;
    QComboBox* m_type;
    QComboBox* m_motion;
    NumberSpinBox* m_radius;
    NumberSpinBox* m_offset;
    NumberSpinBox* m_pivotX;
    NumberSpinBox* m_pivotY;
    NumberSpinBox* m_armLength;
    QComboBox* m_side;
    NumberSpinBox* m_limit;
    /// The settings; the rows a follower does not use are hidden (an arm's on a line, the
    /// line's offset on an arm, the lands without a groove) so that the checks and plots keep
    /// their room.
    QFormLayout* m_form = nullptr;
    QComboBox* m_closure;
    NumberSpinBox* m_clearance;
    NumberSpinBox* m_innerLand;
    NumberSpinBox* m_outerLand;
    NumberSpinBox* m_conjugateDistance;
    NumberSpinBox* m_conjugateRadius;
    NumberSpinBox* m_conjugateAngle;
    NumberSpinBox* m_conjugateArm;
    /// A conjugate pair's first carrier of the second roller, where the follower has none:
    /// a yoke of 2·(largest radius + roller), or on an arm the first arm mirrored about the line
    /// from the pivot to the cam centre.
    void conjugateDefaults(FollowerSpec& f) const;
    /// The cam's largest radius in the last result (mm; 0 before one): a first conjugate yoke
    /// reaches twice its radius plus the roller's across.
    double m_largestRadius = 0.0;
    TurningPicture* m_turning;
    QLabel* m_turningText;
    CheckList* m_checks;
    QCustomPlot* m_pressurePlot;
    std::array<QCPItemStraightLine*, 2> m_limitLines{};
    QCPItemStraightLine* m_cursor;
    QCustomPlot* m_curvaturePlot;
    /// At the roller's radius (the pitch curve's convex radius must stay above it) and at
    /// minus the tool's (the profile's concave radius must stay beyond it).
    std::array<QCPItemStraightLine*, 2> m_radiusLines{};
    QCPItemStraightLine* m_curvatureCursor;
    double m_curvatureClip = 0.0;
    int m_gesture = 0;
    bool m_refreshing = false;
};

}  // namespace cam
