#pragma once
/// @file
/// @brief The compute engine: snapshots in, results out, in a worker thread; newest wins.

#include <QMutex>
#include <QObject>
#include <QThread>
#include <QTimer>
#include <QWaitCondition>
#include <atomic>
#include <memory>

#include "engine/compute_result.h"
#include "engine/plot_data_preparer.h"

namespace cam {

/// @brief The worker thread. Holds at most one pending request; a new one cancels the
/// computation in progress. Never touches anything of the GUI. Nothing it runs can end the
/// program: an exception (e.g. std::bad_alloc) becomes a failed result with its message.
class ComputeWorker : public QThread {
    Q_OBJECT
public:
    explicit ComputeWorker(QObject* parent = nullptr);
    /// Stops the thread, waiting as long as it takes (see stop() for a bounded wait).
    ~ComputeWorker() override;

    /// @brief Replaces the pending request (thread-safe) and cancels the current computation.
    void submit(ComputeRequest request);
    /// @brief Used for every following request (thread-safe); null: results carry no
    /// prepared plot data.
    void setPreparer(std::shared_ptr<const PlotDataPreparer> preparer);
    /// @brief Cancels the computation, ends the loop and waits at most `timeoutMs` for the
    /// thread to finish. Returns whether it finished.
    bool stop(int timeoutMs);

signals:
    void finished(cam::ComputeResultPtr result);
    void timingFinished(cam::TimingOutcomePtr outcome);

protected:
    void run() override;

private:
    void computeTimingOf(const ComputeRequest& request, const ComputeResult& result,
                         const PlotDataPreparer* preparer);

    QMutex m_mutex;
    QWaitCondition m_wake;
    std::optional<ComputeRequest> m_pending;
    std::shared_ptr<const PlotDataPreparer> m_preparer;
    std::atomic<bool> m_cancel{false};
    bool m_abort = false;
};

/// @brief Lives in the GUI thread. request() never blocks. A lone request is submitted at once;
/// requests that follow within the coalescing interval are held, and only the newest of them is
/// submitted when it ends. Results that answer an older request than the newest are dropped, so
/// a stale result is never shown.
class ComputeEngine : public QObject {
    Q_OBJECT
public:
    explicit ComputeEngine(QObject* parent = nullptr);
    ~ComputeEngine() override;

    /// @brief Asks for the project as it is now (a copy is taken). With `timing`, the machining
    /// times follow the kinematics (if the project has machining limits).
    void request(const Project& project, PlotAxis axis, bool timing = false,
                 TimingMethod plotMethod = TimingMethod::Optimal);
    /// @brief Milliseconds that a burst of requests is coalesced over (0: submit at once).
    void setCoalesceMs(int ms) { m_timer.setInterval(ms); }
    /// @brief The views' preparer, run in the worker on every following result (see
    /// PlotDataPreparer).
    void setPlotDataPreparer(std::shared_ptr<const PlotDataPreparer> preparer);

    /// How long the destructor waits for a computation to notice its cancellation. Everything
    /// the worker runs polls the flag, so it normally ends within milliseconds; should some
    /// step not, the thread is abandoned (it ends on its own) rather than hanging the caller.
    static constexpr int kStopTimeoutMs = 1000;

    [[nodiscard]] std::uint64_t latestGeneration() const { return m_generation; }
    [[nodiscard]] const ComputeResultPtr& latestResult() const { return m_latest; }
    [[nodiscard]] int droppedResults() const { return m_dropped; }
    [[nodiscard]] const TimingOutcomePtr& latestTiming() const { return m_latestTiming; }

signals:
    /// A result for the newest request.
    void resultReady(const cam::ComputeResultPtr& result);
    /// Machining times for the newest request.
    void timingReady(const cam::TimingOutcomePtr& outcome);

private:
    void submitPending();
    void onFinished(const ComputeResultPtr& result);

    ComputeWorker* m_worker;  ///< owned; abandoned instead of deleted if it does not stop
    QTimer m_timer;
    std::optional<ComputeRequest> m_pending;
    std::uint64_t m_generation = 0;
    ComputeResultPtr m_latest;
    TimingOutcomePtr m_latestTiming;
    int m_dropped = 0;
};

}  // namespace cam
