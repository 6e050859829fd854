#pragma once
/// @file
/// @brief The one table of how many significant digits each kind of number the window shows
/// has, and its unit (issue 14): the readout, the follower checks, the Joints tab, the
/// machining times, the motion and design summaries, the tables' cells and tooltips, dialogs
/// and status messages all write a number through it. How a number is written (the user's
/// decimal separator, no thousands groups, round-off as 0, no exponent for large values) is
/// number_format.h's; plot ticks follow their step instead (views/axis_format.h).

#include <QString>
#include <QtGlobal>
#include <array>
#include <cstddef>

namespace cam {

/// @brief What a shown number is: it decides the digits and the unit. (The core's Quantity
/// names the curves whose extremes it finds.)
enum class DisplayQuantity {
    Angle,                     ///< φ, windows, pressure and tangent-break angles [°]
    Length,                    ///< coordinates, radii, r, path lengths [mm]
    Velocity,                  ///< [mm/s]
    Acceleration,              ///< [mm/s²]
    Jerk,                      ///< [mm/s³]
    Time,                      ///< t on the cam's clock, periods, machining times [s]
    Duration,                  ///< how long a computation took [ms]
    AngularSpeed,              ///< ω [rad/s]
    RotationSpeed,             ///< the cam's speed in turns [rpm]
    Ratio,                     ///< dimensionless: speed ratios, relative jumps, law coefficients
    LengthError,               ///< a deviation, tolerance or error bound [mm]
    AngleError,                ///< the same of a swinging arm's angle [°]
    VelocityError,             ///< [mm/s]
    AngularVelocityError,      ///< a swinging arm's [°/s]
    AccelerationError,         ///< [mm/s²]
    AngularAccelerationError,  ///< a swinging arm's [°/s²]
    RelativeError,             ///< a dimensionless error estimate
    Force,                     ///< contact, spring and guide forces [N]
    Moment,                    ///< camshaft torque, an arm's moment [N·m]
    Power,                     ///< the camshaft's power [W]
    Stress,                    ///< the Hertz contact stress [MPa]
    AngularVelocity,           ///< a swinging arm's speed [°/s]
    AngularAcceleration,       ///< [°/s²]
    AngularJerk,               ///< [°/s³]
    Count,                     ///< samples, grid points (whole numbers)
    Input,                     ///< a value the user types in a cell; its unit is in the header
};

inline constexpr std::size_t kQuantityCount = static_cast<std::size_t>(DisplayQuantity::Input) + 1;

/// @brief How one DisplayQuantity is written.
struct QuantityFormat {
    DisplayQuantity quantity;
    int significant;   ///< significant digits (formatNumber's rule)
    const char* unit;  ///< untranslated unit (context cam::DisplayQuantity); "" for none
    bool spaced;       ///< a space between number and unit ("12 mm"), or none ("12°")
};

/// @brief The table, in the order of DisplayQuantity. Digits are significant digits
/// (formatNumber): from 10^digits up a value is written whole, rounded to its digits, never
/// with an exponent, so a jerk of 123456789012 mm/s³ (the six-lobe example reaches 1.2·10¹¹
/// at 1000 rpm) reads 123457000000 mm/s³; below 10⁻⁴ (a tiny deviation) %g writes an
/// exponent: 2.5E-05 mm.
inline constexpr std::array<QuantityFormat, kQuantityCount> kQuantityFormats{{
    // 359.9999°: 10⁻⁴° is 0.1 µm of arc at 60 mm, the resolution of a Length at cam sizes.
    {DisplayQuantity::Angle, 7, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°"), false},
    // 123.4567 mm: 0.1 µm on cams of 10 to 999 mm, finer than a grinding machine holds (1 µm).
    {DisplayQuantity::Length, 7, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm"), true},
    // 1234.56 mm/s, 356524 mm/s²: one part in 10⁵ to 10⁶, more than any check of a drive or
    // a measurement of the follower resolves; the seed's Table 2 prints fewer.
    {DisplayQuantity::Velocity, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm/s"), true},
    {DisplayQuantity::Acceleration, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm/s²"), true},
    {DisplayQuantity::Jerk, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm/s³"), true},
    // 0.123456 s: 1 µs in a turn of a tenth of a second (a 10⁻⁴° step at 1000 rpm is 17 ns,
    // below any drive's cycle); a machining time of minutes to the millisecond.
    {DisplayQuantity::Time, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "s"), true},
    // 12.3 ms: a measured compute time varies by more than 1 % from run to run.
    {DisplayQuantity::Duration, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "ms"), true},
    // 157.08 rad/s, 1500 rpm: a speed typed with a few digits reads back as typed, and one
    // converted from another unit keeps one part in 10⁶.
    {DisplayQuantity::AngularSpeed, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "rad/s"), true},
    {DisplayQuantity::RotationSpeed, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "rpm"), true},
    // 6.283, 0.9987: four digits tell two laws (Ca 6.283 against 5.528) or two Bézier
    // approximations apart; the rest is the sampling that computed them.
    {DisplayQuantity::Ratio, 4, "", false},
    // 0.00123 mm: an error bound or estimate is itself known to a few digits; the third says
    // which way to move a tolerance, more would be noise.
    {DisplayQuantity::LengthError, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm"), true},
    {DisplayQuantity::AngleError, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°"), false},
    {DisplayQuantity::VelocityError, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm/s"), true},
    {DisplayQuantity::AngularVelocityError, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°/s"),
     true},
    {DisplayQuantity::AccelerationError, 3, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "mm/s²"),
     true},
    {DisplayQuantity::AngularAccelerationError, 3,
     QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°/s²"), true},
    {DisplayQuantity::RelativeError, 3, "", false},
    // 123.456 N, 1.23456 N·m: the forces follow from a mass, a rate and materials a designer
    // knows to a few per cent; six digits let two results (law and arcs, window and CLI) be
    // compared, more would be noise.
    {DisplayQuantity::Force, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "N"), true},
    {DisplayQuantity::Moment, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "N·m"), true},
    {DisplayQuantity::Power, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "W"), true},
    {DisplayQuantity::Stress, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "MPa"), true},
    // An arm's motion as its lift's (°) and a translating follower's (mm/s and on): six digits.
    {DisplayQuantity::AngularVelocity, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°/s"), true},
    {DisplayQuantity::AngularAcceleration, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°/s²"),
     true},
    {DisplayQuantity::AngularJerk, 6, QT_TRANSLATE_NOOP("cam::DisplayQuantity", "°/s³"), true},
    // 10000000 samples: every digit of a count up to 9999999999 (the sample limit is 10⁷).
    {DisplayQuantity::Count, 10, "", false},
    // A typed value reads back as typed: 10 digits, as many as a message quotes (the core's
    // kMessageDigits) and as the cell's editor shows (NumberSpinBox).
    {DisplayQuantity::Input, 10, "", false},
}};

static_assert(
    [] {
        for (std::size_t i = 0; i < kQuantityCount; ++i) {
            if (kQuantityFormats[i].quantity != static_cast<DisplayQuantity>(i)) return false;
        }
        return true;
    }(),
    "kQuantityFormats lists every DisplayQuantity once, in the enum's order");

/// @brief The table's entry for `quantity`.
[[nodiscard]] constexpr const QuantityFormat& quantityFormat(DisplayQuantity quantity) {
    return kQuantityFormats[static_cast<std::size_t>(quantity)];
}

/// @brief The unit of `quantity` in the window's language; empty for a dimensionless one.
[[nodiscard]] QString quantityUnit(DisplayQuantity quantity);

/// @brief `value` with its quantity's digits and no unit: for a cell whose header names the
/// unit, or a point's coordinates. A Count is rounded to a whole number first.
[[nodiscard]] QString formatQuantityValue(DisplayQuantity quantity, double value);

/// @brief `value` with its quantity's digits and unit: "123.4568 mm", "45°", "0.25".
[[nodiscard]] QString formatQuantity(DisplayQuantity quantity, double value);

/// @brief A cam angle given in radians, written in degrees as an Angle: "123.4568°".
[[nodiscard]] QString formatRadians(double rad);

/// @brief A point of the cam's plane with Length digits and no unit (mm): "(12.5, -3)", in
/// German "(12,5; -3)".
[[nodiscard]] QString formatPoint(double x, double y);

}  // namespace cam
