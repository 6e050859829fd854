#include "mainwindow.h"

#include <qcustomplot.h>

#include <QSplitter>
#include <QStatusBar>

#include "common/angles.h"
#include "contour/contour.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"

namespace cam {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle("Camwright");
    auto* splitter = new QSplitter(this);
    m_contourPlot = new QCustomPlot(splitter);
    m_radiusPlot = new QCustomPlot(splitter);
    m_contourPlot->xAxis->setLabel("x [mm]");
    m_contourPlot->yAxis->setLabel("y [mm]");
    m_radiusPlot->xAxis->setLabel("φ [°]");
    m_radiusPlot->yAxis->setLabel("r [mm]");
    setCentralWidget(splitter);
    resize(1200, 600);
    statusBar()->showMessage(tr("Open a project to see its contour."));
}

QString MainWindow::openProject(const QString& path) {
    const auto loaded = loadProjectFile(path.toStdString());
    if (!loaded.ok()) {
        QStringList lines;
        for (const Diagnostic& d : loaded.errors()) lines << QString::fromStdString(d.text());
        return tr("%1 cannot be opened:\n%2").arg(path, lines.join('\n'));
    }
    const auto contour = Contour::build(loaded.value());
    SampledTurn turn;
    const double omega = loaded.value().motion.omegaRadS();
    sampleTurn(contour.value(), omega, 3600, turn);

    auto* curve = new QCPCurve(m_contourPlot->xAxis, m_contourPlot->yAxis);
    QVector<double> x(turn.x.begin(), turn.x.end()), y(turn.y.begin(), turn.y.end());
    x.push_back(x.front());
    y.push_back(y.front());
    curve->setData(x, y);
    m_contourPlot->rescaleAxes();
    m_contourPlot->yAxis->setScaleRatio(m_contourPlot->xAxis, 1.0);
    m_contourPlot->replot();

    QVector<double> phi, r(turn.r.begin(), turn.r.end());
    for (double p : turn.phi) phi.push_back(radToDeg(p));
    m_radiusPlot->addGraph()->setData(phi, r, true);
    m_radiusPlot->rescaleAxes();
    m_radiusPlot->replot();
    setWindowTitle(QString("%1 — Camwright").arg(QString::fromStdString(loaded.value().name)));
    statusBar()->showMessage(tr("%1 segments").arg(loaded.value().contour.size()));
    return {};
}

}  // namespace cam
