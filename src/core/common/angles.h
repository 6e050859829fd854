#pragma once
/// @file
/// @brief Angle constants and conversions. The core works in radians; files and UI in degrees.

#include <numbers>

namespace cam {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

[[nodiscard]] constexpr double degToRad(double deg) { return deg * (kPi / 180.0); }
[[nodiscard]] constexpr double radToDeg(double rad) { return rad * (180.0 / kPi); }

}  // namespace cam
