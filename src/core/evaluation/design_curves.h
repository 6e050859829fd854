#pragma once
/// @file
/// @brief The project's motion design over one turn (math.md §8): its law at the project's
/// speed, and the follower placed by contact on the contour as it is, in the law's unit and
/// sense (after Synthesize: what the arcs cost the motion).

#include <array>
#include <atomic>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_law.h"
#include "evaluation/evaluation.h"
#include "forces/forces.h"

namespace cam {

struct DesignEvaluation {
    /// Why the design cannot be drawn: its own problems, or a base circle the follower cannot
    /// reach (then `onContour` is empty, and `law` too when the design itself has problems).
    Diagnostics errors;
    /// Velocity or acceleration jumps at joints; undercut and pressure angles beyond the limit
    /// of the exact profile with this follower (undercut is an error: Synthesize refuses it).
    Diagnostics notes;
    std::vector<LawCoefficients> coefficients;  ///< per design segment
    bool swinging = false;                      ///< lifts in degrees (a swinging arm), else mm
    /// Lift (mm or °), velocity, acceleration, jerk (per s, s², s³) at n + 1 equal time steps
    /// t_k = k·T/n of the turn (the last closes it: the first sample again).
    std::array<std::vector<double>, 4> law;
    /// The same for the follower on the contour (empty without a contour it can ride).
    std::array<std::vector<double>, 4> onContour;
    /// The largest |onContour − law| of lift, velocity and acceleration over those samples.
    std::array<double, 3> maxError{};
    /// With the project's `dynamics`: the forces the law itself asks for (its exact s'' and
    /// the exact profile's pressure angle and curvature) at the same n + 1 steps — beside the
    /// forces on the synthesised arcs, the price of the arcs in newtons. Empty without
    /// dynamics, or when the design has no exact profile.
    ForceTurn lawForces;
    /// Why onContour is empty while there is a contour (the follower cannot ride it).
    Diagnostics onContourErrors;
};

/// @brief Evaluates `project.design` (which must be present) at the evaluation's speed (which
/// must be usable: `evaluation.omega` ≠ 0) at n + 1 samples, and the follower the evaluation
/// placed on its contour against it, when it has a contour. Polls `cancel`; returns false,
/// `out` incomplete, once it reads true.
bool evaluateDesign(const Project& project, const ProjectEvaluation& evaluation, std::size_t n,
                    DesignEvaluation& out, const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
