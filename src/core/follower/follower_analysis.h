#pragma once
/// @file
/// @brief Design checks of a follower over one turn (math.md §7): extremes of s and its
/// derivatives, the largest pressure angle on rise and return against the limit, the smallest
/// radii of curvature, the flat face's width, and where the follower cannot reach the profile.

#include <atomic>
#include <vector>

#include "follower/follower.h"

namespace cam {

struct FollowerExtremum {
    double value = 0.0;
    double phi = 0.0;  ///< rad, in the contour's turn
};

/// @brief A stretch of profile the follower never touches: at cam angle `phi` it jumps from
/// the contact `from` to `to` (a roller or face bridging a hollow it cannot enter, a knife
/// whose line never meets a part hidden behind another).
struct NonContact {
    double phi = 0.0;
    Eigen::Vector2d from{0.0, 0.0};
    Eigen::Vector2d to{0.0, 0.0};
};

/// @brief An interval of cam angles [from, to] (rad) where |pressure angle| exceeds the limit.
struct AngleRange {
    double from = 0.0;
    double to = 0.0;
};

struct FollowerAnalysis {
    FollowerExtremum sMin, sMax, vMin, vMax, aMin, aMax, jMin, jMax;
    /// The largest pressure angle while rising (≥ 0) and the most negative while returning.
    FollowerExtremum pressureRise, pressureReturn;
    double limitRad = 0.0;
    std::vector<AngleRange> pressureExceeded;
    FollowerExtremum rhoProfileMin, rhoPitchMin;
    /// Flat face: the smallest face that always holds the contact, max h' − min h' (mm).
    double faceWidth = 0.0;
    std::vector<NonContact> undercut;
};

/// @brief How many angles the design checks sample per turn by default.
inline constexpr int kFollowerCheckSamples = 7200;

/// @brief Samples the turn at `samples` angles, refines every extreme by golden sections and
/// every jump of the contact point and limit crossing by bisection. Polls `cancel` while it
/// samples: once set, what it returns is incomplete and meant to be dropped.
[[nodiscard]] FollowerAnalysis analyzeFollower(const FollowerModel& model, double omega,
                                               double phiBegin, int samples = kFollowerCheckSamples,
                                               const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
