#include "views/kinematics_plots.h"

#include <QVBoxLayout>
#include <cmath>

#include "common/angles.h"
#include "export/plot_picture.h"
#include "views/palette.h"
#include "views/plot_data.h"
#include "views/plot_redraw.h"
#include "views/plot_setup.h"
#include "views/stale_label.h"

namespace cam {
namespace {

/// The law: dashed; the follower riding the contour: solid.
QPen designPen(int which) {
    return which == 0 ? QPen(QColor(0, 130, 60), 1.6, Qt::DashLine)
                      : QPen(QColor(230, 120, 0), 1.2);
}

/// The follower's quantity each plot shows: velocity, acceleration, jerk, then the lift (the
/// index into ComputeResult::followerMotion).
std::size_t motionIndex(std::size_t plot) { return (plot + 1) % 4; }

}  // namespace

QString KinematicsPlots::motionName(int plot, bool swinging) {
    if (swinging) {
        const QString names[kPlotCount] = {tr("ψ'"), tr("ψ''"), tr("ψ'''"), tr("ψ")};
        return names[plot];
    }
    const QString names[kPlotCount] = {tr("v"), tr("a"), tr("j"), tr("s")};
    return names[plot];
}

void KinematicsPlots::applyTitles() {
    const QString polar[kPlotCount] = {tr("Velocity [mm/s]"), tr("Acceleration [mm/s²]"),
                                       tr("Jerk [mm/s³]"), tr("Radius r [mm]")};
    const QString follower[kPlotCount] = {tr("Velocity v [mm/s]"), tr("Acceleration a [mm/s²]"),
                                          tr("Jerk j [mm/s³]"), tr("Lift s [mm]")};
    const QString arm[kPlotCount] = {tr("Arm speed ψ' [°/s]"), tr("Arm acceleration ψ'' [°/s²]"),
                                     tr("Arm jerk ψ''' [°/s³]"), tr("Arm swing ψ [°]")};
    for (int p = 0; p < kPlotCount; ++p) {
        m_plots[static_cast<std::size_t>(p)]->yAxis->setLabel(!m_follower  ? polar[p]
                                                              : m_swinging ? arm[p]
                                                                           : follower[p]);
    }
}

QString KinematicsPlots::liftTitle() const {
    return !m_follower ? tr("Radius r") : m_swinging ? tr("Arm swing") : tr("Lift");
}

KinematicsPlots::KinematicsPlots(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    // The lift plot draws r alone: its other two curves stay empty and out of its legend.
    const QString names[kPlotCount][3] = {{tr("v_r"), tr("v_φ"), tr("|v|")},
                                          {tr("a_r"), tr("a_φ"), tr("|a|")},
                                          {tr("j_r"), tr("j_φ"), tr("|j|")},
                                          {tr("r"), {}, {}}};
    const char* objectNames[] = {"velocityPlot", "accelerationPlot", "jerkPlot", "liftPlot"};
    for (int p = 0; p < kPlotCount; ++p) {
        QCustomPlot* plot = newAlongXPlot(this, objectNames[p], QString());
        plot->setFocusPolicy(Qt::ClickFocus);  // the cursor keys (window/cursor_actions.h)
        for (int c = 0; c < 3; ++c) {
            QCPGraph* g = plot->addGraph();
            g->setName(names[p][c]);
            g->setPen(QPen(componentColor(c), 1.0));
            // The engine's levels are min/max envelopes of at most a pixel per bucket: the
            // graph draws them as they are. (QCustomPlot's own reduction would start a pixel's
            // cluster at a NaN break and then lose that pixel's extremes.)
            g->setAdaptiveSampling(false);
            if (names[p][c].isEmpty()) g->removeFromLegend();
        }
        // The motion design's law (dashed) and the follower on the contour, after the
        // kinematics' own curves: drawn while the project has a translating design.
        QCPGraph* law = plot->addGraph();
        law->setName(tr("law"));
        law->setPen(designPen(0));
        QCPGraph* follower = plot->addGraph();
        follower->setName(tr("follower"));
        follower->setPen(designPen(1));
        // The project's follower: its lift, velocity, acceleration or jerk (kFollowerGraph).
        QCPGraph* motion = plot->addGraph();
        motion->setPen(QPen(componentColor(0), 1.2));
        motion->removeFromLegend();
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
        m_cursors[static_cast<std::size_t>(p)] = addCursorLine(plot);
        // Only the bottom plot labels the shared x axis.
        plot->xAxis->setTickLabels(p == 2);
        connect(plot, &QCustomPlot::mouseMove, this, [this, plot](QMouseEvent* e) {
            emit cursorMoved(plot->xAxis->pixelToCoord(e->position().x()));
        });
        m_plots[static_cast<std::size_t>(p)] = plot;
        // The lift plot above the three it explains; it needs less height.
        if (p == kLiftPlot) {
            layout->insertWidget(0, plot, 2);
        } else {
            layout->addWidget(plot, 3);
        }
    }
    // Law and follower of a motion design are drawn over velocity, acceleration and jerk
    // only (the design's lift is the follower's, not r), and over the follower's lift.
    for (int which = 0; which < 2; ++which)
        m_plots[kLiftPlot]->graph(kCurvesPerPlot + which)->removeFromLegend();
    applyTitles();
    // One shared x axis: panning or zooming any plot moves them all.
    for (QCustomPlot* a : m_plots) {
        for (QCustomPlot* b : m_plots) {
            if (a == b) continue;
            connect(a->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), b,
                    [b](const QCPRange& r) {
                        if (b->xAxis->range() != r) {
                            b->xAxis->setRange(r);
                            queueReplot(b);
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
    // Legend columns of equal width keep the x axes exactly above each other. (The widest
    // names, "law" and "follower" of a design, are in the legends now; the follower's own
    // quantities are shorter.)
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
            for (int c = 0; c < plot->graphCount(); ++c) clearGraph(plot->graph(c));
        }
        for (QCPItemStraightLine* m : m_jointMarkers) m->parentPlot()->removeItem(m);
        m_jointMarkers.clear();
        m_result.reset();
        m_data.reset();
        m_level = static_cast<std::size_t>(-1);
        m_levelBucket = 0;
        setStale(staleText(*result));
        return;
    }
    if (!result->valid()) {
        // Not computed, or computed for a project with problems (an open joint): the last
        // valid curves stay, greyed under the reason; never an invalid cam's curves as if
        // they were the cam's (the contour view still draws its contour).
        setStale(staleText(*result));
        return;
    }
    setStale({});
    if (m_result && result->generation == m_result->generation) {
        // The same result with its finer levels: drawn when the zoom asks for one of them (the
        // levels it had are the same).
        m_result = result;
        m_data = std::dynamic_pointer_cast<const KinematicsPlotData>(result->prepared);
        if (!m_data) m_data = makeKinematicsPlotData(*result, nullptr);
        chooseResolution();
        return;
    }
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
    if (refit) {
        m_fitted = true;
        for (QCustomPlot* p : m_plots) p->xAxis->setRange(x.lower, x.upper);
    }
    chooseQuantities();
}

void KinematicsPlots::setPolarChosen(bool polar) {
    if (polar == m_polarChosen) return;
    m_polarChosen = polar;
    if (m_result) chooseQuantities();
}

void KinematicsPlots::chooseQuantities() {
    const bool follower = !m_polarChosen && m_data && m_data->followerMotion[0];
    const bool swinging = follower && m_result->follower && m_result->follower->oscillating();
    const bool changed = follower != m_follower;
    m_follower = follower;
    m_swinging = swinging;
    applyTitles();
    for (std::size_t p = 0; p < m_plots.size(); ++p) {
        // The other set's curves leave the plot and its legend.
        for (int c = 0; c < kCurvesPerPlot; ++c) {
            QCPGraph* g = m_plots[p]->graph(c);
            if (follower) {
                clearGraph(g);
                g->removeFromLegend();
            } else if (!g->name().isEmpty()) {
                g->addToLegend();
            }
        }
    }
    rebuildJointMarkers();
    if (follower) {
        showFollower();
    } else {
        for (QCustomPlot* plot : m_plots) {
            clearGraph(plot->graph(kFollowerGraph));
            plot->graph(kFollowerGraph)->removeFromLegend();
        }
    }
    chooseResolution(true);  // always the new result's data, also when the level stays
    showDesign();
    orderLegends();
    fitY();
    if (changed) emit followerShownChanged(follower);
}

void KinematicsPlots::orderLegends() {
    // The quantities first (the follower's, or r's three components), then law and follower of
    // a design: whichever were added last, each legend reads the same way.
    std::vector<int> order{kFollowerGraph};
    for (int g = 0; g < kFollowerGraph; ++g) order.push_back(g);
    for (QCustomPlot* plot : m_plots) {
        std::vector<QCPGraph*> shown;
        for (int g : order) {
            if (plot->legend->hasItemWithPlottable(plot->graph(g))) shown.push_back(plot->graph(g));
        }
        for (QCPGraph* g : shown) g->removeFromLegend();
        for (QCPGraph* g : shown) g->addToLegend();
    }
}

void KinematicsPlots::showFollower() {
    for (std::size_t p = 0; p < m_plots.size(); ++p) {
        QCPGraph* graph = m_plots[p]->graph(kFollowerGraph);
        graph->setData(m_data->followerMotion[motionIndex(p)]);
        graph->setName(motionName(static_cast<int>(p), m_swinging));
        graph->addToLegend();
        queueReplot(m_plots[p]);
    }
}

void KinematicsPlots::showDesign() {
    // Over the polar kinematics in mm only (an arm's lift is an angle, shown in the Motion
    // Design dock); over the follower's motion the law alone, in the follower's unit: the
    // follower on the contour is the curve drawn already.
    const auto& design = m_result->design;
    const bool shown =
        design && (m_follower || !design->swinging) && m_data && m_data->designLaw[1];
    for (std::size_t p = 0; p < m_plots.size(); ++p) {
        QCustomPlot* plot = m_plots[p];
        const bool r = p == kLiftPlot && !m_follower;  // r is not the design's lift
        for (int which = 0; which < 2; ++which) {
            QCPGraph* graph = plot->graph(kCurvesPerPlot + which);
            const auto& data = which == 0 ? m_data->designLaw : m_data->designOnContour;
            const std::size_t d = m_follower ? motionIndex(p) : std::min<std::size_t>(p + 1, 3);
            const bool has = shown && !r && data[d] && !(m_follower && which == 1);
            if (has) {
                graph->setData(data[d]);
                graph->addToLegend();
            } else {
                clearGraph(graph);
                graph->removeFromLegend();
            }
        }
        queueReplot(plot);
    }
}

bool KinematicsPlots::showsDesign() const {
    return m_plots[0]->graph(kCurvesPerPlot)->dataCount() > 0;
}

QString KinematicsPlots::staleReason() const { return m_staleLabel->reason(); }

void KinematicsPlots::setStale(const QString& reason) {
    if (!m_staleLabel->setReason(reason)) return;
    const bool stale = m_staleLabel->isStale();
    for (QCustomPlot* plot : m_plots) {
        for (int c = 0; c < plot->graphCount(); ++c) {
            QPen pen = plot->graph(c)->pen();
            pen.setColor(stale                 ? staleColor()
                         : c < kCurvesPerPlot  ? componentColor(c)
                         : c == kFollowerGraph ? componentColor(0)
                                               : designPen(c - kCurvesPerPlot).color());
            plot->graph(c)->setPen(pen);
        }
        queueReplot(plot);
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
        std::min(curves.levelFor(visible, axisWidth > 0 ? axisWidth : m_plots[0]->width()),
                 m_data->levels.size() - 1);
    // By its buckets: a result with finer levels numbers the same levels differently.
    const std::size_t bucket = curves.levels[level].samplesPerBucket;
    const bool same = bucket == m_levelBucket;
    m_level = level;
    m_levelBucket = bucket;
    if ((same && !force) || m_follower) return;  // the follower's curves have one level
    const auto& containers = m_data->levels[m_level];
    for (int p = 0; p < 3; ++p) {
        for (int c = 0; c < 3; ++c) {
            m_plots[static_cast<std::size_t>(p)]->graph(c)->setData(
                containers[static_cast<std::size_t>(3 * p + c)]);
        }
        queueReplot(m_plots[static_cast<std::size_t>(p)]);
    }
    m_plots[kLiftPlot]->graph(0)->setData(containers[static_cast<std::size_t>(Curve::R)]);
    queueReplot(m_plots[kLiftPlot]);
}

void KinematicsPlots::fitY() {
    if (!m_result) return;
    // The worker measured the ranges; rescaling here would scan every point again.
    for (std::size_t p = 0; p < m_plots.size(); ++p) {
        const PlotRange& y = m_follower ? m_result->followerMotionRanges[motionIndex(p)]
                                        : m_result->curves.yRanges[p];
        QCPRange range(y.lower, y.upper);
        if (showsDesign() && (p < 3 || m_follower)) {
            // The law's own range (over the follower's motion the on-contour one is drawn
            // already, but the design's range holds it too: no harm).
            const PlotRange& d = m_result->design->yRanges[m_follower ? motionIndex(p) : p + 1];
            range.expand(QCPRange(d.lower, d.upper));
        }
        if (!(range.size() > 0.0)) range = QCPRange(range.lower - 1.0, range.upper + 1.0);
        m_plots[p]->yAxis->setRange(range);
        m_plots[p]->yAxis->scaleRange(1.08);
        queueReplot(m_plots[p]);
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
    for (QCPItemStraightLine* cursor : m_cursors) moveCursorLine(cursor, x);
}

void KinematicsPlots::rebuildJointMarkers() {
    // Where (phi = omega·t, t in [0, T)) each joint where a_r jumps comes up in the plotted turn.
    std::vector<double> xs;
    if (m_result && m_result->valid() && m_follower) {
        // Where the follower passes a joint at which a_r jumps: the contact passes it there,
        // not where the ray does (a roller, an offset, an arm).
        for (std::size_t i = 0; i < m_result->followerJointX.size(); ++i) {
            for (const JointAnalysis& j : m_result->joints) {
                if (j.left == m_result->followerJointLeft[i] && j.continuity != Continuity::C2) {
                    xs.push_back(m_result->followerJointX[i]);
                }
            }
        }
    } else if (m_result && m_result->valid()) {
        const double omega = m_result->omega;
        for (const JointAnalysis& j : m_result->joints) {
            if (j.continuity == Continuity::C2) continue;  // a_r is continuous here
            const double sign = omega > 0 ? 1.0 : -1.0;
            double phi = std::fmod(sign * j.phi, kTwoPi);
            if (phi < 0) phi += kTwoPi;
            xs.push_back(m_axis == PlotAxis::Angle ? radToDeg(sign * phi) : phi / std::abs(omega));
        }
    }
    // The lines there are, moved; only the difference is made or removed (an edit seldom
    // changes the number of joints, and items are costly to make and remove).
    const std::size_t wanted = xs.size() * m_plots.size();
    while (m_jointMarkers.size() > wanted) {
        m_jointMarkers.back()->parentPlot()->removeItem(m_jointMarkers.back());
        m_jointMarkers.pop_back();
    }
    while (m_jointMarkers.size() < wanted) {
        auto* line = new QCPItemStraightLine(m_plots[m_jointMarkers.size() % m_plots.size()]);
        line->setPen(QPen(QColor(200, 120, 0, 150), 1, Qt::DotLine));
        line->setSelectable(false);
        line->setVisible(!m_staleLabel->isStale());
        line->setProperty(kNotInPictures, true);
        m_jointMarkers.push_back(line);
    }
    for (std::size_t i = 0; i < wanted; ++i) {
        const double x = xs[i / m_plots.size()];
        m_jointMarkers[i]->point1->setCoords(x, 0);
        m_jointMarkers[i]->point2->setCoords(x, 1);
    }
}

}  // namespace cam
