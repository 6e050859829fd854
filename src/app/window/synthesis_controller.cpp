#include "window/synthesis_controller.h"

#include <QAction>
#include <QMessageBox>
#include <QProgressDialog>
#include <utility>

#include "document/commands.h"
#include "document/project_document.h"
#include "engine/synthesis_runner.h"
#include "messages/diagnostic_text.h"
#include "views/motion_design_panel.h"
#include "widgets/quantity_format.h"

namespace cam {

SynthesisController::SynthesisController(ProjectDocument* document, MotionDesignPanel* panel,
                                         QWidget* window)
    : QObject(window), m_document(document), m_panel(panel), m_window(window) {
    m_action = new QAction(tr("S&ynthesize Contour"), window);
    m_action->setObjectName("actionSynthesize");
    m_action->setShortcut(QKeySequence(Qt::Key_F6));
    m_action->setToolTip(
        tr("Replace the contour by tangent arcs fitted to the design's exact profile within "
           "its tolerance (F6; one undo step)"));
    panel->setSynthesizeAction(m_action);
    m_runner = new SynthesisRunner(this);
    connect(m_document, &ProjectDocument::designChanged, this, &SynthesisController::enable);
    connect(m_action, &QAction::triggered, this, [this] {
        m_interactive = true;
        start();
    });
    connect(m_runner, &SynthesisRunner::finished, this, &SynthesisController::finish);
    connect(m_runner, &SynthesisRunner::finished, this, &SynthesisController::enable);
    enable();
}

void SynthesisController::enable() {
    m_action->setEnabled(m_document->project().design.has_value() && !m_runner->isRunning());
}

bool SynthesisController::start() {
    const auto& design = m_document->project().design;
    if (!design || m_runner->isRunning()) return false;
    m_clock.start();
    m_runner->start(m_document->project(), design->tolerance);
    m_action->setEnabled(false);
    emit message(tr("Synthesizing the contour…"), 0);
    // Most designs take milliseconds; a fine tolerance or a swinging arm may take longer, and
    // then a busy dialog offers Cancel.
    m_progress = new QProgressDialog(tr("Synthesizing the contour from the design…"), tr("Cancel"),
                                     0, 0, m_window);
    m_progress->setObjectName("synthesisProgress");
    m_progress->setWindowTitle(tr("Synthesize"));
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(300);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    connect(m_progress, &QProgressDialog::canceled, this, &SynthesisController::cancel);
    m_progress->setValue(0);
    return true;
}

void SynthesisController::cancel() { m_runner->cancel(); }

void SynthesisController::finish(const std::shared_ptr<const Result<Synthesis>>& result,
                                 bool cancelled) {
    const bool interactive = std::exchange(m_interactive, false);
    if (m_progress) {
        m_progress->disconnect(this);
        m_progress->reset();
        m_progress->deleteLater();
        m_progress = nullptr;
    }
    QString problem;
    const Project& from = m_runner->startedFrom();
    const Project& now = m_document->project();
    if (cancelled) {
        problem = tr("Synthesis cancelled: the contour is unchanged.");
    } else if (from.design != now.design || from.follower != now.follower ||
               from.motion != now.motion) {
        // Made for a design that is no longer the project's: never applied.
        problem =
            tr("The design, follower or speed changed while synthesizing: press "
               "Synthesize again.");
    } else if (!result->ok()) {
        problem = tr("The contour cannot be made from this design:\n%1")
                      .arg(diagnosticsText(result->errors()));
    }
    if (!problem.isEmpty()) {
        emit message(problem.section('\n', 0, 0), 8000);
        if (interactive && !cancelled) QMessageBox::warning(m_window, tr("Synthesize"), problem);
        emit finished(problem);
        return;
    }
    const Synthesis& made = result->value();
    if (made.contour == now.contour) {
        // The same arcs again: nothing to undo.
        m_panel->setReport(made.report, now);
        emit message(tr("Synthesized: the contour already is this design's."), 6000);
        emit finished({});
        return;
    }
    m_document->undoStack()->push(
        new SynthesizeContour(m_document, made.contour, from.design->tolerance));
    m_panel->setReport(made.report, m_document->project());
    emit message(tr("Synthesized %n segment(s) within %1 in %2", nullptr,
                    static_cast<int>(made.report.segments))
                     .arg(formatQuantity(DisplayQuantity::LengthError, made.report.maxDeviationMm),
                          formatQuantity(DisplayQuantity::Duration,
                                         static_cast<double>(m_clock.nsecsElapsed()) / 1e6)),
                 8000);
    emit finished({});
}

}  // namespace cam
