#pragma once
/// @file
/// @brief The seed document's machining-time method (math.md §6): 1 mm steps from rest to the
/// middle of a segment, each at the largest speed every axis allows, doubled for braking. Used
/// for the seed time and for its plotted profile, so both come from the same steps.

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <optional>
#include <string>

#include "common/cancel.h"
#include "timing/machining_time.h"

namespace cam {

/// @brief Most steps the seed method takes on one path (path length / step): some tenths of a
/// second of work. A step that small relative to the path is refused, not walked for minutes.
inline constexpr double kMaxSeedSteps = 1e7;

/// @brief A step the seed method can walk on `path`: finite, at least kMinLengthMm, and at most
/// kMaxSeedSteps steps over the path's length. Errors are located at `field` (the caller names
/// where the step came from: `machining.step`, `--step`) and name the limit and the smallest
/// step that would do.
[[nodiscard]] Diagnostics checkSeedStep(const ToolPath& path, double step, Field field);

/// @brief The seed's speed for one step of length `step` in direction n after axis speeds
/// vPrev: the largest x with |n_i·x − v_i|·x/step <= a_i on every axis, capped by the feed.
[[nodiscard]] double seedStepSpeed(const Eigen::Vector3d& n, const Eigen::Vector3d& vPrev,
                                   double step, const MachineLimits& lim);

/// One step of the seed method: where it starts on the segment (mm), its length, its unit
/// direction, its speed and the axis velocities it starts from.
struct SeedStep {
    double s = 0.0;
    double length = 0.0;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    double speed = 0.0;
    Eigen::Vector3d previousVelocity = Eigen::Vector3d::Zero();
};

/// The seed method's walk over one segment from rest up to its midpoint (math.md §6), one call
/// of `visit` per step. The only place the seed's steps are taken: its time and its profile
/// both come from here. False if cancelled (polled every kCancelPollInterval steps).
template <class Visit>
bool walkSeed(const PathSegment& segment, const MachineLimits& lim, Visit&& visit,
              const std::atomic<bool>* cancel = nullptr) {
    const double half = segment.length() / 2.0;
    SeedStep step;
    std::size_t count = 0;
    for (double s = 0.0; s < half - 1e-12;) {
        if (++count % kCancelPollInterval == 0 && cancelRequested(cancel)) return false;
        step.s = s;
        step.length = std::min(lim.seedStep, half - s);
        // The chord's direction. On an arc that is the tangent half way along it, which does not
        // subtract the large coordinates of a point on a circle of huge radius from each other.
        step.direction = segment.kind == PathSegment::Kind::Line
                             ? segment.tangent(0.0)
                             : segment.tangent(s + step.length / 2.0);
        step.speed = seedStepSpeed(step.direction, step.previousVelocity, step.length, lim);
        visit(step);
        step.previousVelocity = step.direction * step.speed;
        s += step.length;
    }
    return true;
}

/// @brief The seed time of one segment; nullopt if cancelled.
[[nodiscard]] std::optional<double> seedTime(const PathSegment& segment, const MachineLimits& lim,
                                             const std::atomic<bool>* cancel);

}  // namespace cam
