#pragma once
/// @file
/// @brief The contour as the engine sees it: segments with polar windows in radians.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "project/project.h"
#include "project/validate.h"

namespace cam {

/// @brief One segment with its window [phiStart, phiEnd) in radians, ready to evaluate.
struct ContourSegment {
    SegmentType type = SegmentType::Arc;
    Arc arc;
    Line line;
    Arc::Kernel arcKernel;
    Line::Kernel lineKernel;
    double phiStart = 0.0;
    double phiEnd = 0.0;

    [[nodiscard]] PolarDerivatives evaluate(double cosPhi, double sinPhi) const {
        return type == SegmentType::Arc ? arcKernel(cosPhi, sinPhi) : lineKernel(cosPhi, sinPhi);
    }
    /// @brief The segment's own formula at phi, also just outside its window (one-sided limits).
    [[nodiscard]] PolarDerivatives evaluate(double phi) const;
};

/// @brief A closed chain of segments whose windows are contiguous and cover one turn.
class Contour {
public:
    /// @brief Validates the document and compiles it; the errors are located.
    [[nodiscard]] static Result<Contour> build(const Project& project,
                                               ValidationOptions options = {});

    [[nodiscard]] std::size_t size() const { return m_segments.size(); }
    [[nodiscard]] const ContourSegment& segment(std::size_t k) const { return m_segments[k]; }
    [[nodiscard]] const std::vector<ContourSegment>& segments() const { return m_segments; }

    /// @brief Start of the first window (rad); windows cover [phiBegin, phiBegin + 2π).
    [[nodiscard]] double phiBegin() const { return m_segments.front().phiStart; }

    /// @brief phi reduced into [phiBegin, phiBegin + 2π).
    [[nodiscard]] double normalize(double phi) const;

    /// @brief Index of the segment whose window holds phi (any real angle).
    [[nodiscard]] std::size_t segmentAt(double phi) const;

    /// @brief Index of the segment whose window holds an angle already normalized.
    [[nodiscard]] std::size_t segmentAtNormalized(double phiNormalized) const;

    /// @brief r(phi) and its derivatives from the segment that owns phi.
    [[nodiscard]] PolarDerivatives evaluate(double phi) const {
        return m_segments[segmentAt(phi)].evaluate(phi);
    }

private:
    std::vector<ContourSegment> m_segments;
};

}  // namespace cam
