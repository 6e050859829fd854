#pragma once
/// @file
/// @brief How every plot axis of the window writes its tick labels: the user's decimal
/// separator, no group separators, at most six significant digits, and a power of ten written
/// as one ("7.5·10⁶", German "7,5·10⁶") when the value is that large or small. QCustomPlot's own
/// "gb" format gives "7.5·10⁶" in English but "7,5E+06" in German (it looks for a lower-case
/// 'e', and German writes 'E').

#include <QLocale>
#include <QString>

class QCustomPlot;

namespace cam {

/// @brief A tick label for `value` in `locale` by the policy above.
[[nodiscard]] QString axisTickLabel(double value, const QLocale& locale);

/// @brief Gives every axis of `plot` (all its axis rects) the policy: call where the plot's
/// axes are made, after the last axis rect is added.
void applyAxisFormat(QCustomPlot* plot);

}  // namespace cam
