#include "evaluation/design_curves.h"

#include <cmath>

#include "common/angles.h"
#include "common/cancel.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "follower/follower_turn.h"

namespace cam {

bool evaluateDesign(const Project& project, const ProjectEvaluation& evaluation, std::size_t n,
                    DesignEvaluation& out, const std::atomic<bool>* cancel) {
    const double omega = evaluation.omega;
    const double period = evaluation.period;
    auto motion = MotionDesign::build(*project.design);
    if (!motion.ok()) {
        out.errors = motion.errors();
        return true;
    }
    const MotionDesign& design = motion.value();
    const FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    out.swinging = follower.motion == FollowerMotion::Oscillating;
    out.notes = design.jumps();
    for (std::size_t k = 0; k < project.design->segments.size(); ++k) {
        out.coefficients.push_back(design.coefficients(k));
    }
    for (auto& curve : out.law) curve.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const double phi = omega * period * static_cast<double>(k % n) / static_cast<double>(n);
        const std::array<double, 4> q = design.liftAt(phi);
        // d/dt = ω d/dφ: the lift's unit (mm or °) per second.
        out.law[0][k] = q[0];
        out.law[1][k] = omega * q[1];
        out.law[2][k] = omega * omega * q[2];
        out.law[3][k] = omega * omega * omega * q[3];
    }
    auto exact = ExactProfile::build(design, follower);
    if (!exact.ok()) {
        out.errors = exact.errors();
        return true;
    }
    if (cancelRequested(cancel)) return false;
    for (const ProfileProblem& problem :
         exact.value().problems(project.design->strictPressureAngle)) {
        out.notes.push_back(problem.what);
    }
    if (project.dynamics) {
        const ForceModel model = ForceModel::of(*project.dynamics, follower);
        out.lawForces.resize(n + 1);
        for (std::size_t k = 0; k <= n; ++k) {
            const double phi = omega * period * static_cast<double>(k % n) / static_cast<double>(n);
            const ForcePoint f =
                forceAt(model, designForceMotion(design, exact.value(), phi, out.swinging), omega);
            out.lawForces.load[k] = f.load;
            out.lawForces.normal[k] = f.normal;
            out.lawForces.torque[k] = f.torque;
            out.lawForces.stress[k] = f.stress;
        }
    }
    if (cancelRequested(cancel)) return false;
    // No follower placed: no contour, or one it cannot ride (then followerProblems says why).
    if (!evaluation.follower) {
        out.onContourErrors = evaluation.followerProblems;
        return true;
    }
    FollowerTurn turn;
    if (!sampleFollowerTurn(*evaluation.follower, omega, n, turn, cancel)) return false;
    // The follower's coordinate (mm, or the arm's angle in rad) against the one the design
    // asks for, turned into the lift's unit and sense.
    const double unit =
        out.swinging ? (follower.arm == ArmSide::Cw ? -1.0 : 1.0) * 180.0 / kPi : 1.0;
    for (auto& curve : out.onContour) curve.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const std::size_t i = k % n;
        const double phi = omega * period * static_cast<double>(i) / static_cast<double>(n);
        const std::array<double, 4> q = exact.value().followerCoordinate(phi);
        const double w[4] = {1.0, omega, omega * omega, omega * omega * omega};
        const double actual[4] = {turn.s[i], turn.v[i], turn.a[i], turn.j[i]};
        for (std::size_t d = 0; d < 4; ++d) {
            out.onContour[d][k] = out.law[d][k] + unit * (actual[d] - w[d] * q[d]);
            if (d < 3) {
                out.maxError[d] =
                    std::max(out.maxError[d], std::abs(out.onContour[d][k] - out.law[d][k]));
            }
        }
    }
    return true;
}

}  // namespace cam
