#include "views/stress_overlay.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

#include "widgets/quantity_format.h"

namespace cam {

StressOverlay::StressOverlay(QCustomPlot* plot) : m_plot(plot) {
    // Blue for no stress through green and yellow to red at the top of the scale.
    QCPColorGradient gradient(QCPColorGradient::gpJet);
    for (int i = 0; i < kBands; ++i) {
        auto* curve = new QCPCurve(plot->xAxis, plot->yAxis);
        curve->setName(QStringLiteral("stress band %1").arg(i));
        curve->removeFromLegend();
        curve->setPen(QPen(QColor::fromRgb(gradient.color(i + 0.5, QCPRange(0, kBands))), 4.0,
                           Qt::SolidLine, Qt::RoundCap));
        curve->setSelectable(QCP::stNone);
        curve->setVisible(false);
        m_bands[static_cast<std::size_t>(i)] = curve;
    }
    m_label = new QCPItemText(plot);
    m_label->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_label->position->setCoords(0.02, 0.02);
    m_label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_label->setBrush(QColor(255, 255, 255, 220));
    m_label->setPadding(QMargins(4, 2, 4, 2));
    m_label->setTextAlignment(Qt::AlignLeft);
    m_label->setVisible(false);
}

int StressOverlay::bandOf(double stress) const {
    if (!(m_top > 0.0) || !std::isfinite(stress)) return 0;
    return std::clamp(static_cast<int>(stress / m_top * kBands), 0, kBands - 1);
}

QString StressOverlay::label() const { return m_label->visible() ? m_label->text() : QString(); }

void StressOverlay::show(const ComputeResult* r, bool on) {
    for (QCPCurve* curve : m_bands) {
        curve->data()->clear();
        curve->setVisible(false);
    }
    m_label->setVisible(false);
    m_top = 0.0;
    if (!on || !r || !r->valid() || !r->forces || r->forces->contactX.empty()) return;
    const ForceCurves& f = *r->forces;
    const std::vector<double>& stress = f.curves.stress;
    double largest = 0.0;
    for (const double p : stress) {
        if (std::isfinite(p)) largest = std::max(largest, p);
    }
    m_top = f.model.allowableMpa ? *f.model.allowableMpa : largest;
    if (!(m_top > 0.0)) return;
    // Each step k → k + 1 of the turn in the band of its stress; a band's runs are separated
    // by a gap (NaN), so that twelve curves draw the whole profile.
    constexpr double kGap = std::numeric_limits<double>::quiet_NaN();
    std::array<QVector<QCPCurveData>, kBands> data;
    int previous = -1;
    const std::vector<double>& normal = f.curves.normal;
    for (std::size_t k = 0; k + 1 < stress.size(); ++k) {
        if (!std::isfinite(stress[k])) {  // the follower has left the cam: nothing touches
            previous = -1;
            continue;
        }
        // Form-closed, the load passes to the other contact (the outer flank, the second
        // plate) and back: no line across from one to the other.
        if (f.model.formClosed() && (normal[k] < 0.0) != (normal[k + 1] < 0.0)) {
            previous = -1;
            continue;
        }
        const int b = bandOf(stress[k]);
        auto& points = data[static_cast<std::size_t>(b)];
        if (b != previous) {
            if (!points.isEmpty()) points.append(QCPCurveData(points.size(), kGap, kGap));
            points.append(QCPCurveData(points.size(), f.contactX[k], f.contactY[k]));
        }
        points.append(QCPCurveData(points.size(), f.contactX[k + 1], f.contactY[k + 1]));
        previous = b;
    }
    for (int i = 0; i < kBands; ++i) {
        QCPCurve* curve = m_bands[static_cast<std::size_t>(i)];
        curve->data()->set(data[static_cast<std::size_t>(i)], true);
        curve->setVisible(true);
    }
    const QString top = formatQuantity(DisplayQuantity::Stress, m_top);
    // Two short lines: the contour view is often narrow.
    m_label->setText(f.model.allowableMpa
                         ? QCoreApplication::translate("cam::StressOverlay",
                                                       "Contact stress\nblue 0 … red %1 "
                                                       "(allowable)")
                               .arg(top)
                         : QCoreApplication::translate("cam::StressOverlay",
                                                       "Contact stress\nblue 0 … red %1 "
                                                       "(largest)")
                               .arg(top));
    m_label->setVisible(true);
}

}  // namespace cam
