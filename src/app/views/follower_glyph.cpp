#include "views/follower_glyph.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "project/follower_kind.h"

namespace cam {

std::optional<FollowerGlyphShape> followerGlyphShape(const FollowerSpec& spec,
                                                     const FollowerState& state, double phi) {
    if (!std::isfinite(state.center.x())) return std::nullopt;
    FollowerGlyphShape g;
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x());
    const double size = std::max(state.center.norm(), 1.0);
    const double rho = contactRadius(spec);
    g.center = state.center;
    if (spec.motion == FollowerMotion::Oscillating) {
        const Eigen::Vector2d pivot(u.x() * spec.pivot.x() + n.x() * spec.pivot.y(),
                                    u.y() * spec.pivot.x() + n.y() * spec.pivot.y());
        g.pivot = pivot;
        g.guideStart = pivot;
        g.guideEnd = state.center;
    } else {
        // The line of motion, from behind the contact out past the follower.
        g.guideStart = state.center;
        g.guideEnd = state.center + (rho + 0.25 * size) * u;
    }
    if (spec.type == FollowerType::Roller) {
        g.rollerRadius = rho;
    } else if (spec.type == FollowerType::Flat) {
        // The face through the contact, perpendicular to the line of motion, a little wider
        // than the contact's distance from the axis either side.
        const double half = std::max(std::abs(state.sPhi[1]) * 1.3, 0.1 * size);
        g.face = std::array<Eigen::Vector2d, 2>{state.center - half * n, state.center + half * n};
    }
    g.contact = state.contact;
    g.normalTip = state.contact + 0.12 * size * state.normal;
    return g;
}

std::optional<FollowerGlyphShape> followerGlyphAt(const FollowerModel& model, double phi,
                                                  double omega) {
    // One state of the shared model: a few hundred nanoseconds, like the ray's r(φ).
    return followerGlyphShape(model.spec(), model.at(phi, omega), phi);
}

FollowerGlyphShape withSecondRoller(FollowerGlyphShape shape, const FollowerModel& model,
                                    const SecondRoller& yoke, double phi) {
    const ConjugatePoint second = conjugatePoint(model, yoke, phi);
    shape.second =
        FollowerGlyphShape::Second{second.centre, second.plate, yoke.rollerRadiusMm, std::nullopt};
    if (yoke.bellCrank()) {
        shape.second->arm = shape.pivot;
    } else {
        shape.guideStart = second.centre;
    }
    return shape;
}

FollowerGlyph::FollowerGlyph(QCustomPlot* plot, QCPLayer* layer) {
    const QColor follower(20, 90, 160);
    m_guide = new QCPItemLine(plot);
    m_guide->setPen(QPen(follower, 2.0));
    m_pivot = new QCPItemTracer(plot);
    m_pivot->setStyle(QCPItemTracer::tsCircle);
    m_pivot->setSize(9);
    m_pivot->setPen(QPen(follower, 1.5));
    m_pivot->setBrush(Qt::white);
    m_roller = new QCPItemEllipse(plot);
    m_roller->setPen(QPen(follower, 1.5));
    m_roller->setBrush(QColor(20, 90, 160, 40));
    m_face = new QCPItemLine(plot);
    m_face->setPen(QPen(follower, 2.5));
    m_contact = new QCPItemTracer(plot);
    m_contact->setStyle(QCPItemTracer::tsCircle);
    m_contact->setSize(6);
    m_contact->setPen(QPen(QColor(200, 40, 40)));
    m_contact->setBrush(QColor(200, 40, 40));
    m_normal = new QCPItemLine(plot);
    m_normal->setPen(QPen(QColor(200, 40, 40), 1.2));
    m_normal->setHead(QCPLineEnding::esSpikeArrow);
    m_secondRoller = new QCPItemEllipse(plot);
    m_secondRoller->setPen(QPen(follower, 1.5));
    m_secondRoller->setBrush(QColor(20, 90, 160, 40));
    m_secondContact = new QCPItemTracer(plot);
    m_secondContact->setStyle(QCPItemTracer::tsCircle);
    m_secondContact->setSize(6);
    m_secondContact->setPen(QPen(QColor(200, 40, 40)));
    m_secondContact->setBrush(QColor(200, 40, 40));
    m_secondArm = new QCPItemLine(plot);
    m_secondArm->setPen(QPen(follower, 2.0));
    for (QCPAbstractItem* item : items()) {
        item->setLayer(layer);
        item->setVisible(false);
        item->setSelectable(false);
    }
}

std::array<QCPAbstractItem*, 9> FollowerGlyph::items() const {
    return {m_guide,  m_pivot,        m_roller,        m_face,     m_contact,
            m_normal, m_secondRoller, m_secondContact, m_secondArm};
}

FollowerGlyphShape turnedBy(FollowerGlyphShape shape, double angle) {
    const Eigen::Rotation2Dd turn(angle);
    for (Eigen::Vector2d* p :
         {&shape.guideStart, &shape.guideEnd, &shape.center, &shape.contact, &shape.normalTip}) {
        *p = turn * *p;
    }
    if (shape.pivot) shape.pivot = turn * *shape.pivot;
    if (shape.face) {
        for (Eigen::Vector2d& p : *shape.face) p = turn * p;
    }
    if (shape.second) {
        shape.second->center = turn * shape.second->center;
        shape.second->contact = turn * shape.second->contact;
        if (shape.second->arm) shape.second->arm = turn * *shape.second->arm;
    }
    return shape;
}

void FollowerGlyph::show(const std::optional<FollowerGlyphShape>& shape) {
    for (QCPAbstractItem* item : items()) item->setVisible(false);
    if (!shape) return;
    const FollowerGlyphShape& g = *shape;
    m_center = QPointF(g.center.x(), g.center.y());
    if (g.pivot) {
        m_pivot->position->setCoords(g.pivot->x(), g.pivot->y());
        m_pivot->setVisible(true);
    }
    m_guide->start->setCoords(g.guideStart.x(), g.guideStart.y());
    m_guide->end->setCoords(g.guideEnd.x(), g.guideEnd.y());
    m_guide->setVisible(true);
    if (g.rollerRadius) {
        const double rho = *g.rollerRadius;
        m_roller->topLeft->setCoords(g.center.x() - rho, g.center.y() + rho);
        m_roller->bottomRight->setCoords(g.center.x() + rho, g.center.y() - rho);
        m_roller->setVisible(true);
    }
    if (g.face) {
        const auto& [a, b] = *g.face;
        m_face->start->setCoords(a.x(), a.y());
        m_face->end->setCoords(b.x(), b.y());
        m_face->setVisible(true);
    }
    m_contact->position->setCoords(g.contact.x(), g.contact.y());
    m_contact->setVisible(true);
    m_normal->start->setCoords(g.contact.x(), g.contact.y());
    m_normal->end->setCoords(g.normalTip.x(), g.normalTip.y());
    m_normal->setVisible(true);
    if (g.second) {
        const FollowerGlyphShape::Second& r = *g.second;
        m_secondRoller->topLeft->setCoords(r.center.x() - r.radius, r.center.y() + r.radius);
        m_secondRoller->bottomRight->setCoords(r.center.x() + r.radius, r.center.y() - r.radius);
        m_secondRoller->setVisible(true);
        m_secondContact->position->setCoords(r.contact.x(), r.contact.y());
        m_secondContact->setVisible(true);
        if (r.arm) {
            m_secondArm->start->setCoords(r.arm->x(), r.arm->y());
            m_secondArm->end->setCoords(r.center.x(), r.center.y());
            m_secondArm->setVisible(true);
        }
    }
}

FollowerMarkers FollowerGlyph::markers() const {
    FollowerMarkers m;
    m.shown = m_contact->visible();
    m.pivotShown = m_pivot->visible();
    m.pivot = m_pivot->position->coords();
    m.contact = m_contact->position->coords();
    m.normalTip = m_normal->end->coords();
    if (m_roller->visible()) {
        const QPointF a = m_roller->topLeft->coords(), b = m_roller->bottomRight->coords();
        m.rollerRadius = (b.x() - a.x()) / 2.0;
    }
    m.secondShown = m_secondRoller->visible();
    if (m.secondShown) {
        const QPointF a = m_secondRoller->topLeft->coords(),
                      b = m_secondRoller->bottomRight->coords();
        m.secondCenter = (a + b) / 2.0;
        m.secondRadius = (b.x() - a.x()) / 2.0;
        m.secondContact = m_secondContact->position->coords();
    }
    // The follower point itself, not an end of the guide: a translating knife's or flat
    // face's line of motion runs on past it.
    m.center = m_center;
    return m;
}

}  // namespace cam
