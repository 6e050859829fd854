#include "views/contour_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <algorithm>
#include <cmath>
#include <limits>

#include "document/project_document.h"
#include "project/follower_kind.h"
#include "views/axis_format.h"
#include "views/palette.h"
#include "views/plot_redraw.h"
#include "views/stale_label.h"

namespace cam {

ContourView::ContourView(ProjectDocument* document, QWidget* parent)
    : QCustomPlot(parent), m_document(document) {
    setObjectName("contourView");
    setFocusPolicy(Qt::StrongFocus);  // Escape must reach it while a point is being picked
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    xAxis->setLabel(tr("x [mm]"));
    yAxis->setLabel(tr("y [mm]"));
    xAxis2->setVisible(true);
    yAxis2->setVisible(true);
    xAxis2->setTickLabels(false);
    yAxis2->setTickLabels(false);
    applyAxisFormat(this);
    connect(xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), xAxis2,
            qOverload<const QCPRange&>(&QCPAxis::setRange));
    connect(yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), yAxis2,
            qOverload<const QCPRange&>(&QCPAxis::setRange));
    setToolTip(
        tr("Wheel: zoom · drag: pan · drag a square/diamond handle: move the centre or "
           "change the radius of the selected arc. Dragged points snap to centres, joints and "
           "the grid; Shift keeps one axis, Alt does not snap."));

    // Centres and joints above the segments' curves (which come and go with the segments): a
    // marker never disappears under the line it marks. Above them the follower ray and its
    // point, on a buffered layer of their own: a cursor move redraws them alone.
    addLayer("markers", layer("main"), QCustomPlot::limAbove);
    // Drawn last: the drag handles, then the follower and the ray above them.
    m_handlesLayer = addBufferedTopLayer(this, QStringLiteral("handles"));
    m_cursorLayer = addBufferedTopLayer(this, QStringLiteral("cursor"));
    m_ray = new QCPItemLine(this);
    m_ray->setLayer(m_cursorLayer);
    m_ray->setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
    m_ray->start->setCoords(0, 0);
    m_ray->end->setCoords(0, 0);
    m_rayPoint = new QCPItemTracer(this);
    m_rayPoint->setLayer(m_cursorLayer);
    m_rayPoint->setStyle(QCPItemTracer::tsCircle);
    m_rayPoint->setSize(7);
    m_rayPoint->setPen(QPen(Qt::black));
    m_rayPoint->setBrush(Qt::white);
    m_follower = std::make_unique<FollowerGlyph>(this, m_cursorLayer);

    // No legend here: the table names the segments. (QCustomPlot would otherwise add a legend
    // item per plottable, and removing items one by one is quadratic.)
    setAutoAddPlottableToLegend(false);
    for (int c = 0; c < kSegmentColorCount; ++c) {
        auto* curve = new QCPCurve(xAxis, yAxis);
        curve->setName(QStringLiteral("segments %1 mod %2").arg(c).arg(kSegmentColorCount));
        curve->setPen(QPen(segmentColor(c), 2));
        m_colourCurves[static_cast<std::size_t>(c)] = curve;
    }
    // A groove's outer flank, drawn as the profile is, and the roller centre's path dashed.
    for (std::size_t g = 0; g < 2; ++g) {
        auto* curve = new QCPCurve(xAxis, yAxis);
        curve->setName(g == 0 ? tr("outer flank") : tr("pitch curve"));
        curve->setPen(g == 0 ? QPen(QColor(40, 40, 40), 2)
                             : QPen(QColor(120, 120, 120), 1, Qt::DashLine));
        m_closureCurves[g] = curve;
    }
    // Over the segments' colours, under the markers: the profile coloured by stress.
    m_stress = std::make_unique<StressOverlay>(this);
    m_centers = addGraph();
    m_centers->setLayer("markers");
    m_centers->setName(tr("centres"));
    m_centers->setLineStyle(QCPGraph::lsNone);
    m_centers->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QColor(80, 80, 80), 6));
    m_joints = addGraph();
    m_joints->setLayer("markers");
    m_joints->setName(tr("joints"));
    m_joints->setLineStyle(QCPGraph::lsNone);
    m_joints->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black), QBrush(Qt::white), 5));
    // Origin: the rotation centre.
    auto* origin = new QCPItemTracer(this);
    origin->position->setCoords(0, 0);
    origin->setStyle(QCPItemTracer::tsPlus);
    origin->setSize(12);
    origin->setPen(QPen(Qt::black));

    m_editTool = new ContourEditTool(this, document, m_joints, m_handlesLayer, m_cursorLayer);
    connect(m_editTool, &ContourEditTool::pointPicked, this, &ContourView::pointPicked);
    connect(m_editTool, &ContourEditTool::pickCancelled, this, &ContourView::pickCancelled);

    m_staleLabel = new StaleLabel(this);

    connect(this, &QCustomPlot::mouseWheel, this, [this] { m_autoFit = false; });
}

void ContourView::setResult(const ComputeResultPtr& result) {
    if (!result) return;
    if (result->awaitsContour()) {
        // Nothing to draw yet; an earlier project's contour would only mislead.
        for (QCPCurve* curve : m_colourCurves) curve->data()->clear();
        for (QCPCurve* curve : m_closureCurves) curve->data()->clear();
        m_standingClosure = {};
        m_centers->data()->clear();
        m_joints->data()->clear();
        setStale(staleText(*result));
        return;
    }
    if (!result->ok()) {
        // The last contour stays for orientation, greyed and labelled as out of date (its
        // stress is not the project's).
        m_stress->show(nullptr, false);
        setStale(staleText(*result));
        return;
    }
    setStale({});
    m_result = result;
    const std::size_t n = result->outlines.size();
    constexpr double kGap = std::numeric_limits<double>::quiet_NaN();
    std::array<QVector<QCPCurveData>, kSegmentColorCount> data;
    m_runs.assign(n, {0, 0});
    QVector<double> cx, cy, jx, jy;
    double left = 0, right = 0, bottom = 0, top = 0;
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) {
        const auto& outline = result->outlines[k];
        auto& points = data[static_cast<std::size_t>(colourSlot(static_cast<int>(k)))];
        if (!points.isEmpty()) points.append(QCPCurveData(points.size(), kGap, kGap));
        m_runs[k] = {static_cast<int>(points.size()), static_cast<int>(outline.size())};
        for (const QPointF& p : outline) {
            points.append(QCPCurveData(points.size(), p.x(), p.y()));
            if (!any) {
                left = right = p.x();
                bottom = top = p.y();
                any = true;
            }
            left = std::min(left, p.x());
            right = std::max(right, p.x());
            bottom = std::min(bottom, p.y());
            top = std::max(top, p.y());
        }
        if (!outline.empty()) {
            jx << outline.front().x();
            jy << outline.front().y();
        }
        const ContourSegment& s = result->contour->segment(k);
        if (s.type == SegmentType::Arc) {
            cx << s.arc.center.x();
            cy << s.arc.center.y();
        }
    }
    // A groove's outer flank and pitch curve, or a conjugate pair's second plate.
    std::array<QVector<QCPCurveData>, 2> groove;
    std::array<const QVector<QPointF>*, 2> closure{};
    if (result->groove) closure = {&result->groove->outer, &result->groove->pitch};
    if (result->conjugate) closure[0] = &result->conjugate->outline;
    m_closureCurves[0]->setName(result->conjugate ? tr("second plate") : tr("outer flank"));
    {
        // The outer flank lies outside the contour, the second plate across the centre: the
        // view's bounds hold them.
        for (std::size_t g = 0; g < 2; ++g) {
            if (!closure[g]) continue;
            const QVector<QPointF>& outline = *closure[g];
            for (const QPointF& p : outline) {
                groove[g].append(QCPCurveData(groove[g].size(), p.x(), p.y()));
                if (g == 0 && any) {
                    left = std::min(left, p.x());
                    right = std::max(right, p.x());
                    bottom = std::min(bottom, p.y());
                    top = std::max(top, p.y());
                }
            }
        }
    }
    m_hasBounds = any;
    if (any && result->follower && result->follower->oscillating()) {
        // The pivot turns round the cam on a circle: keep it, and so the whole arm, in view.
        const double reach = result->follower->spec().pivot.norm();
        left = std::min(left, -reach);
        right = std::max(right, reach);
        bottom = std::min(bottom, -reach);
        top = std::max(top, reach);
    }
    if (any && result->follower && contactRadius(result->follower->spec()) > 0.0) {
        // A roller rides outside the contour, up to its diameter beyond it (a second roller
        // beyond its plate): keep it in view.
        const double reach =
            2.0 * std::max(contactRadius(result->follower->spec()),
                           result->conjugate ? result->conjugate->yoke.rollerRadiusMm : 0.0);
        left -= reach;
        right += reach;
        bottom -= reach;
        top += reach;
    }
    m_xBounds = QCPRange(left, right);
    m_yBounds = QCPRange(bottom, top);
    m_standing = data;
    m_standingCx = cx;
    m_standingCy = cy;
    m_standingJx = jx;
    m_standingJy = jy;
    m_standingClosure = groove;
    m_turnedBy = 0.0;
    for (std::size_t g = 0; g < 2; ++g) m_closureCurves[g]->data()->set(groove[g], true);
    for (int c = 0; c < kSegmentColorCount; ++c) {
        m_colourCurves[static_cast<std::size_t>(c)]->data()->set(data[static_cast<std::size_t>(c)],
                                                                 true);
    }
    m_centers->setData(cx, cy);
    // Around the contour x goes back and forth: the graph must sort the joints by x itself, or
    // its search for the visible ones skips some when zoomed in.
    m_joints->setData(jx, jy);
    m_stress->show(result.get(), m_stressColouring && !m_turning);
    if (m_autoFit) resetZoom();
    // The new contour, cursor and all, in one replot: queued first, so that the cursor's move
    // does not redraw its layer over the old contour before.
    queueReplot(this);
    setCursorAngle(m_cursorPhi);
}

void ContourView::setStressColouring(bool on) {
    m_stressColouring = on;
    m_stress->show(m_result.get(), on);
    queueReplot(this);
}

ContourView::~ContourView() = default;

QCPCurve* ContourView::segmentCurve(int k) const {
    return m_colourCurves[static_cast<std::size_t>(colourSlot(k))];
}

int ContourView::colourSlot(int k) const {
    // The document's slots while they describe the drawn contour (a result of its rows).
    const bool same =
        m_result && m_result->outlines.size() == m_document->segmentColourSlots().size();
    return same ? m_document->segmentColourSlot(k) : k % kSegmentColorCount;
}

std::pair<int, int> ContourView::segmentRun(int k) const {
    return m_runs.at(static_cast<std::size_t>(k));
}

void ContourView::resetZoom() {
    if (!m_hasBounds) return;
    m_autoFit = true;
    const double pad = 0.08 * std::max(m_xBounds.size(), m_yBounds.size());
    xAxis->setRange(m_xBounds.lower - pad, m_xBounds.upper + pad);
    yAxis->setRange(m_yBounds.lower - pad, m_yBounds.upper + pad);
    keepEqualAspect();
    queueReplot(this);
}

void ContourView::keepEqualAspect() {
    // Grow whichever axis is relatively shorter so one mm is as long on both.
    // The axis rect gets its size from the layout: bring it up to date first.
    plotLayout()->update(QCPLayoutElement::upPreparation);
    plotLayout()->update(QCPLayoutElement::upMargins);
    plotLayout()->update(QCPLayoutElement::upLayout);
    const double w = axisRect()->width(), h = axisRect()->height();
    if (w <= 0 || h <= 0) return;
    const double xs = xAxis->range().size() / w, ys = yAxis->range().size() / h;
    if (xs > ys) {
        yAxis->setRange(yAxis->range().center(), xs * h, Qt::AlignCenter);
    } else {
        xAxis->setRange(xAxis->range().center(), ys * w, Qt::AlignCenter);
    }
}

void ContourView::resizeEvent(QResizeEvent* event) {
    QCustomPlot::resizeEvent(event);
    m_staleLabel->place();
    fitToViewport();
}

void ContourView::fitToViewport() {
    if (m_autoFit) {
        resetZoom();
    } else {
        keepEqualAspect();
    }
}

void ContourView::setCursorAngle(double phi) {
    m_cursorPhi = phi;
    if (!m_result || !m_result->ok()) return;
    // Turning, the cam is drawn turned by −φ: its point at φ comes under the follower, which
    // stands where it is at φ = 0 (the follower assembly turns by φ in the cam's frame,
    // math.md §7).
    const double turn = m_turning ? -phi : 0.0;
    const double shown = phi + turn;  // where the ray is drawn
    const double r = m_result->contour->evaluate(phi).r;
    const double reach = std::max(r * 1.25, r + 5.0);
    m_ray->end->setCoords(reach * std::cos(shown), reach * std::sin(shown));
    m_rayPoint->position->setCoords(r * std::cos(shown), r * std::sin(shown));
    const FollowerModel* follower = m_result->follower.get();
    std::optional<FollowerGlyphShape> glyph = follower && !m_staleLabel->isStale()
                                                  ? followerGlyphAt(*follower, phi, m_result->omega)
                                                  : std::nullopt;
    if (glyph && m_result->conjugate) {
        glyph = withSecondRoller(*glyph, *follower, m_result->conjugate->yoke, phi);
    }
    if (glyph && turn != 0.0) glyph = cam::turnedBy(*glyph, turn);
    m_follower->show(glyph);
    if (turn != m_turnedBy) {
        turnDrawing(turn);
        queueReplot(this);  // the whole cam moves, not only the cursor's layer
    } else {
        replotLayer(m_cursorLayer);
    }
}

void ContourView::turnDrawing(double angle) {
    m_turnedBy = angle;
    const double c = std::cos(angle), s = std::sin(angle);
    // The standing points turned into `curve` (the colour curves, a groove's two curves).
    const auto turnInto = [c, s](QVector<QCPCurveData> points, QCPCurve* curve) {
        for (QCPCurveData& p : points) {
            const double x = p.key, y = p.value;
            p.key = c * x - s * y;
            p.value = s * x + c * y;
        }
        curve->data()->set(points, true);
    };
    for (std::size_t k = 0; k < m_standing.size(); ++k) turnInto(m_standing[k], m_colourCurves[k]);
    for (std::size_t g = 0; g < 2; ++g) turnInto(m_standingClosure[g], m_closureCurves[g]);
    const auto turned = [c, s](const QVector<double>& x, const QVector<double>& y,
                               QCPGraph* graph) {
        QVector<double> tx(x.size()), ty(y.size());
        for (qsizetype k = 0; k < x.size(); ++k) {
            tx[k] = c * x[k] - s * y[k];
            ty[k] = s * x[k] + c * y[k];
        }
        graph->setData(tx, ty);
    };
    turned(m_standingCx, m_standingCy, m_centers);
    turned(m_standingJx, m_standingJy, m_joints);
}

void ContourView::setTurning(bool on) {
    if (on == m_turning) return;
    m_turning = on;
    m_handlesLayer->setVisible(!on);
    m_stress->show(m_result.get(), m_stressColouring && !on);
    if (on && m_hasBounds) {
        // The turning cam stays in view: the circle its farthest point sweeps, and the
        // follower's reach beyond it (the bounds' own margins for a roller or an arm).
        m_rangesBeforeTurning = {xAxis->range(), yAxis->range()};
        double reach = 0.0;
        for (const auto& curve : m_standing) {
            for (const QCPCurveData& p : curve) {
                if (std::isfinite(p.key)) reach = std::max(reach, std::hypot(p.key, p.value));
            }
        }
        for (const QCPCurveData& p : m_standingClosure[0]) {
            reach = std::max(reach, std::hypot(p.key, p.value));
        }
        for (double v : {m_xBounds.lower, m_xBounds.upper, m_yBounds.lower, m_yBounds.upper}) {
            reach = std::max(reach, std::abs(v));
        }
        const double pad = 0.08 * 2.0 * reach;
        xAxis->setRange(-reach - pad, reach + pad);
        yAxis->setRange(-reach - pad, reach + pad);
        keepEqualAspect();
    }
    if (!on && m_turnedBy != 0.0) turnDrawing(0.0);
    setCursorAngle(m_cursorPhi);
    if (!on && m_rangesBeforeTurning) {
        // Back where the user had the view (or fitted anew while it follows the contour).
        xAxis->setRange(m_rangesBeforeTurning->first);
        yAxis->setRange(m_rangesBeforeTurning->second);
        m_rangesBeforeTurning.reset();
        if (m_autoFit) resetZoom();
    }
    queueReplot(this);
}

ContourView::FollowerMarkers ContourView::followerMarkers() const { return m_follower->markers(); }

QString ContourView::staleReason() const { return m_staleLabel->reason(); }

void ContourView::setStale(const QString& reason) {
    if (!m_staleLabel->setReason(reason)) return;
    const bool stale = m_staleLabel->isStale();
    for (int c = 0; c < kSegmentColorCount; ++c) {
        QCPCurve* curve = m_colourCurves[static_cast<std::size_t>(c)];
        QPen pen = curve->pen();
        pen.setColor(stale ? staleColor() : segmentColor(c));
        curve->setPen(pen);
    }
    for (auto [graph, color] :
         {std::pair{m_centers, QColor(80, 80, 80)}, std::pair{m_joints, QColor(Qt::black)}}) {
        QCPScatterStyle style = graph->scatterStyle();
        style.setPen(QPen(stale ? staleColor() : color));
        graph->setScatterStyle(style);
    }
    m_ray->setVisible(!stale);
    m_rayPoint->setVisible(!stale);
    queueReplot(this);
}

void ContourView::setSelectedSegment(int row) {
    m_editTool->setSelectedSegment(row);
    queueReplot(this);
}

void ContourView::keyPressEvent(QKeyEvent* event) {
    if (m_editTool->keyPress(event)) return;
    QCustomPlot::keyPressEvent(event);
}

void ContourView::mousePressEvent(QMouseEvent* event) {
    if (!m_turning && m_editTool->mousePress(event)) return;
    QCustomPlot::mousePressEvent(event);
}

void ContourView::mouseMoveEvent(QMouseEvent* event) {
    if (event->buttons() & Qt::LeftButton && !m_editTool->isDragging()) m_autoFit = false;
    if (m_editTool->mouseMove(event)) return;
    const double x = xAxis->pixelToCoord(event->position().x());
    const double y = yAxis->pixelToCoord(event->position().y());
    // A turning cam turns with the cursor: the mouse would spin it under itself.
    if ((x != 0.0 || y != 0.0) && !m_turning) emit cursorAngleChanged(std::atan2(y, x));
    QCustomPlot::mouseMoveEvent(event);
}

void ContourView::mouseReleaseEvent(QMouseEvent* event) {
    m_editTool->mouseRelease();
    QCustomPlot::mouseReleaseEvent(event);
}

}  // namespace cam
