#include "design/arc_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "geometry/planar.h"

namespace cam {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The arc from a with unit tangent ta to b (a straight piece when b lies on the tangent line).
FittedArc arcFrom(const Eigen::Vector2d& a, const Eigen::Vector2d& ta, const Eigen::Vector2d& b) {
    FittedArc arc;
    arc.from = a;
    arc.to = b;
    const Eigen::Vector2d chord = b - a;
    const Eigen::Vector2d left(-ta.y(), ta.x());
    const double across = chord.dot(left), length2 = chord.squaredNorm();
    if (std::abs(across) <= 1e-12 * length2 || length2 == 0.0) {
        arc.straight = true;
        return arc;
    }
    const double signedRadius = length2 / (2.0 * across);  // + when b is on the left: ccw
    arc.center = a + signedRadius * left;
    arc.radius = std::abs(signedRadius);
    const Eigen::Vector2d ra = a - arc.center, rb = b - arc.center;
    double sweep = std::atan2(cross(ra, rb), ra.dot(rb));
    // Turning left the sweep is positive and may exceed π; right, negative.
    if (signedRadius > 0.0 && sweep < 0.0) sweep += kTwoPi;
    if (signedRadius < 0.0 && sweep > 0.0) sweep -= kTwoPi;
    arc.sweep = sweep;
    return arc;
}

/// The unit tangent at the end of an arc.
Eigen::Vector2d endTangent(const FittedArc& arc, const Eigen::Vector2d& startTangent) {
    if (arc.straight) return startTangent;
    const double c = std::cos(arc.sweep), s = std::sin(arc.sweep);
    return {c * startTangent.x() - s * startTangent.y(),
            s * startTangent.x() + c * startTangent.y()};
}

/// The biarc from (a, ta) to (b, tb) with the first control leg α (math of the biarc family:
/// |b − β·tb − a − α·ta| = α + β); none (empty) when α admits no biarc.
bool biarc(const Eigen::Vector2d& a, const Eigen::Vector2d& ta, const Eigen::Vector2d& b,
           const Eigen::Vector2d& tb, double alpha, std::array<FittedArc, 2>& out) {
    const Eigen::Vector2d w = b - a - alpha * ta;
    const double denominator = 2.0 * (w.dot(tb) + alpha);
    if (!(std::abs(denominator) > 1e-300)) return false;
    const double beta = (w.squaredNorm() - alpha * alpha) / denominator;
    if (!(beta > 0.0)) return false;
    const Eigen::Vector2d p = a + alpha * ta, q = b - beta * tb;
    const Eigen::Vector2d junction = p + (alpha / (alpha + beta)) * (q - p);
    out[0] = arcFrom(a, ta, junction);
    const Eigen::Vector2d tj = endTangent(out[0], ta);
    out[1] = arcFrom(junction, tj, b);
    return true;
}

/// Points of the curve sampled densely once, with unit tangents.
struct Samples {
    std::vector<Eigen::Vector2d> point, tangent;
    std::vector<double> t;
    [[nodiscard]] std::size_t size() const { return t.size(); }
};

/// The largest distance from samples i … j (indices mod n, j > i) to the two arcs.
double deviation(const Samples& s, std::size_t i, std::size_t j,
                 const std::array<FittedArc, 2>& arcs, double giveUpAbove, std::size_t stride = 1) {
    const std::size_t n = s.size() - 1;  // the last sample repeats the first
    double worst = 0.0;
    for (std::size_t k = i + 1; k < j; k += stride) {
        const Eigen::Vector2d& x = s.point[k % n];
        const double d = std::min(distanceToArc(arcs[0], x), distanceToArc(arcs[1], x));
        worst = std::max(worst, d);
        if (worst > giveUpAbove) return worst;
    }
    return worst;
}

/// The smallest deviation of a biarc from sample i to sample j over its free junction.
double bestBiarc(const Samples& s, std::size_t i, std::size_t j, double tolerance,
                 std::array<FittedArc, 2>& best, std::size_t stride) {
    const std::size_t n = s.size() - 1;
    const Eigen::Vector2d &a = s.point[i % n], &ta = s.tangent[i % n];
    const Eigen::Vector2d &b = s.point[j % n], &tb = s.tangent[j % n];
    const double chord = (b - a).norm();
    double bestValue = kInfinity;
    std::array<FittedArc, 2> trial;
    const auto value = [&](double logLambda) {
        if (!biarc(a, ta, b, tb, chord * std::exp(logLambda), trial)) return kInfinity;
        const double d = deviation(s, i, j, trial, std::min(bestValue, 4.0 * tolerance), stride);
        if (d < bestValue) {
            bestValue = d;
            best = trial;
        }
        return d;
    };
    // The leg α as a fraction λ of the chord, on a log scale: a coarse scan, then golden
    // sections round the best of it (the deviation need not be unimodal over all λ).
    // The scan starts in the middle (the legs of a symmetric biarc) and stops at the first
    // biarc within the tolerance: the greedy search only asks whether one exists.
    constexpr int kScan = 9;
    constexpr double lo = -3.0, hi = 0.7;
    int bestIndex = kScan / 2;
    double bestScan = kInfinity;
    for (int step = 0; step < kScan; ++step) {
        const int k = kScan / 2 + (step % 2 == 0 ? step / 2 : -(step + 1) / 2);
        const double v = value(lo + (hi - lo) * k / (kScan - 1));
        if (v < bestScan) {
            bestScan = v;
            bestIndex = k;
        }
        if (bestValue <= tolerance) return bestValue;
    }
    double left = lo + (hi - lo) * std::max(bestIndex - 1, 0) / (kScan - 1);
    double right = lo + (hi - lo) * std::min(bestIndex + 1, kScan - 1) / (kScan - 1);
    constexpr double g = 0.6180339887498949;
    double x1 = right - g * (right - left), x2 = left + g * (right - left);
    double f1 = value(x1), f2 = value(x2);
    for (int it = 0; it < 24 && bestValue > tolerance; ++it) {
        if (f1 <= f2) {
            right = x2;
            x2 = x1;
            f2 = f1;
            x1 = right - g * (right - left);
            f1 = value(x1);
        } else {
            left = x1;
            x1 = x2;
            f1 = f2;
            x2 = left + g * (right - left);
            f2 = value(x2);
        }
    }
    return bestValue;
}

bool sameCircle(const FittedArc& a, const FittedArc& b) {
    if (a.straight || b.straight) return false;
    const double scale = std::max(a.radius, 1.0);
    return (a.center - b.center).norm() <= 1e-9 * scale &&
           std::abs(a.radius - b.radius) <= 1e-9 * scale && (a.sweep > 0.0) == (b.sweep > 0.0);
}

}  // namespace

double distanceToArc(const FittedArc& arc, const Eigen::Vector2d& x) {
    if (arc.straight) {
        const Eigen::Vector2d d = arc.to - arc.from;
        const double t = std::clamp((x - arc.from).dot(d) / d.squaredNorm(), 0.0, 1.0);
        return (x - (arc.from + t * d)).norm();
    }
    // Inside the wedge from the start radius to the end radius (by cross products: no angle).
    const Eigen::Vector2d ra = arc.from - arc.center, rb = arc.to - arc.center;
    const Eigen::Vector2d rx = x - arc.center;
    const double sign = arc.sweep >= 0.0 ? 1.0 : -1.0;
    const bool afterStart = sign * cross(ra, rx) >= 0.0, beforeEnd = sign * cross(rx, rb) >= 0.0;
    const bool inside =
        std::abs(arc.sweep) <= kPi ? afterStart && beforeEnd : afterStart || beforeEnd;
    if (inside) return std::abs(rx.norm() - arc.radius);
    return std::min((x - arc.from).norm(), (x - arc.to).norm());
}

Result<ArcFit> fitArcs(const std::function<CurveSample(double)>& curve, double t0, double tolerance,
                       const std::atomic<bool>* cancel) {
    // Dense enough that the curve between two samples strays from their chord by far less
    // than any tolerance a drawing asks for.
    constexpr std::size_t n = 1 << 14;
    Samples s;
    s.point.resize(n + 1);
    s.tangent.resize(n + 1);
    s.t.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const double t = t0 + kTwoPi * static_cast<double>(k) / n;
        const CurveSample c = curve(t);
        s.t[k] = t;
        s.point[k] = c.point;
        s.tangent[k] = c.tangent.normalized();
    }
    ArcFit fit;
    std::array<FittedArc, 2> pair;
    for (std::size_t i = 0; i < n;) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return Diagnostics{};
        // The longest biarc from sample i within the tolerance: double the span while it
        // fits, then bisect between the last that fitted and the first that did not.
        std::size_t good = i + 1, bad = n + 1;
        std::array<FittedArc, 2> goodPair;
        if (!(bestBiarc(s, i, good, tolerance, goodPair, 1) <= tolerance)) {
            return Diagnostics{
                Diagnostic{"design.tolerance",
                           "cannot be met: no biarc joins two neighbouring points of the "
                           "profile's sampling within it (the profile has a corner or a "
                           "cusp there, or the tolerance is too small)"}
                    .coded(DiagnosticCode::ToleranceCannotBeMet, {})};
        }
        // The search looks at every fourth sample; a biarc is taken only when every sample of
        // its stretch is within the tolerance too.
        constexpr std::size_t kStride = 4;
        const auto fits = [&](std::size_t j) {
            return bestBiarc(s, i, j, tolerance, pair, kStride) <= tolerance &&
                   deviation(s, i, j, pair, tolerance) <= tolerance;
        };
        for (std::size_t span = 2; i + span <= n; span *= 2) {
            if (fits(i + span)) {
                good = i + span;
                goodPair = pair;
            } else {
                bad = i + span;
                break;
            }
        }
        if (bad > n && good < n && fits(n)) {
            good = n;
            goodPair = pair;
        }
        bad = std::min(bad, n + 1);
        while (bad - good > 1 && good < n) {
            const std::size_t mid = good + (bad - good) / 2;
            if (fits(mid)) {
                good = mid;
                goodPair = pair;
            } else {
                bad = mid;
            }
        }
        for (FittedArc& arc : goodPair) {
            arc.t0 = s.t[i];
            arc.t1 = s.t[good];
            if (!fit.arcs.empty() && sameCircle(fit.arcs.back(), arc)) {
                fit.arcs.back().to = arc.to;
                fit.arcs.back().sweep += arc.sweep;
                fit.arcs.back().t1 = arc.t1;
            } else {
                fit.arcs.push_back(arc);
            }
        }
        i = good;
    }
    // The first and the last arc may be one circle (a fit that starts inside a dwell).
    if (fit.arcs.size() > 2 && sameCircle(fit.arcs.back(), fit.arcs.front())) {
        FittedArc last = fit.arcs.back();
        fit.arcs.pop_back();
        last.to = fit.arcs.front().to;
        last.sweep += fit.arcs.front().sweep;
        last.t1 = fit.arcs.front().t1;
        fit.arcs.front() = last;
    }
    // The deviation as fitted, over every sample: each against the arcs whose stretch of the
    // parameter holds it and their neighbours (the arcs are in the curve's order).
    const std::size_t m = fit.arcs.size();
    std::size_t arc = 0;
    for (std::size_t k = 0; k < n; ++k) {
        while (arc + 1 < m && fit.arcs[arc].t1 <= s.t[k]) ++arc;
        double d = kInfinity;
        for (std::size_t j : {arc + m - 1, arc, arc + 1}) {
            d = std::min(d, distanceToArc(fit.arcs[j % m], s.point[k]));
        }
        fit.maxDeviation = std::max(fit.maxDeviation, d);
    }
    fit.checkedPoints = n;
    return fit;
}

}  // namespace cam
