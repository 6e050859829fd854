#pragma once
/// @file
/// @brief Design checks of a follower over one turn (math.md §7): extremes of s and its
/// derivatives, the largest pressure angle on rise and return against the limit, the smallest
/// radii of curvature, the flat face's width, and where the follower cannot reach the profile.

#include <atomic>
#include <optional>
#include <vector>

#include "follower/follower.h"
#include "project/project.h"

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

/// @brief An interval of cam angles [from, to] (rad) where |pressure angle| exceeds the limit,
/// and the largest |pressure angle| inside it (rad, a magnitude: it exceeds the limit by
/// peak.value − limit).
struct AngleRange {
    double from = 0.0;
    double to = 0.0;
    FollowerExtremum peak;
};

/// @brief The largest |pressure angle| (rad, a magnitude) in each phase of the motion, and
/// where: while the follower rises (dq/dφ > 0), returns (dq/dφ < 0) and dwells (|dq/dφ| at most
/// kDwellSlope of its largest value over the turn, or a rise or return of less than kPhaseLift
/// of the stroke) — or, given a motion design's phases, in each of those; none for a phase the
/// motion does not have.
/// The pressure angle is not zero in a dwell when the follower is offset or swings on an arm.
struct PressurePhases {
    std::optional<FollowerExtremum> rise, fall, dwell;
    FollowerExtremum max;  ///< over the whole turn
};

/// @brief Where the follower dwells: |dq/dφ| ≤ kDwellSlope · max |dq/dφ| over the turn (an arc
/// table's dwell arc, fitted to 1e-6 mm, is not exactly centred).
inline constexpr double kDwellSlope = 1e-6;

/// @brief A rise or return that moves the follower by less than kPhaseLift of its stroke is a
/// dwell's ripple, part of the dwell: an arc table fitted to a law within 0.001 mm rises and
/// falls by that much round its dwells (a swinging arm's "return" at 119° of a rise ending at
/// 120° was one).
inline constexpr double kPhaseLift = 1e-3;

/// @brief A phase of the motion: the follower rises, returns, dwells, or (a design's segment
/// that ends at the lift it starts with) either, as it moves.
enum class MotionPhase { Rise, Fall, Dwell, Either };

/// @brief A stretch of the turn in one phase of a motion design: the cam's angle from `from`
/// to `to` (rad, from < to, taken round the turn).
struct PhaseSpan {
    double from = 0.0, to = 0.0;
    MotionPhase phase = MotionPhase::Either;
    friend bool operator==(const PhaseSpan&, const PhaseSpan&) = default;
};

/// @brief The phases of a motion design's segments, in the cam's angle (the first segment
/// starts at 0° and at the lift the last ends with): a dwell law dwells, a segment rises or
/// returns as its lift goes.
[[nodiscard]] std::vector<PhaseSpan> designPhases(const DesignSpec& design);

/// @brief The phases of the project's motion design; none without one.
[[nodiscard]] inline std::vector<PhaseSpan> phasesOf(const Project& project) {
    return project.design ? designPhases(*project.design) : std::vector<PhaseSpan>{};
}

/// @brief The smallest radius of curvature of each sense over a turn, as magnitudes (mm), and
/// where: convex (bending round the cam centre) and concave (hollow); none where the curve never
/// bends that way. A signed minimum would mix them: it reads the flattest hollow near an
/// inflection, not the tightest bend.
struct CurvatureExtremes {
    std::optional<FollowerExtremum> minConvex, minConcave;
};

struct FollowerAnalysis {
    FollowerExtremum sMin, sMax, vMin, vMax, aMin, aMax, jMin, jMax;
    PressurePhases pressure;
    double limitRad = 0.0;
    std::vector<AngleRange> pressureExceeded;
    /// The profile's at the contact point; the pitch curve's at the roller centre (the
    /// profile's for a knife and a flat face).
    CurvatureExtremes profileCurvature, pitchCurvature;
    /// Flat face: the smallest face that always holds the contact, max h' − min h' (mm).
    double faceWidth = 0.0;
    std::vector<NonContact> undercut;
};

/// @brief What the curvature allows: a roller rolls without undercut where the pitch curve's
/// convex radius stays above the roller's (else the offset profile folds), a cutter of radius
/// r_t enters every hollow where the profile's concave radius is at least r_t. None where the
/// check does not apply (no roller; no tool radius given).
struct CurvatureVerdict {
    std::optional<bool> rollerFits, toolFits;
};

/// @brief The curvature checks of `a` for the follower `spec` and a cutter of `toolRadius` mm
/// (0: none).
[[nodiscard]] CurvatureVerdict curvatureVerdict(const FollowerAnalysis& a, const FollowerSpec& spec,
                                                double toolRadius);

/// @brief How many angles the design checks sample per turn by default.
inline constexpr int kFollowerCheckSamples = 7200;

/// @brief Samples the turn at `samples` angles, refines every extreme by golden sections and
/// every jump of the contact point and limit crossing by bisection. Polls `cancel` while it
/// samples: once set, what it returns is incomplete and meant to be dropped.
/// `phases`: a motion design's (designPhases), which are then the phases of the pressure
/// angle, whatever ripple the arc table fitted to it has (round a dwell it rises and falls by
/// up to the fit's tolerance); without, the follower's own (see PressurePhases).
[[nodiscard]] FollowerAnalysis analyzeFollower(const FollowerModel& model, double omega,
                                               double phiBegin, int samples = kFollowerCheckSamples,
                                               const std::atomic<bool>* cancel = nullptr,
                                               const std::vector<PhaseSpan>& phases = {});

}  // namespace cam
