#pragma once
/// @file
/// @brief VDI 2143's boundary classes of a motion segment and the law recommended for each
/// pair (Suggest): at each end a segment is at rest (v = 0, a = 0), at constant velocity
/// (v ≠ 0, a = 0), reversing (v = 0, a ≠ 0) or moving (v ≠ 0, a ≠ 0), as its neighbour there
/// demands.

#include <optional>
#include <string_view>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_design.h"
#include "project/project.h"

namespace cam {

enum class BoundaryClass { Rest, Velocity, Reversal, Movement };

/// @brief The class of a joint where the lift moves at v and accelerates at a (any unit; below
/// `zero` counts as zero).
[[nodiscard]] BoundaryClass classifyBoundary(double v, double a, double zero);
/// @brief "rest", "velocity", "reversal", "movement" (the CLI's JSON).
[[nodiscard]] std::string_view boundaryClassName(BoundaryClass c);
/// @brief The class as a term of the core's messages, marked for translation in context
/// "Diagnostic": "rest", "constant velocity", "reversal", "movement".
[[nodiscard]] const char* boundaryClassTerm(BoundaryClass c);
/// @brief The letter VDI 2143 gives it: R, G, U, B (Rast, Geschwindigkeit, Umkehr, Bewegung).
[[nodiscard]] char boundaryClassLetter(BoundaryClass c);

/// @brief A segment's classes as its neighbours demand them: at its start the class of where
/// the segment before ends, at its end the class of where the segment after starts (the turn's
/// end joining its start).
struct SegmentClasses {
    BoundaryClass start = BoundaryClass::Rest, end = BoundaryClass::Rest;
};
[[nodiscard]] std::vector<SegmentClasses> boundaryClasses(const MotionDesign& design);
/// @brief The same for a design whose joints need not fit yet (MotionDesign::
/// buildIgnoringJoints); its errors when it cannot be evaluated at all.
[[nodiscard]] Result<std::vector<SegmentClasses>> boundaryClasses(const DesignSpec& spec);

/// @brief Suggest: the recommended law for segment `only` (every segment that is not a dwell
/// or a line when none), from its classes — CODESYS SoftMotion's table of segment types for
/// each pair of boundary classes, with these choices where it lists several or we differ:
///   rest → rest: the modified sine (CODESYS: Line, Poly5/7, InclinedSine, ModifiedSine);
///   equal velocities at both ends: a line where that is the stretch's own slope, else the
///     inclined sine through them (CODESYS: Line, Poly5/7, ModifiedSine; its InclinedSine is
///     rest to rest only);
///   every other pair (rest ↔ velocity, reversal, movement): poly5 with the joint's velocity
///     and acceleration at each end (CODESYS: Poly5/7, or its modified sine with end
///     velocities, which ours is not).
/// Where two suggested segments meet, their joint is chosen first: a reversal (the lift turns
/// back) at v = 0 with a = 6(Δ₂/h₂² − Δ₁/h₁²), the acceleration two quartic turns would share;
/// a movement on in the same direction at the harmonic mean of the two stretches' slopes, a = 0.
/// Errors: those of a design that cannot be evaluated (its joints aside).
[[nodiscard]] Result<DesignSpec> suggestLaws(const DesignSpec& spec,
                                             std::optional<std::size_t> only = std::nullopt);

}  // namespace cam
