#pragma once
/// @file
/// @brief How the window writes a number: the user's decimal separator, no thousands
/// separators anywhere (a cell shows what one types into it), round-off of an exact zero
/// written as 0, never "-0" or "1.279561153e-15", and no exponent for a large value. How many
/// digits each kind of number gets, and its unit, is quantity_format.h's table. Exports write
/// numbers their own way (core export/number_text.h).

#include <QString>

namespace cam {

/// @brief Below this, a value in the unit it is shown in (mm, degrees, mm/s, …) is round-off
/// of an exact 0: cos 90° is 6.1e-17, a centre computed on the y axis 1.3e-15 mm.
inline constexpr double kRoundOffZero = 1e-9;

/// @brief `value` with at most `significant` significant digits in the user's locale, as %g
/// writes it except from 10^significant up: there the value rounded to `significant` digits is
/// written whole (a jerk of 407472740.8 mm/s³ to 6 digits is 407473000, not 4.07473E+08).
/// Below 10⁻⁴ it keeps %g's exponent (2E-09), the notation a cell accepts. ±∞ is "∞", "-∞".
[[nodiscard]] QString formatNumber(double value, int significant);

/// @brief `text`, a finite `value` written by a locale, with its exponent as "E" whatever the
/// locale (C writes 1e-06, German 1E-06): numbers read the same in either language.
[[nodiscard]] QString withCapitalExponent(QString text, double value);

}  // namespace cam
