#pragma once
/// @file
/// @brief Small geometry shared by the translating and the swinging-arm contact searches:
/// angle spans of pitch circles, cubic pieces in power basis (on jets), and the root scan that
/// finds every contact on a spline piece.

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "common/angles.h"
#include "follower/jet.h"
#include "geometry/planar.h"

namespace cam::follower_detail {

/// How far outside its span a crossing may fall and still count (rad, or parameter fraction):
/// joints meet at rounding distance, and an extended piece sticks out only by its square.
inline constexpr double kSpanSlack = 1e-9;

/// The angle from `start` to `angle` in the direction of `sweep`, in [0, 2π).
inline double angleIntoSweep(double angle, double start, double sweep) {
    double d = sweep >= 0.0 ? angle - start : start - angle;
    d = std::fmod(d, kTwoPi);
    if (d < 0.0) d += kTwoPi;
    return d;
}

inline bool inSpan(double angle, double start, double sweep, double slack = kSpanSlack) {
    if (std::abs(sweep) >= kTwoPi) return true;
    const double d = angleIntoSweep(angle, start, sweep);
    return d <= std::abs(sweep) + slack || d >= kTwoPi - slack;
}

/// The same test for a direction w from the circle's centre (|w| = `radius`), without an angle:
/// inside the wedge from `from` to `to` (unit vectors at the span's ends).
inline bool inSpanDirection(const Eigen::Vector2d& w, const Eigen::Vector2d& from,
                            const Eigen::Vector2d& to, double sweep, double radius,
                            double slack = kSpanSlack) {
    if (std::abs(sweep) >= kTwoPi) return true;
    const double sign = sweep >= 0.0 ? 1.0 : -1.0, tolerance = -slack * radius;
    const bool afterFrom = sign * cross(from, w) >= tolerance;
    const bool beforeTo = sign * cross(w, to) >= tolerance;
    // A wedge up to a half turn is where both hold; a wider one, where either does.
    return std::abs(sweep) <= kPi ? afterFrom && beforeTo : afterFrom || beforeTo;
}

/// p(τ) of a cubic in power basis, with a jet τ.
inline JetVec polynomial(const std::array<Eigen::Vector2d, 4>& k, const Jet& t) {
    Jet x = Jet::constant(k[3].x()), y = Jet::constant(k[3].y());
    for (int i = 2; i >= 0; --i) {
        x = x * t + k[static_cast<std::size_t>(i)].x();
        y = y * t + k[static_cast<std::size_t>(i)].y();
    }
    return {x, y};
}

/// p'(τ) of a cubic in power basis, with a jet τ.
inline JetVec polynomialDerivative(const std::array<Eigen::Vector2d, 4>& k, const Jet& t) {
    const std::array<Eigen::Vector2d, 4> d{k[1], 2.0 * k[2], 3.0 * k[3], Eigen::Vector2d::Zero()};
    return polynomial(d, t);
}

/// The pitch curve of a spline piece at a jet τ: p(τ), moved by `offset` along the normal on
/// the right of dp/dτ (the signed roller radius; 0 for the profile itself).
inline JetVec splinePitch(const std::array<Eigen::Vector2d, 4>& k, double offset, const Jet& t) {
    const JetVec p = polynomial(k, t);
    if (offset == 0.0) return p;
    const JetVec d = polynomialDerivative(k, t);
    const Jet len = sqrt(dot(d, d));
    const Jet scale = Jet::constant(offset) / len;
    return p + JetVec{d.y * scale, -(d.x * scale)};
}

/// The same point in plain doubles, four times cheaper (for root scans).
inline Eigen::Vector2d splinePitch(const std::array<Eigen::Vector2d, 4>& k, double offset,
                                   double t) {
    Eigen::Vector2d c = ((k[3] * t + k[2]) * t + k[1]) * t + k[0];
    if (offset != 0.0) {
        const Eigen::Vector2d d = (3.0 * k[3] * t + 2.0 * k[2]) * t + k[1];
        c += (offset / d.norm()) * Eigen::Vector2d(d.y(), -d.x());
    }
    return c;
}

/// Calls onRoot(τ) for every sign change of g over [lo, hi]: 48 intervals scanned, each change
/// bisected to the last bit.
template <class G, class OnRoot>
void forEachRoot(const G& g, double lo, double hi, const OnRoot& onRoot) {
    constexpr int kIntervals = 48;
    double t0 = lo, g0 = g(t0);
    for (int i = 1; i <= kIntervals; ++i) {
        const double t1 = lo + (hi - lo) * i / kIntervals;
        const double g1 = g(t1);
        if ((g0 <= 0.0) != (g1 <= 0.0) || g1 == 0.0) {
            double a = t0, b = t1, ga = g0;
            for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
                const double mid = 0.5 * (a + b), gm = g(mid);
                if ((gm <= 0.0) == (ga <= 0.0)) {
                    a = mid;
                    ga = gm;
                } else {
                    b = mid;
                }
            }
            onRoot(0.5 * (a + b));
        }
        t0 = t1;
        g0 = g1;
    }
}

}  // namespace cam::follower_detail
