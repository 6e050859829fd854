#pragma once
/// @file
/// @brief The contour as the engine sees it: segments with polar windows in radians.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "geometry/arc.h"
#include "geometry/bezier.h"
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
    CubicBezier::Kernel bezierKernel;  ///< Bézier and Hermite segments
    double phiStart = 0.0;
    double phiEnd = 0.0;

    [[nodiscard]] PolarDerivatives evaluate(double cosPhi, double sinPhi) const {
        switch (type) {
            case SegmentType::Arc:
                return arcKernel(cosPhi, sinPhi);
            case SegmentType::Line:
                return lineKernel(cosPhi, sinPhi);
            default:
                return bezierKernel(cosPhi, sinPhi, splineHint(cosPhi, sinPhi));
        }
    }
    /// @brief Where along a spline the ray at this direction should meet it: the angle's place in
    /// the window. Chooses between hits at the window ends, where a ray may touch the curve again.
    [[nodiscard]] double splineHint(double cosPhi, double sinPhi) const {
        const double width = phiEnd - phiStart;
        const double mid = 0.5 * (phiStart + phiEnd);
        // Angle relative to the window's middle, in (-π, π].
        const double rel = std::atan2(sinPhi * std::cos(mid) - cosPhi * std::sin(mid),
                                      cosPhi * std::cos(mid) + sinPhi * std::sin(mid));
        return 0.5 + rel / width;
    }

    /// @brief The segment's own formula at phi, also just outside its window (one-sided limits).
    [[nodiscard]] PolarDerivatives evaluate(double phi) const;
};

/// @brief Why a project with no segments (a design waiting for its synthesis) has no contour:
/// "contour: is empty: the design's contour was never synthesised …".
[[nodiscard]] Diagnostic contourNeverSynthesised();

/// @brief A closed chain of segments whose windows are contiguous and cover one turn.
class Contour {
public:
    /// @brief Validates the document and compiles it; the errors are located.
    [[nodiscard]] static Result<Contour> build(const Project& project,
                                               ValidationOptions options = {});
    /// @brief Compiles a document whose segments validateProject found sound (with or without
    /// its joints checked); one with no segments gives contourNeverSynthesised().
    [[nodiscard]] static Result<Contour> buildValidated(const Project& project);

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
