#pragma once
/// @file
/// @brief Synthesize (F6): the contour made from the motion design in a worker, with a busy
/// dialog offering Cancel when it takes long, applied as one undo step only if the design,
/// follower and speed are still the ones it was made for.

#include <QElapsedTimer>
#include <QObject>
#include <memory>

#include "common/diagnostic.h"
#include "design/synthesis.h"

class QAction;
class QProgressDialog;
class QWidget;

namespace cam {

class MotionDesignPanel;
class ProjectDocument;
class SynthesisRunner;

class SynthesisController : public QObject {
    Q_OBJECT
public:
    SynthesisController(ProjectDocument* document, MotionDesignPanel* panel, QWidget* window);

    [[nodiscard]] QAction* action() const { return m_action; }
    /// @brief Starts synthesising; false when there is no design or a synthesis is running.
    /// Its end is reported by finished().
    bool start();
    /// @brief Cancels a running synthesis.
    void cancel();

signals:
    /// A synthesis ended: `problem` is empty when the contour was replaced (one undo step).
    void finished(const QString& problem);
    /// What the status bar says of it.
    void message(const QString& text, int timeoutMs);

private:
    void finish(const std::shared_ptr<const Result<Synthesis>>& result, bool cancelled);
    void enable();

    ProjectDocument* m_document;
    MotionDesignPanel* m_panel;
    QWidget* m_window;
    QAction* m_action;
    SynthesisRunner* m_runner;
    QProgressDialog* m_progress = nullptr;
    QElapsedTimer m_clock;
    /// Started from the action (not a test's call): a problem is shown in a message box.
    bool m_interactive = false;
};

}  // namespace cam
