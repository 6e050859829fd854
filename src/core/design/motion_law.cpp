#include "design/motion_law.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "common/kind_table.h"
#include "common/translate_marker.h"

namespace cam {
namespace {

/// One piece of a law given by its acceleration a(x) = c0 + cs·sin(ω d) + cc·cos(ω d),
/// d = x − x0, integrated in closed form from v and y at its start.
struct AccelerationPiece {
    double x0, x1, c0, cs, cc, omega;
};

LawPoint evaluatePiece(const AccelerationPiece& p, double v0, double y0, double x) {
    const double d = x - p.x0, w = p.omega;
    LawPoint r;
    if (w == 0.0) {
        r.a = p.c0;
        r.v = v0 + p.c0 * d;
        r.y = y0 + v0 * d + p.c0 * d * d / 2.0;
        return r;
    }
    const double s = std::sin(w * d), c = std::cos(w * d);
    r.j = p.cs * w * c - p.cc * w * s;
    r.a = p.c0 + p.cs * s + p.cc * c;
    r.v = v0 + p.c0 * d + p.cs * (1.0 - c) / w + p.cc * s / w;
    r.y = y0 + v0 * d + p.c0 * d * d / 2.0 + p.cs * (d - s / w) / w + p.cc * (1.0 - c) / (w * w);
    return r;
}

/// A law made of acceleration pieces, scaled so that y(1) = 1.
class PiecewiseLaw {
public:
    explicit PiecewiseLaw(std::vector<AccelerationPiece> pieces) : m_pieces(std::move(pieces)) {
        double v = 0.0, y = 0.0;
        for (const AccelerationPiece& p : m_pieces) {
            m_start.push_back({y, v});
            const LawPoint end = evaluatePiece(p, v, y, p.x1);
            v = end.v;
            y = end.y;
        }
        m_scale = 1.0 / y;
    }
    [[nodiscard]] LawPoint at(double x) const {
        std::size_t k = 0;
        while (k + 1 < m_pieces.size() && x > m_pieces[k].x1) ++k;
        LawPoint r = evaluatePiece(m_pieces[k], m_start[k][1], m_start[k][0], x);
        r.y *= m_scale;
        r.v *= m_scale;
        r.a *= m_scale;
        r.j *= m_scale;
        return r;
    }

private:
    std::vector<AccelerationPiece> m_pieces;
    std::vector<std::array<double, 2>> m_start;  // y, v at each piece's start (unscaled)
    double m_scale = 1.0;
};

constexpr double kQuarterWave = 4.0 * kPi;  // a quarter sine over 1/8

// The classic modified trapezoid: sine ramps of 1/8 round constant acceleration stretches.
const PiecewiseLaw& modifiedTrapezoid() {
    static const PiecewiseLaw law({{0.0, 0.125, 0.0, 1.0, 0.0, kQuarterWave},
                                   {0.125, 0.375, 1.0, 0.0, 0.0, 0.0},
                                   {0.375, 0.625, 0.0, 0.0, 1.0, kQuarterWave},
                                   {0.625, 0.875, -1.0, 0.0, 0.0, 0.0},
                                   {0.875, 1.0, 0.0, 0.0, -1.0, kQuarterWave}});
    return law;
}

// The classic modified sine: quarter sines of 1/8 at the ends, a half cosine of 3/4 between.
const PiecewiseLaw& modifiedSine() {
    static const PiecewiseLaw law({{0.0, 0.125, 0.0, 1.0, 0.0, kQuarterWave},
                                   {0.125, 0.875, 0.0, 0.0, 1.0, 4.0 * kPi / 3.0},
                                   {0.875, 1.0, 0.0, 0.0, -1.0, kQuarterWave}});
    return law;
}

LawPoint polynomial(const std::array<double, 8>& c, double x) {
    // y = Σ c_k x^k, k ≤ 7, and its derivatives by Horner.
    LawPoint r;
    for (int k = 7; k >= 0; --k) {
        r.j = r.j * x + 3.0 * r.a;
        r.a = r.a * x + 2.0 * r.v;
        r.v = r.v * x + r.y;
        r.y = r.y * x + c[static_cast<std::size_t>(k)];
    }
    return r;
}

LawPoint harmonic(double x) {
    const double s = std::sin(kPi * x), c = std::cos(kPi * x);
    return {(1.0 - c) / 2.0, kPi / 2.0 * s, kPi * kPi / 2.0 * c, -kPi * kPi * kPi / 2.0 * s};
}

LawPoint cycloidal(double x) {
    const double s = std::sin(kTwoPi * x), c = std::cos(kTwoPi * x);
    return {x - s / kTwoPi, 1.0 - c, kTwoPi * s, kTwoPi * kTwoPi * c};
}

// Constant velocity (VDI 2143's straight line): y = x. Next to a dwell its velocity jumps from 0
// (its acceleration is an impulse there), which the design's continuity check reports
// (MotionDesign::jumps, a note): that is the law's nature. Issue 33 will add boundary classes
// (which laws start and end at rest, at speed) so that a design can say so before it is built.
LawPoint constantVelocity(double x) { return {x, 1.0, 0.0, 0.0}; }

LawPoint modifiedTrapezoidAt(double x) { return modifiedTrapezoid().at(x); }
LawPoint modifiedSineAt(double x) { return modifiedSine().at(x); }
LawPoint poly345(double x) { return polynomial({0, 0, 0, 10, -15, 6, 0, 0}, x); }
LawPoint poly4567(double x) { return polynomial({0, 0, 0, 0, 35, -84, 70, -20}, x); }

// Closed forms: the velocity peaks mid-way; the acceleration of the piecewise laws is their
// plateau or crest; poly4567's where its jerk vanishes, x = (5 − √5)/10.
LawCoefficients harmonicCoefficients() {
    return {kPi / 2.0, kPi * kPi / 2.0, kPi * kPi * kPi / 2.0};
}
LawCoefficients cycloidalCoefficients() { return {2.0, kTwoPi, kTwoPi * kTwoPi}; }
/// y' = 1 everywhere, y'' = y''' = 0 inside the interval (the jumps at its ends are the
/// joints', not the law's).
LawCoefficients constantVelocityCoefficients() { return {1.0, 0.0, 0.0}; }
/// A law of sine ramps of 1/8: its crest at 1/8, its jerk there a quarter wave of it.
template <LawPoint (*law)(double)>
LawCoefficients rampedCoefficients() {
    const LawPoint crest = law(0.125);
    return {law(0.5).v, crest.a, kQuarterWave * crest.a};
}
LawCoefficients poly345Coefficients() { return {1.875, 10.0 / std::sqrt(3.0), 60.0}; }
LawCoefficients poly4567Coefficients() {
    return {2.1875, std::abs(poly4567((5.0 - std::sqrt(5.0)) / 10.0).a), 52.5};
}

/// Every law, one row each, in MotionLawType order. The titles are marked for the app's
/// translations (context "MotionLaw").
constexpr std::array<MotionLawKind, kMotionLawCount> kLaws{{
    {MotionLawType::Dwell, "dwell", CAM_TRANSLATE_NOOP("MotionLaw", "Dwell"), LawShape::Dwell,
     nullptr, nullptr},
    {MotionLawType::Harmonic, "harmonic", CAM_TRANSLATE_NOOP("MotionLaw", "Harmonic"),
     LawShape::Normalised, harmonic, harmonicCoefficients},
    {MotionLawType::Cycloidal, "cycloidal", CAM_TRANSLATE_NOOP("MotionLaw", "Cycloidal"),
     LawShape::Normalised, cycloidal, cycloidalCoefficients},
    {MotionLawType::ModifiedTrapezoid, "modified-trapezoid",
     CAM_TRANSLATE_NOOP("MotionLaw", "Modified trapezoid"), LawShape::Normalised,
     modifiedTrapezoidAt, rampedCoefficients<modifiedTrapezoidAt>},
    {MotionLawType::ModifiedSine, "modified-sine", CAM_TRANSLATE_NOOP("MotionLaw", "Modified sine"),
     LawShape::Normalised, modifiedSineAt, rampedCoefficients<modifiedSineAt>},
    {MotionLawType::Poly345, "poly345", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 3-4-5"),
     LawShape::Normalised, poly345, poly345Coefficients},
    {MotionLawType::Poly4567, "poly4567", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 4-5-6-7"),
     LawShape::Normalised, poly4567, poly4567Coefficients},
    {MotionLawType::Poly5, "poly5", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 5 (boundary values)"),
     LawShape::BoundaryValues, nullptr, nullptr},
    {MotionLawType::ConstantVelocity, "line", CAM_TRANSLATE_NOOP("MotionLaw", "Constant velocity"),
     LawShape::Normalised, constantVelocity, constantVelocityCoefficients},
}};

/// A function and coefficients for each normalised law, and only for those.
constexpr bool lawFunctionsMatchShapes() {
    for (const MotionLawKind& law : kLaws) {
        if ((law.shape == LawShape::Normalised) != (law.normalised != nullptr)) return false;
        if ((law.normalised == nullptr) != (law.coefficients == nullptr)) return false;
    }
    return true;
}
static_assert(rowsFollowTheirEnum(kLaws, &MotionLawKind::type),
              "one row per law, in MotionLawType order");
static_assert(lawFunctionsMatchShapes(), "a function for each normalised law and only for those");

}  // namespace

std::span<const MotionLawKind> motionLaws() { return kLaws; }

const MotionLawKind& motionLaw(MotionLawType law) {
    return kLaws.at(static_cast<std::size_t>(law));
}

LawPoint normalisedLaw(MotionLawType law, double x) {
    const MotionLawKind& kind = motionLaw(law);
    return kind.normalised ? kind.normalised(std::clamp(x, 0.0, 1.0)) : LawPoint{};
}

LawCoefficients lawCoefficients(MotionLawType law) {
    const MotionLawKind& kind = motionLaw(law);
    return kind.coefficients ? kind.coefficients() : LawCoefficients{};
}

std::string_view lawName(MotionLawType law) { return motionLaw(law).name; }

std::optional<MotionLawType> lawFromName(std::string_view name) {
    for (const MotionLawKind& kind : kLaws) {
        if (kind.name == name) return kind.type;
    }
    return std::nullopt;
}

Poly5Law::Poly5Law(double h, double y0, double y1, double v0, double a0, double v1, double a1)
    : m_h(h) {
    const double d = y1 - y0, h2 = h * h;
    m_c = {y0,
           h * v0,
           h2 * a0 / 2.0,
           10.0 * d - 6.0 * h * v0 - 4.0 * h * v1 - (3.0 * a0 - a1) * h2 / 2.0,
           -15.0 * d + 8.0 * h * v0 + 7.0 * h * v1 + (3.0 * a0 - 2.0 * a1) * h2 / 2.0,
           6.0 * d - 3.0 * h * (v0 + v1) - (a0 - a1) * h2 / 2.0};
}

LawPoint Poly5Law::at(double u) const {
    const LawPoint p = polynomial({m_c[0], m_c[1], m_c[2], m_c[3], m_c[4], m_c[5], 0.0, 0.0}, u);
    return {p.y, p.v / m_h, p.a / (m_h * m_h), p.j / (m_h * m_h * m_h)};
}

}  // namespace cam
