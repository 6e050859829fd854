#pragma once
/// @file
/// @brief The follower's full state at the cursor, like one row of the seed's Table 2, and the
/// forces there when the project has dynamics.

#include <QWidget>
#include <array>

#include "follower/follower.h"
#include "forces/forces.h"
#include "kinematics/kinematics.h"

class QLabel;

namespace cam {

class NumberSpinBox;

class StateReadout : public QWidget {
    Q_OBJECT
public:
    explicit StateReadout(QWidget* parent = nullptr);
    /// @brief The polar state along the ray: r and the radial, tangential and whole velocity,
    /// acceleration and jerk. `spans` (velocity, acceleration, jerk, r: the largest magnitude
    /// over the turn) tell round-off from a value: below 10⁻⁹ of its span a value reads 0.
    void setState(const KinematicState& state, const std::array<double, 4>& spans = {});
    /// @brief The follower's state: the lift and its velocity, acceleration and jerk (`lift`:
    /// FollowerModel::liftMotion, an arm's in degrees), the pressure angle and the profile's
    /// radius of curvature at the contact, and the segment it touches. `spans`: of lift,
    /// velocity, acceleration, jerk over the turn, as in setState.
    void setFollowerState(const KinematicState& state, const FollowerState& follower,
                          const std::array<double, 4>& lift, bool swinging,
                          const std::array<double, 4>& spans = {});
    void clear();
    /// @brief What the t and φ boxes step by with their arrow keys: one sample of the turn
    /// (s) and its angle (°).
    void setSteps(double timeStep, double angleStep);
    /// @brief The boxes the cursor's time and angle are typed into.
    [[nodiscard]] NumberSpinBox* timeBox() const { return m_time; }
    [[nodiscard]] NumberSpinBox* angleBox() const { return m_angle; }
    /// @brief The forces at the cursor (math.md §9), below the kinematics; none: their rows
    /// are hidden (a project without dynamics).
    void setForces(const std::optional<ForcePoint>& forces, bool swinging);
    /// @brief The shown values as "name value unit" lines (for tests and copying).
    [[nodiscard]] QString text() const;

signals:
    /// A time was typed (s) or stepped to: put the cursor there.
    void timeTyped(double t);
    /// An angle on the cam was typed (°, 0 … 360 whichever way the cam turns).
    void angleTyped(double degrees);

private:
    /// Shows `text` in the value label of `row`, widening it first if the text needs more room.
    void showValue(int row, const QString& text);
    /// The rows' names for the polar state or the follower's (an arm's when `swinging`).
    void showNames(bool follower, bool swinging);
    /// Sets the t and φ boxes (where on the cam, 0 … 360°, whichever way it turns).
    void showInstant(const KinematicState& state);
    static constexpr int kKinematicRows = 13;
    /// Normal force, load (or the arm's moment), torque, power, contact stress.
    static constexpr int kRows = kKinematicRows + 5;
    std::array<QLabel*, kRows> m_names{};
    /// The value labels; none for t and φ, which are typed into m_time and m_angle.
    std::array<QLabel*, kRows> m_values{};
    std::array<QString, kRows> m_texts{};  ///< what each row shows
    NumberSpinBox* m_time = nullptr;
    NumberSpinBox* m_angle = nullptr;
    bool m_updating = false;  ///< the boxes are being set from the cursor, not typed
    int m_namesShown = -1;    ///< which names the rows have: 0 polar, 1 follower, 2 arm
};

}  // namespace cam
