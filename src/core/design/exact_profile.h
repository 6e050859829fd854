#pragma once
/// @file
/// @brief The exact cam for a motion design and a follower (math.md §8): at cam angle φ the
/// follower's lift is the design's. The pitch curve follows from s(φ) or ψ(φ) in the frame of
/// math.md §7, the profile is its inner offset by the roller radius (a knife rides the pitch
/// curve itself), or for a flat face the envelope of the face lines h·u + h'·n.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_design.h"
#include "project/project.h"

namespace cam {

/// @brief The profile at one cam angle, its φ-derivatives and the pitch point.
struct ProfilePoint {
    double phi = 0.0;                            ///< rad
    Eigen::Vector2d point{0.0, 0.0};             ///< on the profile, cam frame, mm
    Eigen::Vector2d d1{0.0, 0.0}, d2{0.0, 0.0};  ///< dP/dφ, d²P/dφ²
    Eigen::Vector2d pitch{0.0, 0.0};             ///< roller centre, knife tip, or
                                                 ///< where the face meets its line
    double rho = 0.0;            ///< the profile's radius of curvature, mm (+ convex, − concave)
    double pressureAngle = 0.0;  ///< rad, as FollowerState::pressureAngle (0 for a flat face)
};

/// @brief A stretch of cam angles where the design cannot be made with this follower.
struct ProfileProblem {
    double fromPhi = 0.0, toPhi = 0.0;  ///< rad, within the turn
    Diagnostic what;                    ///< located "design" or "follower.radius", with angles
};

class ExactProfile {
public:
    /// @brief The exact cam of `design` for `follower` (knife, roller and flat face on a
    /// translating line with offset; knife and roller on a swinging arm). Errors: a base
    /// circle the follower's line or arm cannot reach (|offset| ≥ base radius + roller radius;
    /// an arm that cannot touch the base circle), located "design.base_radius".
    [[nodiscard]] static Result<ExactProfile> build(const MotionDesign& design,
                                                    const FollowerSpec& follower);

    /// @brief The profile at cam angle φ (rad, any real).
    [[nodiscard]] ProfilePoint at(double phi) const;

    /// @brief The follower's coordinate the design asks for at φ and its φ-derivatives: s (mm)
    /// on a translating line, as FollowerState::s (the flat face's support distance), or the
    /// arm's angle ψ (rad) in the follower frame.
    [[nodiscard]] std::array<double, 4> followerCoordinate(double phi) const;

    /// @brief Where the profile cannot be made or ridden, checked at `samples` angles and
    /// bisected to its ends: undercut (a roller's pitch curve convex tighter than the roller,
    /// a flat face's h + h'' < 0, where the profile would fold back) and a pressure angle
    /// beyond the follower's limit. Undercut is an error; the pressure angle only when
    /// `strictPressureAngle`, otherwise Severity::Info.
    [[nodiscard]] std::vector<ProfileProblem> problems(bool strictPressureAngle,
                                                       int samples = 7200) const;

    [[nodiscard]] const MotionDesign& design() const { return m_design; }
    [[nodiscard]] const FollowerSpec& follower() const { return m_follower; }

private:
    ExactProfile(MotionDesign design, const FollowerSpec& follower)
        : m_design(std::move(design)), m_follower(follower) {}

    MotionDesign m_design;
    FollowerSpec m_follower;
    double m_s0 = 0.0;      ///< translating: s at lift 0 (the pitch point on the base circle)
    double m_theta0 = 0.0;  ///< swinging arm: the angle from pivot → centre at lift 0 (rad)
    double m_beta = 0.0;    ///< swinging arm: the follower-frame angle from the pivot to the centre
};

}  // namespace cam
