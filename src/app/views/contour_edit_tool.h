#pragma once
/// @file
/// @brief The contour view's editing tool: the drag handles of the selected segment (an arc's
/// centre and radius, a spline's inner control points), dragging them as undoable edits of the
/// ProjectDocument, and picking a point for a construction. Dragged and picked points snap
/// (views/contour_snapping.h).

#include <qcustomplot.h>

#include <Eigen/Core>

#include "views/contour_snapping.h"

class QKeyEvent;
class QMouseEvent;

namespace cam {

class ProjectDocument;

class ContourEditTool : public QObject {
    Q_OBJECT
public:
    /// @brief Adds the handles to `plot` on `handlesLayer` and the pick marker on `cursorLayer`;
    /// `joints` (drawn by the view) are points to snap to. The tool is a child of `plot`.
    ContourEditTool(QCustomPlot* plot, ProjectDocument* document, const QCPGraph* joints,
                    QCPLayer* handlesLayer, QCPLayer* cursorLayer);

    /// @brief Shows the drag handles of this segment (-1: none).
    void setSelectedSegment(int row);

    /// @brief Where a dragged or picked point at this pixel lands, mm: snapPoint() with the
    /// rotation centre, the arcs' centres (but skipSegment's) and the joints as last drawn,
    /// within kSnapPixels, and the grid step gridStep().
    [[nodiscard]] Eigen::Vector2d snap(const QPointF& pixel, Qt::KeyboardModifiers modifiers,
                                       const Eigen::Vector2d* origin = nullptr,
                                       int skipSegment = -1) const;
    /// @brief The smallest 1-2-5 step that spans at least kGridPixels at the current zoom, mm.
    [[nodiscard]] double gridStep() const;
    static constexpr double kSnapPixels = 10.0;
    static constexpr double kGridPixels = 8.0;

    /// @brief The next left click picks a point (snapped): pointPicked, or pickCancelled on
    /// Escape. The mouse shows a cross where the point would land.
    void beginPointPick();
    [[nodiscard]] bool isPickingPoint() const { return m_picking; }
    void cancelPointPick();
    /// @brief Whether a handle is being dragged.
    [[nodiscard]] bool isDragging() const { return m_dragging != Handle::None; }

    /// @brief The plot's events, given to the tool first; true when the tool took the event
    /// (the plot must not pan or zoom with it).
    bool mousePress(QMouseEvent* event);
    bool mouseMove(QMouseEvent* event);
    void mouseRelease();
    bool keyPress(QKeyEvent* event);

signals:
    /// A point was picked (mm) after beginPointPick.
    void pointPicked(const QPointF& point);
    void pickCancelled();

private:
    enum class Handle { None, First, Second };
    void updateHandles();
    [[nodiscard]] Handle handleAt(const QPointF& pixel) const;
    [[nodiscard]] QPointF secondHandlePosition(int row) const;
    [[nodiscard]] double mmPerPixel() const;
    [[nodiscard]] GridStep grid() const;
    void endPointPick();
    /// Moves the dragged handle to the mouse: one undoable edit of the selected segment.
    void dragTo(QMouseEvent* event);

    QCustomPlot* m_plot;
    ProjectDocument* m_document;
    const QCPGraph* m_joints;
    QCPLayer* m_handlesLayer;
    QCPLayer* m_cursorLayer;
    QCPGraph* m_firstHandle = nullptr;     ///< square: the arc's centre, or a spline's P1
    QCPGraph* m_secondHandle = nullptr;    ///< diamond: the arc's radius, or a spline's P2
    QCPCurve* m_controlPolygon = nullptr;  ///< P0–P1–P2–P3 of the selected spline
    int m_selected = -1;
    Handle m_dragging = Handle::None;
    int m_gesture = 0;
    Eigen::Vector2d m_dragOrigin{0.0, 0.0};  ///< where the dragged handle was when it was taken
    bool m_picking = false;
    QCPItemTracer* m_pickMarker = nullptr;  ///< where a picked point would land
};

}  // namespace cam
