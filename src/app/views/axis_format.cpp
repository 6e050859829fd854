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
            const QSharedPointer<QCPAxisTicker> own(new LocaleAxisTicker);
            own->setTickCount(axis->ticker()->tickCount());
            own->setTickStepStrategy(axis->ticker()->tickStepStrategy());
            own->setTickOrigin(axis->ticker()->tickOrigin());
            axis->setTicker(own);
        }
    }
}

}  // namespace cam
