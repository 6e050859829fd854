#pragma once
/// @file
/// @brief The profile as a 1:1 SVG drawing in millimetres (exports.md).

#include <optional>
#include <string>

#include "closure/groove.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "export/dxf.h"

namespace cam {

/// @brief The default spline tolerance of an SVG drawing, mm.
inline constexpr double kSvgToleranceMm = 1e-6;

struct SvgOptions {
    /// Bézier and Hermite segments as tangent arc pairs within this distance, mm: by default
    /// the 1e-6 mm to which exports.md holds the whole path.
    double toleranceMm = kSvgToleranceMm;
    /// Shown above the drawing and as its <title>.
    std::string title;
    /// A grooved cam (closure/groove.h): its outer flank as <path id="outer-flank"> beside the
    /// profile (the inner flank) and the roller's pitch curve dashed (<path id="pitch">).
    std::optional<GrooveSize> groove;
    /// A conjugate pair (closure/conjugate.h): its second plate's fitted lines and arcs as
    /// <path id="second-plate">, drawn as the profile (the first plate) is.
    std::optional<ToolPath> secondPlate;
};

/// @brief The SVG text: width, height and viewBox in mm (1 user unit = 1 mm); y up is drawn up
/// (SVG y = -y). The profile is one closed <path id="profile"> of M, L and A commands, exact
/// to 17 digits for arcs and lines; a cross marks the rotation centre and every arc's centre;
/// the title is a <text> above the drawing. Errors: a tolerance out of range.
[[nodiscard]] Result<std::string> svgDocument(const Contour& contour, const SvgOptions& options);

}  // namespace cam
