#pragma once
/// @file
/// @brief The forces of a project's `dynamics` over one turn (math.md §9), as `camwright-cli
/// analyze` and the window's Forces dock both report them: the turn sampled at the project's
/// samples per turn, the forces at every sample and the summary a cam is released on.

#include <atomic>
#include <cstddef>

#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "forces/forces.h"
#include "project/project.h"

namespace cam {

struct ForceEvaluation {
    ForceModel model;
    FollowerTurn turn;  ///< the follower at samplesPerTurnOrDefault() equal angle steps
    ForceTurn forces;   ///< the forces at the same samples
    ForceSummary summary;
};

/// @brief The forces of `project.dynamics` (which must be present) on `follower` (the project's,
/// placed on its contour) at ω rad/s. Polls `cancel`; returns false, `out` incomplete, once it
/// reads true.
bool evaluateForces(const Project& project, const FollowerModel& follower, double omega,
                    ForceEvaluation& out, const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
