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

/// The follower's rows after t, φ and segment: lift, velocity, acceleration, jerk, pressure
/// angle, radius of curvature; the polar rows after them are hidden.
constexpr int kFollowerRows = 6;
constexpr DisplayQuantity kFollowerQuantities[kFollowerRows] = {
    DisplayQuantity::Length, DisplayQuantity::Velocity, DisplayQuantity::Acceleration,
    DisplayQuantity::Jerk,   DisplayQuantity::Angle,    DisplayQuantity::Length};
constexpr DisplayQuantity kArmQuantities[kFollowerRows] = {DisplayQuantity::Angle,
                                                           DisplayQuantity::AngularVelocity,
                                                           DisplayQuantity::AngularAcceleration,
                                                           DisplayQuantity::AngularJerk,
                                                           DisplayQuantity::Angle,
                                                           DisplayQuantity::Length};

/// `value`, or 0 where it is below 10⁻⁷ of the largest magnitude its quantity reaches in the
/// turn (`span`), a tenth of the last of the six digits that largest value is shown with: the
/// round-off of a dwell (−2.3·10⁻⁶ mm/s beside 500 mm/s) is no velocity.
double withoutRoundOff(double value, double span) {
    return std::abs(value) <= 1e-7 * std::abs(span) ? 0.0 : value;
}

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

void StateReadout::setState(const KinematicState& s, const std::array<double, 4>& spans) {
    showNames(false, false);
    const PolarMotion& m = s.motion;
    const auto segment = static_cast<double>(s.segment);
    const double values[kKinematicRows] = {s.t,  0.0,    segment, s.polar.r, m.vR,   m.vPhi, m.v,
                                           m.aR, m.aPhi, m.a,     m.jR,      m.jPhi, m.j};
    // Each row's span: r's, then velocity, acceleration and jerk three rows each.
    for (int i = 2; i < kKinematicRows; ++i) {
        const double span = i == 2 ? 0.0 : spans[i == 3 ? 3 : static_cast<std::size_t>(i - 4) / 3];
        showValue(i, formatQuantity(kReadoutQuantities[i], withoutRoundOff(values[i], span)));
    }
    showInstant(s);
}

void StateReadout::setFollowerState(const KinematicState& s, const FollowerState& f,
                                    const std::array<double, 4>& lift, bool swinging,
                                    const std::array<double, 4>& spans) {
    showNames(true, swinging);
    showValue(2, formatQuantity(DisplayQuantity::Count, static_cast<double>(f.segment)));
    const DisplayQuantity* quantities = swinging ? kArmQuantities : kFollowerQuantities;
    const double values[kFollowerRows] = {
        lift[0], lift[1], lift[2], lift[3], radToDeg(f.pressureAngle), f.rhoProfile};
    for (int i = 0; i < kFollowerRows; ++i) {
        const double v =
            i < 4 ? withoutRoundOff(values[i], spans[static_cast<std::size_t>(i)]) : values[i];
        // A straight stretch of the profile has no finite radius of curvature.
        showValue(3 + i, std::isfinite(v) ? formatQuantity(quantities[i], v) : tr("∞ (straight)"));
    }
    showInstant(s);
}

void StateReadout::showInstant(const KinematicState& s) {
    // Where on the cam, 0 … 360°, whichever way it turns (s.phi = ω·t is negative when ω is).
    double phiDeg = mod360(radToDeg(s.phi));
    if (phiDeg >= 360.0) phiDeg = 0.0;  // −1e-17 reduces to 360 in floating point
    showValue(0, formatQuantity(DisplayQuantity::Time, s.t));
    showValue(1, formatQuantity(DisplayQuantity::Angle, phiDeg));
    // The boxes follow the cursor, but not over what the user is typing.
    m_updating = true;
    for (auto [box, v] : {std::pair{m_time, s.t}, std::pair{m_angle, phiDeg}}) {
        box->setEnabled(true);
        if (!(box->hasFocus() && box->isTyping())) box->setValue(v);
    }
    m_updating = false;
}

void StateReadout::showNames(bool follower, bool swinging) {
    const int shown = !follower ? 0 : swinging ? 2 : 1;
    if (shown == m_namesShown) return;
    m_namesShown = shown;
    const QString polar[kKinematicRows - 3] = {tr("r"),   tr("v_r"), tr("v_φ"), tr("|v|"),
                                               tr("a_r"), tr("a_φ"), tr("|a|"), tr("j_r"),
                                               tr("j_φ"), tr("|j|")};
    const QString polarTips[4] = {
        tr("The contour's radius along the ray at the cursor"),
        tr("Velocity of the contour point on the ray: radial, tangential and whole"),
        tr("Acceleration of the contour point on the ray: radial, tangential and whole"),
        tr("Jerk of the contour point on the ray: radial, tangential and whole")};
    const QString names[kFollowerRows] = {tr("s"), tr("v"), tr("a"), tr("j"), tr("α"), tr("ρ")};
    const QString armNames[kFollowerRows] = {tr("ψ"),    tr("ψ'"), tr("ψ''"),
                                             tr("ψ'''"), tr("α"),  tr("ρ")};
    const QString tips[kFollowerRows] = {
        swinging ? tr("The arm's swing away from the cam, from its closest position")
                 : tr("The follower's lift above its lowest position"),
        swinging ? tr("The arm's angular velocity, away from the cam positive")
                 : tr("The follower's velocity, rising positive"),
        swinging ? tr("The arm's angular acceleration") : tr("The follower's acceleration"),
        swinging ? tr("The arm's angular jerk") : tr("The follower's jerk"),
        tr("The pressure angle: between the contact normal and the follower's direction of "
           "motion, positive while it rises"),
        tr("The profile's radius of curvature at the contact: positive convex, negative "
           "concave")};
    m_names[2]->setToolTip(follower ? tr("The contour segment the follower touches")
                                    : tr("The contour segment the ray meets"));
    for (int i = 3; i < kKinematicRows; ++i) {
        const int k = i - 3;
        const bool used = !follower || k < kFollowerRows;
        m_names[i]->setVisible(used);
        m_values[i]->setVisible(used);
        if (!used) continue;
        m_names[i]->setText(!follower ? polar[k] : swinging ? armNames[k] : names[k]);
        m_names[i]->setToolTip(!follower ? polarTips[(k + 2) / 3] : tips[k]);
    }
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
