#include "views/state_readout.h"

#include <QGridLayout>
#include <QLabel>
#include <cmath>

#include "common/angles.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

/// What each row of the readout shows, in its order.
constexpr DisplayQuantity kReadoutQuantities[] = {
    DisplayQuantity::Time,         DisplayQuantity::Angle,        DisplayQuantity::Count,
    DisplayQuantity::Length,       DisplayQuantity::Velocity,     DisplayQuantity::Velocity,
    DisplayQuantity::Velocity,     DisplayQuantity::Acceleration, DisplayQuantity::Acceleration,
    DisplayQuantity::Acceleration, DisplayQuantity::Jerk,         DisplayQuantity::Jerk,
    DisplayQuantity::Jerk,         DisplayQuantity::Force,        DisplayQuantity::Force,
    DisplayQuantity::Moment,       DisplayQuantity::Power,        DisplayQuantity::Stress};

}  // namespace

StateReadout::StateReadout(QWidget* parent) : QWidget(parent) {
    static_assert(std::size(kReadoutQuantities) == kRows);
    auto* grid = new QGridLayout(this);
    grid->setVerticalSpacing(2);
    const QString names[kRows] = {tr("t"),   tr("φ"),   tr("segment"), tr("r"),   tr("v_r"),
                                  tr("v_φ"), tr("|v|"), tr("a_r"),     tr("a_φ"), tr("|a|"),
                                  tr("j_r"), tr("j_φ"), tr("|j|"),     tr("F_n"), tr("F"),
                                  tr("T"),   tr("P"),   tr("p_H")};
    const QString tips[kRows - kKinematicRows] = {
        tr("Contact normal force"), tr("Load along the follower's line of motion"),
        tr("Torque on the camshaft"), tr("Power on the camshaft"), tr("Hertz contact stress")};
    // t and φ are typed into: Enter (or a step with the arrow keys) puts the cursor there.
    const auto typed = [this](const char* name, DisplayQuantity quantity, const QString& suffix,
                              double low, const QString& tip) {
        auto* box = new NumberSpinBox(this);
        box->setObjectName(name);
        // The readout's digits, and room for its widest value as the other rows have.
        box->setSignificantDigits(quantityFormat(quantity).significant);
        box->setMinimumWidth(
            fontMetrics().horizontalAdvance(formatQuantity(quantity, -8.888888888888e-4)) + 6);
        box->setSuffix(suffix);
        box->setRange(low, 1e9);
        box->setKeyboardTracking(false);
        box->setButtonSymbols(QAbstractSpinBox::NoButtons);
        // No frame: a white field no taller than the readout's lines, so that the dock (and
        // the smallest window) keeps its height.
        box->setFrame(false);
        box->setFixedHeight(fontMetrics().height());
        box->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        box->setToolTip(tip);
        box->setEnabled(false);
        return box;
    };
    m_time = typed("cursorTimeBox", DisplayQuantity::Time, tr(" s"), 0.0,
                   tr("The cursor's time in the turn: type one and press Enter to go there "
                      "(Up/Down: one sample)"));
    m_angle = typed("cursorAngleBox", DisplayQuantity::Angle, tr("°"), -1e9,
                    tr("The cam's angle at the cursor, 0–360° whichever way it turns: type one "
                       "and press Enter to go there (Up/Down: one sample)"));
    connect(m_time, &QDoubleSpinBox::valueChanged, this, [this](double t) {
        if (!m_updating) emit timeTyped(t);
    });
    connect(m_angle, &QDoubleSpinBox::valueChanged, this, [this](double deg) {
        if (!m_updating) emit angleTyped(deg);
    });
    for (int i = 0; i < kRows; ++i) {
        m_names[i] = new QLabel(names[i], this);
        if (i == 0 || i == 1) {
            NumberSpinBox* box = i == 0 ? m_time : m_angle;
            m_names[i]->setBuddy(box);
            grid->addWidget(m_names[i], i, 0);
            grid->addWidget(box, i, 1, Qt::AlignRight);
            continue;
        }
        m_values[i] = new QLabel(QStringLiteral("—"), this);
        m_values[i]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_values[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // The widest value short of an exponent or of 10¹¹: negative, below 1 with three zeros
        // after the point and all of its digits ("-0.0008888889 mm"); a wider one widens the
        // column (showValue()). A fixed size: a new text asks for no layout pass (0.5 ms for the
        // readout's thirteen labels on every edit and cursor move).
        m_values[i]->setFixedSize(fontMetrics().horizontalAdvance(
                                      formatQuantity(kReadoutQuantities[i], -8.888888888888e-4)),
                                  m_values[i]->sizeHint().height());
        grid->addWidget(m_names[i], i, 0);
        grid->addWidget(m_values[i], i, 1, Qt::AlignRight);
        if (i >= kKinematicRows) {
            m_names[i]->setToolTip(tips[i - kKinematicRows]);
            m_names[i]->hide();
            m_values[i]->hide();
        }
    }
    grid->setRowStretch(kRows, 1);
    setToolTip(
        tr("The state at the cursor: move the mouse over a plot, type a time or an angle, or "
           "step with the arrow keys in a plot (Shift: to the next joint; Home, End)"));
}

void StateReadout::setState(const KinematicState& s) {
    const PolarMotion& m = s.motion;
    // Where on the cam, 0 … 360°, whichever way it turns (s.phi = ω·t is negative clockwise).
    double phiDeg = mod360(radToDeg(s.phi));
    if (phiDeg >= 360.0) phiDeg = 0.0;  // −1e-17 reduces to 360 in floating point
    const auto segment = static_cast<double>(s.segment);
    const double values[kRows] = {s.t,  phiDeg, segment, s.polar.r, m.vR,   m.vPhi, m.v,
                                  m.aR, m.aPhi, m.a,     m.jR,      m.jPhi, m.j};
    for (int i = 0; i < kKinematicRows; ++i) {
        showValue(i, formatQuantity(kReadoutQuantities[i], values[i]));
    }
    // The boxes follow the cursor, but not over what the user is typing.
    m_updating = true;
    for (auto [box, v] : {std::pair{m_time, s.t}, std::pair{m_angle, phiDeg}}) {
        box->setEnabled(true);
        if (!(box->hasFocus() && box->isTyping())) box->setValue(v);
    }
    m_updating = false;
}

void StateReadout::setSteps(double timeStep, double angleStep) {
    m_time->setSingleStep(timeStep);
    m_angle->setSingleStep(angleStep);
}

void StateReadout::setForces(const std::optional<ForcePoint>& f, bool swinging) {
    for (int i = kKinematicRows; i < kRows; ++i) {
        m_names[i]->setVisible(f.has_value());
        m_values[i]->setVisible(f.has_value());
    }
    if (!f) return;
    const int load = kKinematicRows + 1;
    m_names[load]->setText(swinging ? tr("M") : tr("F"));
    m_names[load]->setToolTip(swinging ? tr("The arm's moment about its pivot")
                                       : tr("Load along the follower's line of motion"));
    const double values[] = {f->normal, f->load, f->torque, f->power, f->stress};
    for (int i = kKinematicRows; i < kRows; ++i) {
        const double v = values[i - kKinematicRows];
        const DisplayQuantity q =
            i == load && swinging ? DisplayQuantity::Moment : kReadoutQuantities[i];
        showValue(i, std::isfinite(v) ? formatQuantity(q, v) : QStringLiteral("—"));
    }
}

void StateReadout::clear() {
    for (int i = 0; i < kRows; ++i) showValue(i, QStringLiteral("—"));
    m_time->setEnabled(false);
    m_angle->setEnabled(false);
}

void StateReadout::showValue(int row, const QString& text) {
    m_texts[static_cast<std::size_t>(row)] = text;
    QLabel* label = m_values[static_cast<std::size_t>(row)];
    if (!label) return;  // t and φ: their boxes
    const int needed = label->fontMetrics().horizontalAdvance(text);
    if (needed > label->width()) label->setFixedWidth(needed);
    label->setText(text);
}

QString StateReadout::text() const {
    QStringList lines;
    for (int i = 0; i < kRows; ++i) {
        if (!m_names[i]->isHidden()) lines << m_names[i]->text() + " " + m_texts[i];
    }
    return lines.join('\n');
}

}  // namespace cam
