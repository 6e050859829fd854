#pragma once
/// @file
/// @brief Polar kinematics of the follower at constant angular speed (math.md §2).

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contour/contour.h"
#include "geometry/polar_derivatives.h"

namespace cam {

/// @brief Radial/tangential velocity, acceleration and jerk (mm/s, mm/s², mm/s³).
struct PolarMotion {
    double vR = 0.0, vPhi = 0.0, v = 0.0;
    double aR = 0.0, aPhi = 0.0, a = 0.0;
    double jR = 0.0, jPhi = 0.0, j = 0.0;
};

/// @brief Kinematics from r(phi) and its derivatives at angular speed omega (rad/s).
[[nodiscard]] inline PolarMotion polarMotion(const PolarDerivatives& d, double omega) {
    const double w2 = omega * omega;
    const double rDot = omega * d.dr;
    const double rDdot = w2 * d.d2r;
    const double rDddot = w2 * omega * d.d3r;
    PolarMotion m;
    m.vR = rDot;
    m.vPhi = d.r * omega;
    m.v = std::sqrt(m.vR * m.vR + m.vPhi * m.vPhi);
    m.aR = rDdot - d.r * w2;
    m.aPhi = 2.0 * rDot * omega;
    m.a = std::sqrt(m.aR * m.aR + m.aPhi * m.aPhi);
    m.jR = rDddot - 3.0 * rDot * w2;
    m.jPhi = 3.0 * rDdot * omega - d.r * w2 * omega;
    m.j = std::sqrt(m.jR * m.jR + m.jPhi * m.jPhi);
    return m;
}

/// @brief The follower's state at one instant.
struct KinematicState {
    double t = 0.0;    ///< s
    double phi = 0.0;  ///< rad, omega·t (not reduced)
    std::size_t segment = 0;
    PolarDerivatives polar;
    PolarMotion motion;
};

/// @brief State at time t for angular speed omega (rad/s).
[[nodiscard]] KinematicState stateAt(const Contour& contour, double omega, double t);

/// @brief How many turns the cam has made at time t (negative when it turns clockwise),
/// computed from the speed as the project gives it (t/period, t·rpm/60, ω·t/2π) with one
/// rounding, not through ω·t in radians.
[[nodiscard]] double turnsAt(const MotionSpec& motion, double t);

/// @brief State at time t, the angle reduced through whole turns of the motion as given: an
/// instant many turns out keeps its angle (t = 1e14 s at a period of 0.4 s is 2.5e14 whole
/// turns, so φ ≡ 0), where ω·t in radians would carry a rounding of 0.25 rad into r. `phi`
/// still reports ω·t. Requires a valid motion.
[[nodiscard]] KinematicState stateAt(const Contour& contour, const MotionSpec& motion, double t);

/// @brief One turn sampled at N instants t_k = k·T/N, as flat arrays (structure of arrays).
struct SampledTurn {
    std::vector<double> t, phi, r, x, y;
    std::vector<double> vR, vPhi, v, aR, aPhi, a, jR, jPhi, j;
    std::vector<std::int32_t> segment;

    [[nodiscard]] std::size_t size() const { return t.size(); }
    void resize(std::size_t n);
};

/// @brief Samples one turn into `out`, reusing its storage. Requires n >= 1 and omega != 0.
///
/// If `cancel` is given it is polled every few thousand samples; when it reads true the
/// function returns false at once and `out` holds a partial turn. Returns true when complete.
bool sampleTurn(const Contour& contour, double omega, std::size_t n, SampledTurn& out,
                const std::atomic<bool>* cancel = nullptr);

/// @brief Chunks aligned to this many samples reproduce sampleTurn() exactly.
inline constexpr std::size_t kSampleBlock = 1024;

/// @brief Samples k = first … first + count − 1 of an n-sample turn into `out` (resized to
/// `count`; out.t[i] is the time of sample first + i), so that a big turn can be computed in
/// chunks of bounded memory. When the chunk starts and ends on multiples of kSampleBlock (or
/// ends at n) the values are bit for bit those that sampleTurn() gives for the same k;
/// otherwise they may differ in the last bit (the vectorised loop and its scalar remainder
/// round differently). Requires
/// first + count <= n. Cancellation as for sampleTurn().
bool sampleTurnRange(const Contour& contour, double omega, std::size_t n, std::size_t first,
                     std::size_t count, SampledTurn& out,
                     const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
