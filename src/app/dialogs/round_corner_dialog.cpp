#include "dialogs/round_corner_dialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

/// Whether the corner at `joint` is concave: its switch arc takes the inner branch (fillet.h).
bool concaveCorner(const Project& project, std::size_t joint, const FilletRange& range) {
    const auto probe = filletJoint(project.contour, joint, 0.5 * range.maxRadius);
    if (!probe.ok()) return false;
    const std::vector<SegmentSpec>& contour = probe.value().contour;
    const std::size_t at = joint == 0 ? contour.size() - 1 : joint;
    const Arc* arc = contour[at].as<Arc>();
    return arc && arc->branch == Branch::Inner;
}

NumberSpinBox* box(QWidget* parent, const char* name, const QString& suffix, double value,
                   const QString& tip) {
    auto* b = new NumberSpinBox(parent);
    b->setObjectName(name);
    b->setSuffix(suffix);
    b->setRange(0.0, 1e9);
    b->setValue(value);
    b->setToolTip(tip);
    return b;
}

}  // namespace

RoundCornerDialog::RoundCornerDialog(const Project& project, std::size_t joint,
                                     const FilletRange& range, QWidget* parent)
    : QDialog(parent), m_range(range) {
    setWindowTitle(tr("Round Corner"));
    setObjectName("roundCornerDialog");
    if (project.machining && project.machining->toolRadius > 0.0 &&
        concaveCorner(project, joint, range)) {
        m_cutter = project.machining->toolRadius;
    }
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    const double start = m_cutter ? std::min(1.5 * *m_cutter, 0.5 * (*m_cutter + range.maxRadius))
                                  : std::min(range.maxRadius / 2.0, 5.0);
    m_radius = box(this, "radiusSpinBox", QStringLiteral(" mm"), start,
                   tr("The switch arc's radius: tangent to both neighbours"));
    m_radius->setRange(range.minRadius, range.maxRadius);
    form->addRow(tr("Radius"), m_radius);
    auto* fits = new QLabel(tr("Below %1 fits this corner.")
                                .arg(formatQuantity(DisplayQuantity::Length, range.maxRadius)),
                            this);
    fits->setObjectName("fitsLabel");
    form->addRow(fits);
    if (m_cutter) {
        auto* cutter = new QLabel(
            tr("The corner is concave: a switch arc smaller than the cutter's radius (%1) "
               "cannot be cut.")
                .arg(formatQuantity(DisplayQuantity::Length, *m_cutter)),
            this);
        cutter->setObjectName("cutterLabel");
        cutter->setWordWrap(true);
        form->addRow(cutter);
    }
    layout->addLayout(form);

    // The seed's radius from the speed at the joint (math.md §5), started from the project's
    // machining limits and remembered from the last time.
    auto* speedGroup = new QGroupBox(tr("From the speed at the joint"), this);
    auto* speedForm = new QFormLayout(speedGroup);
    QSettings settings;
    const MachiningSpec machining = project.machining.value_or(MachiningSpec{});
    const double accel = std::min(machining.axisAccel.at(0), machining.axisAccel.at(1));
    m_speed = box(this, "speedSpinBox", QStringLiteral(" mm/s"),
                  settings.value("roundCorner/speed", machining.feedMax).toDouble(),
                  tr("The speed V through the corner (the project's feed limit to start with)"));
    m_accel = box(this, "accelSpinBox", QStringLiteral(" mm/s²"),
                  settings.value("roundCorner/accel", accel).toDouble(),
                  tr("The vector acceleration ACv the machine allows (the smaller of the "
                     "project's x and y limits to start with)"));
    m_vae = box(this, "vaeSpinBox", QString(), settings.value("roundCorner/vae", 0.1).toDouble(),
                tr("The admissible acceleration error vae, a fraction (0.1: 10 %)"));
    speedForm->addRow(tr("Speed V"), m_speed);
    speedForm->addRow(tr("Acceleration ACv"), m_accel);
    speedForm->addRow(tr("Admissible error vae"), m_vae);
    m_speedResult = new QLabel(this);
    m_speedResult->setObjectName("speedRadiusLabel");
    auto* use = new QPushButton(tr("Use This Radius"), this);
    use->setObjectName("useSpeedRadius");
    speedForm->addRow(m_speedResult, use);
    layout->addWidget(speedGroup);

    m_verdict = new QLabel(this);
    m_verdict->setObjectName("verdictLabel");
    m_verdict->setWordWrap(true);
    layout->addWidget(m_verdict);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, [this] {
        QSettings s;
        s.setValue("roundCorner/speed", m_speed->value());
        s.setValue("roundCorner/accel", m_accel->value());
        s.setValue("roundCorner/vae", m_vae->value());
        accept();
    });
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(use, &QPushButton::clicked, this, [this] {
        const double rho = speedRadius();
        if (std::isfinite(rho)) m_radius->setValue(rho);
    });
    for (NumberSpinBox* b : {m_radius, m_speed, m_accel, m_vae}) {
        connect(b, &QDoubleSpinBox::valueChanged, this, &RoundCornerDialog::check);
    }
    check();
}

double RoundCornerDialog::radius() const {
    m_radius->interpretText();
    return m_radius->value();
}

double RoundCornerDialog::speedRadius() const {
    return minimumSwitchRadius(m_speed->value(), m_accel->value(), m_vae->value());
}

void RoundCornerDialog::check() {
    const double rho = speedRadius();
    const QString length =
        std::isfinite(rho) ? formatQuantity(DisplayQuantity::Length, rho) : QStringLiteral("—");
    m_speedResult->setText(tr("ρ_min = V² / (vae · ACv) = %1").arg(length));
    const double r = m_radius->value();
    QString problem;
    if (m_cutter && r <= *m_cutter) {
        problem = tr("%1 is not larger than the cutter's radius %2: the cutter cannot follow it.")
                      .arg(formatQuantity(DisplayQuantity::Length, r),
                           formatQuantity(DisplayQuantity::Length, *m_cutter));
    } else if (!(r < m_range.maxRadius)) {
        problem = tr("%1 does not fit: below %2 does.")
                      .arg(formatQuantity(DisplayQuantity::Length, r),
                           formatQuantity(DisplayQuantity::Length, m_range.maxRadius));
    }
    QString note;
    if (problem.isEmpty() && std::isfinite(rho) && r < rho) {
        note = tr("Below the speed's %1: the acceleration through the arc exceeds the machine's "
                  "by more than vae.")
                   .arg(length);
    }
    m_verdict->setText(problem.isEmpty() ? note : problem);
    m_verdict->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #b00000"));
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

}  // namespace cam
