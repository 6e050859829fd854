#pragma once
/// @file
/// @brief The motion laws of VDI 2143 that a design segment follows (math.md §8), normalised
/// on x in [0, 1], and poly5 with boundary values.

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "project/project.h"

namespace cam {

/// @brief y and its derivatives with respect to x.
struct LawPoint {
    double y = 0.0, v = 0.0, a = 0.0, j = 0.0;
};

/// @brief A law's characteristic values: the largest |y'|, |y''|, |y'''| over [0, 1] (for
/// Harmonic cj is the largest |y'''| inside the interval: its acceleration jumps at the ends).
struct LawCoefficients {
    double cv = 0.0, ca = 0.0, cj = 0.0;
};

/// @brief How a law's stretch is shaped.
enum class LawShape {
    Dwell,           ///< keeps the lift it starts with
    Normalised,      ///< a rise (or return) law y(x) on [0, 1] scaled to the stretch
    BoundaryValues,  ///< poly5: slopes and curvatures given at both ends (Poly5Law)
};

/// @brief A motion law, described once. Adding a law: its enumerator in CAM_MOTION_LAWS
/// (project/project.h), its row of the table in motion_law.cpp (name, title, shape, function,
/// coefficients in closed form), and what docs/architecture.md's recipe "A motion law" lists
/// beside (its reference row in tests/core/motion_law_test.cpp, the German title, the docs and
/// the spec). No code elsewhere lists laws.
struct MotionLawKind {
    MotionLawType type;
    std::string_view name;  ///< in project files: "modified-trapezoid"
    /// English, for the window's law column; the app translates it in context "MotionLaw".
    const char* title;
    LawShape shape;
    /// Normalised: y and its derivatives on x ∈ [0, 1], y(0) = 0, y(1) = 1; null otherwise.
    LawPoint (*normalised)(double x);
    /// Normalised: its coefficients in closed form; null otherwise (a dwell has none, a
    /// poly5's depend on its segment: MotionDesign::coefficients).
    LawCoefficients (*coefficients)();
};

/// @brief Every law, in MotionLawType order.
[[nodiscard]] std::span<const MotionLawKind> motionLaws();
/// @brief The row of a law.
[[nodiscard]] const MotionLawKind& motionLaw(MotionLawType law);

/// @brief A rise law normalised to y(0) = 0, y(1) = 1; zero for a law that is not normalised
/// (the dwell, poly5: see Poly5Law). x outside [0, 1] is clamped.
[[nodiscard]] LawPoint normalisedLaw(MotionLawType law, double x);
/// @brief A normalised law's coefficients; zero for the others.
[[nodiscard]] LawCoefficients lawCoefficients(MotionLawType law);

/// @brief The name in project files ("dwell", "harmonic", …) and back (none for an unknown
/// name: a file that names one is refused, never read as a dwell).
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
