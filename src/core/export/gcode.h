#pragma once
/// @file
/// @brief G-code that mills the cam from outside on a 3-axis machine (exports.md `gcode`).

#include <optional>
#include <string>

#include "closure/groove.h"
#include "common/diagnostic.h"
#include "contour/contour.h"

namespace cam {

/// @brief Splines become arcs this close to the curve in G-code, mm: a tenth of the 1e-4 mm to
/// which a program is checked, so that the 4-decimal rounding of a controller still fits.
inline constexpr double kDefaultGcodeToleranceMm = 1e-5;
/// @brief The total cut depth when none is given, mm.
inline constexpr double kDefaultGcodeDepthMm = 5.0;
/// @brief The height of the rapid moves above the stock (Z0) when none is given, mm.
inline constexpr double kDefaultGcodeSafeZMm = 5.0;
/// @brief A program has at most this many passes (depth / step-down).
inline constexpr long long kMaxGcodePasses = 10'000;

/// @brief Which way the cutter goes round the part, for a spindle turning clockwise (M3).
enum class MillingDirection {
    Climb,         ///< clockwise round the part (the material right of the cutter's travel)
    Conventional,  ///< counter-clockwise round the part
};

struct GcodeOptions {
    /// The cutter's radius, mm (> 0). The CLI takes the project's machining.tool_radius when the
    /// option is not given; without either it is an error there.
    double toolRadiusMm = 0.0;
    /// Feed along the profile, mm/min (the CLI: machining.feed_max × 60). Plunges go at half.
    double feedMmMin = 6000.0;
    /// Total depth of cut below the stock's top (Z0), mm (> 0).
    double depthMm = kDefaultGcodeDepthMm;
    /// Depth of each pass, mm (> 0): passes at Z −step, −2·step, …, −depth. None: one pass.
    std::optional<double> stepDownMm;
    /// Height of the rapid moves, mm (> 0).
    double safeZMm = kDefaultGcodeSafeZMm;
    /// Bézier and Hermite segments as tangent arc pairs within this distance, mm.
    double toleranceMm = kDefaultGcodeToleranceMm;
    /// Shown in the header comment.
    std::string projectName;
    /// Program the part contour itself with cutter compensation (G41 climb, G42 conventional)
    /// and the radius of tool `toolNumber` from the machine's tool table, instead of the
    /// tool-centre path. The lead-in and lead-out are then planned for `toolRadiusMm`.
    bool compensation = false;
    int toolNumber = 1;  ///< the D word of G41/G42, 1 … 99999
    MillingDirection direction = MillingDirection::Climb;
    /// Mill this groove: a tool of half its width (ρ + c/2) cuts it in one slot pass on its
    /// centre line; a narrower one (at least a sixth of the width) roughs there and then
    /// finishes each flank, the inner one climbing clockwise, the outer counter-clockwise.
    /// Every pass plunges on the centre line and moves sideways onto a flank's path: no lead
    /// arcs, nothing outside the groove is cut. Never with `compensation`.
    std::optional<GrooveSize> groove;
};

/// @brief The program, "\n" line ends, numbers in the C locale: `%`, header comments, `G21 G90
/// G91.1 G17 G94 G40`, then per pass a rapid at safe Z to the lead-in start, a plunge, a
/// quarter-turn tangent lead-in arc, the closed loop (G1 lines, G2/G3 arcs with incremental I/J,
/// never R; arcs of more than half a turn in halves, a full circle as two), a tangent lead-out
/// arc and a rapid retract; `M30`, `%`. The loop starts where the tool-centre path is farthest
/// from the rotation centre, so the lead arcs lie beyond a tangent of the whole part. X, Y, Z,
/// I and J have 6 decimals: every arc's I/J is taken from its printed start, so its printed end
/// lies on the circle to about 1e-6 mm. Under compensation the program starts G41/G42 with a
/// straight move onto the lead-in arc (programmed at the tool radius plus the lead radius) and
/// ends it with G40 and a straight move off the lead-out. Errors: an option out of range
/// (located `--tool-radius`, `--tolerance`, `--depth`, `--step-down`, or the field's name), a tool
/// too wide for a concave arc or corner (located `contour[k]`), and under compensation a concave
/// corner whose crossing lies beyond the next programmed arc of a spline (`contour[k]`), which a
/// controller's compensation would turn into a cut through the part. With `groove`, the
/// groove's program (GcodeOptions::groove), and a tool wider than the groove or too narrow to
/// clear it in three passes is an error (located `--tool-radius`).
[[nodiscard]] Result<std::string> gcodeProgram(const Contour& contour, const GcodeOptions& options);

}  // namespace cam
