#pragma once
/// @file
/// @brief cli.md's JSON objects of the follower and of a kinematic state, as `state` and
/// `analyze` print them.

#include "cli/command_support.h"
#include "follower/follower.h"
#include "forces/forces.h"
#include "kinematics/kinematics.h"

namespace cam::cli {

/// @brief The contour point under the follower ray at one instant (cli.md `state`).
[[nodiscard]] Json stateJson(const KinematicState& s);

/// @brief cli.md's `follower` object of `state`; a swinging arm gives psi_deg, omega_arm,
/// alpha_arm and jerk_arm (rad/s…) in place of s, v, a, j, and its lift in degrees.
[[nodiscard]] Json followerJson(const FollowerModel& model, const FollowerState& f);
/// @brief cli.md's `outer_flank` of a grooved cam's follower: `f` (onOuterFlank's) as
/// followerJson gives it, less the type and motion, its lift measured as the inner flank's.
[[nodiscard]] Json outerFlankJson(const FollowerModel& inner, const FollowerState& f);
/// @brief analyze's `follower.conjugate`: the second roller, the plate's arcs and the play.
[[nodiscard]] Json conjugateJson(const Loaded& loaded, const ConjugatePlate& plate);

/// @brief cli.md's `follower` object of `analyze`: the design checks over the turn.
[[nodiscard]] Json followerAnalysisJson(const Loaded& loaded);

/// @brief cli.md's `forces` object of `state` (math.md §9): the load (axial_N, or moment_Nm on
/// an arm), normal_N, lateral_N (translating), torque_Nm, power_W, contact_stress_MPa and
/// contact_half_width_mm (null for a knife edge, without width or materials, or where the
/// follower has left the cam).
[[nodiscard]] Json forcesJson(const ForceModel& model, const ForcePoint& f);

/// @brief cli.md's `forces` object of `analyze`: the turn's lift-off ranges, jump speed, least
/// preload, peaks and largest contact stress (and its ratio to the allowable).
[[nodiscard]] Json forcesAnalysisJson(const Loaded& loaded);

}  // namespace cam::cli
