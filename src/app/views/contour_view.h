#pragma once
/// @file
/// @brief The contour in the cam's plane: segments coloured, centres and joints marked, the
/// follower ray at the cursor angle; drag an arc's centre or radius handle to edit it, or pick
/// a point for a construction. Dragged and picked points snap (see snap()).
///
/// The widget draws the result, keeps equal scales and follows the cursor; its parts:
/// the editing tool (views/contour_edit_tool.h: handles, dragging, point picking), snapping
/// (views/contour_snapping.h) and the follower's glyph (views/follower_glyph.h).

#include <qcustomplot.h>

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>

#include "engine/compute_result.h"
#include "views/contour_edit_tool.h"
#include "views/follower_glyph.h"
#include "views/palette.h"
#include "views/stress_overlay.h"

namespace cam {

class ProjectDocument;
class StaleLabel;

class ContourView : public QCustomPlot {
    Q_OBJECT
public:
    explicit ContourView(ProjectDocument* document, QWidget* parent = nullptr);
    ~ContourView() override;

    void setResult(const ComputeResultPtr& result);
    /// @brief The curve that draws segment k (shared by every tenth segment, see
    /// m_colourCurves), and where segment k's points begin in it and how many there are.
    [[nodiscard]] QCPCurve* segmentCurve(int k) const;
    /// @brief Segment k's colour slot: the document's (it stays with the segment).
    [[nodiscard]] int colourSlot(int k) const;
    [[nodiscard]] std::pair<int, int> segmentRun(int k) const;
    /// @brief A grooved cam's outer flank and the roller's pitch curve (dashed), as drawn now:
    /// empty for a spring-closed cam.
    [[nodiscard]] QCPCurve* outerFlankCurve() const { return m_closureCurves[0]; }
    /// @brief A conjugate pair's second plate, as drawn now (the same curve as the outer flank:
    /// a cam has one or the other).
    [[nodiscard]] QCPCurve* secondPlateCurve() const { return m_closureCurves[0]; }
    [[nodiscard]] QCPCurve* pitchCurve() const { return m_closureCurves[1]; }
    /// @brief Colours the profile by the contact stress where the follower touches it (a
    /// project with dynamics, a contact width and materials), or not.
    void setStressColouring(bool on);
    [[nodiscard]] const StressOverlay& stressOverlay() const { return *m_stress; }
    /// @brief Shows the follower ray at this angle (rad) and the contour point on it; while
    /// the view turns the cam, turns the cam by −phi under the follower standing at its place
    /// at 0 instead.
    void setCursorAngle(double phi);
    /// @brief Turns the cam under a follower that stands still (Play with Play Turns the Cam)
    /// or draws the cam standing still with the follower round it (the inversion). While it
    /// turns, the stress colours and the drag handles are hidden and the mouse moves no cursor.
    void setTurning(bool on);
    [[nodiscard]] bool turning() const { return m_turning; }
    /// @brief How far the drawing of the cam is turned now (rad, counter-clockwise; 0 unless
    /// turning).
    [[nodiscard]] double turnedBy() const { return m_turnedBy; }
    /// @brief Shows the drag handles of this segment (-1: none).
    void setSelectedSegment(int row);
    /// @brief Fits the contour into the view with equal scales.
    void resetZoom();
    /// @brief Keeps equal scales at the current viewport: refits while the user has not zoomed
    /// or panned, else widens one axis (what a resize does; a picture at another size too).
    void fitToViewport();
    /// @brief Where the follower is drawn now (mm, the cam frame): for tests and pictures.
    using FollowerMarkers = cam::FollowerMarkers;
    [[nodiscard]] FollowerMarkers followerMarkers() const;
    /// @brief Why the contour shown is out of date; empty when it is the current project's.
    [[nodiscard]] QString staleReason() const;

    /// @brief Where a dragged or picked point at this pixel lands, mm. Without modifiers it
    /// snaps to the rotation centre, an arc's centre (but skipSegment's) or a joint as last
    /// drawn within kSnapPixels, else to
    /// the grid: the multiples of the smallest step of 1, 2 or 5 × 10^k mm that spans at
    /// least kGridPixels on screen. Alt: no snapping. Shift with an `origin` (where a drag
    /// began): only the axis the mouse moved farther along changes.
    [[nodiscard]] Eigen::Vector2d snap(const QPointF& pixel, Qt::KeyboardModifiers modifiers,
                                       const Eigen::Vector2d* origin = nullptr,
                                       int skipSegment = -1) const {
        return m_editTool->snap(pixel, modifiers, origin, skipSegment);
    }
    /// @brief The grid step snap() uses at the current zoom, mm.
    [[nodiscard]] double gridStep() const { return m_editTool->gridStep(); }
    static constexpr double kSnapPixels = ContourEditTool::kSnapPixels;
    static constexpr double kGridPixels = ContourEditTool::kGridPixels;

    /// @brief The next left click picks a point (snapped): pointPicked, or pickCancelled on
    /// Escape. The mouse shows a cross where the point would land.
    void beginPointPick() { m_editTool->beginPointPick(); }
    [[nodiscard]] bool isPickingPoint() const { return m_editTool->isPickingPoint(); }
    void cancelPointPick() { m_editTool->cancelPointPick(); }

signals:
    /// A point was picked (mm) after beginPointPick.
    void pointPicked(const QPointF& point);
    void pickCancelled();
    /// The mouse points at this polar angle (rad).
    void cursorAngleChanged(double phi);
    void segmentPicked(int row);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void keepEqualAspect();
    void setStale(const QString& reason);

    /// Draws the cam turned by `angle` (rad) from the points of the last result.
    void turnDrawing(double angle);

    ProjectDocument* m_document;
    ComputeResultPtr m_result;
    bool m_turning = false;
    double m_turnedBy = 0.0;
    std::optional<std::pair<QCPRange, QCPRange>> m_rangesBeforeTurning;
    /// The cam as the result has it (turned by 0): the colour curves, centres, joints.
    std::array<QVector<QCPCurveData>, kSegmentColorCount> m_standing;
    QVector<double> m_standingCx, m_standingCy, m_standingJx, m_standingJy;
    /// A groove's outer flank and pitch curve, or a conjugate pair's second plate, turned by 0,
    /// and their curves.
    std::array<QVector<QCPCurveData>, 2> m_standingClosure;
    std::array<QCPCurve*, 2> m_closureCurves{};
    /// One curve per segment colour: segment k is a run of colourCurves[its slot], the runs
    /// separated by a NaN point (a gap). Ten curves whatever the number of segments: drawing,
    /// replacing and closing cost what the points cost, not a plottable per segment.
    std::array<QCPCurve*, kSegmentColorCount> m_colourCurves{};
    QCPRange m_xBounds, m_yBounds;            ///< of every outline point
    bool m_hasBounds = false;                 ///< false until a result with points arrives
    std::vector<std::pair<int, int>> m_runs;  ///< per segment: first index, count in its curve
    QCPGraph* m_centers = nullptr;
    QCPGraph* m_joints = nullptr;
    QCPItemLine* m_ray = nullptr;
    QCPItemTracer* m_rayPoint = nullptr;
    QCPLayer* m_cursorLayer = nullptr;   ///< buffered: the ray, its point and the follower
    QCPLayer* m_handlesLayer = nullptr;  ///< buffered: the drag handles and control polygon
    /// The follower at the cursor angle, on the cursor layer.
    std::unique_ptr<FollowerGlyph> m_follower;
    ContourEditTool* m_editTool = nullptr;  ///< a child: handles, dragging, point picking
    StaleLabel* m_staleLabel = nullptr;
    std::unique_ptr<StressOverlay> m_stress;
    bool m_stressColouring = false;
    double m_cursorPhi = 0.0;
    bool m_autoFit = true;  ///< refit on resize until the user zooms or pans
};

}  // namespace cam
