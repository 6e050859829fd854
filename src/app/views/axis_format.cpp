#include "views/axis_format.h"

#include <qcustomplot.h>

#include <cmath>
#include <typeinfo>

namespace cam {
namespace {

/// Significant digits of a tick label (QCustomPlot's default precision).
constexpr int kTickDigits = 6;

/// The default ticker's tick positions with the policy's labels.
class LocaleAxisTicker : public QCPAxisTicker {
public:
    int mostTicks = 5;  ///< the tick count asked for where the axis is long enough

protected:
    QString getTickLabel(double tick, const QLocale& locale, QChar /*formatChar*/,
                         int /*precision*/) override {
        return axisTickLabel(tick, locale);
    }

    QVector<double> createTickVector(double tickStep, const QCPRange& range) override {
        QVector<double> ticks = QCPAxisTicker::createTickVector(tickStep, range);
        // A tick at k·step that should be 0 can be 1e-17: written as such it reads 1·10⁻¹⁷.
        for (double& t : ticks) {
            if (std::abs(t) < std::abs(tickStep) * 1e-9) t = 0.0;
        }
        return ticks;
    }
};

/// Fewer ticks on a vertical axis too short for the default's labels: the ticker's readable
/// steps are kept, and at least a label's height and a fifth is left from one tick to the next.
/// (The Motion Design dock's four plots share a small dock: at 70 px the lift axis wrote
/// "15 12.5 10 7.5" into one another.)
void fitVerticalTickCounts(QCustomPlot* plot) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPAxis* axis : rect->axes(QCPAxis::atLeft | QCPAxis::atRight)) {
            auto* ticker = dynamic_cast<LocaleAxisTicker*>(axis->ticker().data());
            if (!ticker || !axis->tickLabels() || rect->height() <= 0) continue;
            const double room = 1.2 * QFontMetricsF(axis->tickLabelFont()).height();
            const double pixelsPerUnit = rect->height() / axis->range().size();
            int count = ticker->mostTicks;
            for (; count > 1; --count) {
                ticker->setTickCount(count);
                QVector<double> ticks;
                ticker->generate(axis->range(), plot->locale(), QLatin1Char('g'),
                                 axis->numberPrecision(), ticks, nullptr, nullptr);
                if (ticks.size() < 2 || (ticks[1] - ticks[0]) * pixelsPerUnit >= room) break;
            }
            ticker->setTickCount(count);
        }
    }
}

QString superscript(int exponent) {
    static const QChar digits[] = {u'⁰', u'¹', u'²', u'³', u'⁴', u'⁵', u'⁶', u'⁷', u'⁸', u'⁹'};
    QString out = exponent < 0 ? QStringLiteral("⁻") : QString();
    for (const QChar c : QString::number(std::abs(exponent))) out += digits[c.digitValue()];
    return out;
}

}  // namespace

QString axisTickLabel(double value, const QLocale& locale) {
    QLocale shown = locale;
    shown.setNumberOptions(shown.numberOptions() | QLocale::OmitGroupSeparator);
    if (value == 0.0 || !std::isfinite(value)) return shown.toString(value == 0.0 ? 0.0 : value);
    // Rounded to the label's digits first: 999999.7 is 1·10⁶, not 10·10⁵.
    const QString c = QString::number(value, 'e', kTickDigits - 1);
    const int exponent = c.mid(c.indexOf('e') + 1).toInt();
    // Where %g would write an exponent: below 1e-4 or from 10^digits up.
    if (exponent >= -4 && exponent < kTickDigits) return shown.toString(value, 'g', kTickDigits);
    const double mantissa = c.left(c.indexOf('e')).toDouble();
    return shown.toString(mantissa, 'g', kTickDigits) + QStringLiteral("·10") +
           superscript(exponent);
}

void applyAxisFormat(QCustomPlot* plot) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPAxis* axis : rect->axes()) {
            // Only the default ticker: a special one (time, text) keeps its own labels.
            if (typeid(*axis->ticker()) != typeid(QCPAxisTicker)) continue;
            const QSharedPointer<LocaleAxisTicker> own(new LocaleAxisTicker);
            own->mostTicks = axis->ticker()->tickCount();
            own->setTickCount(own->mostTicks);
            own->setTickStepStrategy(axis->ticker()->tickStepStrategy());
            own->setTickOrigin(axis->ticker()->tickOrigin());
            axis->setTicker(own);
        }
    }
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot,
                     [plot] { fitVerticalTickCounts(plot); });
}

}  // namespace cam
