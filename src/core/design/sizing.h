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
    /// mm: a base radius near the answer (a neighbouring placement's), where the search starts
    /// instead of bracketing from 1 µm — on a swinging arm only when it passes; the answer is
    /// the same where the radii that pass form one interval.
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

/// @brief The largest base radius of `design` that passes with `follower`, above `smallest`
/// (which passes: sizeBaseRadius's answer): +∞ for a translating follower; for a swinging arm
/// its reach (Rb + ρ < a) when the checks hold there, else bisected to 1e-6 mm relative.
[[nodiscard]] double largestBaseRadius(const DesignSpec& design, const FollowerSpec& follower,
                                       const SizingOptions& options, double smallest);

/// @brief What places a follower beside the cam, apart from the base radius: a translating
/// knife's or roller's offset, or a swinging arm's pivot distance (the pivot moves along the
/// line from the cam centre through it; its direction only turns the cam, and the arm keeps
/// its length).
enum class Placement {
    Offset,         ///< FollowerSpec::offset, mm
    PivotDistance,  ///< |FollowerSpec::pivot|, mm
};

/// @brief The placement that changes what `follower` needs; none for a flat face, whose
/// pressure angle is 0 at any offset.
[[nodiscard]] std::optional<Placement> placementOf(const FollowerSpec& follower);
/// @brief The follower's offset or pivot distance (mm).
[[nodiscard]] double placementValue(const FollowerSpec& follower, Placement placement);
/// @brief The follower placed at `value` mm: its offset, or its pivot moved to that distance
/// along its own direction (+x when it has none).
[[nodiscard]] FollowerSpec placedAt(FollowerSpec follower, Placement placement, double value);

/// @brief The base radii that pass at one placement (mm): every one from `smallest` to
/// `largest`. Both NaN where none passes; `largest` is +∞ on a translating follower (a larger
/// cam only eases its checks). A swinging arm's pressure angle grows again on a large cam,
/// and the arm reaches a base circle only while Rb + ρ < a: its `largest` is where either
/// ends the radii, to within 1e-6 of it. (The radii that pass are taken to form one interval,
/// as they do on every design tried.)
struct FeasibleSpan {
    double placement = 0.0;
    double smallest = 0.0;
    double largest = 0.0;
};

/// @brief The placement that allows the smallest base radius, and the feasible region over
/// base radius × placement.
struct PlacementSizing {
    Placement placement = Placement::Offset;
    double value = 0.0;   ///< mm, the offset or pivot distance, to within kPlacementTolerance
    SizingResult sizing;  ///< the smallest base radius there
    /// At evenly spaced placements over the range searched.
    std::vector<FeasibleSpan> region;
};

/// @brief The tolerance of the search for the best placement (mm).
inline constexpr double kPlacementTolerance = 1e-6;

/// @brief The placement of `follower` (which must have one, placementOf; its own value is only
/// a start) that allows the
/// smallest base radius of `design`, by golden sections round the best of `edgePoints`
/// placements, each base radius certified as sizeBaseRadius certifies it. An offset is
/// searched over ±1.1 · max |s'| of the design; a pivot distance a from the contact radius ρ
/// to L + ρ + R, R the smallest base radius at the arm's own pivot (beyond it the arm cannot
/// reach a smaller base circle: the pitch base circle's radius is at least a − L), or 2·(L + ρ)
/// + a when none passes there — and of that, after a look at 11 distances, only from a tenth
/// of it before the first where radii pass to a tenth after the last. Errors: as sizeBaseRadius's,
/// when no placement passes; none but an empty result when `cancel` reads true.
[[nodiscard]] Result<PlacementSizing> sizePlacement(const DesignSpec& design,
                                                    const FollowerSpec& follower,
                                                    const SizingOptions& options = {},
                                                    int edgePoints = 41,
                                                    const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
