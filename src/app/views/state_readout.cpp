#include "views/state_readout.h"

#include <QGridLayout>
#include <QLabel>
#include <QLocale>

#include "common/angles.h"
#include "widgets/number_format.h"

namespace cam {

StateReadout::StateReadout(QWidget* parent) : QWidget(parent) {
    auto* grid = new QGridLayout(this);
    grid->setVerticalSpacing(2);
    const QString names[kRows] = {tr("t"),   tr("φ"),   tr("segment"), tr("r"),   tr("v_r"),
                                  tr("v_φ"), tr("|v|"), tr("a_r"),     tr("a_φ"), tr("|a|"),
                                  tr("j_r"), tr("j_φ"), tr("|j|")};
    for (int i = 0; i < kRows; ++i) {
        m_names[i] = new QLabel(names[i], this);
        m_values[i] = new QLabel(QStringLiteral("—"), this);
        m_values[i]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_values[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_values[i]->setMinimumWidth(fontMetrics().horizontalAdvance("-0000000.000 mm/s²"));
        grid->addWidget(m_names[i], i, 0);
        grid->addWidget(m_values[i], i, 1);
    }
    grid->setRowStretch(kRows, 1);
    setToolTip(tr("State of the follower at the cursor: move the mouse over a plot"));
}

void StateReadout::setState(const KinematicState& s) {
    auto num = [&](double v, const QString& unit) {
        return formatNumber(v, 8) + QStringLiteral(" ") + unit;
    };
    const PolarMotion& m = s.motion;
    // Where on the cam, 0 … 360°, whichever way it turns (s.phi = ω·t is negative clockwise).
    double phiDeg = mod360(radToDeg(s.phi));
    if (phiDeg >= 360.0) phiDeg = 0.0;  // −1e-17 reduces to 360 in floating point
    const QString values[kRows] = {
        num(s.t, "s"),        num(phiDeg, "°"),    QString::number(s.segment), num(s.polar.r, "mm"),
        num(m.vR, "mm/s"),    num(m.vPhi, "mm/s"), num(m.v, "mm/s"),           num(m.aR, "mm/s²"),
        num(m.aPhi, "mm/s²"), num(m.a, "mm/s²"),   num(m.jR, "mm/s³"),         num(m.jPhi, "mm/s³"),
        num(m.j, "mm/s³")};
    for (int i = 0; i < kRows; ++i) m_values[i]->setText(values[i]);
}

void StateReadout::clear() {
    for (QLabel* l : m_values) l->setText(QStringLiteral("—"));
}

QString StateReadout::text() const {
    QStringList lines;
    for (int i = 0; i < kRows; ++i) lines << m_names[i]->text() + " " + m_values[i]->text();
    return lines.join('\n');
}

}  // namespace cam
