#include "views/plot_redraw.h"

#include <QCoreApplication>
#include <QPointer>
#include <deque>
#include <utility>
#include <vector>

namespace cam {
namespace {

/// The plots waiting for queueReplot(), oldest first, and whether a pass is posted to take the
/// next one (GUI thread only).
struct ReplotQueue {
    std::deque<QPointer<QCustomPlot>> plots;
    /// What waits for the plots (whenReplotsDone), oldest first.
    std::vector<std::pair<QPointer<QObject>, std::function<void()>>> then;
    bool posted = false;
};

ReplotQueue& replotQueue() {
    static ReplotQueue queue;
    return queue;
}

/// Calls what waits for the plots; what they queue (a contour view's replot) comes after.
void runWaiting(ReplotQueue& queue) {
    auto waiting = std::exchange(queue.then, {});
    for (auto& [context, then] : waiting) {
        if (context) then();
    }
}

void replotNext() {
    ReplotQueue& queue = replotQueue();
    queue.posted = false;
    bool replotted = false;
    while (!queue.plots.empty() && !replotted) {
        const QPointer<QCustomPlot> plot = queue.plots.front();
        queue.plots.pop_front();
        if (!plot) continue;  // closed meanwhile
        plot->replot();
        replotted = true;
    }
    // The waiting calls get a pass of their own, after the last replot's.
    if (!replotted && queue.plots.empty()) runWaiting(queue);
    if ((!queue.plots.empty() || !queue.then.empty()) && !queue.posted) {
        // Posted while this pass runs: Qt delivers it in the next one, after input and timers.
        queue.posted = true;
        QMetaObject::invokeMethod(QCoreApplication::instance(), replotNext, Qt::QueuedConnection);
    }
}

/// QCustomPlot's protected members, read through member pointers of a subclass.
struct PlotAccess : QCustomPlot {
    using QCustomPlot::hasInvalidatedPaintBuffers;
    using QCustomPlot::mReplotQueued;
};

}  // namespace

void queueReplot(QCustomPlot* plot) {
    ReplotQueue& queue = replotQueue();
    for (const QPointer<QCustomPlot>& p : queue.plots) {
        if (p == plot) return;
    }
    queue.plots.emplace_back(plot);
    if (!queue.posted) {
        queue.posted = true;
        QMetaObject::invokeMethod(QCoreApplication::instance(), replotNext, Qt::QueuedConnection);
    }
}

void whenReplotsDone(QObject* context, std::function<void()> then) {
    ReplotQueue& queue = replotQueue();
    queue.then.emplace_back(context, std::move(then));
    if (!queue.posted) {
        queue.posted = true;
        QMetaObject::invokeMethod(QCoreApplication::instance(), replotNext, Qt::QueuedConnection);
    }
}

void replotQueuedNow() {
    ReplotQueue& queue = replotQueue();
    while (!queue.plots.empty() || !queue.then.empty()) {
        while (!queue.plots.empty()) {
            const QPointer<QCustomPlot> plot = queue.plots.front();
            queue.plots.pop_front();
            if (plot) plot->replot();
        }
        runWaiting(queue);
    }
}

bool isReplotQueued(QCustomPlot* plot) {
    if (plot->*(&PlotAccess::mReplotQueued)) return true;
    for (const QPointer<QCustomPlot>& p : replotQueue().plots) {
        if (p == plot) return true;
    }
    return false;
}

void replotLayer(QCPLayer* layer) {
    QCustomPlot* plot = layer->parentPlot();
    if (isReplotQueued(plot)) return;
    if ((plot->*(&PlotAccess::hasInvalidatedPaintBuffers))()) {
        queueReplot(plot);
    } else {
        layer->replot();
    }
}

QCPLayer* addBufferedTopLayer(QCustomPlot* plot, const QString& name) {
    plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    QCPLayer* top = plot->layer(plot->layerCount() - 1);
    plot->addLayer(name, top, QCustomPlot::limAbove);
    QCPLayer* layer = plot->layer(name);
    layer->setMode(QCPLayer::lmBuffered);
    return layer;
}

}  // namespace cam
