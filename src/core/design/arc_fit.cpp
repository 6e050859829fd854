#include "design/arc_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/golden_section.h"
#include "geometry/planar.h"
#include "project/project.h"

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

/// How many points between two neighbouring samples the deviation is also checked at.
constexpr std::size_t kBetween = 3;

/// Points of the curve sampled densely once, with unit tangents; per interval the curve's mean
/// signed curvature (the turn of its tangent over its chord, + counter-clockwise) and its chord.
/// kBetween more points inside each interval are evaluated when a check first asks for them
/// (interval k holds between[k·kBetween …]): most biarcs are settled by the samples alone.
struct Samples {
    const std::function<CurveSample(double)>* curve = nullptr;
    std::vector<Eigen::Vector2d> point, tangent;
    std::vector<double> t;
    std::vector<double> curvature, chord;
    double minConcaveRadius = 0.0;  ///< see representable
    mutable std::vector<Eigen::Vector2d> between;
    mutable std::vector<char> haveBetween;

    /// The q-th point inside interval k.
    const Eigen::Vector2d& betweenPoint(std::size_t k, std::size_t q) const {
        if (!haveBetween[k]) {
            for (std::size_t p = 0; p < kBetween; ++p) {
                const double f = static_cast<double>(p + 1) / static_cast<double>(kBetween + 1);
                between[k * kBetween + p] = (*curve)(t[k] + f * (t[k + 1] - t[k])).point;
            }
            haveBetween[k] = 1;
        }
        return between[k * kBetween + q];
    }
};

/// The curve at n + 1 points from ta to tb (both ends included); finishSamples completes it.
Samples sampleCurve(const std::function<CurveSample(double)>& curve, double ta, double tb,
                    std::size_t n) {
    Samples s;
    s.curve = &curve;
    s.point.resize(n + 1);
    s.tangent.resize(n + 1);
    s.t.resize(n + 1);
    const double h = (tb - ta) / static_cast<double>(n);
    for (std::size_t k = 0; k <= n; ++k) {
        const double t = k == n ? tb : ta + h * static_cast<double>(k);
        const CurveSample c = curve(t);
        s.t[k] = t;
        s.point[k] = c.point;
        s.tangent[k] = c.tangent.normalized();
    }
    return s;
}

/// The per-interval curvature and chord of samples whose points and tangents are final.
void finishSamples(Samples& s) {
    const std::size_t n = s.t.size() - 1;
    s.curvature.resize(n);
    s.chord.resize(n);
    s.between.resize(n * kBetween);
    s.haveBetween.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const double chord = (s.point[k + 1] - s.point[k]).norm();
        const double turn =
            std::atan2(cross(s.tangent[k], s.tangent[k + 1]), s.tangent[k].dot(s.tangent[k + 1]));
        s.curvature[k] = chord > 0.0 ? turn / chord : 0.0;
        s.chord[k] = chord;
    }
}

/// An arc's signed curvature (+ counter-clockwise), 0 for a straight piece.
double curvatureOf(const FittedArc& arc) {
    if (arc.straight) return 0.0;
    return arc.sweep >= 0.0 ? 1.0 / arc.radius : -1.0 / arc.radius;
}

/// A bound on how far the curve strays from the two arcs over samples i … j (j > i), the
/// biarc's ends; with `fine` also at the points between the samples.
///
/// The distance is taken at the points, and between each two of them the bound adds what it can
/// grow there: the signed distance d from the curve to an arc it follows closely changes along
/// the curve with d'' ≈ κ_arc − κ_curve, so between two points a gap g apart it exceeds the
/// larger of its two values by at most g²/8·max|κ_arc − κ_curve|. So an arc much shorter than the
/// gap, or curved much unlike the curve, is not taken on the strength of points that miss its
/// bulge.
double boundedDeviation(const Samples& s, std::size_t i, std::size_t j,
                        const std::array<FittedArc, 2>& arcs, double giveUpAbove, bool fine) {
    const double kappa[2] = {curvatureOf(arcs[0]), curvatureOf(arcs[1])};
    const std::size_t steps = fine ? kBetween + 1 : 1;
    double worst = 0.0;
    // The biarc starts on the curve, on its first arc.
    double previous = 0.0;
    int previousArc = 0;
    for (std::size_t k = i; k < j; ++k) {
        // The curvature within interval k lies about between its neighbours' means: the
        // largest difference from an arc's is taken over the three.
        const double curve[3] = {s.curvature[k > 0 ? k - 1 : k], s.curvature[k],
                                 s.curvature[k + 1 < s.curvature.size() ? k + 1 : k]};
        const auto bendOf = [&](double kappaArc) {
            return std::max({std::abs(kappaArc - curve[0]), std::abs(kappaArc - curve[1]),
                             std::abs(kappaArc - curve[2])});
        };
        const double gap = s.chord[k] / static_cast<double>(steps);
        const double g2 = gap * gap / 8.0;
        for (std::size_t q = 0; q < steps; ++q) {
            double d = 0.0;
            int which = 1;  // the end of the biarc: on the curve, on its second arc
            const bool inside = q + 1 < steps;
            if (inside || k + 1 < j) {
                const Eigen::Vector2d& x = inside ? s.betweenPoint(k, q) : s.point[k + 1];
                const double d0 = distanceToArc(arcs[0], x), d1 = distanceToArc(arcs[1], x);
                which = d1 < d0 ? 1 : 0;
                d = std::min(d0, d1);
            }
            const double bend = std::max(bendOf(kappa[which]), bendOf(kappa[previousArc]));
            worst = std::max(worst, std::max(d, previous) + g2 * bend);
            if (worst > giveUpAbove) return worst;
            previous = d;
            previousArc = which;
        }
    }
    return worst;
}

/// How far the curve strays from the two arcs over samples i … j (j > i). With `stride` 1 a
/// bound (boundedDeviation): from the samples alone when that is within `enough`, else from the
/// points between them too (a tighter bound, from more points). Otherwise every stride-th
/// sample's distance only (a coarse look).
double deviation(const Samples& s, std::size_t i, std::size_t j,
                 const std::array<FittedArc, 2>& arcs, double giveUpAbove, std::size_t stride,
                 double enough) {
    if (stride == 1) {
        const double coarse = boundedDeviation(s, i, j, arcs, std::max(giveUpAbove, enough), false);
        if (coarse <= enough) return coarse;
        return boundedDeviation(s, i, j, arcs, giveUpAbove, true);
    }
    double worst = 0.0;
    for (std::size_t k = i + 1; k < j; k += stride) {
        const Eigen::Vector2d& x = s.point[k];
        worst = std::max(worst, std::min(distanceToArc(arcs[0], x), distanceToArc(arcs[1], x)));
        if (worst > giveUpAbove) return worst;
    }
    return worst;
}

/// Whether an arc can stand in a contour within the tolerance: its centre within the lengths a
/// project holds (kMaxLengthMm), its radius small enough that the contour's r(φ) of it
/// (μ ± √(μ² + R² − |c|²), whose rounding grows as ε·R) stays below a sixteenth of the
/// tolerance, and, turning clockwise (concave on a curve that runs counter-clockwise round the
/// centre), wider than `minConcaveRadius` (a roller's radius: it must fit into every concave arc).
/// Where a biarc's arc fails one of these, the search takes another junction, or a shorter biarc.
bool representable(const FittedArc& arc, double tolerance, double minConcaveRadius) {
    if (arc.straight) return true;
    const double radiusLimit = tolerance / (16.0 * std::numeric_limits<double>::epsilon());
    if (arc.sweep < 0.0 && !(arc.radius > minConcaveRadius * (1.0 + 1e-9))) return false;
    return arc.center.cwiseAbs().maxCoeff() <= kMaxLengthMm && arc.radius <= radiusLimit;
}

/// The smallest deviation of a biarc from sample i to sample j over its free junction.
double bestBiarc(const Samples& s, std::size_t i, std::size_t j, double tolerance,
                 std::array<FittedArc, 2>& best, std::size_t stride) {
    const Eigen::Vector2d &a = s.point[i], &ta = s.tangent[i];
    const Eigen::Vector2d &b = s.point[j], &tb = s.tangent[j];
    const double chord = (b - a).norm();
    double bestValue = kInfinity;
    std::array<FittedArc, 2> trial;
    const auto value = [&](double logLambda) {
        if (!biarc(a, ta, b, tb, chord * std::exp(logLambda), trial) ||
            !representable(trial[0], tolerance, s.minConcaveRadius) ||
            !representable(trial[1], tolerance, s.minConcaveRadius)) {
            return kInfinity;
        }
        const double d =
            deviation(s, i, j, trial, std::min(bestValue, 4.0 * tolerance), stride, tolerance);
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
    const double left = lo + (hi - lo) * std::max(bestIndex - 1, 0) / (kScan - 1);
    const double right = lo + (hi - lo) * std::min(bestIndex + 1, kScan - 1) / (kScan - 1);
    goldenSectionMin(value, left, right,
                     [&](double, double, int step) { return step < 24 && bestValue > tolerance; });
    return bestValue;
}

/// Whether b continues a's circle, so that a may take over b's stretch: centres and radii
/// within 1e-9 of the radius (one circle but for rounding), and within 1/64 of the tolerance,
/// which bounds how much further from the curve b's stretch lies on a's circle.
bool sameCircle(const FittedArc& a, const FittedArc& b, double tolerance) {
    if (a.straight || b.straight) return false;
    const double slack = std::min(1e-9 * std::max(a.radius, 1.0), tolerance / 64.0);
    return (a.center - b.center).norm() + std::abs(a.radius - b.radius) <= slack &&
           (a.sweep > 0.0) == (b.sweep > 0.0);
}

bool cancelled(const std::atomic<bool>* cancel) {
    return cancel && cancel->load(std::memory_order_relaxed);
}

/// How often fitFiner may halve one interval of the sampling. A biarc's deviation from a smooth
/// curve shrinks with the cube of its length, so a tolerance a thousand times below what one
/// interval reaches needs about three halvings; only a corner or a cusp (whose deviation
/// shrinks only in proportion) needs many, and one that 2^-24 of the interval does not fit is
/// one no tangent-continuous arcs can follow.
constexpr int kMaxHalvings = 24;

/// A point of the curve with its unit tangent.
struct Node {
    Eigen::Vector2d point, tangent;
};

/// Biarcs from a (at ta) to b (at tb) within the tolerance over every point between, halving
/// the stretch where one biarc does not do (each half sampled anew). False when cancelled or
/// when even kMaxHalvings halvings do not do (`where`: the start of that piece).
bool fitFiner(const std::function<CurveSample(double)>& curve, double ta, const Node& a, double tb,
              const Node& b, double tolerance, double minConcaveRadius, int depth,
              std::vector<FittedArc>& out, double& worst, double& where,
              const std::atomic<bool>* cancel) {
    if (cancelled(cancel)) return false;
    constexpr std::size_t kLocal = 4;
    Samples local = sampleCurve(curve, ta, tb, kLocal);
    // The ends are the caller's, so that neighbouring pieces meet exactly.
    local.point.front() = a.point;
    local.tangent.front() = a.tangent;
    local.point.back() = b.point;
    local.tangent.back() = b.tangent;
    finishSamples(local);
    local.minConcaveRadius = minConcaveRadius;
    std::array<FittedArc, 2> pair;
    if (const double d = bestBiarc(local, 0, kLocal, tolerance, pair, 1); d <= tolerance) {
        worst = std::max(worst, d);
        for (FittedArc& arc : pair) {
            arc.t0 = ta;
            arc.t1 = tb;
            out.push_back(arc);
        }
        return true;
    }
    if (depth >= kMaxHalvings) {
        where = ta;
        return false;
    }
    const Node middle{local.point[kLocal / 2], local.tangent[kLocal / 2]};
    const double tm = local.t[kLocal / 2];
    return fitFiner(curve, ta, a, tm, middle, tolerance, minConcaveRadius, depth + 1, out, worst,
                    where, cancel) &&
           fitFiner(curve, tm, middle, tb, b, tolerance, minConcaveRadius, depth + 1, out, worst,
                    where, cancel);
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
                       const std::atomic<bool>* cancel, double minConcaveRadius) {
    // Dense enough that most biarcs span many samples; where one interval is not fine enough
    // for the tolerance, fitFiner halves it.
    constexpr std::size_t n = 1 << 14;
    Samples s = sampleCurve(curve, t0, t0 + kTwoPi, n);
    // The curve is closed: the last point is the first (the last arc ends where the first
    // begins, not a rounding away).
    s.point[n] = s.point[0];
    s.tangent[n] = s.tangent[0];
    finishSamples(s);
    s.minConcaveRadius = minConcaveRadius;
    ArcFit fit;
    bool merged = false;
    const auto append = [&](const FittedArc& arc) {
        if (!fit.arcs.empty() && sameCircle(fit.arcs.back(), arc, tolerance)) {
            merged = true;
            fit.arcs.back().to = arc.to;
            fit.arcs.back().sweep += arc.sweep;
            fit.arcs.back().t1 = arc.t1;
        } else {
            fit.arcs.push_back(arc);
        }
    };
    std::array<FittedArc, 2> pair;
    // The search looks at every fourth sample; a biarc is taken only when every sample of its
    // stretch and every point between them is within the tolerance too.
    constexpr std::size_t kStride = 4;
    std::vector<FittedArc> pieces;
    for (std::size_t i = 0; i < n;) {
        if (cancelled(cancel)) return Diagnostics{};
        double value = 0.0, goodValue = 0.0;
        const auto fits = [&](std::size_t j) {
            // A short stretch is searched over all its points: a coarse look at one with no
            // sample inside would see nothing.
            if (j - i < 4 * kStride) {
                value = bestBiarc(s, i, j, tolerance, pair, 1);
                return value <= tolerance;
            }
            if (!(bestBiarc(s, i, j, tolerance, pair, kStride) <= tolerance)) return false;
            value = deviation(s, i, j, pair, tolerance, 1, tolerance);
            return value <= tolerance;
        };
        if (!fits(i + 1)) {
            // Not even one interval: its biarcs are made from finer samples.
            pieces.clear();
            double where = s.t[i];
            if (!fitFiner(curve, s.t[i], {s.point[i], s.tangent[i]}, s.t[i + 1],
                          {s.point[i + 1], s.tangent[i + 1]}, tolerance, minConcaveRadius, 1,
                          pieces, fit.maxDeviation, where, cancel)) {
                if (cancelled(cancel)) return Diagnostics{};
                const double deg = radToDeg(where);
                return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignTolerance},
                                                    DiagnosticCode::ToleranceCannotBeMet,
                                                    {deg, static_cast<double>(kMaxHalvings)})};
            }
            for (const FittedArc& arc : pieces) append(arc);
            ++i;
            continue;
        }
        // The longest biarc from sample i within the tolerance: double the span while it
        // fits, then bisect between the last that fitted and the first that did not.
        std::size_t good = i + 1, bad = n + 1;
        std::array<FittedArc, 2> goodPair = pair;
        goodValue = value;
        for (std::size_t span = 2; i + span <= n; span *= 2) {
            if (fits(i + span)) {
                good = i + span;
                goodPair = pair;
                goodValue = value;
            } else {
                bad = i + span;
                break;
            }
        }
        if (bad > n && good < n && fits(n)) {
            good = n;
            goodPair = pair;
            goodValue = value;
        }
        bad = std::min(bad, n + 1);
        while (bad - good > 1 && good < n) {
            const std::size_t mid = good + (bad - good) / 2;
            if (fits(mid)) {
                good = mid;
                goodPair = pair;
                goodValue = value;
            } else {
                bad = mid;
            }
        }
        fit.maxDeviation = std::max(fit.maxDeviation, goodValue);
        for (FittedArc& arc : goodPair) {
            arc.t0 = s.t[i];
            arc.t1 = s.t[good];
            append(arc);
        }
        i = good;
    }
    // The first and the last arc may be one circle (a fit that starts inside a dwell).
    if (fit.arcs.size() > 2 && sameCircle(fit.arcs.back(), fit.arcs.front(), tolerance)) {
        merged = true;
        FittedArc last = fit.arcs.back();
        fit.arcs.pop_back();
        last.to = fit.arcs.front().to;
        last.sweep += fit.arcs.front().sweep;
        last.t1 = fit.arcs.front().t1;
        fit.arcs.front() = last;
    }
    // A circle that took over its continuation may lie up to 1/64 of the tolerance further
    // from that stretch (sameCircle).
    if (merged) fit.maxDeviation += tolerance / 64.0;
    return fit;
}

}  // namespace cam
