#include "engine/compute_engine.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QMutexLocker>
#include <new>

#include "engine/background_priority.h"

namespace cam {

ComputeWorker::ComputeWorker(QObject* parent) : QThread(parent) {}

ComputeWorker::~ComputeWorker() { stop(-1); }

bool ComputeWorker::stop(int timeoutMs) {
    {
        QMutexLocker lock(&m_mutex);
        m_abort = true;
        m_cancel = true;
        m_wake.wakeOne();
    }
    return timeoutMs < 0 ? wait() : wait(QDeadlineTimer(timeoutMs));
}

void ComputeWorker::submit(ComputeRequest request) {
    QMutexLocker lock(&m_mutex);
    m_pending = std::move(request);
    m_cancel = true;  // whatever is running answers an older request
    if (!isRunning()) {
        start();
    } else {
        m_wake.wakeOne();
    }
}

void ComputeWorker::setPreparer(std::shared_ptr<const PlotDataPreparer> preparer) {
    QMutexLocker lock(&m_mutex);
    m_preparer = std::move(preparer);
}

namespace {

/// What the user reads when a computation threw: the message names the cause and the way out.
std::string failureMessage(const std::exception* e) {
    if (dynamic_cast<const std::bad_alloc*>(e)) {
        return QCoreApplication::translate("cam::ComputeWorker",
                                           "out of memory — fewer samples per turn would need less")
            .toStdString();
    }
    const QString what = e ? QString::fromLocal8Bit(e->what()) : QStringLiteral("?");
    return QCoreApplication::translate("cam::ComputeWorker", "the computation failed: %1")
        .arg(what)
        .toStdString();
}

/// The barrier: an exception escaping run() would end the program in std::terminate. Whatever
/// the computation held is released by the unwinding; the request is answered with a result
/// that says what happened, and the next request starts afresh.
template <class Step>
ComputeResultPtr guarded(const ComputeRequest& request, Step&& step) {
    try {
        return step();
    } catch (const std::exception& e) {
        return failedResult(request, failureMessage(&e));
    } catch (...) {
        return failedResult(request, failureMessage(nullptr));
    }
}

}  // namespace

void ComputeWorker::run() {
    runInTheBackground();
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
        const ComputeResultPtr result =
            guarded(request, [&] { return computeProject(request, m_cancel, preparer.get()); });
        if (!result || m_cancel.load()) continue;
        emit finished(result);
        // The first picture is shown; the finer plot levels (for zooming in) and the
        // follower's design checks follow, unless a newer request came meanwhile.
        if (!result->complete()) {
            const ComputeResultPtr refined =
                guarded(request, [&] { return refineResult(*result, m_cancel, preparer.get()); });
            if (!refined || m_cancel.load()) continue;
            emit finished(refined);
        }
        if (request.timing && result->ok() && request.project->machining) {
            if (result->valid()) {
                computeTimingOf(request, *result, preparer.get());
            } else {
                // A contour with problems is not machined: its times would be shown as the
                // cam's while nothing can be exported from it.
                auto outcome = std::make_shared<TimingOutcome>();
                outcome->generation = request.generation;
                outcome->errors = result->reasonsNotShown();
                emit timingFinished(outcome);
            }
        }
    }
}

void ComputeWorker::computeTimingOf(const ComputeRequest& request, const ComputeResult& result,
                                    const PlotDataPreparer* preparer) {
    TimingOutcomePtr outcome;
    try {
        outcome = computeTiming(request, *result.contour, m_cancel);
        if (outcome && preparer && outcome->errors.empty()) {
            auto prepared = std::make_shared<TimingOutcome>(*outcome);
            prepared->prepared = preparer->prepareTiming(*prepared);
            outcome = std::move(prepared);
        }
    } catch (const std::exception& e) {
        auto failed = std::make_shared<TimingOutcome>();
        failed->generation = request.generation;
        failed->errors = {Diagnostic{"", failureMessage(&e)}};
        outcome = std::move(failed);
    } catch (...) {
        auto failed = std::make_shared<TimingOutcome>();
        failed->generation = request.generation;
        failed->errors = {Diagnostic{"", failureMessage(nullptr)}};
        outcome = std::move(failed);
    }
    if (outcome && !m_cancel.load()) emit timingFinished(outcome);
}

ComputeEngine::ComputeEngine(QObject* parent) : QObject(parent), m_worker(new ComputeWorker) {
    qRegisterMetaType<cam::ComputeResultPtr>();
    qRegisterMetaType<cam::TimingOutcomePtr>();
    m_timer.setSingleShot(true);
    m_timer.setInterval(30);
    connect(&m_timer, &QTimer::timeout, this, &ComputeEngine::submitPending);
    connect(m_worker, &ComputeWorker::finished, this, &ComputeEngine::onFinished,
            Qt::QueuedConnection);
    connect(
        m_worker, &ComputeWorker::timingFinished, this,
        [this](const TimingOutcomePtr& outcome) {
            if (outcome->generation != m_generation) return;  // answers an older request
            m_latestTiming = outcome;
            emit timingReady(outcome);
        },
        Qt::QueuedConnection);
}

ComputeEngine::~ComputeEngine() {
    QObject::disconnect(m_worker, nullptr, this, nullptr);
    if (m_worker->stop(kStopTimeoutMs)) {
        delete m_worker;
        return;
    }
    // Some step does not poll the cancel flag. Deleting a running QThread would abort the
    // program, and waiting could hang it: the thread is left to end on its own (it sees the
    // abort flag as soon as the step returns) and its few bytes are not reclaimed.
    qWarning("camwright: the compute thread did not stop within %d ms; leaving it to finish",
             kStopTimeoutMs);
}

void ComputeEngine::setPlotDataPreparer(std::shared_ptr<const PlotDataPreparer> preparer) {
    m_worker->setPreparer(std::move(preparer));
}

void ComputeEngine::request(const Project& project, PlotAxis axis, bool timing,
                            TimingMethod plotMethod) {
    m_pending =
        ComputeRequest{++m_generation, std::make_shared<const Project>(project), axis, timing,
                       plotMethod,     PlotCurves::kFirstPictureBuckets};
    // Leading edge: a lone edit is computed at once. Edits that follow within the interval
    // are held and only the newest is submitted when it ends (trailing edge).
    if (!m_timer.isActive()) {
        submitPending();
        if (m_timer.interval() > 0) m_timer.start();
    }
}

void ComputeEngine::submitPending() {
    if (m_pending) m_worker->submit(std::move(*std::exchange(m_pending, std::nullopt)));
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
