#include "views/feasible_region_plot.h"

#include <algorithm>
#include <cmath>

#include "views/axis_format.h"

namespace cam {

FeasibleRegionPlot::FeasibleRegionPlot(QWidget* parent) : QCustomPlot(parent) {
    setObjectName("feasibleRegionPlot");
    setMinimumHeight(200);
    applyAxisFormat(this);
    xAxis->setLabel(tr("Offset [mm]"));
    yAxis->setLabel(tr("Base radius [mm]"));
    QCPGraph* edge = addGraph();
    edge->setName(tr("smallest base radius"));
    edge->setPen(QPen(QColor(31, 119, 180), 1.5));
    QCPGraph* top = addGraph();  // the shading runs from the edge up to it
    top->setName(tr("largest base radius"));
    top->setPen(Qt::NoPen);
    top->removeFromLegend();
    edge->setChannelFillGraph(top);
    edge->setBrush(QColor(44, 160, 44, 50));
    QCPGraph* chosen = addGraph();
    chosen->setName(tr("smallest cam"));
    chosen->setLineStyle(QCPGraph::lsNone);
    chosen->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(214, 39, 40), 8));
    QCPGraph* current = addGraph();
    current->setName(tr("design"));
    current->setLineStyle(QCPGraph::lsNone);
    current->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(60, 60, 60), 1.5), Qt::NoBrush, 8));
    // The legend in a row under the plot: inside it would hide a point wherever it sat.
    legend->setVisible(true);
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    legend->setFont(small);
    legend->setBorderPen(Qt::NoPen);
    axisRect()->insetLayout()->take(legend);
    plotLayout()->addElement(1, 0, legend);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend->setWrap(2);  // two entries a row: four in one are clipped in a narrow dock
    legend->setMargins(QMargins(4, 0, 4, 2));
    plotLayout()->setRowStretchFactor(1, 0.001);
}

void FeasibleRegionPlot::setRegion(Placement placement, const std::vector<FeasibleSpan>& region,
                                   std::array<double, 2> chosen, std::array<double, 2> current) {
    xAxis->setLabel(placement == Placement::Offset ? tr("Offset [mm]") : tr("Pivot distance [mm]"));
    QVector<double> x, lower, upper;
    double low = chosen[1], high = std::max(chosen[1], current[1]);
    bool bounded = false;  // an arm's radii end above too
    for (const FeasibleSpan& span : region) {
        x.push_back(span.placement);
        lower.push_back(std::isfinite(span.smallest) ? span.smallest : std::nan(""));
        if (std::isfinite(span.smallest)) {
            low = std::min(low, span.smallest);
            high = std::max(high, span.smallest);
        }
        if (std::isfinite(span.largest)) {
            high = std::max(high, span.largest);
            bounded = true;
        }
    }
    // Everything between the edges passes; where nothing bounds the radii from above, the
    // shading runs to a little above the tallest point.
    const double ceiling = high + (bounded ? 0.05 : 0.25) * std::max(high - low, 1.0);
    for (const FeasibleSpan& span : region) {
        upper.push_back(std::isfinite(span.largest)    ? span.largest
                        : std::isfinite(span.smallest) ? ceiling
                                                       : std::nan(""));
    }
    graph(0)->setData(x, lower, true);
    graph(1)->setData(x, upper, true);
    graph(1)->setPen(bounded ? QPen(QColor(255, 127, 14), 1.5) : QPen(Qt::NoPen));
    if (bounded) {
        graph(1)->addToLegend();
    } else {
        graph(1)->removeFromLegend();
    }
    graph(2)->setData(QVector<double>{chosen[0]}, QVector<double>{chosen[1]});
    graph(3)->setData(QVector<double>{current[0]}, QVector<double>{current[1]});
    const double left = std::min(x.isEmpty() ? chosen[0] : x.front(), current[0]);
    const double right = std::max(x.isEmpty() ? chosen[0] : x.back(), current[0]);
    xAxis->setRange(left, right);
    yAxis->setRange(std::max(0.0, low - 0.1 * (ceiling - low)), ceiling);
    replot();
}

void FeasibleRegionPlot::setCurrent(std::array<double, 2> current) {
    const QCPGraphDataContainer& now = *graph(3)->data();
    if (!now.isEmpty() && now.constBegin()->key == current[0] &&
        now.constBegin()->value == current[1]) {
        return;
    }
    graph(3)->setData(QVector<double>{current[0]}, QVector<double>{current[1]});
    // The axes grow to keep the marker in sight; they never shrink under it.
    const QCPRange x = xAxis->range(), y = yAxis->range();
    const double marginX = 0.05 * x.size(), marginY = 0.05 * y.size();
    if (!x.contains(current[0])) {
        xAxis->setRange(std::min(x.lower, current[0] - marginX),
                        std::max(x.upper, current[0] + marginX));
    }
    if (!y.contains(current[1])) {
        yAxis->setRange(std::min(y.lower, current[1] - marginY),
                        std::max(y.upper, current[1] + marginY));
    }
    replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace cam
