#pragma once
/// @file
/// @brief The electronic cam for a servo drive (exports.md `camtable`): master angle → follower
/// lift, N equidistant points over one period.

#include <cstddef>
#include <string>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "follower/follower.h"

namespace cam {

inline constexpr long long kDefaultCamTablePoints = 360;
inline constexpr long long kMinCamTablePoints = 4;
inline constexpr long long kMaxCamTablePoints = 1'000'000;

enum class CamTableDialect {
    Csv,      ///< exports.md's CSV: header comments, then master_deg,position,velocity,accel
    Codesys,  ///< IEC 61131-3 Structured Text: ARRAY OF SMC_CAMXYVA and its MC_CAM_REF
};

struct CamTableOptions {
    std::size_t points = kDefaultCamTablePoints;
    CamTableDialect dialect = CamTableDialect::Csv;
    std::string name;       ///< the project's name (a comment in CSV, the variables' names in ST)
    FollowerSpec follower;  ///< whose lift the table holds (the project's; a knife by default)
};

/// @brief One knot of the table: master angle (deg), lift (mm) and its first two derivatives
/// per master degree.
struct CamKnot {
    double masterDeg = 0.0;
    double position = 0.0;      ///< mm
    double velocity = 0.0;      ///< mm/deg
    double acceleration = 0.0;  ///< mm/deg²
};

/// @brief The knots at master angles 360·i/N, i = 0 … N−1 (periodic: 360 is not repeated). The
/// lift is the follower's (math.md §7): s(φ) − min s over the turn, with its derivatives per
/// degree; for the default knife edge on the radial line r(φ) − min r.
[[nodiscard]] std::vector<CamKnot> camKnots(const FollowerModel& follower, std::size_t points);

/// @brief The table in the dialect's text. CSV: comment lines `# master_start_deg=0`,
/// `# master_step_deg=…`, `# points=N`, `# periodic=true`, `# slave=lift_mm`, then
/// `master_deg,position,velocity_per_deg,acceleration_per_deg2` and one row per knot, each number
/// the shortest text that reads back exactly (appendExact).
/// CODESYS: a VAR_GLOBAL block with `<name>_knots : ARRAY[0..N] OF SMC_CAMXYVA` (dX master deg,
/// dY lift mm, dV mm/deg, dA mm/deg²; the knot at 360° repeats the first, as a cam over
/// [xStart, xEnd] needs) and `<name> : MC_CAM_REF` with byType := 3 (XYVA polynomials),
/// byVarType := 6 (LREAL), nElements := N + 1, xStart := 0, xEnd := 360, pce := ADR(knots).
/// `name` is the project's name made an IEC identifier.
/// Errors: a point count outside [4, 1e6], located `--points`; a follower that cannot be placed
/// (located `follower.…`).
[[nodiscard]] Result<std::string> camTableText(const Contour& contour,
                                               const CamTableOptions& options);

}  // namespace cam
