#include "views/turning_picture.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "widgets/quantity_format.h"

namespace cam {

TurningPicture::TurningPicture(QWidget* parent) : QAbstractButton(parent) {
    setObjectName("turningPicture");
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    setCheckable(true);
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::PointingHandCursor);
}

bool turnsClockwise(const MotionSpec& motion) {
    return motion.unit == SpeedUnit::PeriodS || motion.value > 0.0;
}

void TurningPicture::show(bool clockwise, const std::optional<FollowerSpec>& follower) {
    m_clockwise = clockwise;
    m_follower = follower;
    setChecked(clockwise);
    const bool arm = follower && follower->motion == FollowerMotion::Oscillating;
    const double e = follower && !arm ? follower->offset : 0.0;
    setToolTip(
        (clockwise ? tr("The cam turns clockwise, seen from the front (the drawing); click to "
                        "turn it counter-clockwise.")
                   : tr("The cam turns counter-clockwise, seen from the front (the drawing); "
                        "click to turn it clockwise.")) +
        tr(" A period has no sign: counter-clockwise writes the speed in rpm.") +
        (arm        ? QString()
         : e == 0.0 ? tr(" The follower's line of motion passes through the cam's centre.")
         : e > 0.0  ? tr(" The follower's line is offset %1 mm to the left of its direction "
                          "(positive e): this lowers the pressure angle of the rise when the cam "
                          "turns clockwise and raises it when it turns counter-clockwise.")
                         .arg(formatQuantityValue(DisplayQuantity::Length, e))
                   : tr(" The follower's line is offset %1 mm to the right of its direction "
                        "(negative e): this lowers the pressure angle of the rise when the cam "
                        "turns counter-clockwise and raises it when it turns clockwise.")
                         .arg(formatQuantityValue(DisplayQuantity::Length, -e))));
    update();
}

void TurningPicture::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor ink =
        palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText);
    // A button's frame: faint, stronger under the mouse or with the focus.
    p.setPen(QPen(hasFocus() || underMouse() ? palette().color(QPalette::Highlight)
                                             : palette().color(QPalette::Mid),
                  1.0));
    p.setBrush(isDown() ? palette().color(QPalette::Midlight) : palette().color(QPalette::Button));
    p.drawRoundedRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5), 3.0, 3.0);
    const QPointF c(30.0, height() / 2.0);
    const double r = std::min(20.0, height() / 2.0 - 7.0);
    // The cam and its centre.
    p.setPen(QPen(ink, 1.2));
    p.setBrush(palette().color(QPalette::Base));
    p.drawEllipse(c, r, r);
    p.setBrush(ink);
    p.drawEllipse(c, 1.6, 1.6);
    // The turning arrow: an arc round the cam with its head in the direction of turning.
    const double ar = r + 5.0;
    const QRectF box(c.x() - ar, c.y() - ar, 2 * ar, 2 * ar);
    const double start = 120.0, span = 120.0;  // degrees, counter-clockwise on screen
    QPen arrow(QColor(31, 111, 208), 1.6);
    p.setPen(arrow);
    p.setBrush(Qt::NoBrush);
    p.drawArc(box, static_cast<int>(start * 16), static_cast<int>(span * 16));
    const double headDeg = m_clockwise ? start : start + span;
    const double a = headDeg * kPi / 180.0;
    const QPointF tip(c.x() + ar * std::cos(a), c.y() - ar * std::sin(a));
    // The tangent on screen in the direction of travel.
    const double s = m_clockwise ? -1.0 : 1.0;
    const QPointF along(-s * std::sin(a), -s * std::cos(a));
    const QPointF across(-along.y(), along.x());
    QPainterPath head;
    head.moveTo(tip + 4.5 * along);
    head.lineTo(tip - 3.0 * along + 3.5 * across);
    head.lineTo(tip - 3.0 * along - 3.5 * across);
    head.closeSubpath();
    p.setBrush(arrow.color());
    p.setPen(Qt::NoPen);
    p.drawPath(head);
    // The follower at φ = 0: its line along +x, offset e along +y (up on screen), to scale
    // with the base circle as far as the picture allows.
    const bool arm = m_follower && m_follower->motion == FollowerMotion::Oscillating;
    if (arm) return;
    const double e = m_follower ? m_follower->offset : 0.0;
    const double ey = e == 0.0 ? 0.0 : std::copysign(std::clamp(std::abs(e) / 40.0, 0.25, 0.7), e);
    const double y = c.y() - ey * r;
    const double x0 = c.x() + std::sqrt(std::max(0.0, r * r - (ey * r) * (ey * r)));
    p.setPen(QPen(ink, 1.0, Qt::DashLine));
    p.drawLine(QPointF(c.x(), y), QPointF(width() - 2.0, y));
    const bool roller = m_follower && m_follower->type == FollowerType::Roller;
    const bool flat = m_follower && m_follower->type == FollowerType::Flat;
    p.setPen(QPen(ink, 1.4));
    p.setBrush(Qt::NoBrush);
    if (roller) {
        p.drawEllipse(QPointF(x0 + 5.0, y), 5.0, 5.0);
        p.drawLine(QPointF(x0 + 10.0, y), QPointF(width() - 4.0, y));
    } else if (flat) {
        p.drawLine(QPointF(x0, y - 9.0), QPointF(x0, y + 9.0));
        p.drawLine(QPointF(x0, y), QPointF(width() - 4.0, y));
    } else {
        p.drawLine(QPointF(x0, y), QPointF(width() - 4.0, y));
    }
    if (e != 0.0) {
        // The offset's dimension at the right: from the centre's height to the line, "e".
        const double dx = width() - 8.0;
        p.setPen(QPen(ink, 0.8, Qt::DotLine));
        p.drawLine(QPointF(c.x() + r + 2.0, c.y()), QPointF(dx + 3.0, c.y()));
        p.setPen(QPen(ink, 0.8));
        p.drawLine(QPointF(dx, c.y()), QPointF(dx, y));
        QFont f = font();
        f.setPointSizeF(f.pointSizeF() * 0.85);
        f.setItalic(true);
        p.setFont(f);
        const double below = e > 0.0 ? c.y() + 11.0 : c.y() - 3.0;
        p.drawText(QPointF(dx - 4.0, below), QStringLiteral("e"));
    }
}

}  // namespace cam
