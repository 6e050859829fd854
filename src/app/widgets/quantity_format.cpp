#include "widgets/quantity_format.h"

#include <QCoreApplication>
#include <cmath>

#include "common/angles.h"
#include "widgets/number_format.h"

namespace cam {

QString quantityUnit(DisplayQuantity quantity) {
    const char* unit = quantityFormat(quantity).unit;
    return *unit ? QCoreApplication::translate("cam::DisplayQuantity", unit) : QString();
}

QString formatQuantityValue(DisplayQuantity quantity, double value) {
    // A count of 2.5 is a computed mean, not a count: counts are whole.
    if (quantity == DisplayQuantity::Count && std::isfinite(value)) value = std::round(value);
    return formatNumber(value, quantityFormat(quantity).significant);
}

QString formatQuantity(DisplayQuantity quantity, double value) {
    const QString number = formatQuantityValue(quantity, value);
    const QString unit = quantityUnit(quantity);
    if (unit.isEmpty()) return number;
    return quantityFormat(quantity).spaced ? number + QLatin1Char(' ') + unit : number + unit;
}

QString formatRadians(double rad) { return formatQuantity(DisplayQuantity::Angle, radToDeg(rad)); }

QString formatPoint(double x, double y) {
    // German writes (12,5; -3): a comma between the coordinates would read as a decimal one.
    return QCoreApplication::translate("cam::DisplayQuantity", "(%1, %2)")
        .arg(formatQuantityValue(DisplayQuantity::Length, x),
             formatQuantityValue(DisplayQuantity::Length, y));
}

}  // namespace cam
