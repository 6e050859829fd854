#include "widgets/number_format.h"

#include <QLocale>
#include <cmath>

namespace cam {

namespace {

QLocale displayLocale() {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale;
}

double cleaned(double value) {
    return std::abs(value) < kRoundOffZero ? 0.0 : value;  // -0 included
}

}  // namespace

QString formatNumber(double value, int significant) {
    const QLocale locale = displayLocale();
    if (std::isinf(value)) return value > 0 ? QStringLiteral("∞") : locale.negativeSign() + "∞";
    const double v = cleaned(value);
    // Only a value of at least 9·10^(digits−1) can round to 10^digits or more: the others (every
    // table cell, most readout values) skip the rounding through text.
    if (std::isfinite(v) && std::abs(v) >= 9.0 * std::pow(10.0, significant - 1)) {
        // Rounded first, as %g rounds: 999999.7 to 6 digits is 1000000, which %g writes 1E+06.
        const double rounded = QString::number(v, 'e', significant - 1).toDouble();
        if (std::abs(rounded) >= std::pow(10.0, significant)) {
            return locale.toString(rounded, 'f', 0);
        }
    }
    return withCapitalExponent(locale.toString(v, 'g', significant), v);
}

QString withCapitalExponent(QString text, double value) {
    // The C locale (the window's English) writes 1e-06, German 1E-06: one form in both.
    if (std::isfinite(value)) text.replace(QLatin1Char('e'), QLatin1Char('E'));
    return text;
}

}  // namespace cam
