#pragma once
/// @file
/// @brief The follower's lift over one turn from a design (math.md §8): segment k runs from the
/// previous to_deg (0° for the first) to its to_deg, from the previous lift (0 for the first)
/// to its lift, by its law.

#include <array>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_law.h"
#include "project/project.h"

namespace cam {

/// @brief Every problem of a project's motion design (none without one), each located: what
/// MotionDesign::build finds, and lengths beyond the file's range. validateProject checks the
/// rest of the project.
[[nodiscard]] Diagnostics designProblems(const Project& project);

class MotionDesign {
public:
    /// @brief Errors, each located "design.FIELD" or "design.segments[k].FIELD": no segments;
    /// a to_deg not after where its segment starts; the last to_deg not 360; a base radius or
    /// tolerance not > 0; a number not finite; a dwell whose lift differs from the lift it
    /// starts with; another law whose lift equals it (no motion: a dwell); the last lift not 0.
    [[nodiscard]] static Result<MotionDesign> build(const DesignSpec& spec);

    /// @brief lift(φ) and d/dφ, d²/dφ², d³/dφ³ per radian (φ in rad, any real: reduced into
    /// the turn). At a joint, the later segment's values.
    [[nodiscard]] std::array<double, 4> liftAt(double phi) const;
    [[nodiscard]] std::size_t segmentAt(double phi) const;
    /// @brief Joints where the velocity or acceleration jumps (Severity::Info, located
    /// "design.segments[k]/design.segments[k+1]"; the turn's end joins its start).
    [[nodiscard]] const Diagnostics& jumps() const { return m_jumps; }
    /// @brief Cv, Ca, Cj of segment k (poly5: from its polynomial, normalised like the others).
    [[nodiscard]] LawCoefficients coefficients(std::size_t k) const;
    [[nodiscard]] const DesignSpec& spec() const { return m_spec; }

private:
    explicit MotionDesign(DesignSpec spec) : m_spec(std::move(spec)) {}
    /// Lift and derivatives in segment k at φ (rad within [start, end]).
    [[nodiscard]] std::array<double, 4> inSegment(std::size_t k, double phi) const;

    DesignSpec m_spec;
    std::vector<double> m_startRad, m_endRad, m_startLift;
    Diagnostics m_jumps;
};

}  // namespace cam
