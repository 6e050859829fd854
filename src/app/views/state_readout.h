#pragma once
/// @file
/// @brief The follower's full state at the cursor, like one row of the seed's Table 2.

#include <QWidget>
#include <array>

#include "kinematics/kinematics.h"

class QLabel;

namespace cam {

class StateReadout : public QWidget {
    Q_OBJECT
public:
    explicit StateReadout(QWidget* parent = nullptr);
    void setState(const KinematicState& state);
    void clear();
    /// @brief The shown values as "name value unit" lines (for tests and copying).
    [[nodiscard]] QString text() const;

private:
    /// Shows `text` in the value label of `row`, widening it first if the text needs more room.
    void showValue(int row, const QString& text);
    static constexpr int kRows = 13;
    std::array<QLabel*, kRows> m_names{};
    std::array<QLabel*, kRows> m_values{};
};

}  // namespace cam
