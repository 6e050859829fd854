#pragma once
/// @file
/// @brief Design from motion (math.md §8): the project's design and follower → the exact
/// profile → an arc table within the tolerance, and what the arcs cost the motion.

#include <atomic>
#include <cstddef>
#include <optional>
#include <vector>

#include "common/diagnostic.h"
#include "design/arc_fit.h"
#include "design/motion_design.h"
#include "project/project.h"

namespace cam {

struct SynthesisReport {
    std::size_t segments = 0;
    /// The arc table's largest distance from the exact profile, measured on the contour as the
    /// engine evaluates it (not the fit's target): the exact profile's point at `measuredPoints`
    /// cam angles, each one's distance to the contour.
    double maxDeviationMm = 0.0;
    std::size_t measuredPoints = 0;
    /// The follower placed by contact on the arc table against the design, over the turn: its
    /// coordinate (mm, or degrees on an arm), velocity (mm/s or °/s) and acceleration (mm/s² or
    /// °/s²) at the project's speed. The arc table is only C1: the acceleration jumps at joints.
    double maxLiftError = 0.0;
    double maxVelocityError = 0.0;
    double maxAccelerationError = 0.0;
    std::size_t checkedAngles = 0;
    Diagnostics notes;  ///< velocity/acceleration jumps of the design, pressure angle beyond limit
};

struct Synthesis {
    std::vector<SegmentSpec> contour;
    SynthesisReport report;
};

/// @brief Fitted arcs (closed, counter-clockwise round the cam) as contour segments with polar
/// windows (degrees) rising from the first joint's angle through one turn; each arc takes the
/// branch of the ray that holds its midpoint.
[[nodiscard]] std::vector<SegmentSpec> contourOfArcs(const std::vector<FittedArc>& arcs);

/// @brief The validator's problems with a synthesised arc table (`arcs`, contour[k] made from
/// arcs[k]), the first placed: the arc it names (by its place, or the segment argument of its
/// code), the cam angles that arc was made for and the design segment they lie in, located
/// "design.segments[j]" (SynthesisedArcInvalid, the problem nested as its reason); located
/// "design" when it names no arc (SynthesisedContourInvalid). Then the other problems.
[[nodiscard]] Diagnostics placeArcTableProblems(const Diagnostics& problems,
                                                const std::vector<FittedArc>& arcs,
                                                const MotionDesign& design);

/// @brief How many times the machine epsilon of the profile's extent the smallest tolerance is
/// (certifiableTolerance).
inline constexpr double kCertifiableEpsilons = 16.0;

/// @brief The smallest tolerance double precision can certify for a profile reaching
/// `extentMm` from the centre: kCertifiableEpsilons · ε · extent (see synthesis.cpp).
[[nodiscard]] double certifiableTolerance(double extentMm);

/// @brief The arc table for `project`'s design and follower (a knife on the radial line when it
/// names none) within `tolerance` (the design's when not given). Errors, located: no design,
/// an invalid design, a base circle the follower cannot reach, undercut (with its angles), a
/// pressure angle beyond the limit when `strictPressureAngle` or the design asks for it
/// (DesignSpec::strictPressureAngle); located "design.tolerance": a tolerance below
/// certifiableTolerance of the profile's extent (DiagnosticCode::ToleranceBelowPrecision, the
/// limit in the message), one no arcs can follow near a corner (ToleranceCannotBeMet) or one
/// the measured contour does not come within after refitting (ToleranceNotReached); an arc
/// table that does not validate, located at the design segment its first bad arc was made for
/// (SynthesisedArcInvalid, the validator's reason nested). Empty errors: cancelled.
[[nodiscard]] Result<Synthesis> synthesize(const Project& project,
                                           std::optional<double> tolerance = std::nullopt,
                                           bool strictPressureAngle = false,
                                           const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
