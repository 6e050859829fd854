#pragma once
/// @file
/// @brief cli.md's JSON objects of the follower and of a kinematic state, as `state` and
/// `analyze` print them.

#include "cli/command_support.h"
#include "follower/follower.h"
#include "kinematics/kinematics.h"

namespace cam::cli {

/// @brief The contour point under the follower ray at one instant (cli.md `state`).
[[nodiscard]] Json stateJson(const KinematicState& s);

/// @brief cli.md's `follower` object of `state`; a swinging arm gives psi_deg, omega_arm,
/// alpha_arm and jerk_arm (rad/s…) in place of s, v, a, j, and its lift in degrees.
[[nodiscard]] Json followerJson(const FollowerModel& model, const FollowerState& f);

/// @brief cli.md's `follower` object of `analyze`: the design checks over the turn.
[[nodiscard]] Json followerAnalysisJson(const Loaded& loaded);

}  // namespace cam::cli
