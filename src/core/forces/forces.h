#pragma once
/// @file
/// @brief The forces of math.md §9: the follower train (mass or arm inertia, spring, damping,
/// external load) pressed on the cam, rigid and frictionless — the load along the line of
/// motion (or the arm's moment), the contact normal and side forces, the camshaft's torque and
/// power, and the Hertz line contact; over a turn, where the follower leaves the cam, the
/// speed at which it would, the least preload that keeps it on, and the peaks.

#include <array>
#include <optional>
#include <vector>

#include "closure/conjugate.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "project/project.h"

namespace cam {

/// @brief A project's dynamics in SI units, ready to compute with.
struct ForceModel {
    bool swinging = false;
    double mass = 0.0;       ///< kg, or the arm's inertia in kg·m²
    double rate = 0.0;       ///< N/m, or N·m/rad
    double preload = 0.0;    ///< N at lift 0, or N·m
    double external = 0.0;   ///< N pressing the follower on the cam, or N·m
    double damping = 0.0;    ///< N·s/m, or N·m·s/rad
    double armLength = 0.0;  ///< m (swinging)
    double safetyFactor = 1.0;
    /// The Hertz contact: a roller's or a flat face's, with the width and both materials
    /// given; none for a knife edge.
    bool hasStress = false;
    double widthMm = 0.0;
    double modulusMpa = 0.0;  ///< E*: 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2
    /// 1/ρ_f of the follower's contact (1/mm): a roller's curvature, 0 for a flat face.
    double followerCurvature = 0.0;
    std::optional<double> allowableMpa;
    /// A grooved cam's width 2ρ + c (mm; 0: spring-closed). In a groove the follower never
    /// leaves the cam: where the load turns negative the outer flank carries it, whose radius
    /// across the roller from the inner contact is ρ_profile + 2ρ + c (exact within an arc of
    /// an arc table; the roller's shift by the clearance is neglected there and in the motion).
    double grooveWidthMm = 0.0;
    [[nodiscard]] bool grooved() const { return grooveWidthMm > 0.0; }
    /// A conjugate pair's second roller (closure/conjugate.h): where the load turns negative
    /// it carries it, pressed on the second plate at its own pressure angle and on the plate's
    /// curvature there (ForceMotion::second), with its own radius (1/ρ₂ in 1/mm).
    std::optional<SecondRoller> yoke;
    double secondFollowerCurvature = 0.0;
    /// The first follower (its line's offset, or its pivot and side), which the second
    /// roller's place follows.
    FollowerSpec follower;
    /// What a negative load pushes the second roller by: 1 on a yoke (the load is a force), a
    /// bell crank's second arm (m) on an arm (the load is a moment).
    double secondLever = 1.0;
    [[nodiscard]] bool conjugate() const { return yoke.has_value(); }
    /// @brief Form-closed: the follower never leaves the cam; a negative load is carried by a
    /// second contact (a groove's outer flank, a conjugate pair's second roller).
    [[nodiscard]] bool formClosed() const { return grooved() || conjugate(); }

    /// @brief From the project's `dynamics` (absent keys take their defaults) and follower.
    [[nodiscard]] static ForceModel of(const DynamicsSpec& dynamics, const FollowerSpec& follower);
};

/// @brief The follower's motion at one angle, as the forces need it: the lift λ (m, or the
/// arm's swing away from the cam in rad) and its derivatives by the cam angle (per rad), the
/// pressure angle (rad) and the profile's radius of curvature at the contact (mm, signed,
/// +∞ on a straight stretch).
struct ForceMotion {
    std::array<double, 3> lift{};
    double pressureAngle = 0.0;
    double rhoProfile = 0.0;
    /// A conjugate pair's second roller: its pressure angle (rad) and the second plate's
    /// radius of curvature at its contact (mm, positive where convex, +∞ where straight).
    struct Second {
        double pressureAngle = 0.0;
        double rhoPlate = 0.0;
    };
    std::optional<Second> second;
};

/// @brief The forces at one angle. Units: N, N·m, W, MPa, mm.
struct ForcePoint {
    double load = 0.0;     ///< F_axial along the line of motion, or the arm's moment M (N·m)
    double normal = 0.0;   ///< F_n, the contact normal force
    double lateral = 0.0;  ///< F_lat on the guide (translating; NaN on an arm)
    double torque = 0.0;   ///< on the camshaft, N·m
    double power = 0.0;    ///< W
    /// Hertz p_max, the contact half-width a and the largest subsurface shear (about 0.30·p_max
    /// at 0.786·a); NaN for a knife edge, without width or materials, or where contact is lost.
    /// Form-closed, where the normal force is negative, those of the second contact (a
    /// groove's outer flank, a conjugate pair's second roller).
    double stress = 0.0, halfWidth = 0.0, shear = 0.0;
};

/// @brief math.md §9 at one angle, the cam turning at ω rad/s.
[[nodiscard]] ForcePoint forceAt(const ForceModel& model, const ForceMotion& motion, double omega);

/// @brief The state's motion in the forces' units (the follower's lift and its φ-derivatives
/// from `follower`; a conjugate pair's second roller at the same angle).
[[nodiscard]] ForceMotion forceMotion(const FollowerModel& follower, const FollowerState& state);

/// @brief The motion the design's law asks for at cam angle φ, as the forces need it: its
/// lift (mm → m, or on a swinging arm degrees → rad) and derivatives, and the exact profile's
/// pressure angle and radius there — the forces of the law itself, which the arc table
/// synthesised from it only approximates (its s'' jumps at every joint).
[[nodiscard]] ForceMotion designForceMotion(const MotionDesign& design, const ExactProfile& profile,
                                            double phi, bool swinging);

/// @brief The speed (rad/s, ≥ 0) above which the load at this angle turns negative: the
/// smallest positive root W of m·λ''·W² + c·λ'·sgn(ω)·W + (k·λ + F0 + Fe) = 0; 0 when the load
/// is negative at rest already, +∞ when no speed lifts the follower here.
[[nodiscard]] double jumpSpeedAt(const ForceModel& model, const ForceMotion& motion, double omega);

/// @brief The preload that just keeps the load at n times what pulls the follower off at this
/// angle: n·(−m·λ̈ − c·λ̇) − k·λ − Fe (N or N·m).
[[nodiscard]] double preloadNeededAt(const ForceModel& model, const ForceMotion& motion,
                                     double omega);

/// @brief Where the follower's contact passes from one contour segment to the next and the
/// forces jump (an arc table's s'' jumps at every joint): both one-sided values.
struct ForceJump {
    double phi = 0.0;          ///< rad, to 1e-12
    ForcePoint before, after;  ///< just before and just after, in the turning direction
};

/// @brief A turn's forces and what a designer releases a cam on.
struct ForceSummary {
    /// rad ranges [from, to] where the load < 0 (its first and last angle with load < 0): the
    /// follower leaves the cam there — in a groove, the roller crosses its clearance at `from`
    /// and the outer flank carries the load until `to` (the crossovers a designer moves into
    /// stretches of low velocity); on a conjugate pair the second roller carries it.
    std::vector<std::array<double, 2>> liftOff;
    double jumpSpeed = 0.0;                     ///< rad/s, the smallest over the turn (+∞: none)
    double jumpSpeedAt = 0.0;                   ///< rad
    double minPreload = 0.0;                    ///< N or N·m (the largest preloadNeededAt)
    double minPreloadAt = 0.0;                  ///< rad
    double maxNormal = 0.0, maxNormalAt = 0.0;  ///< N, rad
    double peakTorque = 0.0, peakTorqueAt = 0.0;   ///< N·m (largest |T|, signed), rad
    double rmsTorque = 0.0;                        ///< N·m over the turn
    double peakPower = 0.0;                        ///< W (largest |P|, signed)
    std::optional<double> maxStress, maxStressAt;  ///< MPa, rad; none without a contact stress
    /// Form-closed: the largest normal force on the second contact — a groove's outer flank,
    /// a conjugate pair's second roller on its plate — (N, a magnitude) and its largest
    /// contact stress (MPa), with where; none where it never carries. (maxNormal and
    /// maxStress are then the first contact's: the inner flank, the first plate.)
    std::optional<double> maxNormalSecond, maxNormalSecondAt;
    std::optional<double> maxStressSecond, maxStressSecondAt;
    /// Every joint where the load jumps by more than 1e-9 of the largest load; their one-sided
    /// values take part in every extreme above and in the lift-off ranges.
    std::vector<ForceJump> jumps;
};

/// @brief The forces at every sample of a turn, column by column (the batch path: plots, CSV
/// columns, the summary). What follows from these is not stored: lateral = normal · sin α,
/// power = torque · ω, half-width a = 2·p / (E*·κ) and shear 0.30·p (point() gives them).
struct ForceTurn {
    std::vector<double> load, normal, torque;
    std::vector<double> stress;  ///< NaN where there is none (as ForcePoint::stress)

    [[nodiscard]] std::size_t size() const { return load.size(); }
    void resize(std::size_t n);
    /// @brief Sample k as forceAt gives it (to rounding), of the turn it was computed from.
    [[nodiscard]] ForcePoint point(std::size_t k, const ForceModel& model, const FollowerTurn& turn,
                                   double omega) const;
};

/// @brief The forces at every sample of `turn` (sampleFollowerTurn's of `follower`) at ω, into
/// `out`, reusing its storage. Vectorised on the CPU's vector units (common/simd.h).
void forcesOfTurn(const ForceModel& model, const FollowerModel& follower, const FollowerTurn& turn,
                  double omega, ForceTurn& out);

/// @brief The summary of a sampled turn (sample k at φ_k = 2π·k/n in the turning direction):
/// the lift-off ranges to 1e-12 rad (bisected on the load's sign), every extreme refined between
/// samples by golden sections on the follower placed exactly.
[[nodiscard]] ForceSummary summarizeForces(const ForceModel& model, const FollowerModel& follower,
                                           const FollowerTurn& turn, const ForceTurn& forces,
                                           double omega);

}  // namespace cam
