#pragma once
/// @file
/// @brief How the window writes numbers (table cells, readout, Joints, design table, follower
/// checks): the user's decimal separator, no thousands separators anywhere (a cell shows what
/// one types into it), and round-off of an exact zero written as 0, never "-0" or
/// "1.279561153e-15". Exports write numbers their own way (core export/number_text.h).

#include <QString>

namespace cam {

/// @brief Below this, a value in the unit it is shown in (mm, degrees, mm/s, …) is round-off
/// of an exact 0: cos 90° is 6.1e-17, a centre computed on the y axis 1.3e-15 mm.
inline constexpr double kRoundOffZero = 1e-9;

/// @brief `value` with at most `significant` significant digits in the user's locale.
[[nodiscard]] QString formatNumber(double value, int significant);

/// @brief `value` with `decimals` digits after the decimal separator in the user's locale.
[[nodiscard]] QString formatFixed(double value, int decimals);

}  // namespace cam
