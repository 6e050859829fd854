#pragma once
/// @file
/// @brief How long a tool path takes on a machine whose axes have their own limits (math.md §6).

#include <Eigen/Core>
#include <atomic>
#include <limits>
#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"
#include "toolpath/tool_path.h"

namespace cam {

inline constexpr double kUnlimited = std::numeric_limits<double>::infinity();

/// @brief Machine limits. Axes without a limit are +infinity; a finite limit lies within
/// [kMinMachineLimit, kMaxAccelMmS2] (accelerations) or [kMinMachineLimit, kMaxSpeedMmS] (speeds).
/// An axis without an acceleration limit is one the path must not move along (a contour in the
/// plane leaves z alone): checkMovingAxesLimited, and every timing entry point, refuse it.
struct MachineLimits {
    Eigen::Vector3d accel{500, 500, 200};                      ///< per axis, mm/s²
    Eigen::Vector3d vmax{kUnlimited, kUnlimited, kUnlimited};  ///< per axis, mm/s
    double feedMax = kUnlimited;                               ///< along the path, mm/s
    double seedStep = 1.0;                                     ///< step of the seed method, mm
};

/// @brief The limits' errors, located `accel[i]`, `vmax[i]`, `feed`: each must be unlimited
/// (+infinity) or within its range (a denormal or a zero would make times infinite or NaN).
[[nodiscard]] Diagnostics checkMachineLimits(const MachineLimits& limits);

/// @brief One error for every axis the path moves along without an acceleration limit, located
/// `accel[i]` (DiagnosticCode::AccelerationLimitMissing: the axis and the first path segment
/// that moves it): with none the seed's speed is infinite and exact stop and optimal take 0 s
/// or never converge, whatever the other axes allow. A line moves an axis when its unit
/// direction has a component above 1e-12 there (what the planner counts as moving); an arc
/// moves x and y.
[[nodiscard]] Diagnostics checkMovingAxesLimited(const ToolPath& path, const MachineLimits& limits);

/// @brief The limits a project's `machining` section gives (2 axes: z unlimited).
[[nodiscard]] MachineLimits limitsFromProject(const MachiningSpec& machining);

enum class TimingMethod { Seed, ExactStop, Optimal };

/// @brief Most grid points one plan of the refinement may use (a stretch between stops; its two
/// arrays take 16 bytes a point: 256 MB). A stretch whose segments would need more is reported
/// as not converged (TimingResult::converged).
inline constexpr std::size_t kMaxPlanPoints = std::size_t{1} << 24;

[[nodiscard]] const char* timingMethodName(TimingMethod method);

struct SegmentTiming {
    double timeS = 0.0;
    double lengthMm = 0.0;
    double entrySpeed = 0.0;  ///< mm/s
    double exitSpeed = 0.0;   ///< mm/s
};

struct TimingResult {
    TimingMethod method = TimingMethod::Optimal;
    double timeS = 0.0;
    double lengthMm = 0.0;
    std::vector<SegmentTiming> segments;
    /// Optimal (and exact stop on arcs): the grid points of the final plans (summed over the
    /// stretches planned apart: between stops for optimal, every arc for exact stop).
    std::size_t gridPoints = 0;
    /// The estimated relative error: the sum over segments of the larger of the last two moves
    /// of each one's time as its intervals were doubled (its whole time if the grid limit never
    /// let it be doubled), over the total time.
    double convergence = 0.0;
    /// Whether every segment's time moved by at most 1e-6 of itself at its last two doublings.
    /// False when the grid limit (kMaxPlanPoints in one plan) stopped the refinement first: the
    /// time is then an estimate whose error `convergence` gauges.
    bool converged = true;
};

/// @brief Total time by the chosen method; every segment starts and ends at rest for seed and
/// exact stop; optimal stops only at corners (tangent breaks above kTangentToleranceDeg) and at
/// both ends of the path. Optimal (and exact stop on arcs) plans each stretch between stops on a
/// grid that starts from a 4096-point share (at least 4 intervals a segment) and doubles the
/// intervals of every segment whose time is not yet converged (see TimingResult::converged).
/// `maxPlanPoints` bounds one plan's grid (kMaxPlanPoints; smaller for less memory).
/// Errors: the limits' (checkMachineLimits), an axis the path moves along without an
/// acceleration limit (checkMovingAxesLimited), an empty path, and for the seed a step too small
/// for the path (checkSeedStep, located `step`).
/// If `cancel` is given it is polled within every loop (segments, seed steps, grid points), so a
/// cancel is honoured within about a millisecond; a cancelled computation returns the error
/// {"", "cancelled"}.
[[nodiscard]] Result<TimingResult> machiningTime(const ToolPath& path, const MachineLimits& limits,
                                                 TimingMethod method,
                                                 const std::atomic<bool>* cancel = nullptr,
                                                 std::size_t maxPlanPoints = kMaxPlanPoints);

/// @brief The seed method on one segment (math.md §6): steps of `seedStep` from rest up to the
/// midpoint, each at the largest speed that keeps every axis within its limit, doubled.
[[nodiscard]] double seedSegmentTime(const PathSegment& segment, const MachineLimits& limits);

/// @brief Exact rest-to-rest time of a straight segment: the trapezoid (or triangle).
[[nodiscard]] double exactStopLineTime(const PathSegment& line, const MachineLimits& limits);

/// @brief The time-optimal profile on a fixed grid of about `gridPoints` points (at least two
/// intervals a segment; TOPP-RA's backward/forward passes with the limits held at the middle of
/// every interval), stopping at corners. Exposed for the benchmark.
struct OptimalProfile {
    std::vector<double> s;  ///< path parameter of each grid point, mm
    std::vector<double> x;  ///< squared speed at each grid point, (mm/s)²
    double timeS = 0.0;
};
[[nodiscard]] OptimalProfile optimalProfile(const ToolPath& path, const MachineLimits& limits,
                                            std::size_t gridPoints);

/// @brief Feed and per-axis acceleration along the path, for plots: at each sample, the path
/// parameter s (mm), the speed (mm/s) and each axis' acceleration (mm/s²) over the interval that
/// starts there. Optimal and exact stop come from the planner on a grid of about `points` points
/// (exact stop plans every segment alone, rest to rest; the accelerations are those at the middle
/// of each interval, where the plan holds them within the limits); seed gives its steps (every
/// m-th of them where there are more than `points` steps over the path), braking mirrored. Errors
/// as machiningTime's. Polls `cancel` like machiningTime and returns
/// {"", "cancelled"} when it is set.
struct TimingProfile {
    std::vector<double> s, speed;
    std::vector<Eigen::Vector3d> accel;
};
[[nodiscard]] Result<TimingProfile> timingProfile(const ToolPath& path, const MachineLimits& limits,
                                                  TimingMethod method, std::size_t points,
                                                  const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
