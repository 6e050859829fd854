#pragma once
/// @file
/// @brief The smallest base radius of a motion design for which every check holds with its
/// follower (issue 29): the pressure angle within the follower's limit on rise and return, no
/// undercut, and the profile's convex radius at least a given minimum. Found by bisection on
/// the exact checks of the exact profile (design/exact_profile.h), not on a grid of radii.

#include <array>
#include <atomic>
#include <optional>
#include <vector>

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
    /// mm: a base radius near the answer (a neighbouring offset's), where the search starts on
    /// a translating follower instead of bracketing from 1 µm; the answer is the same.
    std::optional<double> near;
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

/// @brief Whether the offset changes what a follower needs: a translating knife or roller (a
/// flat face's pressure angle is 0 at any offset; an arm has a pivot instead).
[[nodiscard]] bool offsetSizable(const FollowerSpec& follower);

/// @brief The offset of a translating follower that allows the smallest base radius, and the
/// lower edge of the feasible region over base radius × offset.
struct OffsetSizing {
    double offset = 0.0;  ///< mm, to within kOffsetTolerance
    SizingResult sizing;  ///< the smallest base radius at that offset
    /// (offset, smallest base radius) in mm at evenly spaced offsets over ±1.1 · max |s'|:
    /// every base radius above the edge passes at that offset; NaN where none passes.
    std::vector<std::array<double, 2>> edge;
};

/// @brief The tolerance of the search for the best offset (mm).
inline constexpr double kOffsetTolerance = 1e-6;

/// @brief The offset (between ±1.1 · max |s'| of the design) that allows the smallest base
/// radius of `design` with `follower` (offsetSizable; its own offset is only a start), by
/// golden sections round the best of `edgePoints` offsets; each base radius certified as
/// sizeBaseRadius certifies it. Errors: as sizeBaseRadius's, when no offset passes; none but
/// an empty result when `cancel` reads true.
[[nodiscard]] Result<OffsetSizing> sizeOffset(const DesignSpec& design,
                                              const FollowerSpec& follower,
                                              const SizingOptions& options = {},
                                              int edgePoints = 41,
                                              const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
