#include "design/motion_law.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "common/kind_table.h"
#include "common/place.h"
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

// Constant velocity (VDI 2143's straight line): y = x. Beside a dwell its velocity would jump
// from 0; the design refuses that joint (its boundary classes, design/boundary_classes.h).
LawPoint constantVelocity(double x) { return {x, 1.0, 0.0, 0.0}; }

LawPoint poly345(double x) { return polynomial({0, 0, 0, 10, -15, 6, 0, 0}, x); }
LawPoint poly4567(double x) { return polynomial({0, 0, 0, 0, 35, -84, 70, -20}, x); }

const SccaLaw& modifiedTrapezoid() {
    static const SccaLaw law(0.25, 0.25);
    return law;
}
const SccaLaw& modifiedSine() {
    static const SccaLaw law(0.25, 0.75);
    return law;
}
LawPoint modifiedTrapezoidAt(double x) { return modifiedTrapezoid().at(x); }
LawPoint modifiedSineAt(double x) { return modifiedSine().at(x); }

/// A symmetric rest-to-rest law Y made asymmetric about its inflection point λ: its first half
/// stretched over [0, λ], its second over [λ, 1] (CODESYS's λ of the modified sine):
/// y = 2λ·Y(x/2λ) before λ, y = 1 − 2μ·Y((1 − x)/2μ) after, μ = 1 − λ. The velocity is Y's
/// at the matching point, so Cv stays; the acceleration scales by 1/2λ and 1/2μ, the jerk by
/// 1/4λ², 1/4μ². λ = 0.5 is Y itself.
template <LawPoint (*symmetric)(double)>
LawPoint asymmetric(double x, const LawParameters& p) {
    const double lambda = p.lambda;
    if (lambda == 0.5) return symmetric(x);
    if (x <= lambda) {
        const double w = 2.0 * lambda;
        const LawPoint y = symmetric(x / w);
        return {w * y.y, y.v, y.a / w, y.j / (w * w)};
    }
    const double w = 2.0 * (1.0 - lambda);
    const LawPoint y = symmetric((1.0 - x) / w);
    return {1.0 - w * y.y, y.v, -y.a / w, y.j / (w * w)};
}
template <const SccaLaw& (*symmetric)()>
LawCoefficients asymmetricCoefficients(const LawParameters& p) {
    const LawCoefficients c = symmetric().coefficients();
    const double w = 2.0 * std::min(p.lambda, 1.0 - p.lambda);
    return {c.cv, c.ca / w, c.cj / (w * w)};
}

/// The inclined sine (Bestehorn's geneigte Sinuslinie, VDI 2143): a sine wave on the line
/// through the stretch, y = x − (1 − v)·sin(2πx)/2π, with y' = v and y'' = 0 at both ends;
/// v = 0 is the cycloid, v = 1 the line.
LawPoint inclinedSine(double x, const LawParameters& p) {
    const double k = 1.0 - p.endVelocity, s = std::sin(kTwoPi * x), c = std::cos(kTwoPi * x);
    return {x - k * s / kTwoPi, 1.0 - k * c, k * kTwoPi * s, k * kTwoPi * kTwoPi * c};
}
LawCoefficients inclinedSineCoefficients(const LawParameters& p) {
    const double k = std::abs(1.0 - p.endVelocity);
    return {std::max(std::abs(p.endVelocity), std::abs(2.0 - p.endVelocity)), kTwoPi * k,
            kTwoPi * kTwoPi * k};
}

LawPoint scca(double x, const LawParameters& p) { return SccaLaw(p.sccaB, p.sccaD).at(x); }
LawCoefficients sccaCoefficients(const LawParameters& p) {
    return SccaLaw(p.sccaB, p.sccaD).coefficients();
}

/// A law without parameters as a row takes it.
template <LawPoint (*law)(double)>
LawPoint plain(double x, const LawParameters& /*p*/) {
    return law(x);
}
template <LawCoefficients (*coefficients)()>
LawCoefficients plainCoefficients(const LawParameters& /*p*/) {
    return coefficients();
}

// Closed forms: the velocity peaks mid-way; poly4567's acceleration where its jerk vanishes,
// x = (5 − √5)/10.
LawCoefficients harmonicCoefficients() {
    return {kPi / 2.0, kPi * kPi / 2.0, kPi * kPi * kPi / 2.0};
}
LawCoefficients cycloidalCoefficients() { return {2.0, kTwoPi, kTwoPi * kTwoPi}; }
/// y' = 1 everywhere, y'' = y''' = 0 inside the interval (the jumps at its ends are the
/// joints', not the law's).
LawCoefficients constantVelocityCoefficients() { return {1.0, 0.0, 0.0}; }
LawCoefficients poly345Coefficients() { return {1.875, 10.0 / std::sqrt(3.0), 60.0}; }
LawCoefficients poly4567Coefficients() {
    return {2.1875, std::abs(poly4567((5.0 - std::sqrt(5.0)) / 10.0).a), 52.5};
}

constexpr unsigned bit(DesignPart part) { return 1U << static_cast<unsigned>(part); }
constexpr unsigned kPoly5Parameters =
    bit(DesignPart::V0) | bit(DesignPart::A0) | bit(DesignPart::V1) | bit(DesignPart::A1);

/// Every law, one row each, in MotionLawType order. The titles and summaries are marked for
/// the app's translations (context "MotionLaw").
constexpr std::array<MotionLawKind, kMotionLawCount> kLaws{{
    {MotionLawType::Dwell, "dwell", CAM_TRANSLATE_NOOP("MotionLaw", "Dwell"), LawShape::Dwell,
     nullptr, nullptr, 0, CAM_TRANSLATE_NOOP("MotionLaw", "Rest: the follower keeps its lift.")},
    {MotionLawType::Harmonic, "harmonic", CAM_TRANSLATE_NOOP("MotionLaw", "Harmonic"),
     LawShape::Normalised, plain<harmonic>, plainCoefficients<harmonicCoefficients>, 0,
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Reversal to reversal: v = 0 at both ends; beside a dwell its "
                        "acceleration jumps.")},
    {MotionLawType::Cycloidal, "cycloidal", CAM_TRANSLATE_NOOP("MotionLaw", "Cycloidal"),
     LawShape::Normalised, plain<cycloidal>, plainCoefficients<cycloidalCoefficients>, 0,
     CAM_TRANSLATE_NOOP("MotionLaw", "Rest to rest with finite jerk.")},
    {MotionLawType::ModifiedTrapezoid, "modified-trapezoid",
     CAM_TRANSLATE_NOOP("MotionLaw", "Modified trapezoid"), LawShape::Normalised,
     asymmetric<modifiedTrapezoidAt>, asymmetricCoefficients<modifiedTrapezoid>,
     bit(DesignPart::Lambda),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Rest to rest, the lowest acceleration with finite jerk; λ moves its "
                        "inflection point (asymmetric).")},
    {MotionLawType::ModifiedSine, "modified-sine", CAM_TRANSLATE_NOOP("MotionLaw", "Modified sine"),
     LawShape::Normalised, asymmetric<modifiedSineAt>, asymmetricCoefficients<modifiedSine>,
     bit(DesignPart::Lambda),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Rest to rest, low velocity and acceleration together; λ moves its "
                        "inflection point.")},
    {MotionLawType::Poly345, "poly345", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 3-4-5"),
     LawShape::Normalised, plain<poly345>, plainCoefficients<poly345Coefficients>, 0,
     CAM_TRANSLATE_NOOP("MotionLaw", "Rest to rest, a polynomial of degree 5.")},
    {MotionLawType::Poly4567, "poly4567", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 4-5-6-7"),
     LawShape::Normalised, plain<poly4567>, plainCoefficients<poly4567Coefficients>, 0,
     CAM_TRANSLATE_NOOP("MotionLaw", "Rest to rest with zero jerk at both ends.")},
    {MotionLawType::Poly5, "poly5", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 5 (boundary values)"),
     LawShape::BoundaryValues, nullptr, nullptr, kPoly5Parameters,
     CAM_TRANSLATE_NOOP("MotionLaw", "Any boundary: velocity and acceleration at both ends.")},
    {MotionLawType::ConstantVelocity, "line", CAM_TRANSLATE_NOOP("MotionLaw", "Constant velocity"),
     LawShape::Normalised, plain<constantVelocity>, plainCoefficients<constantVelocityCoefficients>,
     0, CAM_TRANSLATE_NOOP("MotionLaw", "A straight line: constant velocity, no acceleration.")},
    {MotionLawType::InclinedSine, "inclined-sine",
     CAM_TRANSLATE_NOOP("MotionLaw", "Inclined sine (Bestehorn)"), LawShape::Normalised,
     inclinedSine, inclinedSineCoefficients, bit(DesignPart::V0),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Constant velocity v0 to the same velocity, no acceleration at the ends "
                        "(v0 = 0: the cycloid).")},
    {MotionLawType::Scca, "scca", CAM_TRANSLATE_NOOP("MotionLaw", "SCCA (sine-constant-cosine)"),
     LawShape::Normalised, scca, sccaCoefficients, bit(DesignPart::SccaB) | bit(DesignPart::SccaD),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Rest to rest; b and d are the shares of the sine ramps and of the "
                        "cosine, the rest constant acceleration (Norton).")},
    {MotionLawType::Poly7, "poly7", CAM_TRANSLATE_NOOP("MotionLaw", "Poly 7 (boundary values)"),
     LawShape::BoundaryValues, nullptr, nullptr,
     kPoly5Parameters | bit(DesignPart::J0) | bit(DesignPart::J1),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Any boundary: velocity, acceleration and jerk at both ends.")},
    {MotionLawType::Table, "table", CAM_TRANSLATE_NOOP("MotionLaw", "Motion table"),
     LawShape::Table, nullptr, nullptr, bit(DesignPart::Points),
     CAM_TRANSLATE_NOOP("MotionLaw",
                        "Your points (0…1, as Inventor takes them) joined by a C2 quintic "
                        "spline, at rest at both ends.")},
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

LawPoint normalisedLaw(MotionLawType law, double x, const LawParameters& p) {
    const MotionLawKind& kind = motionLaw(law);
    return kind.normalised ? kind.normalised(std::clamp(x, 0.0, 1.0), p) : LawPoint{};
}

LawCoefficients lawCoefficients(MotionLawType law, const LawParameters& p) {
    const MotionLawKind& kind = motionLaw(law);
    return kind.coefficients ? kind.coefficients(p) : LawCoefficients{};
}

bool lawUses(MotionLawType law, DesignPart part) {
    return (motionLaw(law).parameters & bit(part)) != 0;
}

LawParameters lawParameters(const DesignSegmentSpec& s, double h, double d) {
    LawParameters p;
    p.lambda = s.lambda;
    p.sccaB = s.sccaB;
    p.sccaD = s.sccaD;
    if (s.law == MotionLawType::InclinedSine && d != 0.0) p.endVelocity = s.v0 * h / d;
    return p;
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

Poly7Law::Poly7Law(double h, double y0, double y1, const std::array<double, 3>& start,
                   const std::array<double, 3>& end)
    : m_h(h) {
    // The start fixes c0 … c3; c4 … c7 meet what is left of the end's four values:
    // Σ c_k = Y, Σ k c_k = V, Σ k(k−1) c_k = A, Σ k(k−1)(k−2) c_k = J over k = 4 … 7.
    const double h2 = h * h, h3 = h2 * h;
    m_c = {y0, h * start[0], h2 * start[1] / 2.0, h3 * start[2] / 6.0, 0, 0, 0, 0};
    const double y = y1 - (m_c[0] + m_c[1] + m_c[2] + m_c[3]);
    const double v = h * end[0] - (m_c[1] + 2.0 * m_c[2] + 3.0 * m_c[3]);
    const double a = h2 * end[1] - (2.0 * m_c[2] + 6.0 * m_c[3]);
    const double j = h3 * end[2] - 6.0 * m_c[3];
    // The inverse of [[1,1,1,1],[4,5,6,7],[12,20,30,42],[24,60,120,210]].
    static constexpr double inv[4][4] = {{35.0, -15.0, 2.5, -1.0 / 6.0},
                                         {-84.0, 39.0, -7.0, 0.5},
                                         {70.0, -34.0, 6.5, -0.5},
                                         {-20.0, 10.0, -2.0, 1.0 / 6.0}};
    for (std::size_t r = 0; r < 4; ++r) {
        m_c[4 + r] = inv[r][0] * y + inv[r][1] * v + inv[r][2] * a + inv[r][3] * j;
    }
}

LawPoint Poly7Law::at(double u) const {
    const LawPoint p = polynomial(m_c, u);
    return {p.y, p.v / m_h, p.a / (m_h * m_h), p.j / (m_h * m_h * m_h)};
}

SccaLaw::SccaLaw(double b, double d) : m_b(b), m_d(d) {
    // Acceleration of height 1: sine ramp, constant, a cosine through zero, constant, ramp.
    const double c1 = (1.0 - d) / 2.0, c2 = (1.0 + d) / 2.0;
    const double ramp = b > 0.0 ? kPi / b : 0.0, wave = d > 0.0 ? kPi / d : 0.0;
    m_pieces[0] = {0.0, b / 2.0, 0.0, 1.0, 0.0, ramp};
    m_pieces[1] = {b / 2.0, c1, 1.0, 0.0, 0.0, 0.0};
    m_pieces[2] = {c1, c2, 0.0, 0.0, 1.0, wave};
    m_pieces[3] = {c2, 1.0 - b / 2.0, -1.0, 0.0, 0.0, 0.0};
    m_pieces[4] = {1.0 - b / 2.0, 1.0, 0.0, 0.0, -1.0, ramp};
    double y = 0.0, v = 0.0;
    for (Piece& p : m_pieces) {
        p.y0 = y;
        p.v0 = v;
        if (p.x1 > p.x0) {
            const LawPoint e = evaluatePiece({p.x0, p.x1, p.c0, p.cs, p.cc, p.omega}, v, y, p.x1);
            y = e.y;
            v = e.v;
        }
    }
    m_scale = 1.0 / y;
}

LawPoint SccaLaw::at(double x) const {
    // The piece x lies in; an empty piece (b = 0 or d = 0) is never one.
    std::size_t k = 0;
    while (k + 1 < m_pieces.size() && (x > m_pieces[k].x1 || !(m_pieces[k].x1 > m_pieces[k].x0)))
        ++k;
    const Piece& p = m_pieces[k];
    LawPoint r = evaluatePiece({p.x0, p.x1, p.c0, p.cs, p.cc, p.omega}, p.v0, p.y0, x);
    r.y *= m_scale;
    r.v *= m_scale;
    r.a *= m_scale;
    r.j *= m_scale;
    return r;
}

LawCoefficients SccaLaw::coefficients() const {
    // Norton, Cam Design and Manufacturing Handbook (2nd ed., 2009), §3.8, the SCCA family:
    // with c = 1 − b − d, Ca = 4π² / ((π² − 8)(b² − d²) − 2π(π − 2)b + π²),
    // Cv = Ca (b/π + c/2 + d/π); the jerk's crest is Ca·π/b on the ramps, Ca·π/d on the cosine.
    const double b = m_b, d = m_d, c = 1.0 - b - d, pi2 = kPi * kPi;
    const double ca = 4.0 * pi2 / ((pi2 - 8.0) * (b * b - d * d) - kTwoPi * (kPi - 2.0) * b + pi2);
    double steepest = 0.0;
    if (b > 0.0) steepest = std::max(steepest, kPi / b);
    if (d > 0.0) steepest = std::max(steepest, kPi / d);
    return {ca * (b / kPi + c / 2.0 + d / kPi), ca, ca * steepest};
}

}  // namespace cam
