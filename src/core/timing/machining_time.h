#pragma once
/// @file
/// @brief How long a tool path takes on a machine whose axes have their own limits (math.md §6).

#include <Eigen/Core>
#include <atomic>
#include <limits>
#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"
#include "timing/tool_path.h"

namespace cam {

inline constexpr double kUnlimited = std::numeric_limits<double>::infinity();

/// @brief Machine limits. Axes without a limit are +infinity.
struct MachineLimits {
    Eigen::Vector3d accel{500, 500, 200};                      ///< per axis, mm/s², > 0
    Eigen::Vector3d vmax{kUnlimited, kUnlimited, kUnlimited};  ///< per axis, mm/s, > 0
    double feedMax = kUnlimited;                               ///< along the path, mm/s
    double seedStep = 1.0;                                     ///< step of the seed method, mm
};

/// @brief The limits a project's `machining` section gives (2 axes: z unlimited).
[[nodiscard]] MachineLimits limitsFromProject(const MachiningSpec& machining);

enum class TimingMethod { Seed, ExactStop, Optimal };

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
    /// Optimal (and exact stop on arcs): grid points of the finest resolution used, and the
    /// relative change from the previous resolution. A resolution asks for N = 4096·2^k points
    /// and rounds each segment's share up to whole intervals, at least two, so it has N to
    /// N + 2·segments points.
    std::size_t gridPoints = 0;
    double convergence = 0.0;
};

/// @brief Total time by the chosen method; every segment starts and ends at rest for seed and
/// exact stop; optimal stops only at corners (tangent breaks above kTangentToleranceDeg) and at
/// both ends of the path. Optimal (and exact stop on arcs) plans on a grid of 4096 points and
/// doubles it until two resolutions agree to 1e-6 relative (or 2^24 points).
/// If `cancel` is given it is polled within every loop (segments, seed steps, grid points), so a
/// cancel is honoured within about a millisecond; a cancelled computation returns the error
/// {"", "cancelled"}.
[[nodiscard]] Result<TimingResult> machiningTime(const ToolPath& path, const MachineLimits& limits,
                                                 TimingMethod method,
                                                 const std::atomic<bool>* cancel = nullptr);

/// @brief The seed method on one segment (math.md §6): steps of `seedStep` from rest up to the
/// midpoint, each at the largest speed that keeps every axis within its limit, doubled.
[[nodiscard]] double seedSegmentTime(const PathSegment& segment, const MachineLimits& limits);

/// @brief Exact rest-to-rest time of a straight segment: the trapezoid (or triangle).
[[nodiscard]] double exactStopLineTime(const PathSegment& line, const MachineLimits& limits);

/// @brief The time-optimal profile on a fixed grid of about `gridPoints` points (TOPP-RA's
/// backward/forward passes), stopping at corners. Exposed for the benchmark and the refinement.
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
/// (exact stop plans every segment alone, rest to rest); seed gives its steps, braking mirrored.
/// Polls `cancel` like machiningTime and returns {"", "cancelled"} when it is set.
struct TimingProfile {
    std::vector<double> s, speed;
    std::vector<Eigen::Vector3d> accel;
};
[[nodiscard]] Result<TimingProfile> timingProfile(const ToolPath& path, const MachineLimits& limits,
                                                  TimingMethod method, std::size_t points,
                                                  const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
