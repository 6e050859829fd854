#include "views/motion_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <cmath>

#include "common/angles.h"
#include "document/commands.h"
#include "models/delegates.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {

MotionPanel::MotionPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* form = new QFormLayout(this);
    m_speed = new NumberSpinBox(this);
    m_speed->setObjectName("speedSpinBox");
    m_speed->setToolTip(
        tr("Turning speed; a positive speed turns the cam clockwise under its follower, a negative "
           "one counter-clockwise (the Follower dock pictures the "
           "direction: a click there turns the cam round)"));
    m_unit = new QComboBox(this);
    m_unit->setObjectName("speedUnitComboBox");
    m_unit->addItems({tr("rad/s"), tr("rpm"), tr("period [s]")});
    m_unit->setToolTip(tr("The speed's unit; changing it keeps the physical speed"));
    m_samples = new QSpinBox(this);
    m_samples->setObjectName("samplesSpinBox");
    m_samples->setRange(static_cast<int>(kMinSamplesPerTurn), static_cast<int>(kMaxSamplesPerTurn));
    m_samples->setSingleStep(1000);
    m_samples->setToolTip(tr("Samples per turn for the plots and exports"));
    m_summary = new QLabel(this);
    m_summary->setObjectName("motionSummary");
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);  // never squeezed by its dock
    form->addRow(tr("Speed"), m_speed);
    form->addRow(tr("Unit"), m_unit);
    form->addRow(tr("Samples / turn"), m_samples);
    form->addRow(m_summary);

    connect(m_speed, &QDoubleSpinBox::valueChanged, this, [this] {
        if (m_refreshing) return;
        if (m_gesture == 0) m_gesture = nextGestureId();
        pushSpeed();
    });
    connect(m_speed, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
    connect(m_unit, &QComboBox::activated, this, [this](int index) {
        // Keep the physical speed: convert the value into the new unit.
        const double omega = m_document->project().motion.omegaRadS();
        MotionSpec m;
        m.unit = static_cast<SpeedUnit>(index);
        m.value = m.unit == SpeedUnit::OmegaRadS ? omega
                  : m.unit == SpeedUnit::Rpm     ? omega * 60.0 / kTwoPi
                                                 : kTwoPi / std::abs(omega);
        m_document->undoStack()->push(new SetMotion(m_document, m));
    });
    connect(m_samples, &QSpinBox::editingFinished, this, [this] {
        if (m_refreshing || m_samples->value() == m_document->project().samplesPerTurnOrDefault()) {
            return;
        }
        m_document->undoStack()->push(new SetSamplesPerTurn(m_document, m_samples->value()));
    });
    connect(document, &ProjectDocument::motionChanged, this, &MotionPanel::refresh);
    refresh();
}

void MotionPanel::pushSpeed() {
    MotionSpec m = m_document->project().motion;
    m.value = m_speed->value();
    if (m == m_document->project().motion) return;
    m_document->undoStack()->push(new SetMotion(m_document, m, m_gesture));
}

void MotionPanel::refresh() {
    m_refreshing = true;
    const MotionSpec& m = m_document->project().motion;
    m_unit->setCurrentIndex(static_cast<int>(m.unit));
    if (m_speed->value() != m.value) m_speed->setValue(m.value);
    m_samples->setValue(static_cast<int>(m_document->project().samplesPerTurnOrDefault()));
    const bool valid = std::isfinite(m.value) && m.value != 0.0 &&
                       !(m.unit == SpeedUnit::PeriodS && m.value < 0.0);
    if (valid) {
        const double omega = m.omegaRadS();
        m_summary->setText(
            tr("ω = %1 · %2\nT = %3")
                .arg(formatQuantity(DisplayQuantity::AngularSpeed, omega),
                     formatQuantity(DisplayQuantity::RotationSpeed, omega * 60.0 / kTwoPi),
                     formatQuantity(DisplayQuantity::Time, kTwoPi / std::abs(omega))));
    } else {
        m_summary->setText(tr("The speed must not be 0 (and a period must be positive)."));
    }
    m_refreshing = false;
}

}  // namespace cam
