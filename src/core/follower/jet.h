#pragma once
/// @file
/// @brief Truncated Taylor series ("jets") of order 3: exact derivatives of compositions, used to
/// differentiate a follower's contact condition on splines (no finite differences).

#include <array>
#include <cmath>

namespace cam {

/// @brief f(x0 + ε) = c[0] + c[1]·ε + c[2]·ε² + c[3]·ε³ + O(ε⁴); c[k] = f⁽ᵏ⁾(x0)/k!.
struct Jet {
    std::array<double, 4> c{0.0, 0.0, 0.0, 0.0};

    static Jet constant(double v) { return {{v, 0.0, 0.0, 0.0}}; }
    /// The variable itself at x0.
    static Jet variable(double x0) { return {{x0, 1.0, 0.0, 0.0}}; }
    /// f⁽ᵏ⁾(x0).
    [[nodiscard]] double derivative(int k) const {
        static constexpr double factorial[] = {1.0, 1.0, 2.0, 6.0};
        return c[static_cast<std::size_t>(k)] * factorial[k];
    }
    [[nodiscard]] double value() const { return c[0]; }

    friend Jet operator+(Jet a, const Jet& b) {
        for (std::size_t k = 0; k < 4; ++k) a.c[k] += b.c[k];
        return a;
    }
    friend Jet operator-(Jet a, const Jet& b) {
        for (std::size_t k = 0; k < 4; ++k) a.c[k] -= b.c[k];
        return a;
    }
    friend Jet operator-(Jet a) {
        for (double& x : a.c) x = -x;
        return a;
    }
    friend Jet operator*(const Jet& a, const Jet& b) {
        Jet r;
        for (std::size_t i = 0; i < 4; ++i)
            for (std::size_t j = 0; i + j < 4; ++j) r.c[i + j] += a.c[i] * b.c[j];
        return r;
    }
    friend Jet operator*(Jet a, double s) {
        for (double& x : a.c) x *= s;
        return a;
    }
    friend Jet operator*(double s, Jet a) { return a * s; }
    friend Jet operator+(Jet a, double s) {
        a.c[0] += s;
        return a;
    }
    friend Jet operator-(Jet a, double s) {
        a.c[0] -= s;
        return a;
    }
    friend Jet operator/(const Jet& a, const Jet& b) {
        Jet q;
        for (std::size_t k = 0; k < 4; ++k) {
            double v = a.c[k];
            for (std::size_t j = 0; j < k; ++j) v -= q.c[j] * b.c[k - j];
            q.c[k] = v / b.c[0];
        }
        return q;
    }
};

/// @brief √a (a.c[0] > 0).
inline Jet sqrt(const Jet& a) {
    Jet r;
    r.c[0] = std::sqrt(a.c[0]);
    for (std::size_t k = 1; k < 4; ++k) {
        double v = a.c[k];
        for (std::size_t j = 1; j < k; ++j) v -= r.c[j] * r.c[k - j];
        r.c[k] = v / (2.0 * r.c[0]);
    }
    return r;
}

/// @brief cos and sin of the angle φ0 + ε.
inline Jet cosJet(double phi0) {
    const double c = std::cos(phi0), s = std::sin(phi0);
    return {{c, -s, -c / 2.0, s / 6.0}};
}
inline Jet sinJet(double phi0) {
    const double c = std::cos(phi0), s = std::sin(phi0);
    return {{s, c, -s / 2.0, -c / 6.0}};
}

/// @brief d/dx of the series (its last coefficient is unknown at this order and left 0).
inline Jet derivativeOf(const Jet& a) { return {{a.c[1], 2.0 * a.c[2], 3.0 * a.c[3], 0.0}}; }

/// @brief A plane vector of jets.
struct JetVec {
    Jet x, y;
    friend JetVec operator+(const JetVec& a, const JetVec& b) { return {a.x + b.x, a.y + b.y}; }
    friend JetVec operator-(const JetVec& a, const JetVec& b) { return {a.x - b.x, a.y - b.y}; }
    friend JetVec operator*(const JetVec& a, const Jet& s) { return {a.x * s, a.y * s}; }
    friend Jet dot(const JetVec& a, const JetVec& b) { return a.x * b.x + a.y * b.y; }
    /// The vector turned a quarter counter-clockwise.
    friend JetVec perp(const JetVec& a) { return {-a.y, a.x}; }
};

/// @brief The polar angle of a (a ≠ 0): atan2 at the base point, and the rest integrated from
/// θ' = (x·y' − y·x') / (x² + y²).
inline Jet angleOf(const JetVec& a) {
    const Jet rate = (a.x * derivativeOf(a.y) - a.y * derivativeOf(a.x)) / dot(a, a);
    return {{std::atan2(a.y.c[0], a.x.c[0]), rate.c[0], rate.c[1] / 2.0, rate.c[2] / 3.0}};
}

}  // namespace cam
