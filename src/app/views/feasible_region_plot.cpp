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
    legend->setMargins(QMargins(4, 0, 4, 2));
    plotLayout()->setRowStretchFactor(1, 0.001);
}

void FeasibleRegionPlot::setRegion(const std::vector<std::array<double, 2>>& edge,
                                   std::array<double, 2> chosen, std::array<double, 2> current) {
    QVector<double> x, y;
    double low = chosen[1], high = std::max(chosen[1], current[1]);
    for (const auto& [offset, radius] : edge) {
        x.push_back(offset);
        y.push_back(std::isfinite(radius) ? radius : std::nan(""));
        if (std::isfinite(radius)) {
            low = std::min(low, radius);
            high = std::max(high, radius);
        }
    }
    // Everything above the edge passes: shaded up to a little above the tallest point.
    const double ceiling = high + 0.25 * std::max(high - low, 1.0);
    graph(0)->setData(x, y, true);
    graph(1)->setData(x, QVector<double>(x.size(), ceiling), true);
    graph(2)->setData(QVector<double>{chosen[0]}, QVector<double>{chosen[1]});
    graph(3)->setData(QVector<double>{current[0]}, QVector<double>{current[1]});
    const double left = std::min(x.isEmpty() ? chosen[0] : x.front(), current[0]);
    const double right = std::max(x.isEmpty() ? chosen[0] : x.back(), current[0]);
    xAxis->setRange(left, right);
    yAxis->setRange(std::max(0.0, low - 0.1 * (ceiling - low)), ceiling);
    replot();
}

}  // namespace cam
