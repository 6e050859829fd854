#pragma once
/// @file
/// @brief Turning speed (rad/s, rpm or period) and samples per turn; edits are undo commands.

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace cam {

class NumberSpinBox;
class ProjectDocument;

class MotionPanel : public QWidget {
    Q_OBJECT
public:
    explicit MotionPanel(ProjectDocument* document, QWidget* parent = nullptr);

private:
    void refresh();
    void pushSpeed();

    ProjectDocument* m_document;
    NumberSpinBox* m_speed;
    QComboBox* m_unit;
    QSpinBox* m_samples;
    QLabel* m_summary;
    int m_gesture = 0;
    bool m_refreshing = false;
};

}  // namespace cam
