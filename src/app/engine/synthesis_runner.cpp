#include "engine/synthesis_runner.h"

#include <QtConcurrent/QtConcurrentRun>

#include "engine/background_priority.h"

namespace cam {

SynthesisRunner::SynthesisRunner(QObject* parent)
    : QObject(parent), m_project(std::make_shared<const Project>()) {
    connect(&m_watcher, &QFutureWatcherBase::finished, this, [this] {
        const bool cancelled = m_cancel->load();
        auto result = m_watcher.result();
        // Cancelled, or nothing to show (synthesize returns empty errors when cancelled).
        emit finished(result, cancelled || !result);
    });
}

SynthesisRunner::~SynthesisRunner() {
    if (m_cancel) m_cancel->store(true);
    m_watcher.waitForFinished();
}

bool SynthesisRunner::start(const Project& project, double tolerance) {
    if (m_watcher.isRunning()) return false;
    m_project = std::make_shared<const Project>(project);
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    m_watcher.setFuture(
        QtConcurrent::run([project = m_project, cancel = m_cancel,
                           tolerance]() -> std::shared_ptr<const Result<Synthesis>> {
            runInTheBackground();
            try {
                auto made = synthesize(*project, tolerance, false, cancel.get());
                if (cancel->load()) return nullptr;
                return std::make_shared<const Result<Synthesis>>(std::move(made));
            } catch (const std::exception& e) {
                // Nothing a run meets ends the program (e.g. std::bad_alloc): it says why.
                return std::make_shared<const Result<Synthesis>>(
                    Diagnostics{{"design", std::string("synthesis failed: ") + e.what()}});
            }
        }));
    return true;
}

void SynthesisRunner::cancel() {
    if (m_cancel) m_cancel->store(true);
}

}  // namespace cam
