#include "views/plot_redraw.h"

#include <QCoreApplication>
#include <QPointer>
#include <QTimer>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "export/plot_picture.h"

namespace cam {
namespace {

/// The plots waiting for queueReplot(), oldest first, what waits for them (whenReplotsDone),
/// and the timer that starts the pass taking the next one (GUI thread only). Each queued plot
/// gets the next number; a waiting call waits for the number of the last plot queued before it.
struct ReplotQueue {
    struct Plot {
        QPointer<QCustomPlot> plot;
        std::uint64_t number;
    };
    struct Waiting {
        QPointer<QObject> context;
        std::function<void()> then;
        std::uint64_t after;  ///< runs once the plot of this number is done
    };
    std::deque<Plot> plots;
    std::deque<Waiting> then;
    std::uint64_t queued = 0;  ///< the number of the last plot queued
    std::uint64_t done = 0;    ///< the number of the last plot replotted (or closed)
    QPointer<QTimer> pass;     ///< owned by the application: gone with it

    [[nodiscard]] bool waitingReady() const { return !then.empty() && then.front().after <= done; }
    void post() {
        // A pass is a zero timer's timeout, not a posted event: Qt delivers the events posted
        // in one pass of the event loop together, and the timers and input only after them, so
        // a chain of posted passes held input back for two passes at a time (7 to 10 ms). A
        // zero timer waits while events are posted or input is pending: what a pass changed
        // (labels, a table row) is painted, and input handled, before the next replot.
        if (!pass) {
            pass = new QTimer(QCoreApplication::instance());
            pass->setSingleShot(true);
            pass->setInterval(0);
            QObject::connect(pass, &QTimer::timeout, pass, &ReplotQueue::replotNext);
        }
        if (!pass->isActive()) pass->start();
    }
    /// Calls what waits for plots already done; what they queue (a contour view's replot)
    /// comes after.
    void runReady() {
        std::vector<Waiting> ready;
        while (waitingReady()) {
            ready.push_back(std::move(then.front()));
            then.pop_front();
        }
        for (Waiting& w : ready) {
            if (w.context) w.then();
        }
    }
    /// Replots the next plot still open; false if none is left.
    bool replotOne() {
        while (!plots.empty()) {
            const Plot next = plots.front();
            plots.pop_front();
            done = next.number;
            if (next.plot) {
                next.plot->replot();
                return true;
            }
        }
        return false;
    }

    static void replotNext();
};

ReplotQueue& replotQueue() {
    static ReplotQueue queue;
    return queue;
}

/// One pass: what waits for plots already done, in a pass of its own (so that a stream of new
/// replots never holds it back), else the next plot.
void ReplotQueue::replotNext() {
    ReplotQueue& queue = replotQueue();
    if (queue.waitingReady()) {
        queue.runReady();
    } else {
        queue.replotOne();
    }
    if (!queue.plots.empty() || !queue.then.empty()) queue.post();
}

/// QCustomPlot's protected members, read through member pointers of a subclass.
struct PlotAccess : QCustomPlot {
    using QCustomPlot::hasInvalidatedPaintBuffers;
    using QCustomPlot::mReplotQueued;
};

}  // namespace

void queueReplot(QCustomPlot* plot) {
    ReplotQueue& queue = replotQueue();
    for (const ReplotQueue::Plot& p : queue.plots) {
        if (p.plot == plot) return;
    }
    queue.plots.push_back({plot, ++queue.queued});
    queue.post();
}

void whenReplotsDone(QObject* context, std::function<void()> then) {
    ReplotQueue& queue = replotQueue();
    queue.then.push_back({context, std::move(then), queue.queued});
    queue.post();
}

void replotQueuedNow() {
    ReplotQueue& queue = replotQueue();
    while (!queue.plots.empty() || !queue.then.empty()) {
        while (queue.replotOne()) {
        }
        queue.runReady();
    }
}

bool isReplotQueued(QCustomPlot* plot) {
    if (plot->*(&PlotAccess::mReplotQueued)) return true;
    for (const ReplotQueue::Plot& p : replotQueue().plots) {
        if (p.plot == plot) return true;
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

QCPItemStraightLine* addCursorLine(QCustomPlot* plot) {
    QCPLayer* layer = addBufferedTopLayer(plot, QStringLiteral("cursor"));
    auto* cursor = new QCPItemStraightLine(plot);
    cursor->setLayer(layer);
    cursor->setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
    cursor->point1->setCoords(0, 0);
    cursor->point2->setCoords(0, 1);
    cursor->setProperty(kNotInPictures, true);
    return cursor;
}

void moveCursorLine(QCPItemStraightLine* cursor, double x) {
    if (cursor->point1->coords().x() == x) return;  // drawn there already
    cursor->point1->setCoords(x, 0);
    cursor->point2->setCoords(x, 1);
    replotLayer(cursor->layer());
}

}  // namespace cam
