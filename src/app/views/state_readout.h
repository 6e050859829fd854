#pragma once
/// @file
/// @brief The follower's full state at the cursor, like one row of the seed's Table 2, and the
/// forces there when the project has dynamics.

#include <QWidget>
#include <array>

#include "forces/forces.h"
#include "kinematics/kinematics.h"

class QLabel;

namespace cam {

class StateReadout : public QWidget {
    Q_OBJECT
public:
    explicit StateReadout(QWidget* parent = nullptr);
    void setState(const KinematicState& state);
    void clear();
    /// @brief The forces at the cursor (math.md §9), below the kinematics; none: their rows
    /// are hidden (a project without dynamics).
    void setForces(const std::optional<ForcePoint>& forces, bool swinging);
    /// @brief The shown values as "name value unit" lines (for tests and copying).
    [[nodiscard]] QString text() const;

private:
    /// Shows `text` in the value label of `row`, widening it first if the text needs more room.
    void showValue(int row, const QString& text);
    static constexpr int kKinematicRows = 13;
    /// Normal force, load (or the arm's moment), torque, power, contact stress.
    static constexpr int kRows = kKinematicRows + 5;
    std::array<QLabel*, kRows> m_names{};
    std::array<QLabel*, kRows> m_values{};
};

}  // namespace cam
