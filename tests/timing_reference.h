#pragma once
// An independent reference for machining times (math.md §6), shared by the core, CLI and app
// tests: time-optimal motion along a fixed path by phase-plane integration (Bobrow /
// Shin–McKay), and the seed method written from the wording of math.md §6. Nothing here calls
// the implementation's planner or PathSegment's geometry; timing_test.cpp checks the reference
// itself against an analytic optimum and published TOPP-RA / Kunz–Stilman figures.

#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "contour/contour.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"

namespace cam::test {

using Eigen::Vector2d;
using Eigen::Vector3d;

/// Machine limits: per-axis accelerations, and optionally a feed ceiling and per-axis speeds.
inline MachineLimits limitsOf(const Vector3d& accel, double feedMax = kUnlimited,
                              const Vector3d& vmax = Vector3d::Constant(kUnlimited)) {
    MachineLimits limits;
    limits.accel = accel;
    limits.vmax = vmax;
    limits.feedMax = feedMax;
    return limits;
}

// State: squared path speed x = ṡ² over arc length s, so dx/ds = 2·s̈ and t = ∫ ds/sqrt(x).
// Per axis i: |q_i'(s)|·sqrt(x) <= vmax_i, and |q_i'(s)·s̈ + q_i''(s)·x| <= a_i. The geometry
// below is written here (it does not call PathSegment's point/tangent/curvature).

/// One piece of path with its own q(s), q'(s), q''(s).
struct RefPiece {
    bool isArc = false;
    Vector3d from{0, 0, 0}, to{0, 0, 0};  // line
    Vector2d centre{0, 0};                // arc at height z, polar angle startAngle + sweep·s/L
    double radius = 0.0, startAngle = 0.0, sweep = 0.0, z = 0.0;

    static RefPiece line(const Vector3d& a, const Vector3d& b) {
        RefPiece p;
        p.from = a;
        p.to = b;
        return p;
    }
    static RefPiece arc(const Vector2d& c, double r, double start, double sw, double height) {
        RefPiece p;
        p.isArc = true;
        p.centre = c;
        p.radius = r;
        p.startAngle = start;
        p.sweep = sw;
        p.z = height;
        return p;
    }
    [[nodiscard]] double length() const {
        return isArc ? std::abs(sweep) * radius : (to - from).norm();
    }
    [[nodiscard]] PathSegment toSegment() const {
        return isArc ? PathSegment::arc(centre, radius, startAngle, sweep, z)
                     : PathSegment::line(from, to);
    }
    /// q(s): the point at arc length s from the start.
    [[nodiscard]] Vector3d point(double s) const {
        if (!isArc) return from + (to - from) * (s / length());
        const double th = startAngle + (sweep > 0 ? 1.0 : -1.0) * s / radius;
        return {centre.x() + radius * std::cos(th), centre.y() + radius * std::sin(th), z};
    }
    /// q'(s) (unit tangent) and q''(s).
    void derivatives(double s, std::array<double, 3>& d1, std::array<double, 3>& d2) const {
        if (!isArc) {
            const Vector3d n = (to - from) / (to - from).norm();
            d1 = {n.x(), n.y(), n.z()};
            d2 = {0.0, 0.0, 0.0};
            return;
        }
        // Point c + R·(cos θ, sin θ) with θ = θ0 + σ·s/R, σ = sign(sweep):
        // q' = σ·(−sin θ, cos θ), q'' = −(1/R)·(cos θ, sin θ).
        const double sigma = sweep > 0 ? 1.0 : -1.0;
        const double th = startAngle + sigma * s / radius;
        d1 = {-sigma * std::sin(th), sigma * std::cos(th), 0.0};
        d2 = {-std::cos(th) / radius, -std::sin(th) / radius, 0.0};
    }
};

/// The phase-plane constraints at one point: axis k allows s̈ in [−alpha_k − kappa_k·x,
/// alpha_k − kappa_k·x] (alpha = a_i/|q_i'|, kappa = q_i''/q_i'); xMax is the maximum-velocity
/// curve (the largest x for which all those intervals and the speed limits can be met).
struct PhasePoint {
    std::array<double, 3> alpha{};
    std::array<double, 3> kappa{};
    int count = 0;
    double xMax = kUnlimited;
};

inline PhasePoint phasePoint(const RefPiece& piece, double s, const MachineLimits& limits) {
    std::array<double, 3> d1{}, d2{};
    piece.derivatives(s, d1, d2);
    PhasePoint p;
    p.xMax = limits.feedMax * limits.feedMax;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d1[i]) > 1e-15) {
            p.alpha[p.count] = limits.accel[i] / std::abs(d1[i]);
            p.kappa[p.count] = d2[i] / d1[i];
            ++p.count;
            const double v = limits.vmax[i] / std::abs(d1[i]);
            p.xMax = std::min(p.xMax, v * v);
        } else if (d2[i] != 0.0) {
            // The axis is momentarily still along the path: only its centripetal part, |q''|·x.
            p.xMax = std::min(p.xMax, limits.accel[i] / std::abs(d2[i]));
        }
    }
    // Every lower bound must stay below every upper bound: −alpha_i − kappa_i·x <=
    // alpha_j − kappa_j·x, i.e. (kappa_j − kappa_i)·x <= alpha_i + alpha_j.
    for (int i = 0; i < p.count; ++i) {
        for (int j = 0; j < p.count; ++j) {
            if (p.kappa[j] > p.kappa[i]) {
                p.xMax = std::min(p.xMax, (p.alpha[i] + p.alpha[j]) / (p.kappa[j] - p.kappa[i]));
            }
        }
    }
    return p;
}

inline double maxAccel(const PhasePoint& p, double x) {
    double u = kUnlimited;
    for (int k = 0; k < p.count; ++k) u = std::min(u, p.alpha[k] - p.kappa[k] * x);
    return u;
}

inline double maxDecel(const PhasePoint& p, double x) {
    double u = -kUnlimited;
    for (int k = 0; k < p.count; ++k) u = std::max(u, -p.alpha[k] - p.kappa[k] * x);
    return u;
}

/// Rest-to-rest minimum time over pieces joined tangentially (the speed is free at the joints;
/// a joint must satisfy both neighbours' constraints). Grid of about `step` mm; the backward
/// pass (maximum deceleration from rest at the end) and the forward pass (maximum acceleration
/// from rest at the start) are midpoint (second-order Runge–Kutta) steps of dx/ds = 2·s̈, each
/// clipped to the maximum-velocity curve; the forward pass is clipped to the backward one, so
/// the profile is their pointwise minimum. Time per cell: 2·Δs/(sqrt(x_k) + sqrt(x_k+1)),
/// exact where x is linear in s and finite where x = 0.
inline double referenceTime(const std::vector<RefPiece>& pieces, const MachineLimits& limits,
                            double step) {
    struct Cell {
        const RefPiece* piece;
        double s0;
        double ds;
    };
    std::vector<Cell> cells;
    for (const RefPiece& piece : pieces) {
        const double length = piece.length();
        const auto n =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / step - 1e-9)));
        const double ds = length / static_cast<double>(n);
        for (std::size_t k = 0; k < n; ++k) {
            cells.push_back({&piece, static_cast<double>(k) * ds, ds});
        }
    }
    const std::size_t n = cells.size();

    std::vector<double> mvc(n + 1, kUnlimited);
    for (std::size_t j = 0; j < n; ++j) {
        const Cell& c = cells[j];
        mvc[j] = std::min(mvc[j], phasePoint(*c.piece, c.s0, limits).xMax);
        mvc[j + 1] = std::min(mvc[j + 1], phasePoint(*c.piece, c.s0 + c.ds, limits).xMax);
    }
    mvc[0] = 0.0;
    mvc[n] = 0.0;

    std::vector<double> back(n + 1, 0.0);
    for (std::size_t j = n; j-- > 0;) {
        const Cell& c = cells[j];
        const PhasePoint end = phasePoint(*c.piece, c.s0 + c.ds, limits);
        const PhasePoint mid = phasePoint(*c.piece, c.s0 + c.ds / 2.0, limits);
        const double x1 = back[j + 1];
        const double xMid = std::min(x1 - c.ds * maxDecel(end, x1), mid.xMax);
        back[j] = std::min(x1 - 2.0 * c.ds * maxDecel(mid, xMid), mvc[j]);
    }

    double x = 0.0;
    double time = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const Cell& c = cells[j];
        const PhasePoint start = phasePoint(*c.piece, c.s0, limits);
        const PhasePoint mid = phasePoint(*c.piece, c.s0 + c.ds / 2.0, limits);
        const double xMid = std::min(x + c.ds * maxAccel(start, x), mid.xMax);
        const double next = std::min(x + 2.0 * c.ds * maxAccel(mid, xMid), back[j + 1]);
        time += 2.0 * c.ds / (std::sqrt(x) + std::sqrt(next));
        x = next;
    }
    return time;
}

/// Optimal: stop only where `tangentToPrevious` is false (corners) and at both ends.
inline double referenceOptimal(const std::vector<RefPiece>& pieces,
                               const std::vector<bool>& tangentToPrevious,
                               const MachineLimits& limits, double step) {
    double total = 0.0;
    std::vector<RefPiece> chain;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (k > 0 && !tangentToPrevious[k]) {
            total += referenceTime(chain, limits, step);
            chain.clear();
        }
        chain.push_back(pieces[k]);
    }
    return total + referenceTime(chain, limits, step);
}

/// Exact stop: every piece rest to rest.
inline double referenceExactStop(const std::vector<RefPiece>& pieces, const MachineLimits& limits,
                                 double step) {
    double total = 0.0;
    for (const RefPiece& piece : pieces) total += referenceTime({piece}, limits, step);
    return total;
}

/// The seed method (math.md §6) on one piece, from its wording: steps of length l (the last one
/// shorter) from rest up to the midpoint; each step's direction n is its chord; its speed x is
/// the largest with |n_i·x − v_prev,i|·x/l <= a_i on every axis (v_prev: the previous step's
/// axis velocities n_prev·x_prev), capped by the feed; the time is twice the sum of l/x.
inline double seedReference(const RefPiece& piece, const MachineLimits& limits) {
    const double half = piece.length() / 2.0;
    Vector3d vPrev = Vector3d::Zero();
    double sum = 0.0;
    for (double walked = 0.0; walked < half - 1e-12;) {
        const double l = std::min(limits.seedStep, half - walked);
        const Vector3d n = (piece.point(walked + l) - piece.point(walked)).normalized();
        double x = limits.feedMax;
        for (int i = 0; i < 3; ++i) {
            const double a = limits.accel[i];
            if (!std::isfinite(a)) continue;
            if (n[i] == 0.0) {
                // |0 − v_prev,i|·x/l <= a_i.
                if (vPrev[i] != 0.0) x = std::min(x, a * l / std::abs(vPrev[i]));
                continue;
            }
            // The spec's n_i·x² − v_prev,i·x − a_i·l = 0, written for the axis's direction of
            // motion: |n_i|·x² − sgn(n_i)·v_prev,i·x − a_i·l = 0, the positive root.
            const double an = std::abs(n[i]), v = (n[i] > 0 ? 1.0 : -1.0) * vPrev[i];
            x = std::min(x, (v + std::sqrt(v * v + 4.0 * an * a * l)) / (2.0 * an));
        }
        sum += l / x;
        vPrev = n * x;
        walked += l;
    }
    return 2.0 * sum;
}

inline double seedReference(const std::vector<RefPiece>& pieces, const MachineLimits& limits) {
    double total = 0.0;
    for (const RefPiece& piece : pieces) total += seedReference(piece, limits);
    return total;
}

/// The tool path of a contour made of tangent-joined arcs only (the six-lobe cam), built here
/// from the arcs' data: each arc keeps its centre; its radius grows by rho on the outer branch
/// (convex: the contour turns left, counter-clockwise about the centre) and shrinks on the inner
/// one (concave, clockwise); it runs between the angles about its centre of the contour points
/// at its window's ends, where the ray at φ meets the circle (|φ·u − c| = R: the far root on the
/// outer branch, the near one on the inner). No corners: nothing is rounded or trimmed.
inline std::vector<RefPiece> offsetArcContour(const Contour& contour, double rho) {
    std::vector<RefPiece> pieces;
    for (std::size_t k = 0; k < contour.size(); ++k) {
        const Arc& arc = contour.segment(k).arc;
        const double sense = arc.branch == Branch::Outer ? 1.0 : -1.0;
        auto angleAt = [&](double phi) {
            const Vector2d u(std::cos(phi), std::sin(phi));
            const double b = u.dot(arc.center);
            const double t =
                b + sense * std::sqrt(b * b - arc.center.squaredNorm() + arc.radius * arc.radius);
            const Vector2d w = t * u - arc.center;
            return std::atan2(w.y(), w.x());
        };
        const double from = angleAt(contour.segment(k).phiStart);
        const double to = angleAt(contour.segment(k).phiEnd);
        double sweep = std::remainder(to - from, 2.0 * std::numbers::pi);
        if (sense * sweep < 0) sweep += sense * 2.0 * std::numbers::pi;
        pieces.push_back(RefPiece::arc(arc.center, arc.radius + sense * rho, from, sweep, 0.0));
    }
    return pieces;
}

/// What machining_time.h documents for TimingResult::gridPoints: the final plans' points,
/// summed over the stretches planned apart. The refinement starts from each segment's share of a
/// 4096-point grid and only adds points, and no plan holds more than kMaxPlanPoints.
inline ::testing::AssertionResult onRefinedGrid(std::size_t gridPoints, std::size_t stretches) {
    if (gridPoints >= 4096 && gridPoints <= stretches * kMaxPlanPoints) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << gridPoints << " grid points is not within [4096, " << stretches << "·2^24]";
}

}  // namespace cam::test
