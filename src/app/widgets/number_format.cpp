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
    return displayLocale().toString(cleaned(value), 'g', significant);
}

QString formatFixed(double value, int decimals) {
    const QString text = displayLocale().toString(cleaned(value), 'f', decimals);
    // -0.0004 with three decimals is "-0.000": the sign of a value that rounds to 0 goes.
    const QLocale locale = displayLocale();
    const QString zero = locale.toString(0.0, 'f', decimals);
    return text.mid(1) == zero && text.startsWith(locale.negativeSign()) ? zero : text;
}

}  // namespace cam
