#include "engine/compute_engine.h"

#include <QMutexLocker>

namespace cam {

ComputeWorker::ComputeWorker(QObject* parent) : QThread(parent) {}

ComputeWorker::~ComputeWorker() {
    {
        QMutexLocker lock(&m_mutex);
        m_abort = true;
        m_cancel = true;
        m_wake.wakeOne();
    }
    wait();
}

void ComputeWorker::submit(ComputeRequest request) {
    QMutexLocker lock(&m_mutex);
    m_pending = std::move(request);
    m_cancel = true;  // whatever is running answers an older request
    if (!isRunning()) {
        start(QThread::LowPriority);
    } else {
        m_wake.wakeOne();
    }
}

void ComputeWorker::setPreparer(std::shared_ptr<const PlotDataPreparer> preparer) {
    QMutexLocker lock(&m_mutex);
    m_preparer = std::move(preparer);
}

void ComputeWorker::run() {
    for (;;) {
        ComputeRequest request;
        std::shared_ptr<const PlotDataPreparer> preparer;
        {
            QMutexLocker lock(&m_mutex);
            while (!m_pending && !m_abort) m_wake.wait(&m_mutex);
            if (m_abort) return;
            request = std::move(*m_pending);
            m_pending.reset();
            preparer = m_preparer;
            m_cancel = false;
        }
        ComputeResultPtr result = computeProject(request, m_cancel, preparer.get());
        if (!result || m_cancel.load()) continue;
        emit finished(result);
        if (request.timing && result->ok() && request.project->machining) {
            TimingOutcomePtr outcome = computeTiming(request, *result->contour, m_cancel);
            if (outcome && preparer && outcome->errors.empty()) {
                auto prepared = std::make_shared<TimingOutcome>(*outcome);
                prepared->prepared = preparer->prepareTiming(*prepared);
                outcome = std::move(prepared);
            }
            if (outcome && !m_cancel.load()) emit timingFinished(outcome);
        }
    }
}

ComputeEngine::ComputeEngine(QObject* parent) : QObject(parent) {
    qRegisterMetaType<cam::ComputeResultPtr>();
    qRegisterMetaType<cam::TimingOutcomePtr>();
    m_timer.setSingleShot(true);
    m_timer.setInterval(30);
    connect(&m_timer, &QTimer::timeout, this, &ComputeEngine::submitPending);
    connect(&m_worker, &ComputeWorker::finished, this, &ComputeEngine::onFinished,
            Qt::QueuedConnection);
    connect(
        &m_worker, &ComputeWorker::timingFinished, this,
        [this](const TimingOutcomePtr& outcome) {
            if (outcome->generation != m_generation) return;  // answers an older request
            m_latestTiming = outcome;
            emit timingReady(outcome);
        },
        Qt::QueuedConnection);
}

ComputeEngine::~ComputeEngine() = default;

void ComputeEngine::setPlotDataPreparer(std::shared_ptr<const PlotDataPreparer> preparer) {
    m_worker.setPreparer(std::move(preparer));
}

void ComputeEngine::request(const Project& project, PlotAxis axis, bool timing,
                            TimingMethod plotMethod) {
    m_pending = ComputeRequest{++m_generation, std::make_shared<const Project>(project), axis,
                               timing, plotMethod};
    // Leading edge: a lone edit is computed at once. Edits that follow within the interval
    // are held and only the newest is submitted when it ends (trailing edge).
    if (!m_timer.isActive()) {
        submitPending();
        if (m_timer.interval() > 0) m_timer.start();
    }
}

void ComputeEngine::submitPending() {
    if (m_pending) m_worker.submit(std::move(*std::exchange(m_pending, std::nullopt)));
}

void ComputeEngine::onFinished(const ComputeResultPtr& result) {
    if (result->generation != m_generation) {
        ++m_dropped;  // an older request finished after a newer one was made: never show it
        return;
    }
    m_latest = result;
    emit resultReady(result);
}

}  // namespace cam
