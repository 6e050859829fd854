#include "views/plot_setup.h"

#include <qcustomplot.h>

#include "views/axis_format.h"

namespace cam {

QCustomPlot* newAlongXPlot(QWidget* parent, const char* objectName, const QString& yLabel) {
    auto* plot = new QCustomPlot(parent);
    if (objectName) plot->setObjectName(objectName);
    plot->yAxis->setLabel(yLabel);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot->axisRect()->setRangeDrag(Qt::Horizontal);
    plot->axisRect()->setRangeZoom(Qt::Horizontal);
    applyAxisFormat(plot);
    return plot;
}

void clearGraph(QCPGraph* graph) {
    graph->setData(QSharedPointer<QCPGraphDataContainer>::create());
}

}  // namespace cam
