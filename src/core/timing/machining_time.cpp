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

/// The acceleration limits at one point of the path as bounds on u = s-ddot that are linear in
/// x = s-dot²: lower_i(x) = c_i + d_i·x <= u <= e_i + d_i·x, plus a cap on x (velocity limits
/// and axes that only feel the curvature).
struct PointConstraints {
    std::array<double, 6> c{}, d{}, e{};
    int count = 0;
    double xCap = kUnlimited;

    void add(const Vec3& tangent, const Vec3& curvature, const MachineLimits& lim) {
        for (int i = 0; i < 3; ++i) {
            const double a = lim.accel[i];
            const double A = tangent[i], B = curvature[i];
            if (std::abs(A) > kTiny) {
                const double v = lim.vmax[i] / std::abs(A);
                xCap = std::min(xCap, v * v);
                if (std::isinf(a)) continue;
                c[count] = -a / std::abs(A);
                e[count] = a / std::abs(A);
                d[count] = -B / A;
                ++count;
            } else if (std::abs(B) > kTiny && std::isfinite(a)) {
                xCap = std::min(xCap, a / std::abs(B));
            }
        }
    }

    /// Largest x for which some u satisfies every bound (the maximum-velocity curve).
    [[nodiscard]] double maxX() const {
        double x = xCap;
        for (int i = 0; i < count; ++i) {
            for (int j = 0; j < count; ++j) {
                if (d[i] > d[j]) x = std::min(x, (e[j] - c[i]) / (d[i] - d[j]));
            }
        }
        return x;
    }
    [[nodiscard]] double uMax(double x) const {
        double u = kUnlimited;
        for (int i = 0; i < count; ++i) u = std::min(u, e[i] + d[i] * x);
        return u;
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

/// The grid, kept implicit: each segment is cut into equal intervals and its first point is the
/// boundary with the previous segment (where both segments' constraints apply).
struct SegmentGrid {
    std::size_t first = 0;      ///< index of the segment's first grid point
    std::size_t intervals = 0;  ///< equal intervals on this segment
    double delta = 0.0;         ///< their length, mm
    bool stopAtStart = false;   ///< the path starts here, or the tangent breaks (a corner)
    bool isArc = false;
    PointConstraints inner;     ///< lines: the same at every inner point
    PointConstraints boundary;  ///< at the first point: capped by the previous segment's speed
    // Arcs: angle of the first point and its step, about the centre.
    double theta0 = 0.0, dtheta = 0.0, sign = 1.0, radius = 1.0;
};

PointConstraints constraintsOf(const Vec3& tangent, const Vec3& curvature,
                               const MachineLimits& lim) {
    PointConstraints pc;
    pc.add(tangent, curvature, lim);
    if (std::isfinite(lim.feedMax)) pc.xCap = std::min(pc.xCap, lim.feedMax * lim.feedMax);
    return pc;
}

/// The grid of about `points` points; false if cancelled.
bool makeGrid(const ToolPath& path, const MachineLimits& lim, std::size_t points,
              std::vector<SegmentGrid>& grid, std::size_t* total, const std::atomic<bool>* cancel) {
    const double spacing =
        path.length() / static_cast<double>(std::max<std::size_t>(points, 2) - 1);
    // Grown as it is filled (not assigned up front): memory is touched between the polls.
    grid.clear();
    grid.reserve(path.segments.size());
    std::size_t index = 0;
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
        if (k % kCancelPollInterval == 0 && cancelRequested(cancel)) return false;
        const PathSegment& seg = path.segments[k];
        SegmentGrid& g = grid.emplace_back();
        const double len = seg.length();
        g.first = index;
        g.intervals = static_cast<std::size_t>(std::max(2.0, std::ceil(len / spacing - 1e-9)));
        g.delta = len / static_cast<double>(g.intervals);
        g.stopAtStart = k == 0 || isCorner(path.segments[k - 1], seg);
        g.isArc = seg.kind == PathSegment::Kind::Arc;
        g.inner = constraintsOf(seg.tangent(0.0), seg.curvature(0.0), lim);
        g.boundary = g.inner;
        if (k > 0) {
            // Without a jerk limit the path acceleration may jump at a joint; only the speed is
            // shared. So the previous segment bounds the joint's speed (its maximum-velocity
            // curve there), not the acceleration that leaves the joint.
            const PathSegment& prev = path.segments[k - 1];
            const PointConstraints left =
                constraintsOf(prev.tangent(prev.length()), prev.curvature(prev.length()), lim);
            g.boundary.xCap = std::min(g.boundary.xCap, left.maxX());
        }
        if (g.isArc) {
            g.sign = seg.sweep >= 0 ? 1.0 : -1.0;
            g.radius = seg.radius;
            g.theta0 = seg.startAngle;
            g.dtheta = g.sign * g.delta / seg.radius;
        }
        index += g.intervals;
    }
    *total = index + 1;  // and the end point
    return true;
}

/// Walks the points of one arc segment with a rotation recurrence (cos/sin of θ0 + j·δθ),
/// recomputed exactly every 256 steps so rounding never accumulates.
class ArcWalker {
public:
    ArcWalker(const SegmentGrid& g, std::size_t j, int direction)
        : m_g(g), m_j(j), m_direction(direction) {
        m_cd = std::cos(g.dtheta);
        m_sd = direction * std::sin(g.dtheta);
        sync();
    }
    /// Constraints at the current point, then moves one point in the walking direction.
    PointConstraints next(const MachineLimits& lim) {
        const Vec3 t(-m_g.sign * m_s, m_g.sign * m_c, 0.0);
        const Vec3 k(-m_c / m_g.radius, -m_s / m_g.radius, 0.0);
        PointConstraints pc = constraintsOf(t, k, lim);
        m_j += static_cast<std::size_t>(m_direction);
        if (++m_steps % 256 == 0) {
            sync();
        } else {
            const double c = m_c * m_cd - m_s * m_sd;
            m_s = m_s * m_cd + m_c * m_sd;
            m_c = c;
        }
        return pc;
    }

private:
    void sync() {
        const double theta = m_g.theta0 + static_cast<double>(m_j) * m_g.dtheta;
        m_c = std::cos(theta);
        m_s = std::sin(theta);
    }
    const SegmentGrid& m_g;
    std::size_t m_j;
    int m_direction;
    double m_c = 1.0, m_s = 0.0, m_cd = 1.0, m_sd = 0.0;
    std::size_t m_steps = 0;
};

struct OptimalRun {
    OptimalProfile profile;
    std::vector<SegmentTiming> segments;
    std::size_t points = 0;
    double convergence = 0.0;  ///< refinedOptimal: relative change from the previous grid
    bool cancelled = false;
};

OptimalRun cancelledRun() {
    OptimalRun run;
    run.cancelled = true;
    return run;
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

/// body(j) for j = first, first − 1, …, last (last >= 1), in blocks like countUp.
template <class Body>
bool countDown(std::size_t first, std::size_t last, const std::atomic<bool>* cancel, Body&& body) {
    for (std::size_t j = first; j >= last;) {
        if (cancelRequested(cancel)) return false;
        const std::size_t blockLast =
            j - last >= kCancelPollInterval ? j - kCancelPollInterval + 1 : last;
        for (; j >= blockLast; --j) body(j);
    }
    return true;
}

/// One plan on a grid of about `points` points. Both passes read the cancel flag at every
/// segment and every kCancelPollInterval grid points within one.
OptimalRun runOptimal(const ToolPath& path, const MachineLimits& lim, std::size_t points,
                      bool keepProfile, const std::atomic<bool>* cancel) {
    std::size_t n = 0;
    std::vector<SegmentGrid> grid;
    if (!makeGrid(path, lim, points, grid, &n, cancel)) return cancelledRun();
    OptimalRun run;
    // Uninitialised where possible (every point is written before it is read): zero-filling
    // hundreds of MB up front costs time that no poll could interrupt.
    const std::unique_ptr<double[]> hiStore(new double[n]);
    std::unique_ptr<double[]> xStore;
    if (keepProfile) {
        // Grown in blocks between polls: one resize of a fine plot's grid takes a while.
        run.profile.x.reserve(n);
        while (run.profile.x.size() < n) {
            if (cancelRequested(cancel)) return cancelledRun();
            run.profile.x.resize(std::min(n, run.profile.x.size() + 64 * kCancelPollInterval));
        }
    } else {
        xStore.reset(new double[n]);
    }
    double* const hi = hiStore.get();
    double* const x = keepProfile ? run.profile.x.data() : xStore.get();
    // Backward pass: the largest squared speed at each point from which the end (and every
    // corner) can still be reached at rest (the controllable sets of TOPP-RA).
    hi[n - 1] = 0.0;
    for (std::size_t k = grid.size(); k-- > 0;) {
        const SegmentGrid& g = grid[k];
        auto step = [&](std::size_t j, const PointConstraints& pc) {
            const std::size_t i = g.first + j;
            hi[i] = std::max(0.0, std::min(pc.maxX(), pc.brakeTo(hi[i + 1], g.delta)));
        };
        bool done = true;
        if (g.isArc) {
            ArcWalker walk(g, g.intervals - 1, -1);
            done = countDown(g.intervals - 1, 1, cancel,
                             [&](std::size_t j) { step(j, walk.next(lim)); });
        } else {
            const double mvc = g.inner.maxX();
            done = countDown(g.intervals - 1, 1, cancel, [&](std::size_t j) {
                const std::size_t i = g.first + j;
                hi[i] = std::max(0.0, std::min(mvc, g.inner.brakeTo(hi[i + 1], g.delta)));
            });
        }
        if (!done) return cancelledRun();
        if (g.stopAtStart) {
            hi[g.first] = 0.0;
        } else {
            step(0, g.boundary);
        }
    }
    // Forward pass: accelerate as hard as allowed while staying controllable.
    run.segments.resize(path.segments.size());
    x[0] = 0.0;
    double time = 0.0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const SegmentGrid& g = grid[k];
        SegmentTiming& st = run.segments[k];
        st.lengthMm = path.segments[k].length();
        st.entrySpeed = std::sqrt(x[g.first]);
        double segmentTime = 0.0;
        double rootPrev = std::sqrt(x[g.first]);  // sqrt(x) of the interval's start, carried
        auto step = [&](std::size_t j, const PointConstraints& pc) {
            const std::size_t i = g.first + j;
            const double u = std::min(pc.uMax(x[i]), (hi[i + 1] - x[i]) / (2.0 * g.delta));
            x[i + 1] = std::clamp(x[i] + 2.0 * g.delta * u, 0.0, hi[i + 1]);
            const double root = std::sqrt(x[i + 1]);
            // The exact time of an interval with x linear in s: 2Δ/(sqrt(x0) + sqrt(x1)).
            segmentTime += rootPrev + root > 0 ? 2.0 * g.delta / (rootPrev + root) : kUnlimited;
            rootPrev = root;
        };
        step(0, g.boundary);
        bool done = true;
        if (g.isArc) {
            ArcWalker walk(g, 1, +1);
            done = countUp(1, g.intervals, cancel, [&](std::size_t j) { step(j, walk.next(lim)); });
        } else {
            done = countUp(1, g.intervals, cancel, [&](std::size_t j) { step(j, g.inner); });
        }
        if (!done) return cancelledRun();
        st.timeS = segmentTime;
        st.exitSpeed = std::sqrt(x[g.first + g.intervals]);
        time += segmentTime;
    }
    run.profile.timeS = time;
    run.points = n;
    if (keepProfile) {
        std::vector<double>& sOut = run.profile.s;
        sOut.reserve(n);
        for (const SegmentGrid& g : grid) {
            const double base = g.first == 0 ? 0.0 : sOut.back() + g.delta;
            if (!countUp(0, g.intervals, cancel, [&](std::size_t j) {
                    sOut.push_back(base + g.delta * static_cast<double>(j));
                })) {
                return cancelledRun();
            }
        }
        sOut.push_back(path.length());
    }
    return run;
}

/// Doubles the grid from 4096 points until two resolutions agree to 1e-6 relative (or 2^24
/// points). Every pass polls the cancel flag.
OptimalRun refinedOptimal(const ToolPath& path, const MachineLimits& lim,
                          const std::atomic<bool>* cancel) {
    std::size_t n = 4096;
    OptimalRun previous = runOptimal(path, lim, n, false, cancel);
    constexpr std::size_t kMaxPoints = std::size_t{1} << 24;
    while (!previous.cancelled) {
        n *= 2;
        OptimalRun current = runOptimal(path, lim, n, false, cancel);
        if (current.cancelled) return current;
        const double change =
            std::abs(current.profile.timeS - previous.profile.timeS) / current.profile.timeS;
        if (change <= 1e-6 || n >= kMaxPoints) {
            current.convergence = change;
            return current;
        }
        previous = std::move(current);
    }
    return previous;
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
    return runOptimal(path, limits, gridPoints, true, nullptr).profile;
}

Result<TimingResult> machiningTime(const ToolPath& path, const MachineLimits& lim,
                                   TimingMethod method, const std::atomic<bool>* cancel) {
    Diagnostics errors;
    if (path.segments.empty()) errors.push_back({"path", "is empty"});
    for (int i = 0; i < 3; ++i) {
        if (!(lim.accel[i] > 0)) {
            errors.push_back({"accel[" + std::to_string(i) + "]", "must be > 0"});
        }
        if (!(lim.vmax[i] > 0))
            errors.push_back({"vmax[" + std::to_string(i) + "]", "must be > 0"});
    }
    if (!(lim.feedMax > 0)) errors.push_back({"feed", "must be > 0"});
    if (method == TimingMethod::Seed && !(lim.seedStep > 0 && std::isfinite(lim.seedStep))) {
        errors.push_back({"step", "must be a finite length > 0"});
    }
    if (!errors.empty()) return errors;

    TimingResult r;
    r.method = method;
    r.lengthMm = path.length();
    if (method == TimingMethod::Optimal) {
        OptimalRun run = refinedOptimal(path, lim, cancel);
        if (run.cancelled) return cancelledDiagnostics();
        r.timeS = run.profile.timeS;
        r.gridPoints = run.points;
        r.convergence = run.convergence;
        r.segments = std::move(run.segments);
        return r;
    }
    for (const PathSegment& seg : path.segments) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        SegmentTiming t;
        t.lengthMm = seg.length();
        if (method == TimingMethod::Seed) {
            const std::optional<double> time = seedTime(seg, lim, cancel);
            if (!time) return cancelledDiagnostics();
            t.timeS = *time;
        } else if (seg.kind == PathSegment::Kind::Line) {
            t.timeS = exactStopLineTime(seg, lim);
        } else {
            const OptimalRun run = refinedOptimal(ToolPath{{seg}}, lim, cancel);
            if (run.cancelled) return cancelledDiagnostics();
            t.timeS = run.profile.timeS;
            r.gridPoints = std::max(r.gridPoints, run.points);
            r.convergence = std::max(r.convergence, run.convergence);
        }
        r.timeS += t.timeS;
        r.segments.push_back(t);
    }
    return r;
}

namespace {

/// Appends a planned profile (grid points in ascending s) with each interval's axis
/// accelerations, found on the segment the interval starts on. False if cancelled.
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
            // A point on a joint belongs to the segment its interval runs along: the next one.
            const double s = p.s[k] + 1e-12;
            while (seg + 1 < path.segments.size() && s > segStart + path.segments[seg].length()) {
                segStart += path.segments[seg].length();
                ++seg;
            }
            const PathSegment& sg = path.segments[seg];
            const double local = std::clamp(s - segStart, 0.0, sg.length());
            a = sg.tangent(local) * u + sg.curvature(local) * p.x[k];
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
    TimingProfile out;
    if (method == TimingMethod::Optimal) {
        const OptimalRun run = runOptimal(path, lim, points, true, cancel);
        if (run.cancelled || !appendPlanned(path, run.profile, 0.0, out, cancel)) {
            return cancelledDiagnostics();
        }
        return out;
    }
    const double total = path.length();
    double offset = 0.0;
    for (const PathSegment& seg : path.segments) {
        if (cancelRequested(cancel)) return cancelledDiagnostics();
        const double len = seg.length();
        if (method == TimingMethod::ExactStop) {
            const auto share =
                static_cast<std::size_t>(std::max(16.0, static_cast<double>(points) * len / total));
            const ToolPath alone{{seg}};
            const OptimalRun run = runOptimal(alone, lim, share, true, cancel);
            if (run.cancelled || !appendPlanned(alone, run.profile, offset, out, cancel)) {
                return cancelledDiagnostics();
            }
        } else {
            // The seed's steps up to the middle, each at its constant speed, then mirrored.
            std::vector<std::pair<double, double>> steps;  // (step start, speed)
            std::vector<Vec3> accels;
            const bool done = walkSeed(
                seg, lim,
                [&](const SeedStep& step) {
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
