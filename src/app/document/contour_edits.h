#pragma once
/// @file
/// @brief The contour operations of the Edit menu, without any widget: each is one undo step on
/// the document, or a message saying why it cannot be done (and nothing changed).

#include <QCoreApplication>
#include <QString>

#include <Eigen/Core>

#include "spline/teach_in.h"

namespace cam {

class ProjectDocument;

/// @brief What an operation did: `problem` says why nothing happened; otherwise `status` says
/// what was done (for the status bar) and `row` is the row to select afterwards (-1: keep);
/// `details`, when not empty, lists what it changed beyond what was asked, one line each (Fit
/// Windows: every segment it moved), for the window to show.
struct EditOutcome {
    QString problem;
    QString status;
    int row = -1;
    QString details;

    [[nodiscard]] static EditOutcome refused(QString why) { return {std::move(why), {}, -1, {}}; }
    [[nodiscard]] static EditOutcome done(QString status, int row = -1) {
        return {{}, std::move(status), row, {}};
    }
    [[nodiscard]] bool ok() const { return problem.isEmpty(); }
};

class ContourEdits {
    Q_DECLARE_TR_FUNCTIONS(cam::ContourEdits)
public:
    /// @brief A new project: an eccentric circle in two windows, valid and ready to edit.
    [[nodiscard]] static Project newProject();

    /// @brief Inserts a segment after `row` (at the end when -1): it takes the second half of
    /// the window of the segment before it, as a copy of that segment.
    static EditOutcome insertSegment(ProjectDocument& document, int row);
    static EditOutcome deleteSegment(ProjectDocument& document, int row);
    /// @brief Moves `row` by `delta` rows (the new row is reported).
    static EditOutcome moveSegment(ProjectDocument& document, int row, int delta);
    /// @brief Sets every window boundary to where its neighbours meet (contour/fit_windows.h);
    /// segments that miss by a typing slip are moved to meet, each listed in `details`. The
    /// status says how far the farthest moved and what problem, if any, the project still has.
    static EditOutcome fitWindows(ProjectDocument& document);
    /// @brief Rounds the corner at joint K (between rows K-1 and K) by a tangent arc of radius
    /// rho; the problem gives the feasible range when rho does not fit.
    static EditOutcome roundCorner(ProjectDocument& document, int joint, double rho);
    /// @brief Joins arc `row` to the next arc (the first after the last) by the straight line
    /// tangent to both, the windows written from the tangent points (construction/tangents.h).
    /// Which of the common tangents follows from the two arcs' branches.
    static EditOutcome tangentLineToNext(ProjectDocument& document, int row);
    /// @brief Inserts after `row` the arc that continues it tangentially through `point` (mm).
    static EditOutcome tangentArcThrough(ProjectDocument& document, int row,
                                         const Eigen::Vector2d& point);
    /// @brief Replaces arc `row` by Bézier pieces within `maxErrorMm` radial error.
    static EditOutcome approximateArc(ProjectDocument& document, int row, double maxErrorMm);
    /// @brief Replaces the contour by a closed Bézier spline through the points ("x, y" per line,
    /// read like a point list: see parseNumberRows) with automatic handles.
    static EditOutcome contourThroughPoints(ProjectDocument& document, const QString& pointsText,
                                            HandleRule rule, double bulge);
};

}  // namespace cam
