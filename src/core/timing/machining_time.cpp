#include "timing/machining_time.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "common/angles.h"
#include "common/tolerances.h"

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

std::vector<SegmentGrid> makeGrid(const ToolPath& path, const MachineLimits& lim,
                                  std::size_t points, std::size_t* total) {
    const double spacing =
        path.length() / static_cast<double>(std::max<std::size_t>(points, 2) - 1);
    std::vector<SegmentGrid> grid(path.segments.size());
    std::size_t index = 0;
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
        const PathSegment& seg = path.segments[k];
        SegmentGrid& g = grid[k];
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
    return grid;
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
};

OptimalRun runOptimal(const ToolPath& path, const MachineLimits& lim, std::size_t points,
                      bool keepProfile) {
    std::size_t n = 0;
    const std::vector<SegmentGrid> grid = makeGrid(path, lim, points, &n);
    std::vector<double> hi(n), x(n);
    // Backward pass: the largest squared speed at each point from which the end (and every
    // corner) can still be reached at rest (the controllable sets of TOPP-RA).
    hi[n - 1] = 0.0;
    for (std::size_t k = grid.size(); k-- > 0;) {
        const SegmentGrid& g = grid[k];
        auto step = [&](std::size_t j, const PointConstraints& pc) {
            const std::size_t i = g.first + j;
            hi[i] = std::max(0.0, std::min(pc.maxX(), pc.brakeTo(hi[i + 1], g.delta)));
        };
        if (g.isArc) {
            ArcWalker walk(g, g.intervals - 1, -1);
            for (std::size_t j = g.intervals - 1; j >= 1; --j) step(j, walk.next(lim));
        } else {
            const double mvc = g.inner.maxX();
            for (std::size_t j = g.intervals - 1; j >= 1; --j) {
                const std::size_t i = g.first + j;
                hi[i] = std::max(0.0, std::min(mvc, g.inner.brakeTo(hi[i + 1], g.delta)));
            }
        }
        if (g.stopAtStart) {
            hi[g.first] = 0.0;
        } else {
            step(0, g.boundary);
        }
    }
    // Forward pass: accelerate as hard as allowed while staying controllable.
    OptimalRun run;
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
        if (g.isArc) {
            ArcWalker walk(g, 1, +1);
            for (std::size_t j = 1; j < g.intervals; ++j) step(j, walk.next(lim));
        } else {
            for (std::size_t j = 1; j < g.intervals; ++j) step(j, g.inner);
        }
        st.timeS = segmentTime;
        st.exitSpeed = std::sqrt(x[g.first + g.intervals]);
        time += segmentTime;
    }
    run.profile.timeS = time;
    run.points = n;
    if (keepProfile) {
        run.profile.s.resize(n);
        for (const SegmentGrid& g : grid) {
            const double base = g.first == 0 ? 0.0 : run.profile.s[g.first - 1] + g.delta;
            for (std::size_t j = 0; j < g.intervals; ++j) {
                run.profile.s[g.first + j] = base + g.delta * static_cast<double>(j);
            }
        }
        run.profile.s[n - 1] = path.length();
        run.profile.x = std::move(x);
    }
    return run;
}

/// Doubles the grid until two resolutions agree to 1e-6 relative.
OptimalRun refinedOptimal(const ToolPath& path, const MachineLimits& lim, std::size_t* points,
                          double* convergence, const std::atomic<bool>* cancel) {
    std::size_t n = 4096;
    OptimalRun previous = runOptimal(path, lim, n, false);
    constexpr std::size_t kMaxPoints = std::size_t{1} << 24;
    for (;;) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return previous;
        n *= 2;
        OptimalRun current = runOptimal(path, lim, n, false);
        const double change =
            std::abs(current.profile.timeS - previous.profile.timeS) / current.profile.timeS;
        if (change <= 1e-6 || n >= kMaxPoints) {
            *points = current.points;
            *convergence = change;
            return current;
        }
        previous = std::move(current);
    }
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

namespace {

/// The seed's speed for one step of length `step` in direction n after axis speeds vPrev: the
/// largest x with |n_i·x − v_i|·x/step <= a_i on every axis, capped by the feed (math.md §6).
double seedStepSpeed(const Vec3& n, const Vec3& vPrev, double step, const MachineLimits& lim) {
    double x = lim.feedMax;
    for (int i = 0; i < 3; ++i) {
        const double a = lim.accel[i];
        if (std::isinf(a)) continue;
        if (std::abs(n[i]) < kTiny) {
            // No motion of this axis in this step: only stopping its previous speed counts.
            if (std::abs(vPrev[i]) > 0) x = std::min(x, a * step / std::abs(vPrev[i]));
            continue;
        }
        // The rising root of |n_i|·x² − sgn(n_i)·v_i·x − a_i·step = 0.
        const double an = std::abs(n[i]);
        const double v = std::copysign(1.0, n[i]) * vPrev[i];
        x = std::min(x, (v + std::sqrt(v * v + 4.0 * an * a * step)) / (2.0 * an));
    }
    return x;
}

/// One step of the seed method: where it starts on the segment (mm), its length, its unit
/// direction, its speed and the axis velocities it starts from.
struct SeedStep {
    double s = 0.0;
    double length = 0.0;
    Vec3 direction = Vec3::Zero();
    double speed = 0.0;
    Vec3 previousVelocity = Vec3::Zero();
};

/// The seed method's walk over one segment from rest up to its midpoint (math.md §6), one call
/// of `visit` per step. The only place the seed's steps are taken: its time and its profile
/// both come from here.
template <class Visit>
void walkSeed(const PathSegment& segment, const MachineLimits& lim, Visit&& visit) {
    const double half = segment.length() / 2.0;
    SeedStep step;
    for (double s = 0.0; s < half - 1e-12;) {
        step.s = s;
        step.length = std::min(lim.seedStep, half - s);
        step.direction = (segment.point(s + step.length) - segment.point(s)).normalized();
        step.speed = seedStepSpeed(step.direction, step.previousVelocity, step.length, lim);
        visit(step);
        step.previousVelocity = step.direction * step.speed;
        s += step.length;
    }
}

}  // namespace

double seedSegmentTime(const PathSegment& segment, const MachineLimits& lim) {
    double time = 0.0;
    walkSeed(segment, lim, [&](const SeedStep& step) { time += step.length / step.speed; });
    return 2.0 * time;
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
    return runOptimal(path, limits, gridPoints, true).profile;
}

Result<TimingResult> machiningTime(const ToolPath& path, const MachineLimits& lim,
                                   TimingMethod method, const std::atomic<bool>* cancel) {
    auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
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
        OptimalRun run = refinedOptimal(path, lim, &r.gridPoints, &r.convergence, cancel);
        if (cancelled()) return Diagnostics{{"", "cancelled"}};
        r.timeS = run.profile.timeS;
        r.segments = std::move(run.segments);
        return r;
    }
    for (const PathSegment& seg : path.segments) {
        if (cancelled()) return Diagnostics{{"", "cancelled"}};
        SegmentTiming t;
        t.lengthMm = seg.length();
        if (method == TimingMethod::Seed) {
            t.timeS = seedSegmentTime(seg, lim);
        } else if (seg.kind == PathSegment::Kind::Line) {
            t.timeS = exactStopLineTime(seg, lim);
        } else {
            std::size_t points = 0;
            double change = 0.0;
            t.timeS = refinedOptimal(ToolPath{{seg}}, lim, &points, &change, cancel).profile.timeS;
            r.gridPoints = std::max(r.gridPoints, points);
            r.convergence = std::max(r.convergence, change);
        }
        r.timeS += t.timeS;
        r.segments.push_back(t);
    }
    return r;
}

namespace {

/// Segment index and local arc length of a global arc length.
std::pair<std::size_t, double> locate(const ToolPath& path, double s) {
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
        const double len = path.segments[k].length();
        if (s <= len || k + 1 == path.segments.size()) return {k, std::min(s, len)};
        s -= len;
    }
    return {0, 0.0};
}

void appendPlanned(const ToolPath& path, const OptimalProfile& p, double offset,
                   TimingProfile& out) {
    for (std::size_t k = 0; k < p.s.size(); ++k) {
        Vec3 a = Vec3::Zero();
        if (k + 1 < p.s.size()) {
            const double delta = p.s[k + 1] - p.s[k];
            const double u = delta > 0 ? (p.x[k + 1] - p.x[k]) / (2.0 * delta) : 0.0;
            const auto [seg, local] = locate(path, p.s[k] + 1e-12);
            const PathSegment& sg = path.segments[seg];
            a = sg.tangent(local) * u + sg.curvature(local) * p.x[k];
        }
        out.s.push_back(offset + p.s[k]);
        out.speed.push_back(std::sqrt(std::max(p.x[k], 0.0)));
        out.accel.push_back(a);
    }
}

}  // namespace

TimingProfile timingProfile(const ToolPath& path, const MachineLimits& lim, TimingMethod method,
                            std::size_t points) {
    TimingProfile out;
    if (method == TimingMethod::Optimal) {
        appendPlanned(path, optimalProfile(path, lim, points), 0.0, out);
        return out;
    }
    const double total = path.length();
    double offset = 0.0;
    for (const PathSegment& seg : path.segments) {
        const double len = seg.length();
        if (method == TimingMethod::ExactStop) {
            const auto share =
                static_cast<std::size_t>(std::max(16.0, static_cast<double>(points) * len / total));
            appendPlanned(ToolPath{{seg}}, optimalProfile(ToolPath{{seg}}, lim, share), offset,
                          out);
        } else {
            // The seed's steps up to the middle, each at its constant speed, then mirrored.
            std::vector<std::pair<double, double>> steps;  // (step start, speed)
            std::vector<Vec3> accels;
            walkSeed(seg, lim, [&](const SeedStep& step) {
                accels.push_back((step.direction * step.speed - step.previousVelocity) *
                                 step.speed / step.length);
                steps.emplace_back(step.s, step.speed);
            });
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
