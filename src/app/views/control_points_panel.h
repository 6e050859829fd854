#pragma once
/// @file
/// @brief The control points of the selected spline row, by value: a Bézier's P0…P3 or a
/// Hermite's p0, t0, p3, t1 as x and y, and each end's handle as length and angle (the seed's
/// way). Every edit is one undo step; a spline's window follows its end points.

#include <QWidget>
#include <array>

#include "project/project.h"

class QGridLayout;
class QLabel;

namespace cam {

class NumberSpinBox;
class ProjectDocument;

class ControlPointsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlPointsPanel(ProjectDocument* document, QWidget* parent = nullptr);

    /// @brief Shows segment `row` (-1, or a row that is not a spline: shows why nothing is
    /// editable).
    void setRow(int row);
    [[nodiscard]] int row() const { return m_row; }

    /// @brief The editor of control point k (0…3) coordinate axis (0 x, 1 y); of handle k
    /// (0 start, 1 end) length or angle. For tests.
    [[nodiscard]] NumberSpinBox* pointEditor(int k, int axis) const { return m_points[k][axis]; }
    [[nodiscard]] NumberSpinBox* handleLengthEditor(int k) const { return m_handleLength[k]; }
    [[nodiscard]] NumberSpinBox* handleAngleEditor(int k) const { return m_handleAngle[k]; }

private:
    void refresh();
    void push(const SegmentSpec& after, const QString& what);

    ProjectDocument* m_document;
    int m_row = -1;
    QLabel* m_title;
    QWidget* m_editors;
    std::array<QLabel*, 4> m_pointNames{};
    std::array<std::array<NumberSpinBox*, 2>, 4> m_points{};
    std::array<QLabel*, 2> m_handleNames{};
    std::array<NumberSpinBox*, 2> m_handleLength{};
    std::array<NumberSpinBox*, 2> m_handleAngle{};
    int m_gesture = 0;
    bool m_refreshing = false;
};

}  // namespace cam
