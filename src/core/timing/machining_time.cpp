#include "timing/machining_time.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "common/angles.h"
#include "common/cancel.h"
#include "common/tolerances.h"
#include "timing/seed_method.h"

namespace cam {
namespace {

using Vec3 = Eigen::Vector3d;

/// Below this a tangent component counts as zero: the axis then bounds speed by curvature only.
constexpr double kTiny = 1e-12;

/// A joint is a corner (the tool must stop there) when the tangent turns by more than
/// kTangentToleranceDeg: the rule by which the tool path decides where to round or trim, so a
/// joint it leaves as tangent is one the planner passes through, and every other one stops it.
bool isCorner(const PathSegment& a, const PathSegment& b) {
    const Vec3 ta = a.tangent(a.length()), tb = b.tangent(0.0);
    // atan2 rather than acos: acos(dot) loses half the digits of a small angle.
    return std::atan2(ta.cross(tb).norm(), ta.dot(tb)) > degToRad(kTangentToleranceDeg);
}

/// Linear bounds on the path acceleration u = s-ddot in terms of the squared speed x = s-dot²:
/// c_i + d_i·x <= u <= e_i + d_i·x for every axis with an acceleration limit, and a cap on x.
/// They describe one point of the path (its maximum-velocity curve) or one grid interval (a
/// stage, see stageBounds).
struct Bounds {
    std::array<double, 3> c{}, d{}, e{};
    int count = 0;
    double xCap = kUnlimited;

    /// An axis with limit a whose acceleration is A·u + B·x: −a <= A·u + B·x <= a.
    void addAxis(double A, double B, double a) {
        if (std::isinf(a)) return;
        if (std::abs(A) > kTiny) {
            const double inverse = 1.0 / A;  // one division where three would do the same
            e[count] = a * std::abs(inverse);
            c[count] = -e[count];
            d[count] = -B * inverse;
            ++count;
        } else if (std::abs(B) > kTiny) {
            xCap = std::min(xCap, a / std::abs(B));  // the axis only feels the curvature
        }
    }

    /// Largest x for which some u satisfies every bound: for every pair, c_i + d_i·x <=
    /// e_j + d_j·x, i.e. (d_i − d_j)·x <= e_i + e_j (c_i = −e_i).
    [[nodiscard]] double maxX() const {
        double x = xCap;
        for (int i = 0; i < count; ++i) {
            for (int j = i + 1; j < count; ++j) {
                const double spread = std::abs(d[i] - d[j]);
                if (spread > 0) x = std::min(x, (e[i] + e[j]) / spread);
            }
        }
        return x;
    }
    [[nodiscard]] double uMax(double x) const {
        double u = kUnlimited;
        for (int i = 0; i < count; ++i) u = std::min(u, e[i] + d[i] * x);
        return u;
    }
    /// Largest x from which the gentlest acceleration allowed over an interval Δ keeps
    /// x + 2Δu >= 0: where d_i·Δ < −1/2 (on a coarse grid, where the curvature forces braking
    /// harder than the interval can take) u <= e_i + d_i·x must stay above −x/(2Δ).
    [[nodiscard]] double stayPositive(double delta) const {
        double x = kUnlimited;
        const double floor = -1.0 / (2.0 * delta);
        for (int i = 0; i < count; ++i) {
            if (d[i] < floor) x = std::min(x, e[i] / (floor - d[i]));
        }
        return x;
    }
    /// Largest x from which the hardest braking allowed here keeps x + 2Δu <= next.
    [[nodiscard]] double brakeTo(double next, double delta) const {
        double x = kUnlimited;
        for (int i = 0; i < count; ++i) {
            const double k = 1.0 + 2.0 * delta * d[i];
            if (k > 0) x = std::min(x, (next - 2.0 * delta * c[i]) / k);
        }
        return x;
    }
};

/// The squared-speed cap of the feed and the axis speed limits where the unit tangent is t.
double speedCap(const Vec3& t, const MachineLimits& lim) {
    double x = lim.feedMax * lim.feedMax;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(t[i]) > kTiny) {
            const double v = lim.vmax[i] / std::abs(t[i]);
            x = std::min(x, v * v);
        }
    }
    return x;
}

/// The limits at one point with unit tangent t and curvature vector k: its maximum-velocity
/// curve is maxX().
Bounds pointBounds(const Vec3& t, const Vec3& k, const MachineLimits& lim) {
    Bounds b;
    for (int i = 0; i < 3; ++i) b.addAxis(t[i], k[i], lim.accel[i]);
    b.xCap = std::min(b.xCap, speedCap(t, lim));
    return b;
}

/// The limits of one grid interval of length Δ, on (x, u) at its start: over the interval u is
/// constant and x linear, and the axis accelerations are required at its middle, where
/// x_mid = x + Δ·u. So axis i's A·u + B·x_mid there is (A + Δ·B)·u + B·x (A, B: the middle's
/// tangent and curvature components). Taking them at the middle makes the plan second-order
/// accurate in Δ (the implicit midpoint rule for ẋ = 2u), where taking them at the start made
/// it first-order: on arcs that is what let a coarse grid be far off (issue 9).
Bounds stageBounds(const Vec3& t, const Vec3& k, double delta, const MachineLimits& lim) {
    Bounds b;
    for (int i = 0; i < 3; ++i) b.addAxis(t[i] + delta * k[i], k[i], lim.accel[i]);
    return b;
}

/// cos and sin of start + m·step for m = 0, 1, 2, … by a rotation recurrence, recomputed
/// exactly every 256 steps so rounding never accumulates.
class AngleWalker {
public:
    AngleWalker(double start, double step) : m_start(start), m_step(step) {
        m_cd = std::cos(step);
        m_sd = std::sin(step);
        sync();
    }
    [[nodiscard]] double cos() const { return m_c; }
    [[nodiscard]] double sin() const { return m_s; }
    void advance() {
        if (++m_m % 256 == 0) {
            sync();
        } else {
            const double c = m_c * m_cd - m_s * m_sd;
            m_s = m_s * m_cd + m_c * m_sd;
            m_c = c;
        }
    }

private:
    void sync() {
        const double theta = m_start + static_cast<double>(m_m) * m_step;
        m_c = std::cos(theta);
        m_s = std::sin(theta);
    }
    double m_start, m_step;
    double m_c = 1.0, m_s = 0.0, m_cd = 1.0, m_sd = 0.0;
    std::size_t m_m = 0;
};

/// One segment's share of a plan's grid: equal intervals, the first point on the joint with the
/// previous segment.
struct SegmentGrid {
    std::size_t first = 0;      ///< index of the segment's first grid point
    std::size_t intervals = 0;  ///< equal intervals on this segment
    double delta = 0.0;         ///< their length, mm
    double startCap = 0.0;      ///< cap on x at the first point: 0 at a stop, else both sides'
    bool isArc = false;
    // Lines: the same at every interval and point.
    Bounds lineStage;
    double lineCap = kUnlimited;   ///< speed cap at the inner points (arcs: the feed's alone)
    double lineMaxX = kUnlimited;  ///< lineStage.maxX()
    // Arcs: polar angle of the first point about the centre, its step, the sense and radius.
    double theta0 = 0.0, dtheta = 0.0, sign = 1.0, radius = 1.0;
    bool pointCaps = false;  ///< the speed cap varies along the arc (a finite axis vmax)
};

Vec3 arcTangent(const SegmentGrid& g, double c, double s) { return {-g.sign * s, g.sign * c, 0}; }
Vec3 arcCurvature(const SegmentGrid& g, double c, double s) {
    return {-c / g.radius, -s / g.radius, 0.0};
}

/// The grid of segments [first, last) with `intervals[k - first]` intervals on segment k. The
/// plan stops at `first`, at the end of `last − 1` and at every corner in between. False if
/// cancelled.
bool makeGrid(const ToolPath& path, std::size_t first, std::size_t last,
              const std::size_t* intervals, const MachineLimits& lim,
              std::vector<SegmentGrid>& grid, std::size_t* total, const std::atomic<bool>* cancel) {
    grid.clear();
    grid.reserve(last - first);
    std::size_t index = 0;
    for (std::size_t k = first; k < last; ++k) {
        if ((k - first) % kCancelPollInterval == 0 && cancelRequested(cancel)) return false;
        const PathSegment& seg = path.segments[k];
        SegmentGrid& g = grid.emplace_back();
        g.first = index;
        g.intervals = std::max<std::size_t>(intervals[k - first], 1);
        g.delta = seg.length() / static_cast<double>(g.intervals);
        g.isArc = seg.kind == PathSegment::Kind::Arc;
        if (k > first && !isCorner(path.segments[k - 1], seg)) {
            // Without a jerk limit the path acceleration may jump at a joint; only the speed is
            // shared. So both segments' maximum-velocity curves bound the joint's speed, and
            // the accelerations on either side are their own.
            const PathSegment& prev = path.segments[k - 1];
            g.startCap = std::min(
                pointBounds(prev.tangent(prev.length()), prev.curvature(prev.length()), lim).maxX(),
                pointBounds(seg.tangent(0.0), seg.curvature(0.0), lim).maxX());
        }
        if (g.isArc) {
            g.sign = seg.sweep >= 0 ? 1.0 : -1.0;
            g.radius = seg.radius;
            g.theta0 = seg.startAngle;
            g.dtheta = g.sign * g.delta / seg.radius;
            g.pointCaps = !std::isinf(lim.vmax[0]) || !std::isinf(lim.vmax[1]);
            g.lineCap = lim.feedMax * lim.feedMax;
        } else {
            const Vec3 t = seg.tangent(0.0);
            g.lineStage = stageBounds(t, Vec3::Zero(), g.delta, lim);
            g.lineCap = speedCap(t, lim);
            g.lineMaxX = g.lineStage.maxX();
        }
        index += g.intervals;
    }
    *total = index + 1;  // and the end point
    return true;
}

/// body(j) for j = first, first + 1, …, end − 1, reading the cancel flag before each block of
/// kCancelPollInterval; false if cancelled. The loop within a block is the plain one (a test of
/// the flag at every point cost the planner's benchmark 10–20 %).
template <class Body>
bool countUp(std::size_t first, std::size_t end, const std::atomic<bool>* cancel, Body&& body) {
    for (std::size_t j = first; j < end;) {
        if (cancelRequested(cancel)) return false;
        const std::size_t blockEnd = std::min(end, j + kCancelPollInterval);
        for (; j < blockEnd; ++j) body(j);
    }
    return true;
}

/// The smaller in magnitude of a and b if they have the same sign, else 0 (a slope limiter).
double minmod(double a, double b) {
    if (a * b <= 0.0) return 0.0;
    return std::abs(a) < std::abs(b) ? a : b;
}

/// The backward pass's value at a point: the largest controllable squared speed, the smaller of
/// the point's cap and what braking to the next point allows. Stored negative (−0.0 included)
/// when braking binds, so the forward pass knows the boundary's slope there (kinkTime); every
/// other reader takes its magnitude.
double controllable(double cap, double brake) {
    const double value = std::max(0.0, std::min(cap, brake));
    return brake < cap ? -value : value;
}

/// The time over an interval of length Δ (limits `b`) whose forward profile is clipped at its
/// end (x1 = |hiNext| is less than accelerating from x0 with u = uFree would give), when the
/// switch lies inside it: the profile rises from x0 with uFree (or, riding a speed cap at its
/// start, stays at x0) until it meets the boundary of the controllable set and follows that to
/// x1. x is then two lines, each timed exactly. The boundary is the braking line that ends at x1
/// where braking binds there (hiNext stored negative by `controllable`) or x1 is a stop, else
/// the cap, flat. −1 where the profile is not clipped, or runs along the boundary from the start.
double kinkTime(double x0, double hiHere, double uFree, const Bounds& b, double hiNext,
                double delta) {
    const double x1 = std::abs(hiNext);
    if (!(x0 + 2.0 * delta * uFree > x1)) return -1.0;
    double uBoundary = 0.0;
    if (std::signbit(hiNext) || x1 == 0.0) {
        uBoundary = (x1 - b.brakeTo(x1, delta)) / (2.0 * delta);
        if (!std::isfinite(uBoundary)) uBoundary = 0.0;
    }
    const bool onCap = x0 > 0.0 && !std::signbit(hiHere) && x0 >= std::abs(hiHere) * (1.0 - 1e-9);
    const double uRise = onCap ? 0.0 : uFree;
    const double start = x1 - 2.0 * delta * uBoundary;  // the boundary at the interval's start
    if (!(x0 < start * (1.0 - 1e-12)) || !(uRise > uBoundary)) return -1.0;
    const double sigma = std::clamp((start - x0) / (2.0 * (uRise - uBoundary)), 0.0, delta);
    const double r0 = std::sqrt(x0), r1 = std::sqrt(x1);
    const double rk = std::sqrt(std::max(0.0, x0 + 2.0 * uRise * sigma));
    double t = 0.0;
    if (sigma > 0) t += r0 + rk > 0 ? 2.0 * sigma / (r0 + rk) : kUnlimited;
    if (sigma < delta) t += rk + r1 > 0 ? 2.0 * (delta - sigma) / (rk + r1) : kUnlimited;
    return t;
}

/// The time of a segment's intervals (squared speeds x[0..intervals], step Δ; kink[j] from
/// kinkTime, used where >= 0). With x linear over an interval its time is 2Δ/(√x0 + √x1)
/// exactly. But x is curved, and where it starts from rest (x ~ s) the error of that formula,
/// O(Δ^1.5), would dominate the plan's. With x = linear + β·σ(σ − Δ), to first order in β the
/// time is
///     2Δ/(√x0 + √x1) + (2/3)·β·Δ³/(√x0 + √x1)³
/// (∫ σ(σ − Δ)·x_lin^(-3/2) dσ over the interval is exactly −(4/3)·Δ³/(√x0 + √x1)³). β = du/ds
/// comes from the neighbouring intervals' accelerations u: the smaller of the two one-sided
/// differences, and none where they disagree in sign (a kink in x is no curvature). False if
/// cancelled.
bool timeOfSegment(const double* x, const double* kink, std::size_t intervals, double delta,
                   const std::atomic<bool>* cancel, double* time) {
    const double half = 1.0 / (2.0 * delta), inverse = 1.0 / delta;
    const double cube = (2.0 / 3.0) * delta * delta * delta;
    double total = 0.0;
    double r0 = std::sqrt(x[0]);
    double uPrev = 0.0;
    double u = (x[1] - x[0]) * half;
    const bool done = countUp(0, intervals, cancel, [&](std::size_t j) {
        const double r1 = std::sqrt(x[j + 1]);
        const double uNext = j + 1 < intervals ? (x[j + 2] - x[j + 1]) * half : 0.0;
        if (kink[j] >= 0.0) {
            total += kink[j];
        } else {
            const double sum = r0 + r1;
            if (!(sum > 0)) {
                total = kUnlimited;
            } else {
                double beta = 0.0;
                if (intervals >= 2) {
                    if (j == 0) {
                        beta = (uNext - u) * inverse;
                    } else if (j + 1 == intervals) {
                        beta = (u - uPrev) * inverse;
                    } else {
                        beta = minmod((u - uPrev) * inverse, (uNext - u) * inverse);
                    }
                }
                const double base = 2.0 * delta / sum;
                const double correction = cube * beta / (sum * sum * sum);
                // The expansion holds while the correction is small; beyond, it is no estimate.
                total += base + std::clamp(correction, -0.25 * base, 0.25 * base);
            }
        }
        r0 = r1;
        uPrev = u;
        u = uNext;
    });
    *time = total;
    return done;
}

/// One plan of a stretch of path, stopping at both its ends (and at the corners inside).
struct Plan {
    OptimalProfile profile;               ///< s and x only when asked for
    std::vector<SegmentTiming> segments;  ///< per segment of the stretch
    std::size_t points = 0;
    bool cancelled = false;
};

Plan cancelledPlan() {
    Plan plan;
    plan.cancelled = true;
    return plan;
}

/// The time-optimal plan of segments [first, last) on the given grid: TOPP-RA's backward pass
/// (the largest squared speed at each point from which the end and every corner can still be
/// reached at rest), then the forward pass (accelerate as hard as allowed while staying
/// controllable). Both passes read the cancel flag at every segment and every
/// kCancelPollInterval grid points within one.
Plan planStretch(const ToolPath& path, std::size_t first, std::size_t last,
                 const std::size_t* intervals, const MachineLimits& lim, bool keepProfile,
                 const std::atomic<bool>* cancel) {
    std::size_t n = 0;
    std::vector<SegmentGrid> grid;
    if (!makeGrid(path, first, last, intervals, lim, grid, &n, cancel)) return cancelledPlan();
    Plan plan;
    // Uninitialised where possible (every point is written before it is read): zero-filling
    // hundreds of MB up front costs time that no poll could interrupt.
    const std::unique_ptr<double[]> hiStore(new double[n]);
    std::unique_ptr<double[]> xStore;
    if (keepProfile) {
        // Grown in blocks between polls: one resize of a fine plot's grid takes a while.
        plan.profile.x.reserve(n);
        while (plan.profile.x.size() < n) {
            if (cancelRequested(cancel)) return cancelledPlan();
            plan.profile.x.resize(std::min(n, plan.profile.x.size() + 64 * kCancelPollInterval));
        }
    } else {
        xStore.reset(new double[n]);
    }
    double* const hi = hiStore.get();
    double* const x = keepProfile ? plan.profile.x.data() : xStore.get();

    hi[n - 1] = 0.0;
    for (std::size_t k = grid.size(); k-- > 0;) {
        const SegmentGrid& g = grid[k];
        const double delta = g.delta;
        // Interval j runs from point g.first + j to the next; its cap is that of its first point.
        auto step = [&](std::size_t j, const Bounds& b, double cap) {
            const std::size_t i = g.first + j;
            hi[i] = controllable(std::min({cap, b.maxX(), b.stayPositive(delta)}),
                                 b.brakeTo(std::abs(hi[i + 1]), delta));
        };
        // Counted down in blocks between polls, like countUp.
        std::size_t j = g.intervals;
        bool done = true;
        if (g.isArc) {
            // Half steps from the last interval's middle down: middles at odd counts, points at
            // even ones.
            AngleWalker walk(g.theta0 + (static_cast<double>(g.intervals) - 0.5) * g.dtheta,
                             -g.dtheta / 2.0);
            while (j > 0 && done) {
                if (cancelRequested(cancel)) done = false;
                const std::size_t blockEnd = j > kCancelPollInterval ? j - kCancelPollInterval : 0;
                for (; done && j > blockEnd; --j) {
                    const double cm = walk.cos(), sm = walk.sin();
                    const Bounds b =
                        stageBounds(arcTangent(g, cm, sm), arcCurvature(g, cm, sm), delta, lim);
                    walk.advance();
                    double cap = g.startCap;
                    if (j > 1) {
                        cap = g.pointCaps ? speedCap(arcTangent(g, walk.cos(), walk.sin()), lim)
                                          : g.lineCap;
                    }
                    walk.advance();
                    step(j - 1, b, cap);
                }
            }
        } else {
            while (j > 0 && done) {
                if (cancelRequested(cancel)) done = false;
                const std::size_t blockEnd = j > kCancelPollInterval ? j - kCancelPollInterval : 0;
                const double inner = std::min(g.lineCap, g.lineMaxX);
                for (; done && j > blockEnd; --j) {
                    const std::size_t i = g.first + j - 1;
                    const double cap = j > 1 ? inner : std::min(g.startCap, g.lineMaxX);
                    hi[i] = controllable(cap, g.lineStage.brakeTo(std::abs(hi[i + 1]), delta));
                }
            }
        }
        if (!done) return cancelledPlan();
    }

    plan.segments.resize(grid.size());
    x[0] = 0.0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const SegmentGrid& g = grid[k];
        const double delta = g.delta;
        SegmentTiming& st = plan.segments[k];
        st.lengthMm = path.segments[first + k].length();
        st.entrySpeed = std::sqrt(x[g.first]);
        auto step = [&](std::size_t j, const Bounds& b) {
            const std::size_t i = g.first + j;
            const double uFree = b.uMax(x[i]);
            const double next = std::abs(hi[i + 1]);
            const double uBound = (next - x[i]) / (2.0 * delta);
            x[i + 1] = std::clamp(x[i] + 2.0 * delta * std::min(uFree, uBound), 0.0, next);
            // hi[i] is not read again: it keeps the interval's time if the profile meets the
            // controllable set's boundary inside it, or −1 (timeOfSegment).
            hi[i] = kinkTime(x[i], hi[i], uFree, b, hi[i + 1], delta);
        };
        bool done = true;
        if (g.isArc) {
            AngleWalker walk(g.theta0 + 0.5 * g.dtheta, g.dtheta);
            done = countUp(0, g.intervals, cancel, [&](std::size_t j) {
                const double cm = walk.cos(), sm = walk.sin();
                walk.advance();
                step(j, stageBounds(arcTangent(g, cm, sm), arcCurvature(g, cm, sm), delta, lim));
            });
        } else {
            done = countUp(0, g.intervals, cancel, [&](std::size_t j) { step(j, g.lineStage); });
        }
        if (!done) return cancelledPlan();
        double segmentTime = 0.0;
        if (!timeOfSegment(x + g.first, hi + g.first, g.intervals, delta, cancel, &segmentTime)) {
            return cancelledPlan();
        }
        st.timeS = segmentTime;
        st.exitSpeed = std::sqrt(x[g.first + g.intervals]);
        plan.profile.timeS += segmentTime;
    }
    plan.points = n;
    if (keepProfile) {
        std::vector<double>& sOut = plan.profile.s;
        sOut.reserve(n);
        for (const SegmentGrid& g : grid) {
            const double base = g.first == 0 ? 0.0 : sOut.back() + g.delta;
            if (!countUp(0, g.intervals, cancel, [&](std::size_t j) {
                    sOut.push_back(base + g.delta * static_cast<double>(j));
                })) {
                return cancelledPlan();
            }
        }
        double end = 0.0;
        for (std::size_t k = first; k < last; ++k) end += path.segments[k].length();
        sOut.push_back(end);
    }
    return plan;
}

/// Intervals per segment of [first, last) for a grid spacing of about `spacing`, at least
/// `minimum` each.
std::vector<std::size_t> intervalsFor(const ToolPath& path, std::size_t first, std::size_t last,
                                      double spacing, std::size_t minimum) {
    std::vector<std::size_t> n(last - first);
    for (std::size_t k = first; k < last; ++k) {
        const double share = std::ceil(path.segments[k].length() / spacing - 1e-9);
        n[k - first] = share >= 1e15 ? std::size_t{1} << 50
                                     : std::max(minimum, static_cast<std::size_t>(share));
    }
    return n;
}

/// What the refinement of a path (or of its stretches between stops) gives.
struct Refined {
    std::vector<SegmentTiming> segments;
    double timeS = 0.0;
    std::size_t points = 0;
    double errorS = 0.0;  ///< sum over segments of the larger of their last two changes
    bool converged = true;
    bool cancelled = false;
};

/// A segment's time is taken as converged when the last two doublings of its intervals changed
/// it by at most this fraction. The plan is second-order accurate, so the error left is about a
/// third of the last change.
constexpr double kSegmentTolerance = 1e-6;
/// Intervals per segment on the first grid (beside the share of a 4096-point grid).
constexpr std::size_t kMinIntervals = 4;
/// Most refinements of one stretch.
constexpr int kMaxRounds = 40;

/// Plans segments [first, last), which start and end at rest, refining per segment: every
/// segment whose time moved by more than kSegmentTolerance of itself at either of the last two
/// doublings of its intervals (or when a neighbour's were doubled) is doubled again, and the
/// stretch replanned, until none moves or `budget` grid points would be exceeded. Appends to `out`;
/// false if cancelled.
bool refineStretch(const ToolPath& path, std::size_t first, std::size_t last, double spacing,
                   const MachineLimits& lim, std::size_t budget, const std::atomic<bool>* cancel,
                   Refined& out) {
    const std::size_t count = last - first;
    std::vector<std::size_t> n = intervalsFor(path, first, last, spacing, kMinIntervals);
    std::size_t total = 1;
    for (std::size_t v : n) total += v;
    if (total > budget) {
        n = intervalsFor(path, first, last, kUnlimited, 2);
        total = 2 * count + 1;
    }
    Plan plan = planStretch(path, first, last, n.data(), lim, false, cancel);
    if (plan.cancelled) return false;
    std::vector<double> error(count, kUnlimited), lastChange(count, kUnlimited);
    bool converged = false;
    std::vector<std::size_t> refine;
    for (int round = 0; round < kMaxRounds && total <= budget; ++round) {
        refine.clear();
        for (std::size_t k = 0; k < count; ++k) {
            // A time that is not finite (a grid so coarse that the speed drops to zero inside a
            // segment) is never converged.
            const double t = plan.segments[k].timeS;
            if (!std::isfinite(t) || !(error[k] <= kSegmentTolerance * t)) refine.push_back(k);
        }
        if (refine.empty()) {
            converged = true;
            break;
        }
        // The worst first, as many as the budget allows.
        std::size_t extra = 0;
        for (std::size_t k : refine) extra += n[k];
        if (total + extra > budget) {
            std::stable_sort(refine.begin(), refine.end(),
                             [&](std::size_t a, std::size_t b) { return error[a] > error[b]; });
            std::size_t kept = 0;
            extra = 0;
            while (kept < refine.size() && total + extra + n[refine[kept]] <= budget) {
                extra += n[refine[kept]];
                ++kept;
            }
            refine.resize(kept);
            if (refine.empty()) break;
        }
        for (std::size_t k : refine) n[k] *= 2;
        total += extra;
        Plan next = planStretch(path, first, last, n.data(), lim, false, cancel);
        if (next.cancelled) return false;
        std::vector<bool> refined(count, false);
        for (std::size_t k : refine) refined[k] = true;
        for (std::size_t k = 0; k < count; ++k) {
            const double before = plan.segments[k].timeS, after = next.segments[k].timeS;
            const double change = std::isfinite(before) && std::isfinite(after)
                                      ? std::abs(after - before)
                                      : kUnlimited;
            if (refined[k]) {
                // The larger of its last two changes: where a switch point crosses a grid point
                // one doubling can change the time by much less than the next.
                error[k] = std::max(change, lastChange[k]);
                lastChange[k] = change;
            } else {
                // Left as it was, it moves only by its neighbours: its own estimate stands
                // unless that move is larger.
                error[k] = std::max(error[k], change);
            }
        }
        plan = std::move(next);
    }
    for (std::size_t k = 0; k < count; ++k) {
        out.segments.push_back(plan.segments[k]);
        out.timeS += plan.segments[k].timeS;
        // A segment the budget never let be doubled has no estimate: it counts with its whole
        // time, so an unconverged result never looks better than it is.
        out.errorS += std::isfinite(error[k]) ? error[k] : plan.segments[k].timeS;
    }
    if (!converged) out.converged = false;
    out.points += plan.points;
    return true;
}

/// The grid spacing the refinement starts from: 4096 points over the whole path.
double baseSpacing(const ToolPath& path) { return path.length() / 4095.0; }

/// Optimal: the stretches between the path's stops (its ends and its corners), each refined on
/// its own (a stop decouples them).
Refined refinedOptimal(const ToolPath& path, const MachineLimits& lim, std::size_t budget,
                       const std::atomic<bool>* cancel) {
    Refined out;
    out.segments.reserve(path.segments.size());
    const double spacing = baseSpacing(path);
    std::size_t first = 0;
    for (std::size_t k = 1; k <= path.segments.size(); ++k) {
        if (k % kCancelPollInterval == 0 && cancelRequested(cancel)) {
            out.cancelled = true;
            return out;
        }
        if (k < path.segments.size() && !isCorner(path.segments[k - 1], path.segments[k])) {
            continue;
        }
        if (cancelRequested(cancel) ||
            !refineStretch(path, first, k, spacing, lim, budget, cancel, out)) {
            out.cancelled = true;
            return out;
        }
        first = k;
    }
    return out;
}

}  // namespace

MachineLimits limitsFromProject(const MachiningSpec& m) {
    MachineLimits lim;
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        lim.accel[i] = k < m.axisAccel.size() ? m.axisAccel[k] : kUnlimited;
        lim.vmax[i] = k < m.axisVmax.size() ? m.axisVmax[k] : kUnlimited;
    }
    lim.feedMax = m.feedMax;
    lim.seedStep = m.step;
    return lim;
}

const char* timingMethodName(TimingMethod method) {
    switch (method) {
        case TimingMethod::Seed:
            return "seed";
        case TimingMethod::ExactStop:
            return "exact-stop";
        case TimingMethod::Optimal:
            return "optimal";
    }
    return "?";
}

double exactStopLineTime(const PathSegment& line, const MachineLimits& lim) {
    const Vec3 n = (line.end - line.start).normalized();
    double aEff = kUnlimited, vEff = lim.feedMax;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(n[i]) < kTiny) continue;
        aEff = std::min(aEff, lim.accel[i] / std::abs(n[i]));
        vEff = std::min(vEff, lim.vmax[i] / std::abs(n[i]));
    }
    const double len = line.length();
    if (std::isinf(vEff) || len < vEff * vEff / aEff) return 2.0 * std::sqrt(len / aEff);
    return len / vEff + vEff / aEff;
}

OptimalProfile optimalProfile(const ToolPath& path, const MachineLimits& limits,
                              std::size_t gridPoints) {
    const std::vector<std::size_t> n = intervalsFor(
        path, 0, path.segments.size(),
        path.length() / static_cast<double>(std::max<std::size_t>(gridPoints, 2) - 1), 2);
    return planStretch(path, 0, path.segments.size(), n.data(), limits, true, nullptr).profile;
}

Diagnostics checkMachineLimits(const MachineLimits& lim) {
    Diagnostics errors;
    // Unlimited (+infinity) or within the range in which the arithmetic is sound.
    auto check = [&](const FieldPlace& where, double value, double lo, double hi,
                     const char* unit) {
        if (value == kUnlimited || (value >= lo && value <= hi)) return;
        errors.push_back(Diagnostic::make(where, DiagnosticCode::OutOfRange,
                                          {lo, hi, std::string(unit), value}));
    };
    for (int i = 0; i < 3; ++i) {
        check({Field::MachineAccel, i}, lim.accel[i], kMinMachineLimit, kMaxAccelMmS2, " mm/s²");
        check({Field::MachineVmax, i}, lim.vmax[i], kMinMachineLimit, kMaxSpeedMmS, " mm/s");
    }
    check({Field::MachineFeed}, lim.feedMax, kMinMachineLimit, kMaxSpeedMmS, " mm/s");
    return errors;
}

Diagnostics checkMovingAxesLimited(const ToolPath& path, const MachineLimits& lim) {
    Diagnostics errors;
    for (int i = 0; i < 3; ++i) {
        if (!std::isinf(lim.accel[i])) continue;
        for (std::size_t k = 0; k < path.segments.size(); ++k) {
            const PathSegment& seg = path.segments[k];
            const bool moves =
                seg.kind == PathSegment::Kind::Arc ? i < 2 : std::abs(seg.tangent(0.0)[i]) > kTiny;
            if (!moves) continue;
            errors.push_back(Diagnostic::make(FieldPlace{Field::MachineAccel, i},
                                              DiagnosticCode::AccelerationLimitMissing,
                                              {static_cast<double>(i), static_cast<double>(k)}));
            break;
        }
    }
    return errors;
}

namespace {

/// What every timing entry point refuses before any work: limits out of range, an axis the path
/// moves along without an acceleration limit, an empty path, a seed step that is no step for
/// this path.
Diagnostics checkTimingInputs(const ToolPath& path, const MachineLimits& lim, TimingMethod method) {
    Diagnostics errors = checkMachineLimits(lim);
    if (errors.empty()) {
        const Diagnostics unlimited = checkMovingAxesLimited(path, lim);
        errors.insert(errors.end(), unlimited.begin(), unlimited.end());
    }
    if (path.segments.empty()) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::Path}, DiagnosticCode::PathEmpty));
    }
    if (method == TimingMethod::Seed && errors.empty()) {
        const Diagnostics step = checkSeedStep(path, lim.seedStep, Field::SeedStep);
        errors.insert(errors.end(), step.begin(), step.end());
    }
    return errors;
}

}  // namespace

Result<TimingResult> machiningTime(const ToolPath& path, const MachineLimits& lim,
                                   TimingMethod method, const std::atomic<bool>* cancel,
                                   std::size_t maxPlanPoints) {
    if (Diagnostics errors = checkTimingInputs(path, lim, method); !errors.empty()) return errors;

    TimingResult r;
    r.method = method;
    r.lengthMm = path.length();
    if (method == TimingMethod::Optimal) {
        Refined run = refinedOptimal(path, lim, maxPlanPoints, cancel);
        if (run.cancelled) return cancelledDiagnostics();
        r.timeS = run.timeS;
        r.gridPoints = run.points;
        r.convergence = run.errorS / run.timeS;
        r.converged = run.converged;
        r.segments = std::move(run.segments);
        return r;
    }
    // Exact stop plans every arc on its own (a stretch that starts and ends at rest).
    Refined arcs;
    const double spacing = baseSpacing(path);
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        const PathSegment& seg = path.segments[k];
        SegmentTiming t;
        t.lengthMm = seg.length();
        if (method == TimingMethod::Seed) {
            const std::optional<double> time = seedTime(seg, lim, cancel);
            if (!time) return cancelledDiagnostics();
            t.timeS = *time;
        } else if (seg.kind == PathSegment::Kind::Line) {
            t.timeS = exactStopLineTime(seg, lim);
        } else {
            arcs.segments.clear();
            if (!refineStretch(path, k, k + 1, spacing, lim, maxPlanPoints, cancel, arcs)) {
                return cancelledDiagnostics();
            }
            t.timeS = arcs.segments.front().timeS;
        }
        r.timeS += t.timeS;
        r.segments.push_back(t);
    }
    r.gridPoints = arcs.points;
    r.convergence = arcs.points > 0 ? arcs.errorS / r.timeS : 0.0;
    r.converged = arcs.converged;
    return r;
}

namespace {

/// Appends a planned profile (grid points in ascending s) with each interval's axis
/// accelerations at its middle, where the plan holds them within the limits (stageBounds).
/// False if cancelled.
bool appendPlanned(const ToolPath& path, const OptimalProfile& p, double offset, TimingProfile& out,
                   const std::atomic<bool>* cancel) {
    std::size_t seg = 0;
    double segStart = 0.0;  // path parameter where segment `seg` starts
    for (std::size_t k = 0; k < p.s.size(); ++k) {
        if (k % kCancelPollInterval == 0 && cancelRequested(cancel)) return false;
        Vec3 a = Vec3::Zero();
        if (k + 1 < p.s.size()) {
            const double delta = p.s[k + 1] - p.s[k];
            const double u = delta > 0 ? (p.x[k + 1] - p.x[k]) / (2.0 * delta) : 0.0;
            const double s = p.s[k] + delta / 2.0;
            while (seg + 1 < path.segments.size() && s > segStart + path.segments[seg].length()) {
                segStart += path.segments[seg].length();
                ++seg;
            }
            const PathSegment& sg = path.segments[seg];
            const double local = std::clamp(s - segStart, 0.0, sg.length());
            a = sg.tangent(local) * u + sg.curvature(local) * ((p.x[k] + p.x[k + 1]) / 2.0);
        }
        out.s.push_back(offset + p.s[k]);
        out.speed.push_back(std::sqrt(std::max(p.x[k], 0.0)));
        out.accel.push_back(a);
    }
    return true;
}

}  // namespace

Result<TimingProfile> timingProfile(const ToolPath& path, const MachineLimits& lim,
                                    TimingMethod method, std::size_t points,
                                    const std::atomic<bool>* cancel) {
    if (Diagnostics errors = checkTimingInputs(path, lim, method); !errors.empty()) return errors;
    TimingProfile out;
    if (method == TimingMethod::Optimal) {
        const std::vector<std::size_t> n = intervalsFor(
            path, 0, path.segments.size(),
            path.length() / static_cast<double>(std::max<std::size_t>(points, 2) - 1), 2);
        const Plan plan = planStretch(path, 0, path.segments.size(), n.data(), lim, true, cancel);
        if (plan.cancelled || !appendPlanned(path, plan.profile, 0.0, out, cancel)) {
            return cancelledDiagnostics();
        }
        return out;
    }
    const double total = path.length();
    // The seed's steps, every `every`-th of them when there are more than `points` (its step
    // may make up to kMaxSeedSteps of them: more than a plot can show or should hold).
    const double stepCount = total / lim.seedStep;
    const auto every = static_cast<std::size_t>(std::max(
        1.0, std::ceil(stepCount / static_cast<double>(std::max<std::size_t>(points, 1)))));
    double offset = 0.0;
    for (const PathSegment& seg : path.segments) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        const double len = seg.length();
        if (method == TimingMethod::ExactStop) {
            const auto share =
                static_cast<std::size_t>(std::max(16.0, static_cast<double>(points) * len / total));
            const ToolPath alone{{seg}};
            const Plan plan = planStretch(alone, 0, 1, &share, lim, true, cancel);
            if (plan.cancelled || !appendPlanned(alone, plan.profile, offset, out, cancel)) {
                return cancelledDiagnostics();
            }
        } else {
            // The seed's steps up to the middle, each at its constant speed, then mirrored.
            std::vector<std::pair<double, double>> steps;  // (step start, speed)
            std::vector<Vec3> accels;
            std::size_t count = 0;
            const bool done = walkSeed(
                seg, lim,
                [&](const SeedStep& step) {
                    if (count++ % every != 0) return;
                    accels.push_back((step.direction * step.speed - step.previousVelocity) *
                                     step.speed / step.length);
                    steps.emplace_back(step.s, step.speed);
                },
                cancel);
            if (!done) return cancelledDiagnostics();
            for (std::size_t k = 0; k < steps.size(); ++k) {
                out.s.push_back(offset + steps[k].first);
                out.speed.push_back(steps[k].second);
                out.accel.push_back(accels[k]);
            }
            for (std::size_t k = steps.size(); k-- > 0;) {
                const double end = k + 1 < steps.size() ? steps[k + 1].first : len / 2.0;
                out.s.push_back(offset + len - end);
                out.speed.push_back(steps[k].second);
                out.accel.push_back(-accels[k]);
            }
        }
        offset += len;
    }
    out.s.push_back(total);
    out.speed.push_back(0.0);
    out.accel.push_back(Vec3::Zero());
    return out;
}

}  // namespace cam
