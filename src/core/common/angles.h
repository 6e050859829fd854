#pragma once
/// @file
/// @brief Angle constants and conversions. The core works in radians; files and UI in degrees.

#include <cmath>
#include <numbers>

namespace cam {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

[[nodiscard]] constexpr double degToRad(double deg) { return deg * (kPi / 180.0); }
[[nodiscard]] constexpr double radToDeg(double rad) { return rad * (180.0 / kPi); }

/// @brief An angle in degrees wrapped into (-180, 180].
[[nodiscard]] inline double wrapDeg(double deg) {
    const double w = std::remainder(deg, 360.0);
    return w <= -180.0 ? w + 360.0 : w;
}

/// @brief An angle in degrees reduced into [0, 360).
[[nodiscard]] inline double mod360(double deg) {
    const double m = std::fmod(deg, 360.0);
    return m < 0.0 ? m + 360.0 : m;
}

/// @brief An angle in radians reduced into [0, 2π).
[[nodiscard]] inline double wrapTwoPi(double rad) {
    const double m = std::fmod(rad, kTwoPi);
    return m < 0.0 ? (m + kTwoPi < kTwoPi ? m + kTwoPi : 0.0) : m;
}

}  // namespace cam
