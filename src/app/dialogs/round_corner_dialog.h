#pragma once
/// @file
/// @brief Round Corner: the switch arc's radius, with what bounds it shown before it is chosen —
/// the largest radius that fits the corner, the cutter's radius where the corner is concave (a
/// concave arc smaller than the tool cannot be cut), and the seed's radius from the speed at
/// the joint, rho_min = V² / (vae · ACv) (math.md §5), as `camwright-cli fillet --speed` has it.

#include <QDialog>
#include <cstddef>
#include <optional>

#include "fillet/fillet.h"
#include "project/project.h"

class QDialogButtonBox;
class QLabel;

namespace cam {

class NumberSpinBox;

class RoundCornerDialog : public QDialog {
    Q_OBJECT
public:
    /// @brief For the joint before contour[joint] of `project`, whose radii `range` gives.
    RoundCornerDialog(const Project& project, std::size_t joint, const FilletRange& range,
                      QWidget* parent = nullptr);
    [[nodiscard]] double radius() const;
    /// @brief The smallest radius the cutter allows here: its radius at a concave corner of a
    /// project with a tool; none otherwise.
    [[nodiscard]] std::optional<double> cutterBound() const { return m_cutter; }
    /// @brief V² / (vae · ACv) of the boxes; NaN unless all three are positive.
    [[nodiscard]] double speedRadius() const;

private:
    void check();

    FilletRange m_range;
    std::optional<double> m_cutter;
    NumberSpinBox* m_radius = nullptr;
    NumberSpinBox* m_speed = nullptr;
    NumberSpinBox* m_accel = nullptr;
    NumberSpinBox* m_vae = nullptr;
    QLabel* m_speedResult = nullptr;
    QLabel* m_verdict = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

}  // namespace cam
