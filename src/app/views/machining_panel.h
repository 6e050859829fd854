#pragma once
/// @file
/// @brief Machining limits (undoable edits), the three machining times side by side, and the
/// feed and per-axis acceleration along the path of the chosen method.

#include <QWidget>
#include <array>

#include "engine/compute_result.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace cam {

class NumberSpinBox;
class ProjectDocument;

class MachiningPanel : public QWidget {
    Q_OBJECT
public:
    explicit MachiningPanel(ProjectDocument* document, QWidget* parent = nullptr);
    /// @brief The feed along the path and the axis accelerations (shown with a machining
    /// section).
    [[nodiscard]] QCustomPlot* feedPlot() const { return m_feedPlot; }
    [[nodiscard]] QCustomPlot* accelerationPlot() const { return m_accelPlot; }

    void setOutcome(const TimingOutcomePtr& outcome);
    /// @brief The computation is running (edits arrived, times not back yet).
    void setPending();
    [[nodiscard]] TimingMethod plotMethod() const;
    /// @brief "Seed 4.148 s · Exact stop 4.595 s · Optimal 3.532 s" (for tests and copying).
    [[nodiscard]] QString timesText() const;

signals:
    void plotMethodChanged();

private:
    void refresh();
    void push(const MachiningSpec& spec);

    ProjectDocument* m_document;
    QWidget* m_form;
    QPushButton* m_addButton;
    std::array<NumberSpinBox*, 3> m_accel{};
    std::array<NumberSpinBox*, 3> m_vmax{};
    QCheckBox* m_vmaxEnabled;
    NumberSpinBox* m_feed;
    NumberSpinBox* m_toolRadius;
    NumberSpinBox* m_step;
    QComboBox* m_method;
    std::array<QLabel*, 3> m_times{};
    QLabel* m_status;
    QCustomPlot* m_feedPlot;
    QCustomPlot* m_accelPlot;
    int m_gesture = 0;
    bool m_refreshing = false;
};

}  // namespace cam
