#include "views/kinematics_plots.h"

#include <QVBoxLayout>
#include <cmath>

#include "common/angles.h"
#include "views/axis_format.h"
#include "views/palette.h"
#include "views/plot_data.h"
#include "views/stale_label.h"

namespace cam {
namespace {

/// The law: dashed; the follower riding the contour: solid.
QPen designPen(int which) {
    return which == 0 ? QPen(QColor(0, 130, 60), 1.6, Qt::DashLine) : QPen(QColor(230, 120, 0), 1.2);
}

}  // namespace

KinematicsPlots::KinematicsPlots(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    const QString titles[] = {tr("Velocity [mm/s]"), tr("Acceleration [mm/s²]"),
                              tr("Jerk [mm/s³]")};
    const QString names[3][3] = {{tr("v_r"), tr("v_φ"), tr("|v|")},
                                 {tr("a_r"), tr("a_φ"), tr("|a|")},
                                 {tr("j_r"), tr("j_φ"), tr("|j|")}};
    const char* objectNames[] = {"velocityPlot", "accelerationPlot", "jerkPlot"};
    for (int p = 0; p < 3; ++p) {
        auto* plot = new QCustomPlot(this);
        plot->setObjectName(objectNames[p]);
        plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        plot->axisRect()->setRangeDrag(Qt::Horizontal);
        plot->axisRect()->setRangeZoom(Qt::Horizontal);
        plot->yAxis->setLabel(titles[p]);
        applyAxisFormat(plot);
        for (int c = 0; c < 3; ++c) {
            QCPGraph* g = plot->addGraph();
            g->setName(names[p][c]);
            g->setPen(QPen(componentColor(c), 1.0));
            // The engine's levels are min/max envelopes of at most a pixel per bucket: the
            // graph draws them as they are. (QCustomPlot's own reduction would start a pixel's
            // cluster at a NaN break and then lose that pixel's extremes.)
            g->setAdaptiveSampling(false);
        }
        // The motion design's law (dashed) and the follower on the contour, after the
        // kinematics' own curves: drawn while the project has a translating design.
        QCPGraph* law = plot->addGraph();
        law->setName(tr("law"));
        law->setPen(designPen(0));
        QCPGraph* follower = plot->addGraph();
        follower->setName(tr("follower"));
        follower->setPen(designPen(1));
        // The legend gets a narrow column of its own beside the plot: it never hides a curve.
        plot->legend->setVisible(true);
        plot->legend->setFont(QFont(font().family(), 8));
        plot->legend->setRowSpacing(-3);
        plot->legend->setBorderPen(Qt::NoPen);
        plot->legend->setBrush(Qt::NoBrush);
        auto* side = new QCPLayoutGrid;
        plot->plotLayout()->addElement(0, 1, side);
        plot->plotLayout()->setColumnStretchFactor(1, 0.001);
        side->addElement(0, 0, plot->legend);
        side->addElement(1, 0, new QCPLayoutElement(plot));  // spacer: legend stays at the top
        side->setRowStretchFactor(0, 0.001);
        side->setMargins(QMargins(0, 8, 4, 0));
        // The cursor on a buffered layer of its own: a move redraws one line, not the curves.
        plot->addLayer("cursor", plot->layer("main"), QCustomPlot::limAbove);
        QCPLayer* cursorLayer = plot->layer("cursor");
        cursorLayer->setMode(QCPLayer::lmBuffered);
        m_cursorLayers[static_cast<std::size_t>(p)] = cursorLayer;
        auto* cursor = new QCPItemStraightLine(plot);
        cursor->setLayer(cursorLayer);
        cursor->setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
        cursor->point1->setCoords(0, 0);
        cursor->point2->setCoords(0, 1);
        m_cursors[static_cast<std::size_t>(p)] = cursor;
        // Only the bottom plot labels the shared x axis.
        plot->xAxis->setTickLabels(p == 2);
        connect(plot, &QCustomPlot::mouseMove, this, [this, plot](QMouseEvent* e) {
            emit cursorMoved(plot->xAxis->pixelToCoord(e->position().x()));
        });
        m_plots[static_cast<std::size_t>(p)] = plot;
        layout->addWidget(plot, 1);
    }
    // One shared x axis: panning or zooming any plot moves all three.
    for (QCustomPlot* a : m_plots) {
        for (QCustomPlot* b : m_plots) {
            if (a == b) continue;
            connect(a->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), b,
                    [b](const QCPRange& r) {
                        if (b->xAxis->range() != r) {
                            b->xAxis->setRange(r);
                            b->replot(QCustomPlot::rpQueuedReplot);
                        }
                    });
        }
    }
    connect(m_plots[0]->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
            [this] { chooseResolution(); });
    // A new width (the window resized, a dock moved) may want another level: known once the
    // plot has laid itself out, before it draws.
    connect(m_plots[0], &QCustomPlot::afterLayout, this, [this] { chooseResolution(); });
    // The left axes line up however wide their tick labels are.
    auto* group = new QCPMarginGroup(m_plots[0]);
    for (QCustomPlot* p : m_plots) p->axisRect()->setMarginGroup(QCP::msLeft | QCP::msRight, group);
    // Legend columns of equal width keep the three x axes exactly above each other.
    int legendWidth = 0;
    for (QCustomPlot* p : m_plots) {
        legendWidth = std::max(legendWidth, p->legend->minimumOuterSizeHint().width());
    }
    for (QCustomPlot* p : m_plots) {
        p->legend->setMinimumSize(legendWidth, 0);
        p->legend->setMaximumSize(legendWidth, QWIDGETSIZE_MAX);
    }
    m_staleLabel = new StaleLabel(this);
}

void KinematicsPlots::setResult(const ComputeResultPtr& result) {
    if (!result) return;
    if (result->awaitsContour()) {
        // Nothing to draw yet; an earlier project's curves would only mislead.
        for (QCustomPlot* plot : m_plots) {
            for (int c = 0; c < plot->graphCount(); ++c) plot->graph(c)->data()->clear();
        }
        for (QCPItemStraightLine* m : m_jointMarkers) m->parentPlot()->removeItem(m);
        m_jointMarkers.clear();
        m_result.reset();
        m_data.reset();
        m_level = static_cast<std::size_t>(-1);
        setStale(staleText(*result));
        return;
    }
    if (!result->ok()) {
        setStale(staleText(*result));
        return;
    }
    setStale({});
    m_result = result;
    // Made in the worker by the views' preparer; made here only without one (tests).
    m_data = std::dynamic_pointer_cast<const KinematicsPlotData>(result->prepared);
    if (!m_data) m_data = makeKinematicsPlotData(*result, nullptr);
    // A new axis, or a turn that now spans another range (another period, the other sense
    // of rotation), is shown whole; otherwise the user's zoom stays.
    const PlotRange& x = result->curves.xRange;
    const bool refit = !m_fitted || result->axis != m_axis || x.lower != m_xRange.lower ||
                       x.upper != m_xRange.upper;
    m_axis = result->axis;
    m_xRange = x;
    for (int p = 0; p < 3; ++p) {
        QCustomPlot* plot = m_plots[static_cast<std::size_t>(p)];
        plot->xAxis->setLabel(p == 2 ? (m_axis == PlotAxis::Angle ? tr("φ [°]") : tr("t [s]"))
                                     : QString());
    }
    rebuildJointMarkers();
    if (refit) {
        m_fitted = true;
        for (QCustomPlot* p : m_plots) p->xAxis->setRange(x.lower, x.upper);
    }
    chooseResolution(true);  // always the new result's data, also when the level stays
    showDesign();
    fitY();
}

void KinematicsPlots::showDesign() {
    // In mm only: an arm's lift is an angle, shown in the Motion Design dock.
    const auto& design = m_result->design;
    const bool shown = design && !design->swinging && m_data && m_data->designLaw[1];
    for (std::size_t p = 0; p < 3; ++p) {
        QCustomPlot* plot = m_plots[p];
        for (int which = 0; which < 2; ++which) {
            QCPGraph* graph = plot->graph(kCurvesPerPlot + which);
            const auto& data = which == 0 ? m_data->designLaw : m_data->designOnContour;
            const bool has = shown && data[p + 1];
            if (has) {
                graph->setData(data[p + 1]);
                graph->addToLegend();
            } else {
                graph->data()->clear();
                graph->removeFromLegend();
            }
        }
        plot->replot(QCustomPlot::rpQueuedReplot);
    }
}

bool KinematicsPlots::showsDesign() const { return m_plots[0]->graph(kCurvesPerPlot)->dataCount() > 0; }

QString KinematicsPlots::staleReason() const { return m_staleLabel->reason(); }

void KinematicsPlots::setStale(const QString& reason) {
    if (!m_staleLabel->setReason(reason)) return;
    const bool stale = m_staleLabel->isStale();
    for (QCustomPlot* plot : m_plots) {
        for (int c = 0; c < plot->graphCount(); ++c) {
            QPen pen = plot->graph(c)->pen();
            pen.setColor(stale                  ? staleColor()
                         : c < kCurvesPerPlot ? componentColor(c)
                                              : designPen(c - kCurvesPerPlot).color());
            plot->graph(c)->setPen(pen);
        }
        plot->replot(QCustomPlot::rpQueuedReplot);
    }
    for (QCPItemStraightLine* m : m_jointMarkers) m->setVisible(!stale);
}

void KinematicsPlots::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    m_staleLabel->place();
}

void KinematicsPlots::chooseResolution(bool force) {
    if (!m_result || !m_data || m_data->levels.empty()) return;
    const PlotCurves& curves = m_result->curves;
    const double visible = m_plots[0]->xAxis->range().size() / curves.xRange.size();
    // The axis rect's width as of the last layout (before the first, the widget's: wider, so
    // on the safe side).
    const int axisWidth = m_plots[0]->axisRect()->width();
    const std::size_t level =
        curves.levelFor(visible, axisWidth > 0 ? axisWidth : m_plots[0]->width());
    if (level == m_level && !force) return;
    m_level = std::min(level, m_data->levels.size() - 1);
    const auto& containers = m_data->levels[m_level];
    for (int p = 0; p < 3; ++p) {
        for (int c = 0; c < 3; ++c) {
            m_plots[static_cast<std::size_t>(p)]->graph(c)->setData(
                containers[static_cast<std::size_t>(3 * p + c)]);
        }
        m_plots[static_cast<std::size_t>(p)]->replot(QCustomPlot::rpQueuedReplot);
    }
}

void KinematicsPlots::fitY() {
    if (!m_result) return;
    // The worker measured the ranges; rescaling here would scan every point again.
    for (std::size_t p = 0; p < 3; ++p) {
        const PlotRange& y = m_result->curves.yRanges[p];
        QCPRange range(y.lower, y.upper);
        if (showsDesign()) {
            const PlotRange& d = m_result->design->yRanges[p + 1];
            range.expand(QCPRange(d.lower, d.upper));
        }
        if (!(range.size() > 0.0)) range = QCPRange(range.lower - 1.0, range.upper + 1.0);
        m_plots[p]->yAxis->setRange(range);
        m_plots[p]->yAxis->scaleRange(1.08);
        m_plots[p]->replot(QCustomPlot::rpQueuedReplot);
    }
}

void KinematicsPlots::resetZoom() {
    if (!m_result) return;
    const PlotRange& x = m_result->curves.xRange;
    for (QCustomPlot* p : m_plots) p->xAxis->setRange(x.lower, x.upper);
    chooseResolution();
    fitY();
}

void KinematicsPlots::setCursorX(double x) {
    for (std::size_t p = 0; p < 3; ++p) {
        m_cursors[p]->point1->setCoords(x, 0);
        m_cursors[p]->point2->setCoords(x, 1);
        m_cursorLayers[p]->replot();
    }
}

void KinematicsPlots::rebuildJointMarkers() {
    for (QCPItemStraightLine* m : m_jointMarkers) m->parentPlot()->removeItem(m);
    m_jointMarkers.clear();
    if (!m_result || !m_result->ok()) return;
    const double omega = m_result->omega;
    for (const JointAnalysis& j : m_result->analysis.joints) {
        if (j.continuity == Continuity::C2) continue;  // a_r is continuous here
        // Where in the plotted turn (phi = omega·t, t in [0, T)) the joint angle comes up.
        double phi = j.phi;
        const double sign = omega > 0 ? 1.0 : -1.0;
        phi = std::fmod(sign * phi, kTwoPi);
        if (phi < 0) phi += kTwoPi;
        const double x = m_axis == PlotAxis::Angle ? radToDeg(sign * phi) : phi / std::abs(omega);
        for (QCustomPlot* p : m_plots) {
            auto* line = new QCPItemStraightLine(p);
            line->setPen(QPen(QColor(200, 120, 0, 150), 1, Qt::DotLine));
            line->point1->setCoords(x, 0);
            line->point2->setCoords(x, 1);
            line->setSelectable(false);
            m_jointMarkers.push_back(line);
        }
    }
}

}  // namespace cam
