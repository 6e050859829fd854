#pragma once
/// @file
/// @brief The sampled turn as CSV (exports.md `csv`, the `sample` columns): written by
/// `camwright-cli sample`, `export --format csv` and the app's File → Export.

#include <optional>
#include <string>
#include <string_view>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "forces/forces.h"
#include "kinematics/kinematics.h"

namespace cam {

/// @brief The header line: time s, angle deg, segment index, then mm, mm/s, mm/s², mm/s³.
inline constexpr std::string_view kSampleCsvHeader =
    "t,phi_deg,segment,r,x,y,v_r,v_phi,v,a_r,a_phi,a,j_r,j_phi,j\n";

/// @brief The follower's columns that `export --format csv` adds after the `sample` columns
/// (exports.md): s and lift (mm), its velocity, acceleration and jerk along its line (mm/s,
/// mm/s², mm/s³), the signed pressure angle (deg) and the radii of curvature (mm; an empty cell
/// on a straight stretch, whose radius is infinite).
inline constexpr std::string_view kFollowerCsvColumns =
    "s,lift,follower_v,follower_a,follower_j,pressure_angle_deg,rho_profile,rho_pitch";
/// @brief The same for a swinging arm: ψ and lift in degrees, the arm's angular speed,
/// acceleration and jerk (rad/s, rad/s², rad/s³).
inline constexpr std::string_view kArmCsvColumns =
    "psi_deg,lift_deg,omega_arm,alpha_arm,jerk_arm,pressure_angle_deg,rho_profile,rho_pitch";

/// @brief The columns for this follower: kFollowerCsvColumns or kArmCsvColumns.
[[nodiscard]] std::string_view followerCsvColumns(const FollowerModel& follower);

/// @brief Appends "," and the follower's columns of sample k of `turn` (no line end).
void appendFollowerCsvColumns(std::string& out, const FollowerModel& follower,
                              const FollowerTurn& turn, std::size_t k);

/// @brief The forces' columns that `export --format csv` adds after the follower's when the
/// project has dynamics (math.md §9, cli.md's `forces` names): the load along the line (N; on
/// a swinging arm the moment, N·m), the contact normal force and (translating) the side force
/// (N), the camshaft's torque (N·m) and power (W), and the Hertz contact stress (MPa; an empty
/// cell for a knife edge or where the follower has left the cam).
inline constexpr std::string_view kForcesCsvColumns =
    "axial_N,normal_N,lateral_N,torque_Nm,power_W,contact_stress_MPa";
inline constexpr std::string_view kArmForcesCsvColumns =
    "moment_Nm,normal_N,torque_Nm,power_W,contact_stress_MPa";

/// @brief The forces' columns for this model: kForcesCsvColumns or kArmForcesCsvColumns.
[[nodiscard]] std::string_view forcesCsvColumns(const ForceModel& model);

/// @brief Appends "," and the forces' columns of sample k (no line end).
void appendForcesCsvColumns(std::string& out, const ForceModel& model, const ForceTurn& forces,
                            const FollowerTurn& turn, std::size_t k, double omega);

/// @brief A CSV of numbers (as sampleCsv writes) for a spreadsheet in a German locale: cells
/// separated by ";" and the decimal point written ",". Only for text whose cells hold numbers
/// and plain names (no quotes, no "." or "," inside a name). Never the default: every reader
/// of the file but such a spreadsheet expects the plain form.
[[nodiscard]] std::string forGermanSpreadsheets(std::string_view csv);

/// @brief The first sample holding a number that is not finite, located "sample K, COLUMN";
/// none when every value is finite (a turn too fast or too big for a double).
[[nodiscard]] std::optional<Diagnostic> firstNonFiniteSample(const SampledTurn& turn);

/// @brief Appends sample k as one line: each number the shortest text that reads back exactly,
/// in the C locale, never -0; the segment as an integer.
void appendSampleCsvRow(std::string& out, const SampledTurn& turn, std::size_t k);

/// @brief One turn at `points` instants t_k = k·T/points, header included; with a follower
/// its columns follow the `sample` ones, and with a force model (it needs the follower) the
/// forces' after those. Errors: a point count below 1, a value that is not finite.
[[nodiscard]] Result<std::string> sampleCsv(const Contour& contour, double omega,
                                            std::size_t points,
                                            const FollowerModel* follower = nullptr,
                                            const ForceModel* forces = nullptr);

}  // namespace cam
