#include "views/contour_edit_tool.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <algorithm>
#include <cmath>
#include <vector>

#include "document/commands.h"
#include "models/delegates.h"
#include "views/plot_redraw.h"

namespace cam {
namespace {
constexpr double kHandlePickPixels = 9.0;
}  // namespace

ContourEditTool::ContourEditTool(QCustomPlot* plot, ProjectDocument* document,
                                 const QCPGraph* joints, QCPLayer* handlesLayer,
                                 QCPLayer* cursorLayer)
    : QObject(plot),
      m_plot(plot),
      m_document(document),
      m_joints(joints),
      m_handlesLayer(handlesLayer),
      m_cursorLayer(cursorLayer) {
    for (auto [graph, shape] : {std::pair{&m_firstHandle, QCPScatterStyle::ssSquare},
                                std::pair{&m_secondHandle, QCPScatterStyle::ssDiamond}}) {
        *graph = plot->addGraph();
        (*graph)->setLineStyle(QCPGraph::lsNone);
        (*graph)->setScatterStyle(QCPScatterStyle(shape, QPen(QColor(0, 90, 200), 1.5),
                                                  QBrush(QColor(120, 180, 255)), 10));
    }
    m_controlPolygon = new QCPCurve(plot->xAxis, plot->yAxis);
    m_controlPolygon->setPen(QPen(QColor(0, 90, 200, 160), 1, Qt::DashLine));
    m_controlPolygon->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 4));
    // The drag handles above the markers: a centre cross never hides the handle on it.
    // Buffered: an edit moves them at once, while the contour waits for the engine's result.
    for (QCPAbstractPlottable* p : std::initializer_list<QCPAbstractPlottable*>{
             m_firstHandle, m_secondHandle, m_controlPolygon}) {
        p->setLayer(handlesLayer);
    }

    m_pickMarker = new QCPItemTracer(plot);
    m_pickMarker->setLayer(cursorLayer);
    m_pickMarker->setStyle(QCPItemTracer::tsCrosshair);
    m_pickMarker->setPen(QPen(QColor(0, 90, 200), 1, Qt::DotLine));
    m_pickMarker->setVisible(false);

    connect(document, &ProjectDocument::changed, this, [this] {
        updateHandles();
        replotLayer(m_handlesLayer);  // the contour follows with the result
    });
}

void ContourEditTool::setSelectedSegment(int row) {
    m_selected = row;
    updateHandles();
}

QPointF ContourEditTool::secondHandlePosition(int row) const {
    const SegmentSpec& s = m_document->project().contour.at(static_cast<std::size_t>(row));
    const Arc& arc = *s.as<Arc>();
    // On the circle, in the direction of the middle of the window as seen from the centre.
    const double mid = (s.phiStartDeg + s.phiEndDeg) / 2.0 * M_PI / 180.0;
    const double r = arc.evaluate(mid).r;
    Eigen::Vector2d dir = Eigen::Vector2d(r * std::cos(mid), r * std::sin(mid)) - arc.center;
    if (!std::isfinite(dir.x()) || dir.norm() < 1e-12) dir = {1.0, 0.0};
    const Eigen::Vector2d p = arc.center + arc.radius * dir.normalized();
    return {p.x(), p.y()};
}

void ContourEditTool::updateHandles() {
    const auto& c = m_document->project().contour;
    m_controlPolygon->data()->clear();
    if (m_selected < 0 || m_selected >= static_cast<int>(c.size()) ||
        c[static_cast<std::size_t>(m_selected)].type() == SegmentType::Line) {
        m_firstHandle->data()->clear();
        m_secondHandle->data()->clear();
        return;
    }
    const SegmentSpec& s = c[static_cast<std::size_t>(m_selected)];
    if (isSpline(s.type())) {
        // Handles on the inner control points; the ends stay on the neighbours' joints.
        const CubicBezier b = bezierOf(s);
        m_firstHandle->setData({b.p[1].x()}, {b.p[1].y()}, true);
        m_secondHandle->setData({b.p[2].x()}, {b.p[2].y()}, true);
        QVector<double> x, y;
        for (const auto& p : b.p) {
            x << p.x();
            y << p.y();
        }
        m_controlPolygon->setData(x, y);
        return;
    }
    const Arc& arc = *s.as<Arc>();
    const QPointF second = secondHandlePosition(m_selected);
    m_firstHandle->setData({arc.center.x()}, {arc.center.y()}, true);
    m_secondHandle->setData({second.x()}, {second.y()}, true);
}

ContourEditTool::Handle ContourEditTool::handleAt(const QPointF& pixel) const {
    auto distance = [&](const QCPGraph* g) {
        if (g->data()->isEmpty()) return kHandlePickPixels + 1.0;
        const auto it = g->data()->constBegin();
        return QLineF(pixel, QPointF(m_plot->xAxis->coordToPixel(it->key),
                                     m_plot->yAxis->coordToPixel(it->value)))
            .length();
    };
    if (distance(m_firstHandle) <= kHandlePickPixels) return Handle::First;
    if (distance(m_secondHandle) <= kHandlePickPixels) return Handle::Second;
    return Handle::None;
}

double ContourEditTool::mmPerPixel() const {
    return std::abs(m_plot->xAxis->pixelToCoord(1.0) - m_plot->xAxis->pixelToCoord(0.0));
}

GridStep ContourEditTool::grid() const { return gridStepFor(kGridPixels * mmPerPixel()); }

double ContourEditTool::gridStep() const { return grid().value(); }

Eigen::Vector2d ContourEditTool::snap(const QPointF& pixel, Qt::KeyboardModifiers modifiers,
                                      const Eigen::Vector2d* origin, int skipSegment) const {
    const Eigen::Vector2d p(m_plot->xAxis->pixelToCoord(pixel.x()),
                            m_plot->yAxis->pixelToCoord(pixel.y()));
    // The rotation centre; the centres from the document (current while dragging); the joints
    // as the engine computed and drew them, so that a mouse move evaluates no segment on this
    // thread.
    const auto& contour = m_document->project().contour;
    std::vector<Eigen::Vector2d> candidates;
    candidates.reserve(1 + contour.size() + static_cast<std::size_t>(m_joints->data()->size()));
    candidates.emplace_back(0.0, 0.0);
    for (std::size_t k = 0; k < contour.size(); ++k) {
        if (static_cast<int>(k) == skipSegment) continue;
        if (const Arc* arc = contour[k].as<Arc>()) candidates.push_back(arc->center);
    }
    for (auto it = m_joints->data()->constBegin(); it != m_joints->data()->constEnd(); ++it) {
        candidates.emplace_back(it->key, it->value);
    }
    return snapPoint(p, candidates, kSnapPixels * mmPerPixel(), grid(), modifiers,
                     origin ? std::optional<Eigen::Vector2d>(*origin) : std::nullopt)
        .point;
}

void ContourEditTool::beginPointPick() {
    m_picking = true;
    m_plot->setCursor(Qt::CrossCursor);
    m_plot->setFocus(Qt::OtherFocusReason);
}

void ContourEditTool::endPointPick() {
    m_picking = false;
    m_plot->unsetCursor();
    m_pickMarker->setVisible(false);
    replotLayer(m_cursorLayer);
}

void ContourEditTool::cancelPointPick() {
    if (!m_picking) return;
    endPointPick();
    emit pickCancelled();
}

bool ContourEditTool::keyPress(QKeyEvent* event) {
    if (!m_picking || event->key() != Qt::Key_Escape) return false;
    cancelPointPick();
    event->accept();
    return true;
}

bool ContourEditTool::mousePress(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return false;
    if (m_picking) {
        const Eigen::Vector2d p = snap(event->position(), event->modifiers());
        endPointPick();
        event->accept();
        emit pointPicked(QPointF(p.x(), p.y()));
        return true;
    }
    m_dragging = handleAt(event->position());
    if (m_dragging != Handle::None) {
        m_gesture = nextGestureId();
        m_plot->setInteraction(QCP::iRangeDrag, false);
        const QCPGraph* handle = m_dragging == Handle::First ? m_firstHandle : m_secondHandle;
        const auto it = handle->data()->constBegin();
        m_dragOrigin = {it->key, it->value};
    }
    return false;  // the plot sees the press too (with a handle taken, it does not pan)
}

bool ContourEditTool::mouseMove(QMouseEvent* event) {
    if (m_dragging != Handle::None && m_selected >= 0) {
        dragTo(event);
        event->accept();
        return true;
    }
    if (m_picking) {
        const Eigen::Vector2d p = snap(event->position(), event->modifiers());
        m_pickMarker->position->setCoords(p.x(), p.y());
        m_pickMarker->setVisible(true);
        replotLayer(m_cursorLayer);
    }
    return false;
}

void ContourEditTool::dragTo(QMouseEvent* event) {
    const double x = m_plot->xAxis->pixelToCoord(event->position().x());
    const double y = m_plot->yAxis->pixelToCoord(event->position().y());
    SegmentSpec s = m_document->project().contour.at(static_cast<std::size_t>(m_selected));
    const bool first = m_dragging == Handle::First;
    const EditedField field = first ? EditedField::FirstHandleDrag : EditedField::SecondHandleDrag;
    QString text;
    const Eigen::Vector2d at =
        snap(event->position(), event->modifiers(), &m_dragOrigin, first ? m_selected : -1);
    if (CubicBezier* b = s.as<CubicBezier>()) {
        b->p[first ? 1 : 2] = at;  // P1 (square) or P2 (diamond)
        text = tr("Shape segment %1").arg(m_selected);
    } else if (HermiteCurve* h = s.as<HermiteCurve>()) {
        // The same handles as tangents (t = 3·handle); the other tangent stays bit-equal.
        if (first) {
            h->t0 = 3.0 * (at - h->p0);
        } else {
            h->t1 = 3.0 * (h->p3 - at);
        }
        text = tr("Shape segment %1").arg(m_selected);
    } else if (Arc* arc = s.as<Arc>(); arc && first) {
        arc->center = at;
        text = tr("Move centre of segment %1").arg(m_selected);
    } else if (arc) {
        // The radius itself snaps to the grid (Alt: not at all).
        const double radius = snapLength(std::hypot(x - arc->center.x(), y - arc->center.y()),
                                         grid(), event->modifiers());
        arc->radius = std::max(1e-3, radius);
        text = tr("Change radius of segment %1").arg(m_selected);
    }
    m_document->undoStack()->push(
        new EditSegment(m_document, m_selected, s, field, text, m_gesture));
}

void ContourEditTool::mouseRelease() {
    if (m_dragging == Handle::None) return;
    m_dragging = Handle::None;
    m_plot->setInteraction(QCP::iRangeDrag, true);
}

}  // namespace cam
