#pragma once
/// @file
/// @brief The motion laws of VDI 2143 that a design segment follows (math.md §8), normalised
/// on x in [0, 1], and poly5 with boundary values.

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "common/place.h"
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
    BoundaryValues,  ///< poly5, poly7: slopes (and their derivatives) given at both ends
    Table,           ///< the user's points, normalised, through a quintic spline (motion_table.h)
};

/// @brief The least distance of an inflection point λ from the ends of its stretch.
inline constexpr double kMinLawLambda = 0.05;

/// @brief The parameters a normalised law's shape takes (DesignSegmentSpec's, normalised).
struct LawParameters {
    double lambda = 0.5;                ///< the inflection point (modified sine, trapezoid)
    double sccaB = 0.25, sccaD = 0.25;  ///< Norton's b and d (scca)
    double endVelocity = 0.0;           ///< y' at both ends (inclined sine)
};

/// @brief The parameters of a segment's law as the law takes them: `h` the stretch and `d`
/// the lift it makes, in the same angle unit as the segment's v0 (so an inclined sine's end
/// velocity v0·h/d).
[[nodiscard]] LawParameters lawParameters(const DesignSegmentSpec& s, double h, double d);

/// @brief The fields of a segment a law may take besides law, to_deg and lift, in file order.
inline constexpr DesignPart kLawParameterParts[] = {
    DesignPart::V0, DesignPart::A0,     DesignPart::J0,    DesignPart::V1,    DesignPart::A1,
    DesignPart::J1, DesignPart::Lambda, DesignPart::SccaB, DesignPart::SccaD, DesignPart::Points};

/// @brief Whether the law reads a field of its segment besides law, to_deg and lift (poly5:
/// v0, a0, v1, a1; scca: b, d; …): the file's keys, the table's editable cells.
[[nodiscard]] bool lawUses(MotionLawType law, DesignPart part);

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
    LawPoint (*normalised)(double x, const LawParameters& p);
    /// Normalised: its coefficients in closed form; null otherwise (a dwell has none, a
    /// poly5's depend on its segment: MotionDesign::coefficients).
    LawCoefficients (*coefficients)(const LawParameters& p);
    /// The fields of DesignSegmentSpec it reads besides law, to_deg, lift: bits 1 << DesignPart.
    unsigned parameters = 0;
    /// English, one line: where it starts and ends and what it is for (the law list's tip).
    const char* summary = nullptr;
};

/// @brief Every law, in MotionLawType order.
[[nodiscard]] std::span<const MotionLawKind> motionLaws();
/// @brief The row of a law.
[[nodiscard]] const MotionLawKind& motionLaw(MotionLawType law);

/// @brief A rise law normalised to y(0) = 0, y(1) = 1; zero for a law that is not normalised
/// (the dwell, poly5: see Poly5Law). x outside [0, 1] is clamped.
[[nodiscard]] LawPoint normalisedLaw(MotionLawType law, double x, const LawParameters& p = {});
/// @brief A normalised law's coefficients; zero for the others.
[[nodiscard]] LawCoefficients lawCoefficients(MotionLawType law, const LawParameters& p = {});

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

/// @brief poly7 on a stretch of width h from y0 to y1 with dy/dx, d²y/dx², d³y/dx³ given at
/// both ends (in that unit): the polynomial of degree 7 that meets the eight values.
class Poly7Law {
public:
    Poly7Law(double h, double y0, double y1, const std::array<double, 3>& start,
             const std::array<double, 3>& end);
    /// @brief At u = (x − x0)/h in [0, 1]; derivatives with respect to x.
    [[nodiscard]] LawPoint at(double u) const;

private:
    double m_h;
    std::array<double, 8> m_c;  ///< y = Σ c_k u^k
};

/// @brief Norton's sine–constant–cosine acceleration (SCCA) law with shares b and d of the
/// stretch (c = 1 − b − d), normalised: b = d = 0.25 the modified trapezoid, b = 0.25,
/// d = 0.75 the modified sine, b = d = 0.5 the cycloid, b = 0, d = 1 the harmonic law.
class SccaLaw {
public:
    SccaLaw(double b, double d);
    [[nodiscard]] LawPoint at(double x) const;
    /// @brief Cv, Ca, Cj in closed form.
    [[nodiscard]] LawCoefficients coefficients() const;

private:
    struct Piece {
        double x0 = 0.0, x1 = 0.0, c0 = 0.0, cs = 0.0, cc = 0.0, omega = 0.0;
        double y0 = 0.0, v0 = 0.0;  // unscaled values at x0
    };
    std::array<Piece, 5> m_pieces{};
    double m_b, m_d, m_scale = 1.0;
};
}  // namespace cam
