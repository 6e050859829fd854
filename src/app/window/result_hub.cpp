#include "window/result_hub.h"

#include <QEventLoop>
#include <QTimer>

#include "engine/compute_engine.h"
#include "views/plot_redraw.h"

namespace cam {

ResultHub::ResultHub(ComputeEngine* engine, QObject* parent) : QObject(parent), m_engine(engine) {
    connect(engine, &ComputeEngine::resultReady, this, &ResultHub::take);
}

void ResultHub::take(const ComputeResultPtr& result) {
    if (m_shown && result->ok() && result->generation == m_shown->generation) {
        // The same result with the finer plot levels (see ComputeWorker): only the plots,
        // which draw them when zoomed in, take it; and the follower's design checks.
        const bool checks = m_shown->followerChecksPending && !result->followerChecksPending;
        m_shown = result;
        emit refined(result, checks);
        emit handed(result);
        return;
    }
    m_handedGeneration = result->generation;
    // The views keep what they drew from the last computable result and mark it out of date.
    // The plots first: each view's redraw is queued, and they are drawn in this order.
    emit arrived(result);
    if (!result->ok()) {
        // A design without a contour yet: the views drew nothing, and nothing of an earlier
        // project may be exported as this one's.
        if (result->awaitsContour()) m_shown.reset();
        emit uncomputed(result);
        emit handed(result);
        return;
    }
    m_shown = result;
    // The rest of the window (the contour view, the Joints tab, the readout, the status bar)
    // follows once the plots are drawn, so that painting it never delays them: it took 1.5 to
    // 2 ms of an edit's redraw. By then it takes the newest result of this request (a first
    // picture may have been refined meanwhile); a newer request's result, computable or not,
    // has its own turn, and this one is then never shown there.
    whenReplotsDone(this, [this, generation = result->generation] {
        if (m_handedGeneration != generation || !m_shown || m_shown->generation != generation) {
            return;
        }
        emit settled(m_shown);
    });
    emit handed(result);
}

bool ResultHub::waitForCurrent(int timeoutMs) {
    const auto current = [this] {
        const auto& r = m_engine->latestResult();
        // A first picture is followed by its finer plot levels and the follower's checks.
        return r && r->generation == m_engine->latestGeneration() && r->complete();
    };
    // Shown: the plots have been replotted with it too (they replot one per pass of the event
    // loop, see queueReplot).
    const auto shown = [] {
        replotQueuedNow();
        return true;
    };
    if (current()) return shown();
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, [&loop] { loop.exit(1); });
    connect(m_engine, &ComputeEngine::resultReady, &loop, [&loop, current] {
        if (current()) loop.exit(0);
    });
    return loop.exec() == 0 && shown();
}

}  // namespace cam
