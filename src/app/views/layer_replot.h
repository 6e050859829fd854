#pragma once
/// @file
/// @brief Redrawing one buffered layer of a plot alone (a cursor, drag handles), the cheap way,
/// without ever turning it into a second full replot.

#include <qcustomplot.h>

namespace cam {

/// @brief Redraws `layer` (buffered) alone when the plot's other paint buffers are up to date
/// and no replot of the whole plot is queued. When one is queued, it draws the layer too.
/// When buffers are out of date (curves or items changed since the last replot),
/// QCPLayer::replot() would replot the whole plot at once, and again when the replot queued for
/// those changes runs: then the layer waits for a queued replot instead.
inline void replotLayer(QCPLayer* layer) {
    // Both are protected; read through member pointers of a subclass.
    struct Access : QCustomPlot {
        using QCustomPlot::hasInvalidatedPaintBuffers;
        using QCustomPlot::mReplotQueued;
    };
    QCustomPlot* plot = layer->parentPlot();
    if (plot->*(&Access::mReplotQueued)) return;
    if ((plot->*(&Access::hasInvalidatedPaintBuffers))()) {
        plot->replot(QCustomPlot::rpQueuedReplot);
    } else {
        layer->replot();
    }
}

}  // namespace cam
