#pragma once
/// @file
/// @brief The Forces dock (math.md §9): the project's dynamics — mass or arm inertia, spring,
/// load, damping, contact width, both materials (picked from the built-in table or typed),
/// the allowable stress and the spring's safety factor; every edit an undo command — and what
/// a cam is released on: where the follower leaves the cam, the speed at which it would, the
/// least preload, the peaks of force, torque, power and contact stress, failures in red.
/// Clicking a line goes to its angle. Below, the normal force (the law's dashed beside it),
/// the torque and the contact stress over the turn on the kinematics plots' x axis, with the
/// lift-off ranges shaded and the allowable stress dashed.

#include <QWidget>
#include <array>
#include <functional>

#include "common/dynamics_key.h"
#include "engine/compute_result.h"

class QComboBox;
class QCPItemRect;
class QCPItemStraightLine;
class QCustomPlot;
class QFormLayout;
class QPushButton;

namespace cam {

class CheckList;
class NumberSpinBox;
class ProjectDocument;

class ForcesPanel : public QWidget {
    Q_OBJECT
public:
    explicit ForcesPanel(ProjectDocument* document, QWidget* parent = nullptr);

    /// @brief Shows the forces of a result (none: the reason why).
    void setResult(const ComputeResultPtr& result);
    /// @brief The results as shown, one line each (for tests and copying).
    [[nodiscard]] QStringList resultLines() const;
    /// @brief How many results fail (lift-off, jump speed, preload, stress).
    [[nodiscard]] int problemCount() const;
    /// @brief The editor of one dynamics value.
    [[nodiscard]] NumberSpinBox* valueBox(DynamicsKey key) const {
        return m_values[static_cast<std::size_t>(key)];
    }
    /// @brief The material pickers: the cam's (0) and the follower's (1).
    [[nodiscard]] QComboBox* materialBox(int which) const {
        return m_materials[static_cast<std::size_t>(which)];
    }
    /// @brief Normal force (graph 0), the law's (graph 1, dashed; empty without a design) and
    /// the load along the line of motion or the arm's moment (graph 2).
    [[nodiscard]] QCustomPlot* forcePlot() const { return m_plots[0]; }
    [[nodiscard]] QCustomPlot* torquePlot() const { return m_plots[1]; }
    [[nodiscard]] QCustomPlot* stressPlot() const { return m_plots[2]; }
    /// @brief The plots over the turn, which share the kinematics plots' x axis.
    [[nodiscard]] std::array<QCustomPlot*, 3> turnPlots() const { return m_plots; }
    /// @brief The shaded lift-off ranges of the force plot.
    [[nodiscard]] const std::vector<QCPItemRect*>& liftOffShades() const { return m_liftOff; }
    /// @brief The allowable stress's dashed line in the stress plot.
    [[nodiscard]] QCPItemStraightLine* allowableLine() const { return m_allowable; }
    void setCursorX(double x);

signals:
    /// A result was clicked: go to this cam angle (rad).
    void anglePicked(double phi);

private:
    void refresh();
    void edit(const std::function<void(DynamicsSpec&)>& change);
    void showCurves(const ComputeResult& result);
    void showSummary(const ComputeResult& result);

    ProjectDocument* m_document;
    QFormLayout* m_form;
    std::array<NumberSpinBox*, kDynamicsKeyCount> m_values{};
    std::array<QComboBox*, 2> m_materials{};
    QPushButton* m_remove;
    CheckList* m_results;
    std::array<QCustomPlot*, 3> m_plots{};
    std::array<QCPItemStraightLine*, 3> m_cursors{};
    QCPItemStraightLine* m_allowable = nullptr;
    std::vector<QCPItemRect*> m_liftOff;
    int m_gesture = 0;
    bool m_refreshing = false;
};

}  // namespace cam
