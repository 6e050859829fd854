#include "design/motion_law.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"

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

constexpr std::array<std::pair<MotionLawType, std::string_view>, 8> kNames{{
    {MotionLawType::Dwell, "dwell"},
    {MotionLawType::Harmonic, "harmonic"},
    {MotionLawType::Cycloidal, "cycloidal"},
    {MotionLawType::ModifiedTrapezoid, "modified-trapezoid"},
    {MotionLawType::ModifiedSine, "modified-sine"},
    {MotionLawType::Poly345, "poly345"},
    {MotionLawType::Poly4567, "poly4567"},
    {MotionLawType::Poly5, "poly5"},
}};

}  // namespace

LawPoint normalisedLaw(MotionLawType law, double x) {
    x = std::clamp(x, 0.0, 1.0);
    switch (law) {
        case MotionLawType::Dwell:
        case MotionLawType::Poly5:
            return {};
        case MotionLawType::Harmonic: {
            const double s = std::sin(kPi * x), c = std::cos(kPi * x);
            return {(1.0 - c) / 2.0, kPi / 2.0 * s, kPi * kPi / 2.0 * c,
                    -kPi * kPi * kPi / 2.0 * s};
        }
        case MotionLawType::Cycloidal: {
            const double s = std::sin(kTwoPi * x), c = std::cos(kTwoPi * x);
            return {x - s / kTwoPi, 1.0 - c, kTwoPi * s, kTwoPi * kTwoPi * c};
        }
        case MotionLawType::ModifiedTrapezoid:
            return modifiedTrapezoid().at(x);
        case MotionLawType::ModifiedSine:
            return modifiedSine().at(x);
        case MotionLawType::Poly345:
            return polynomial({0, 0, 0, 10, -15, 6, 0, 0}, x);
        case MotionLawType::Poly4567:
            return polynomial({0, 0, 0, 0, 35, -84, 70, -20}, x);
    }
    return {};
}

LawCoefficients lawCoefficients(MotionLawType law) {
    // Closed forms: the velocity peaks mid-way; the acceleration of the piecewise laws is their
    // plateau or crest; poly4567's where its jerk vanishes, x = (5 − √5)/10.
    switch (law) {
        case MotionLawType::Dwell:
        case MotionLawType::Poly5:
            return {};
        case MotionLawType::Harmonic:
            return {kPi / 2.0, kPi * kPi / 2.0, kPi * kPi * kPi / 2.0};
        case MotionLawType::Cycloidal:
            return {2.0, kTwoPi, kTwoPi * kTwoPi};
        case MotionLawType::ModifiedTrapezoid:
        case MotionLawType::ModifiedSine: {
            const LawPoint crest = normalisedLaw(law, 0.125);
            return {normalisedLaw(law, 0.5).v, crest.a, kQuarterWave * crest.a};
        }
        case MotionLawType::Poly345:
            return {1.875, 10.0 / std::sqrt(3.0), 60.0};
        case MotionLawType::Poly4567:
            return {2.1875, std::abs(normalisedLaw(law, (5.0 - std::sqrt(5.0)) / 10.0).a), 52.5};
    }
    return {};
}

std::string_view lawName(MotionLawType law) {
    for (const auto& [type, name] : kNames) {
        if (type == law) return name;
    }
    return "dwell";
}

std::optional<MotionLawType> lawFromName(std::string_view name) {
    for (const auto& [type, known] : kNames) {
        if (known == name) return type;
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
