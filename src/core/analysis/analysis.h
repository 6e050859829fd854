#pragma once
/// @file
/// @brief What a designer asks of a contour: how each joint continues, and where the extremes are.

#include <array>
#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include "common/tolerances.h"
#include "contour/contour.h"
#include "kinematics/kinematics.h"

namespace cam {

/// @brief Highest order of continuity at a joint. Kinematic (in φ, what the follower feels):
/// C0 position, C1 dP/dφ (the velocity), C2 d²P/dφ² (the acceleration) — in φ a continuous
/// tangent direction already means C1. Geometric (in each curve's own parameter: a Bézier's s,
/// an arc's angle, a line's 0..1): G1 is a continuous direction with a jump in the derivative's
/// length, as at a spline knot with collinear handles of different lengths.
enum class Continuity { None, C0, G1, C1, C2 };

[[nodiscard]] const char* continuityName(Continuity c);

/// @brief The joint between segment `left` and segment `right` (= left + 1, wrapping).
struct JointAnalysis {
    std::size_t left = 0;
    std::size_t right = 0;
    double phi = 0.0;              ///< rad, the end of the left window
    double gapMm = 0.0;            ///< C0: distance between the two end points
    double tangentBreakDeg = 0.0;  ///< angle between the two contour tangents
    double jumpDr = 0.0;           ///< r'(right) - r'(left), mm/rad
    double jumpD2r = 0.0;          ///< r''(right) - r''(left), mm/rad²
    double jumpD3r = 0.0;          ///< r'''(right) - r'''(left), mm/rad³
    double jumpAR = 0.0;           ///< a_r(right) - a_r(left), mm/s²
    double jumpJR = 0.0;           ///< j_r(right) - j_r(left), mm/s³
    Eigen::Vector2d jumpP{0, 0};   ///< P(right) - P(left), mm
    Eigen::Vector2d jumpD1{0, 0};  ///< dP/dφ(right) - dP/dφ(left), mm/rad
    Eigen::Vector2d jumpD2{0, 0};  ///< d²P/dφ²(right) - d²P/dφ²(left), mm/rad²
    double relativeD1 = 0.0;       ///< |jumpD1| / max(|dP/dφ| left, right)
    double relativeD2 = 0.0;       ///< |jumpD2| / max(|d²P/dφ²| left, right)
    /// In the curves' own parameters (see Continuity): jumps of dP/dp and d²P/dp², relative.
    Continuity geometric = Continuity::None;
    Eigen::Vector2d curveJumpD1{0, 0};
    Eigen::Vector2d curveJumpD2{0, 0};
    double curveRelativeD1 = 0.0;
    double curveRelativeD2 = 0.0;
    Continuity continuity = Continuity::None;
};

/// @brief A joint where the acceleration jumps (an arc table's every joint between arcs of
/// different curvature): there the jerk is unbounded — a Dirac impulse of the jump — and the
/// jerk's extremes a sampling finds are those between joints only.
struct UnboundedJerk {
    std::size_t left = 0, right = 0;
    double phi = 0.0;               ///< rad, the joint's angle
    double accelerationJump = 0.0;  ///< |a(right) − a(left)| = ω²·|d²P/dφ² jump|, mm/s²
};

/// @brief The joints of `joints` (of a contour turning at omega) where the acceleration jumps:
/// every one whose kinematic continuity is below C2.
[[nodiscard]] std::vector<UnboundedJerk> unboundedJerk(const std::vector<JointAnalysis>& joints,
                                                       double omega);

/// @brief A quantity over one turn that analysis reports the extremes of.
enum class Quantity { R, VR, V, AR, A, JR, J };
inline constexpr std::array<Quantity, 7> kAllQuantities{
    Quantity::R, Quantity::VR, Quantity::V, Quantity::AR, Quantity::A, Quantity::JR, Quantity::J};
[[nodiscard]] const char* quantityName(Quantity q);

struct Extremum {
    double value = 0.0;
    double phi = 0.0;  ///< rad, within [phiBegin, phiBegin + 2π)
    std::size_t segment = 0;
};

struct QuantityExtremes {
    Quantity quantity = Quantity::R;
    Extremum min;
    Extremum max;
};

struct ContourAnalysis {
    std::vector<JointAnalysis> joints;
    std::vector<QuantityExtremes> extremes;
};

/// @brief The joints of a contour turning at omega (rad/s), the one at the end of each segment
/// (none for a single segment); empty when `cancel` reads true between two.
[[nodiscard]] std::vector<JointAnalysis> analyzeJoints(const Contour& contour, double omega,
                                                       const std::atomic<bool>* cancel = nullptr);

/// @brief Joints and extremes of a contour turning at omega (rad/s).
///
/// Extremes are found per segment on a fine grid that includes both window ends (one-sided
/// values at joints) and then refined by golden-section search, so they are exact to ~1e-10
/// of the window rather than to the grid spacing.
///
/// If `cancel` is given it is polled between segments; when it reads true the function returns
/// at once with a partial analysis (the caller, who set the flag, drops it).
/// Only segments whose extreme could reach the best coarse value of all are searched finely
/// (a coarse grid of 33 points bounds each segment's); `EverySegment` searches every one, as
/// the tests' reference.
enum class ContourSearch { Bounded, EverySegment };
[[nodiscard]] ContourAnalysis analyzeContour(const Contour& contour, double omega,
                                             const std::atomic<bool>* cancel = nullptr,
                                             ContourSearch search = ContourSearch::Bounded);

/// @brief Kinematic continuity from a joint's measures: C0 needs gap <= kJointToleranceMm, C1 a
/// tangent break <= kTangentToleranceDeg, C2 a relative jump of d²P/dφ² <= kCurvatureToleranceRel.
/// A measure that is NaN (a ray that only touches a curve) never passes its test.
[[nodiscard]] Continuity kinematicContinuity(double gapMm, double tangentBreakDeg,
                                             double relativeD2);
/// @brief Geometric continuity (in each curve's own parameter) of a joint that is at least C1 in
/// φ, from the relative jumps of the curve's first and second derivatives; NaN never passes.
[[nodiscard]] Continuity geometricContinuity(Continuity kinematic, double curveRelativeD1,
                                             double curveRelativeD2);

/// @brief The joint at the end of segment k.
[[nodiscard]] JointAnalysis analyzeJoint(const Contour& contour, std::size_t k, double omega);

[[nodiscard]] double quantityValue(Quantity q, const PolarDerivatives& d, const PolarMotion& m);

}  // namespace cam
