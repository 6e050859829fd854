#include "views/path_study_panel.h"

#include <qcustomplot.h>

#include <QLabel>
#include <QShowEvent>
#include <QVBoxLayout>

#include "views/axis_format.h"
#include "views/palette.h"
#include "views/plot_redraw.h"
#include "widgets/quantity_format.h"

namespace cam {

PathStudyPanel::PathStudyPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    const QString labels[] = {tr("x, y [mm]"), tr("x', y' [mm]"), tr("x'', y'' [mm]"),
                              tr("quot. − anal.")};
    for (int p = 0; p < 4; ++p) {
        auto* plot = new QCustomPlot(this);
        plot->setMinimumHeight(110);
        plot->yAxis->setLabel(labels[p]);
        plot->xAxis->setLabel(p == 3 ? tr("segment parameter t") : QString());
        plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        applyAxisFormat(plot);
        const int graphs = p == 3 ? 4 : 4;
        for (int g = 0; g < graphs; ++g) {
            QCPGraph* graph = plot->addGraph();
            const QColor color = componentColor(g % 2);  // x blue, y red
            if (p < 3) {
                // Analytic solid; difference quotient as small circles on top.
                graph->setPen(g < 2 ? QPen(color, 1.2) : QPen(Qt::NoPen));
                if (g >= 2) {
                    graph->setLineStyle(QCPGraph::lsNone);
                    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, color, 3));
                }
                graph->setName(QString(g % 2 ? "y" : "x") +
                               (g < 2 ? tr(" analytic") : tr(" quotient")));
            } else {
                graph->setPen(QPen(color, 1.0, g < 2 ? Qt::SolidLine : Qt::DashLine));
                graph->setName(QString(g % 2 ? "y" : "x") + (g < 2 ? "'" : "''"));
            }
        }
        m_plots[static_cast<std::size_t>(p)] = plot;
        layout->addWidget(plot, 1);
    }
    m_note->setText(tr("The contour has no Bézier or Hermite segment."));
}

void PathStudyPanel::setResult(const ComputeResultPtr& result) {
    if (!result) return;
    setEnabled(result->ok());  // greyed: the splines of the last project that could be computed
    if (!result->ok()) return;
    m_result = result;
    m_stale = !isVisible();  // hidden (the default): no replots while edits stream in
    if (!m_stale) fill();
}

void PathStudyPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_stale) fill();
}

void PathStudyPanel::fill() {
    m_stale = false;
    if (!m_result) return;
    const PathStudy& s = m_result->pathStudy;
    // Without splines there is nothing to plot: the note alone says so, no empty axes.
    for (QCustomPlot* p : m_plots) p->setVisible(!s.t.empty());
    if (s.t.empty()) {
        m_note->setText(tr("The contour has no Bézier or Hermite segment."));
        for (QCustomPlot* p : m_plots) {
            for (int g = 0; g < p->graphCount(); ++g) p->graph(g)->data()->clear();
        }
        return;
    }
    m_note->setText(tr("The contour's splines one after another over their parameter t (piece "
                       "k runs from k to k + 1). Blue x, red y; lines analytic, circles the "
                       "difference quotients (step h = %1); at the bottom their difference, "
                       "solid for the first and dashed for the second derivative.")
                        .arg(formatQuantityValue(DisplayQuantity::Ratio, s.step)));
    const QVector<double> t(s.t.begin(), s.t.end());
    auto vec = [](const std::vector<double>& v) { return QVector<double>(v.begin(), v.end()); };
    for (int p = 0; p < 3; ++p) {
        for (int c = 0; c < 2; ++c) {
            const std::size_t k = static_cast<std::size_t>(2 * p + c);
            m_plots[static_cast<std::size_t>(p)]->graph(c)->setData(t, vec(s.analytic[k]), true);
            m_plots[static_cast<std::size_t>(p)]->graph(2 + c)->setData(t, vec(s.quotient[k]),
                                                                        true);
        }
    }
    for (int g = 0; g < 4; ++g) {
        const std::size_t k = static_cast<std::size_t>(PathStudy::DX + (g % 2) + 2 * (g / 2));
        QVector<double> diff(static_cast<int>(t.size()));
        for (int i = 0; i < diff.size(); ++i) {
            diff[i] = s.quotient[k][static_cast<std::size_t>(i)] -
                      s.analytic[k][static_cast<std::size_t>(i)];
        }
        m_plots[3]->graph(g)->setData(t, diff, true);
    }
    for (QCustomPlot* p : m_plots) {
        p->rescaleAxes();
        p->yAxis->scaleRange(1.1);
        queueReplot(p);
    }
}

}  // namespace cam
