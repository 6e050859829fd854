#include "window/status_labels.h"

#include <QLabel>
#include <QStatusBar>
#include <QTimer>

#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "messages/diagnostic_text.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

constexpr int kBusyAfterMs = 400;
const char* const kProblemStyle = "color: #b00020;";

}  // namespace

StatusLabels::StatusLabels(QStatusBar* bar, const ProjectDocument* document,
                           const ComputeEngine* engine)
    : QObject(bar), m_bar(bar), m_document(document), m_engine(engine) {
    m_validation = new QLabel(bar);
    m_validation->setObjectName("validationLabel");
    m_compute = new QLabel(bar);
    m_compute->setObjectName("computeLabel");
    // Permanent widgets: transient messages ("Saved …") appear beside them, never over them.
    bar->addPermanentWidget(m_validation);
    bar->addPermanentWidget(m_compute);
    m_busy = new QTimer(this);
    m_busy->setSingleShot(true);
    m_busy->setInterval(kBusyAfterMs);
    connect(m_busy, &QTimer::timeout, this, [this] {
        const ComputeResultPtr& latest = m_engine->latestResult();
        if (latest && latest->generation == m_engine->latestGeneration()) return;
        m_compute->setStyleSheet({});
        m_compute->setText(tr("computing…"));
    });
}

void StatusLabels::showValidation() {
    const Diagnostics& d = m_document->diagnostics();
    const int n = static_cast<int>(m_document->project().contour.size());
    if (d.empty() && m_document->awaitsSynthesis()) {
        m_validation->setText(tr("Valid · no contour yet: Synthesize (F6) makes it"));
        m_validation->setToolTip({});
        m_validation->setStyleSheet({});
    } else if (d.empty()) {
        m_validation->setText(n == 1 ? tr("Valid · 1 segment") : tr("Valid · %1 segments").arg(n));
        m_validation->setToolTip({});
        m_validation->setStyleSheet({});
    } else {
        const QString first = diagnosticText(d.front());
        const QString count = d.size() == 1 ? tr("1 problem: ") : tr("%1 problems: ").arg(d.size());
        m_validation->setText(count +
                              m_validation->fontMetrics().elidedText(first, Qt::ElideRight, 600));
        m_validation->setToolTip(diagnosticsText(d, 40));
        m_validation->setStyleSheet(kProblemStyle);
    }
}

void StatusLabels::computing() { m_busy->start(); }

void StatusLabels::arrived() { m_busy->stop(); }

void StatusLabels::showUncomputed(const ComputeResult& result) {
    const QString first = diagnosticText(result.errors.front());
    // The problems themselves are in the validation label beside it.
    m_compute->setText(result.failed() ? tr("not computed: %1").arg(first)
                       : m_document->awaitsSynthesis()
                           ? tr("no contour yet")
                           : tr("not computed: the project has problems"));
    m_compute->setStyleSheet(kProblemStyle);
    if (result.failed()) m_bar->showMessage(tr("Computation failed: %1").arg(first));
}

void StatusLabels::showComputed(const ComputeResult& result) {
    m_compute->setStyleSheet({});
    m_compute->setText(
        tr("%1 samples computed in %2")
            .arg(formatQuantity(DisplayQuantity::Count, static_cast<double>(result.sampleCount)),
                 formatQuantity(DisplayQuantity::Duration, result.computeMs)));
}

}  // namespace cam
