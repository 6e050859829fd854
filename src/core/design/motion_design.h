#pragma once
/// @file
/// @brief The follower's lift over one turn from a design (math.md §8): segment k runs from the
/// previous to_deg (0° for the first) to its to_deg, from the previous lift (0 for the first)
/// to its lift, by its law.

#include <array>
#include <cstddef>
#include <memory>
#include <variant>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_law.h"
#include "design/motion_table.h"
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
    /// starts with; another law whose lift equals it (no motion: a dwell); the last lift not 0;
    /// a law's parameter out of its range (λ, b, d, a table's points); a joint where the
    /// velocity jumps — a law that cannot meet its boundary class (design/boundary_classes.h),
    /// located at the law of the segment that must change (not a dwell or a line where the
    /// other side can change).
    [[nodiscard]] static Result<MotionDesign> build(const DesignSpec& spec);
    /// @brief As build, but a joint whose velocity jumps is no error: for showing the classes
    /// of a design whose joints do not fit yet, and for suggesting laws that make them fit.
    [[nodiscard]] static Result<MotionDesign> buildIgnoringJoints(const DesignSpec& spec);

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
    /// @brief Lift and d/dφ, d²/dφ², d³/dφ³ per radian at the start and at the end of segment k.
    [[nodiscard]] std::array<double, 4> startOf(std::size_t k) const {
        return inSegment(k, m_startRad[k]);
    }
    [[nodiscard]] std::array<double, 4> endOf(std::size_t k) const {
        return inSegment(k, m_endRad[k]);
    }
    /// @brief Segment k's stretch in radians.
    [[nodiscard]] double widthRad(std::size_t k) const { return m_endRad[k] - m_startRad[k]; }
    /// @brief The scale below which a velocity or acceleration per radian counts as zero.
    [[nodiscard]] double zeroScale() const { return m_zero; }

private:
    /// How a segment's lift is computed, prepared once.
    using SegmentLaw = std::variant<std::monostate, LawParameters, Poly5Law, Poly7Law, SccaLaw,
                                    std::shared_ptr<const MotionTableSpline>>;

    explicit MotionDesign(DesignSpec spec) : m_spec(std::move(spec)) {}
    static Result<MotionDesign> assemble(const DesignSpec& spec, bool jointsMustFit);
    /// Lift and derivatives in segment k at φ (rad within [start, end]).
    [[nodiscard]] std::array<double, 4> inSegment(std::size_t k, double phi) const;

    DesignSpec m_spec;
    std::vector<double> m_startRad, m_endRad, m_startLift;
    std::vector<SegmentLaw> m_laws;
    Diagnostics m_jumps;
    double m_zero = 1e-9;
};

}  // namespace cam
