#pragma once
/// @file
/// @brief The motion laws of VDI 2143 that a design segment follows (math.md §8), normalised
/// on x in [0, 1], and poly5 with boundary values.

#include <array>
#include <optional>
#include <string_view>

#include "project/project.h"

namespace cam {

/// @brief y and its derivatives with respect to x.
struct LawPoint {
    double y = 0.0, v = 0.0, a = 0.0, j = 0.0;
};

/// @brief A rise law normalised to y(0) = 0, y(1) = 1; Dwell is y ≡ 0. Requires law != Poly5
/// (see Poly5Law). x outside [0, 1] is clamped.
[[nodiscard]] LawPoint normalisedLaw(MotionLawType law, double x);

/// @brief A law's characteristic values: the largest |y'|, |y''|, |y'''| over [0, 1] (for
/// Harmonic cj is the largest |y'''| inside the interval: its acceleration jumps at the ends).
struct LawCoefficients {
    double cv = 0.0, ca = 0.0, cj = 0.0;
};
[[nodiscard]] LawCoefficients lawCoefficients(MotionLawType law);

/// @brief The name in project files ("dwell", "harmonic", "cycloidal", "modified-trapezoid",
/// "modified-sine", "poly345", "poly4567", "poly5") and back (none for an unknown name).
[[nodiscard]] std::string_view lawName(MotionLawType law);
[[nodiscard]] std::optional<MotionLawType> lawFromName(std::string_view name);

/// @brief poly5 of math.md §8 on a stretch of width h (any angle unit) from y0 to y1 with
/// dy/dx = v0, v1 and d²y/dx² = a0, a1 at its ends (in that unit).
class Poly5Law {
public:
    Poly5Law(double h, double y0, double y1, double v0, double a0, double v1, double a1);
    /// @brief At u = (x − x0)/h in [0, 1]; derivatives with respect to x.
    [[nodiscard]] LawPoint at(double u) const;

private:
    double m_h;
    std::array<double, 6> m_c;  ///< y = Σ c_k u^k
};

}  // namespace cam
