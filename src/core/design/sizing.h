#pragma once
/// @file
/// @brief The smallest base radius of a motion design for which every check holds with its
/// follower (issue 29): the pressure angle within the follower's limit on rise and return, no
/// undercut, and the profile's convex radius at least a given minimum. Found by bisection on
/// the exact checks of the exact profile (design/exact_profile.h), not on a grid of radii.

#include <optional>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief The check that decides the smallest base radius.
enum class SizingCheck {
    PressureRise,    ///< |α| while the follower rises reaches the limit
    PressureReturn,  ///< |α| while it returns reaches the limit
    ConvexRadius,    ///< the profile's convex radius reaches the minimum (0: a cusp, undercut)
    Reach,           ///< below it the follower's line or arm cannot meet the base circle
};

/// @brief "pressure_angle_rise", "pressure_angle_return", "convex_radius", "reach".
[[nodiscard]] const char* sizingCheckName(SizingCheck check);
/// @brief "the pressure angle on rise", …: English a window translates (context "Diagnostic").
[[nodiscard]] const char* sizingCheckTitle(SizingCheck check);

struct SizingOptions {
    /// mm: the smallest convex radius the profile may have (a cutter's or a roller's needs);
    /// 0 asks only for no cusp (the profile does not fold).
    double minRadius = 0.0;
};

struct SizingResult {
    double baseRadius = 0.0;  ///< mm, the smallest that passes, to within kSizingTolerance
    SizingCheck binding = SizingCheck::PressureRise;
    double bindingPhi = 0.0;  ///< rad: where the binding check is at its limit
    /// At that base radius: the largest |α| on rise and on return (rad; none for a flat face,
    /// whose pressure angle is 0, or a phase the design does not have) and the smallest convex
    /// radius of the profile (mm; none where it is nowhere convex).
    std::optional<double> pressureRise, pressureReturn, minConvexRadius;
    /// A flat face: the face width its motion needs (max s' − min s', which no base radius
    /// changes).
    std::optional<double> faceWidth;
};

/// @brief The tolerance of the bisection (mm): the result passes, and the base radius
/// kSizingTolerance below it fails.
inline constexpr double kSizingTolerance = 1e-9;

/// @brief The smallest base radius of `design` (its own base radius is only a start) with
/// `follower`. Errors: a design that does not build; a follower that no base radius up to
/// 1e6 mm lets pass (named with the check that fails there).
[[nodiscard]] Result<SizingResult> sizeBaseRadius(const DesignSpec& design,
                                                  const FollowerSpec& follower,
                                                  const SizingOptions& options = {});

}  // namespace cam
