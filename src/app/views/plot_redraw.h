#pragma once
/// @file
/// @brief How the views redraw their plots without stalling the window: full replots one per
/// event-loop pass, and buffered layers (a cursor, drag handles) that redraw alone, cheaply,
/// and never turn into a second full replot.

#include <qcustomplot.h>

#include <functional>

namespace cam {

/// @brief Queues a full replot of `plot`. Plots queued together are replotted one per pass of
/// the event loop, in the order asked, so that input and timers get their turn between them:
/// QCustomPlot's own queued replots (rpQueuedReplot) all run in one pass, and a result that
/// redraws the three kinematics plots and the contour view held the window for 12 ms and more.
/// A plot already waiting is not queued again.
void queueReplot(QCustomPlot* plot);

/// @brief Calls `then` (unless `context` is gone by then) in a pass of the event loop of its own
/// once every plot queued so far has been replotted: what the window shows beside its plots
/// (the readout, the contour view, the Joints tab) waits for them, so that an edit's plots are
/// not delayed by painting the rest. Plots queued later never hold it back (while edits stream
/// in, the queue is seldom empty); calls run in the order made. The window paints what they
/// changed, and input has its turn, before the next replot.
void whenReplotsDone(QObject* context, std::function<void()> then);

/// @brief Replots every plot queueReplot() holds, and calls what whenReplotsDone() holds, now
/// (before a picture is taken of them, or a test reads them).
void replotQueuedNow();

/// @brief Whether `plot` waits for a replot queued by queueReplot() or by QCustomPlot itself.
[[nodiscard]] bool isReplotQueued(QCustomPlot* plot);

/// @brief Redraws `layer` (buffered) alone when the plot's other paint buffers are up to date
/// and no full replot of the plot is queued (that one draws the layer too). When the buffers
/// are out of date (curves or items changed since the last replot), QCPLayer::replot() would
/// replot the whole plot at once, and again when the replot queued for those changes runs:
/// then the layer waits for a queued replot instead.
void replotLayer(QCPLayer* layer);

/// @brief Adds a buffered layer `name` above all others. The "overlay" layer (buffered by
/// default, for a selection rectangle the views do not use) becomes logical, so that the plot
/// keeps one paint buffer below its buffered top layers instead of one below and one above
/// each: fewer buffers to clear on every replot and to compose on every paint.
QCPLayer* addBufferedTopLayer(QCustomPlot* plot, const QString& name);

/// @brief Adds the plot's cursor: a dashed vertical line at x = 0 on a buffered top layer
/// "cursor" of its own, so that moving it redraws one line, not the curves.
QCPItemStraightLine* addCursorLine(QCustomPlot* plot);

/// @brief Moves a cursor made by addCursorLine() to x and redraws its layer (replotLayer());
/// a cursor already there is not redrawn (a new result sets every cursor again).
void moveCursorLine(QCPItemStraightLine* cursor, double x);

}  // namespace cam
