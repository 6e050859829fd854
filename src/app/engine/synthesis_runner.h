#pragma once
/// @file
/// @brief Synthesize off the GUI thread: a snapshot of the project goes to the thread pool,
/// the arc table (or why it cannot be made) comes back; Cancel stops it within milliseconds.

#include <QFutureWatcher>
#include <QObject>
#include <atomic>
#include <memory>

#include "design/synthesis.h"

namespace cam {

class SynthesisRunner : public QObject {
    Q_OBJECT
public:
    explicit SynthesisRunner(QObject* parent = nullptr);
    /// Cancels a run and waits for it (it polls its flag: milliseconds).
    ~SynthesisRunner() override;

    /// @brief Starts synthesising `project` (a copy is taken); false while a run is going on.
    bool start(const Project& project, double tolerance);
    /// @brief Asks the run to stop; finished() then reports it cancelled.
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_watcher.isRunning(); }
    /// @brief The project the current or last run started from.
    [[nodiscard]] const Project& startedFrom() const { return *m_project; }

signals:
    /// The run ended: `cancelled`, or the result (its errors say why it cannot be made).
    void finished(const std::shared_ptr<const Result<Synthesis>>& result, bool cancelled);

private:
    std::shared_ptr<const Project> m_project;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    QFutureWatcher<std::shared_ptr<const Result<Synthesis>>> m_watcher;
};

}  // namespace cam
