#pragma once
/// @file
/// @brief The electronic cam for a servo drive (exports.md `camtable`): master angle → follower
/// lift, N equidistant points over one period.

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "design/motion_design.h"
#include "follower/follower.h"

namespace cam {

inline constexpr long long kDefaultCamTablePoints = 360;
inline constexpr long long kMinCamTablePoints = 4;
inline constexpr long long kMaxCamTablePoints = 1'000'000;

enum class CamTableDialect {
    Csv,         ///< exports.md's CSV: header comments, then master_deg,position,velocity,accel
    Codesys,     ///< IEC 61131-3 Structured Text: ARRAY OF SMC_CAMXYVA and its MC_CAM_REF
    Beckhoff,    ///< TwinCAT NC camming: ARRAY OF MC_MotionFunctionPoint, POLYNOM5_MM between
    Rockwell,    ///< Logix: a CAM array (Master, Slave, SegmentType cubic) filled in ST
    Kollmorgen,  ///< KAS IDE's cam profile import CSV (CYCLIC, TABLE_BEGIN, X;Y;SPLINE rows)
};

/// @brief Where a cam table's motion comes from (`--source`).
enum class CamTableSource {
    Law,      ///< the design's motion law, exact (MotionDesign::liftAt)
    Contour,  ///< the follower placed on the compiled contour (arcs: only C1 at their joints)
};

/// @brief The motion a table samples: the slave's lift and its first three derivatives per
/// master degree (mm, mm/°, mm/°², mm/°³; on a swinging arm degrees of swing per master degree)
/// at a master angle in degrees, any real (reduced into the turn).
struct CamMotion {
    std::function<std::array<double, 4>(double masterDeg)> at;
    bool armDegrees = false;  ///< the slave is a swinging arm's angle in degrees, not mm
    CamTableSource source = CamTableSource::Contour;
};

/// @brief The design's law as a table's motion: MotionDesign::liftAt, its derivatives per
/// radian times (π/180)^k. `armDegrees` for a swinging arm (its lifts are degrees of swing).
[[nodiscard]] CamMotion lawMotion(const MotionDesign& design, bool armDegrees);
/// @brief The follower placed on the contour as a table's motion (math.md §7: s(φ) − min s).
/// Errors: a follower that cannot be placed (located `follower.…`).
[[nodiscard]] Result<CamMotion> contourMotion(const Contour& contour, const FollowerSpec& follower);

struct CamTableOptions {
    std::size_t points = kDefaultCamTablePoints;
    CamTableDialect dialect = CamTableDialect::Csv;
    std::string name;       ///< the project's name (a comment in CSV, the variables' names in ST)
    FollowerSpec follower;  ///< whose lift the table holds (the project's; a knife by default)
};

/// @brief One knot of the table: master angle (deg), lift (mm) and its first three derivatives
/// per master degree.
struct CamKnot {
    double masterDeg = 0.0;
    double position = 0.0;      ///< mm
    double velocity = 0.0;      ///< mm/deg
    double acceleration = 0.0;  ///< mm/deg²
    double jerk = 0.0;          ///< mm/deg³
};

/// @brief The knots at master angles 360·i/N, i = 0 … N−1 (periodic: 360 is not repeated). The
/// lift is the follower's (math.md §7): s(φ) − min s over the turn, with its derivatives per
/// degree; for the default knife edge on the radial line r(φ) − min r.
[[nodiscard]] std::vector<CamKnot> camKnots(const FollowerModel& follower, std::size_t points);
/// @brief The knots of any motion, as above.
[[nodiscard]] std::vector<CamKnot> camKnots(const CamMotion& motion, std::size_t points);

/// @brief How the dialect's controller interpolates between the written knots: "quintic" (a
/// fifth-order polynomial matching position, velocity and acceleration at both knots: CSV,
/// CODESYS XYVA, Beckhoff POLYNOM5_MM), "cubic-spline-clamped" (Rockwell: a C2 cubic spline
/// through the REAL positions, its end slopes the motion's velocity) or "cubic-spline-periodic"
/// (Kollmorgen: a C2 cubic spline through the positions, periodic).
[[nodiscard]] const char* camTableInterpolation(CamTableDialect dialect);

/// @brief An extreme value of the motion and the master angle (deg) where it occurs.
struct CamExtreme {
    double value = 0.0;
    double atDeg = 0.0;
};

/// @brief The motion's characteristic values, like Beckhoff's MC_TableCharacValues: the
/// smallest and largest position, velocity, acceleration and jerk per master degree and where
/// they occur, sampled every 0.01° of master angle (36,000 samples).
struct CamCharacteristics {
    CamExtreme positionMin, positionMax;
    CamExtreme velocityMin, velocityMax;
    CamExtreme accelerationMin, accelerationMax;
    CamExtreme jerkMin, jerkMax;
};

/// @brief What a table of `points` knots in a dialect does: the largest differences between the
/// controller's interpolation of the written knots and the exact motion, evaluated at every
/// knot and 15 points evenly inside each interval (x_i + k·h/16, k = 1 … 15), with the master
/// angle of the worst position; and the motion's characteristics.
struct CamTableReport {
    std::size_t points = 0;
    const char* interpolation = "";
    double positionError = 0.0;  ///< mm (deg on a swinging arm)
    double positionErrorAtDeg = 0.0;
    double velocityError = 0.0;      ///< per master degree
    double accelerationError = 0.0;  ///< per master degree²
    CamCharacteristics characteristics;
};

/// @brief The report of a table of `options.points` knots of `motion` in `options.dialect`.
/// Errors: a point count outside [4, 1e6], located `--points`.
[[nodiscard]] Result<CamTableReport> camTableReport(const CamMotion& motion,
                                                    const CamTableOptions& options);

/// @brief A point count (from 4 to 1e6) whose interpolation error in `options.dialect` is at
/// most `toleranceMm`, one point fewer failing it. The error is not monotone in the count (it
/// drops where knots fall on the motion's joints), so every count is tried from 4 up while that
/// costs at most 4e6 evaluations of the motion (up to about 700 points): a count found there is
/// the smallest. Beyond, doubling and then bisection between the last count that failed and the
/// first that met it: a smaller count may meet it too. None when 1e6 points do not meet it.
[[nodiscard]] std::optional<std::size_t> camTablePointsFor(const CamMotion& motion,
                                                           const CamTableOptions& options,
                                                           double toleranceMm);

/// @brief The table and its report.
struct CamTable {
    std::string text;
    CamTableReport report;
};

/// @brief The table of `motion` in the dialect's text, with its report (the characteristics
/// are comments in the text, where the dialect has comments).
/// CSV: comment lines `# master_start_deg=0`, `# master_step_deg=…`, `# points=N`,
/// `# periodic=true`, `# slave=lift_mm`, `# source=law|contour`, the characteristics, then
/// `master_deg,position,velocity_per_deg,acceleration_per_deg2` and one row per knot, each number
/// the shortest text that reads back exactly (appendExact).
/// CODESYS: a VAR_GLOBAL block with `<name>_knots : ARRAY[0..N] OF SMC_CAMXYVA` (dX master deg,
/// dY lift mm, dV mm/deg, dA mm/deg²; the knot at 360° repeats the first, as a cam over
/// [xStart, xEnd] needs) and `<name> : MC_CAM_REF` with byType := 3 (XYVA polynomials),
/// byVarType := 6 (LREAL), nElements := N + 1, xStart := 0, xEnd := 360, pce := ADR(knots).
/// Beckhoff: a VAR_GLOBAL block with `<name> : ARRAY[1..N+1] OF MC_MotionFunctionPoint`, points
/// numbered 1 … N+1, each FunctionType := MOTIONFUNCTYPE_POLYNOM5_MM (15), PointType :=
/// MOTIONPOINTTYPE_MOTION, RelIndexNextPoint := 1, MasterPos deg, SlavePos, SlaveVelo,
/// SlaveAcc, SlaveJerk per master degree; the point at 360° repeats the first.
/// Rockwell: Logix Structured Text filling `<name>[0..N]` of data type CAM (Master, Slave :
/// REAL, SegmentType 1 = cubic); the values are rounded to REAL (single precision).
/// Kollmorgen: `CYCLIC;YES;`, `TABLE_BEGIN;;`, N+1 rows `X;Y;SPLINE`, `TABLE_END;;`.
/// `name` is the project's name made an IEC identifier.
/// Errors: a point count outside [4, 1e6], located `--points`.
[[nodiscard]] Result<CamTable> camTable(const CamMotion& motion, const CamTableOptions& options);

/// @brief camTable(contourMotion(contour, options.follower), options).text: the table of the
/// follower on the contour. Errors: camTable's, and a follower that cannot be placed (located
/// `follower.…`).
[[nodiscard]] Result<std::string> camTableText(const Contour& contour,
                                               const CamTableOptions& options);

}  // namespace cam
