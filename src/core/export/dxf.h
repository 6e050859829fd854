#pragma once
/// @file
/// @brief The profile as a DXF drawing (exports.md): R2000 (AC1015), millimetres, the contour as
/// true LINE and ARC entities.

#include <optional>
#include <string>

#include "closure/groove.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief How splines become DXF entities, and a drawing's default tolerance, mm.
inline constexpr double kDefaultExportToleranceMm = 0.001;

struct DxfOptions {
    /// Bézier and Hermite segments as tangent arc pairs within this distance, mm (> 0).
    double toleranceMm = kDefaultExportToleranceMm;
    /// Layer CONTOUR as one closed LWPOLYLINE with bulges instead of LINE/ARC entities (splines
    /// as their arc pairs there, whatever `splineEntities` says).
    bool polyline = false;
    /// Bézier and Hermite segments as exact SPLINE entities (degree 3) instead of arc pairs.
    bool splineEntities = false;
    /// Layer CENTRES: a POINT at the centre of every arc of the profile.
    bool centres = false;
    /// Layer TOOLPATH: the tool-centre path for this tool radius (mm, > 0), LINE and ARC.
    std::optional<double> toolRadiusMm;
    /// A grooved cam (closure/groove.h): the contour on layer FLANK_INNER instead of CONTOUR,
    /// the outer flank on FLANK_OUTER and the roller's pitch curve on PITCH, LINE and ARC
    /// entities (arcs stay arcs; splines' offsets as tangent arcs within the tolerance).
    std::optional<GrooveSize> groove;
    /// A conjugate pair (closure/conjugate.h): the contour on layer PLATE_1 instead of
    /// CONTOUR, this second plate (its fitted lines and arcs) on PLATE_2.
    std::optional<ToolPath> secondPlate;
};

/// @brief The DXF text (CRLF-free, "\n" line ends, C locale, numbers exact and shortest). Every
/// LINE/ARC of layer CONTOUR is one line or arc segment of the contour, exact to rounding; a
/// one-segment contour (a full circle) is a CIRCLE. Errors: a tolerance or tool radius out of
/// range (located `--tolerance`, `--tool-radius`), a tool path or groove that cannot be made
/// (located `contour[k]`).
[[nodiscard]] Result<std::string> dxfDocument(const Contour& contour, const DxfOptions& options);

}  // namespace cam
