#include "evaluation/force_evaluation.h"

#include "common/cancel.h"

namespace cam {

bool evaluateForces(const Project& project, const FollowerModel& follower, double omega,
                    ForceEvaluation& out, const std::atomic<bool>* cancel) {
    out.model = ForceModel::of(*project.dynamics, follower.spec());
    const auto n = static_cast<std::size_t>(project.samplesPerTurnOrDefault());
    if (!sampleFollowerTurn(follower, omega, n, out.turn, cancel)) return false;
    forcesOfTurn(out.model, follower, out.turn, omega, out.forces);
    if (cancelRequested(cancel)) return false;
    out.summary = summarizeForces(out.model, follower, out.turn, out.forces, omega);
    return true;
}

}  // namespace cam
