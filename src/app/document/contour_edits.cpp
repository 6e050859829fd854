#include "document/contour_edits.h"

#include "construction/tangents.h"
#include "contour/fit_windows.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "fillet/fillet.h"
#include "io/number_rows.h"
#include "messages/diagnostic_text.h"
#include "spline/circle_approximation.h"
#include "widgets/quantity_format.h"

namespace cam {

Project ContourEdits::newProject() {
    Project p;
    p.name = tr("Untitled").toStdString();
    p.motion = {SpeedUnit::PeriodS, 1.0};
    // An eccentric circle in two windows: a valid contour to start editing from.
    for (double start : {0.0, 180.0}) {
        p.contour.push_back(
            SegmentSpec{Arc{{5.0, 0.0}, 30.0, Branch::Outer}, start, start + 180.0});
    }
    return p;
}

EditOutcome ContourEdits::insertSegment(ProjectDocument& document, int row) {
    const auto& contour = document.project().contour;
    const int at = row < 0 ? static_cast<int>(contour.size()) : row + 1;
    QUndoStack* stack = document.undoStack();
    if (at == 0) {
        const SegmentSpec circle{Arc{{0.0, 0.0}, 20.0, Branch::Outer}, 0.0, 360.0};
        stack->push(new InsertSegment(&document, at, circle));
        return EditOutcome::done({}, at);
    }
    // The new segment is a copy of the one before, and shares its window: with the copies
    // inserted before it (a run of the same segment in windows that meet), the run's whole
    // window is divided evenly. One Insert halves a window; three give four quarters — the
    // last window was halved again at each Insert before (issue 31).
    const SegmentSpec& source = contour.at(static_cast<std::size_t>(at - 1));
    const auto sameSegment = [&source](SegmentSpec s) {
        s.phiStartDeg = source.phiStartDeg;
        s.phiEndDeg = source.phiEndDeg;
        return s == source;
    };
    int first = at - 1;
    while (first > 0 && sameSegment(contour[static_cast<std::size_t>(first - 1)]) &&
           contour[static_cast<std::size_t>(first - 1)].phiEndDeg ==
               contour[static_cast<std::size_t>(first)].phiStartDeg) {
        --first;
    }
    const double start = contour[static_cast<std::size_t>(first)].phiStartDeg;
    const double end = source.phiEndDeg;
    const int parts = at - first + 1;
    const auto boundary = [&](int k) {
        return k == parts ? end : start + (end - start) * static_cast<double>(k) / parts;
    };
    stack->beginMacro(tr("Insert segment"));
    for (int row = first; row < at; ++row) {
        SegmentSpec narrowed = contour[static_cast<std::size_t>(row)];
        narrowed.phiStartDeg = boundary(row - first);
        narrowed.phiEndDeg = boundary(row - first + 1);
        if (narrowed == contour[static_cast<std::size_t>(row)]) continue;
        stack->push(
            new EditSegment(&document, row, narrowed, EditedField::Whole, tr("Split window")));
    }
    SegmentSpec copy = source;
    copy.phiStartDeg = boundary(parts - 1);
    copy.phiEndDeg = end;
    stack->push(new InsertSegment(&document, at, copy));
    stack->endMacro();
    return EditOutcome::done({}, at);
}

EditOutcome ContourEdits::deleteSegment(ProjectDocument& document, int row) {
    if (row < 0 || row >= static_cast<int>(document.project().contour.size())) {
        return EditOutcome::refused(tr("Select the segment to delete first."));
    }
    document.undoStack()->push(new RemoveSegment(&document, row));
    const int rows = static_cast<int>(document.project().contour.size());
    return EditOutcome::done({}, std::min(row, rows - 1));
}

EditOutcome ContourEdits::moveSegment(ProjectDocument& document, int row, int delta) {
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= static_cast<int>(document.project().contour.size())) {
        return EditOutcome::refused(tr("The segment cannot move further."));
    }
    document.undoStack()->push(new MoveSegment(&document, row, to));
    return EditOutcome::done({}, to);
}

EditOutcome ContourEdits::fitWindows(ProjectDocument& document) {
    const auto fitted = cam::fitWindows(document.project().contour);
    if (!fitted.ok()) return EditOutcome::refused(diagnosticsText(fitted.errors()));
    const FittedWindows& f = fitted.value();
    if (f.contour == document.project().contour) {
        return EditOutcome::done(tr("The windows already fit."));
    }
    // The windows and every moved segment together: one undo step.
    document.undoStack()->push(new ReplaceContour(&document, f.contour, tr("Fit windows")));
    QString status =
        f.moves.empty() ? tr("Windows fitted to the joints.")
                        : tr("Windows fitted; %n segment(s) changed to meet, by at most %1.", "",
                             static_cast<int>(f.moves.size()))
                              .arg(formatQuantity(DisplayQuantity::LengthError, f.largestMoveMm()));
    // Said, not hidden: what else keeps the project from being valid.
    if (const Diagnostics& left = document.diagnostics(); hasErrors(left)) {
        status += QLatin1Char(' ') +
                  tr("The project still has %n problem(s): %1", "", static_cast<int>(left.size()))
                      .arg(diagnosticText(left.front()));
    }
    EditOutcome outcome = EditOutcome::done(status);
    QStringList changes;
    for (const Diagnostic& d : f.notes) changes << diagnosticText(d);
    outcome.details = changes.join(QLatin1Char('\n'));
    return outcome;
}

EditOutcome ContourEdits::roundCorner(ProjectDocument& document, int joint, double rho) {
    if (joint < 0) return EditOutcome::refused(tr("Select the segment after the corner to round."));
    const auto result =
        filletJoint(document.project().contour, static_cast<std::size_t>(joint), rho);
    if (!result.ok()) return EditOutcome::refused(diagnosticsText(result.errors()));
    document.undoStack()->push(
        new ReplaceContour(&document, result.value().contour, tr("Round corner")));
    return EditOutcome::done(
        tr("Corner rounded with a %1 switch arc").arg(formatQuantity(DisplayQuantity::Length, rho)),
        joint);
}

EditOutcome ContourEdits::tangentLineToNext(ProjectDocument& document, int row) {
    const auto& contour = document.project().contour;
    if (row < 0 || row >= static_cast<int>(contour.size())) {
        return EditOutcome::refused(tr("Select the arc the tangent line starts from first."));
    }
    const std::size_t joint = (static_cast<std::size_t>(row) + 1) % contour.size();
    const auto result = tangentLineJoint(contour, joint);
    if (!result.ok()) return EditOutcome::refused(diagnosticsText(result.errors()));
    const TangentLineChoice& line = result.value().choices.front();
    document.undoStack()->push(
        new ReplaceContour(&document, line.contour, tr("Tangent line to the next arc")));
    const auto point = [](const Eigen::Vector2d& p) { return formatPoint(p.x(), p.y()); };
    return EditOutcome::done(
        tr("Tangent line from %1 to %2").arg(point(line.tangentPoint1), point(line.tangentPoint2)),
        static_cast<int>(line.lineIndex));
}

EditOutcome ContourEdits::tangentArcThrough(ProjectDocument& document, int row,
                                            const Eigen::Vector2d& point) {
    const auto& contour = document.project().contour;
    if (row < 0 || row >= static_cast<int>(contour.size())) {
        return EditOutcome::refused(tr("Select the segment the arc continues first."));
    }
    const auto result = arcThroughPoint(contour, static_cast<std::size_t>(row), point);
    if (!result.ok()) return EditOutcome::refused(diagnosticsText(result.errors()));
    const ArcThroughPointResult& arc = result.value();
    document.undoStack()->push(
        new ReplaceContour(&document, arc.contour, tr("Tangent arc through a point")));
    return EditOutcome::done(tr("Tangent arc: centre %1, radius %2")
                                 .arg(formatPoint(arc.center.x(), arc.center.y()),
                                      formatQuantity(DisplayQuantity::Length, arc.radius)),
                             static_cast<int>(arc.arcIndex));
}

EditOutcome ContourEdits::approximateArc(ProjectDocument& document, int row, double maxErrorMm) {
    if (row < 0) return EditOutcome::refused(tr("Select the arc to approximate first."));
    ArcApproximation report;
    const auto replaced = approximateArcSegment(document.project().contour,
                                                static_cast<std::size_t>(row), maxErrorMm, &report);
    if (!replaced.ok()) return EditOutcome::refused(diagnosticsText(replaced.errors()));
    document.undoStack()->push(
        new ReplaceContour(&document, replaced.value(), tr("Approximate arc by Béziers")));
    return EditOutcome::done(
        tr("%n Bézier piece(s): radial error %1, end/middle speed ratio %2", "",
           static_cast<int>(report.pieces.size()))
            .arg(formatQuantity(DisplayQuantity::LengthError, report.radialErrorMm),
                 formatQuantity(DisplayQuantity::Ratio, report.speedRatio)),
        row);
}

EditOutcome ContourEdits::contourThroughPoints(ProjectDocument& document, const QString& pointsText,
                                               HandleRule rule, double bulge) {
    const auto rows = parseNumberRows(pointsText.toStdString(), {{"x", "y"}, 2});
    if (!rows.ok()) return EditOutcome::refused(diagnosticsText(rows.errors()));
    std::vector<Eigen::Vector2d> knots;
    for (const auto& row : rows.value()) knots.emplace_back(row[0], row[1]);
    const auto contour = cam::contourThroughPoints(knots, rule, bulge);
    if (!contour.ok()) return EditOutcome::refused(diagnosticsText(contour.errors()));
    document.undoStack()->push(
        new ReplaceContour(&document, contour.value(), tr("New contour through points")));
    return EditOutcome::done(
        tr("New contour through %n point(s)", "", static_cast<int>(knots.size())), 0);
}

}  // namespace cam
