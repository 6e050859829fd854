#pragma once
/// @file
/// @brief A conjugate cam pair (issue 32, `closure: conjugate`): two plates on one shaft drive
/// two rollers on one follower, the first plate the contour, the second computed so that its
/// roller touches it at every angle while the first roller touches the first plate. On a
/// translating roller the yoke: the second roller on the follower's line, `distance` behind
/// the first (on the far side of the cam), its centre on P(φ) = (s(φ) − D)·u(φ) + e·n(φ) in
/// the cam frame (u along the line, n its left normal, s the first roller's coordinate). On a
/// swinging arm the bell crank: a second arm of length L₂ on the same pivot Q(φ), turned by β
/// from the first, its roller on P(φ) = Q(φ) + L₂·(cos(θ + β), sin(θ + β)) with θ = φ + ψ(φ)
/// the first arm's direction. The second plate is that path offset towards the cam centre by
/// the second roller's radius, fitted by G1 arcs within the tolerance (design/arc_fit.h, the
/// synthesis machinery).

#include <array>
#include <atomic>
#include <optional>
#include <vector>

#include "closure/groove.h"
#include "common/angles.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "design/arc_fit.h"
#include "follower/follower.h"
#include "project/project.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief The second roller of a conjugate pair and what carries it: a translating yoke, or a
/// swinging arm's bell crank (armLengthMm > 0).
struct SecondRoller {
    double distanceMm = 0.0;      ///< a yoke: from the first roller's centre, back along the line
    double rollerRadiusMm = 0.0;  ///< the second roller's radius
    double armAngleRad = 0.0;     ///< a bell crank: the second arm's turn from the first (ccw)
    double armLengthMm = 0.0;     ///< a bell crank: from the pivot to the second roller's centre

    [[nodiscard]] bool bellCrank() const { return armLengthMm > 0.0; }
    /// @brief The follower's second roller (`closure: conjugate`); none for another closure.
    [[nodiscard]] static std::optional<SecondRoller> of(const FollowerSpec& follower) {
        if (!follower.conjugate()) return std::nullopt;
        if (follower.motion == FollowerMotion::Oscillating) {
            return SecondRoller{0.0, follower.conjugateRadius, degToRad(follower.conjugateAngleDeg),
                                follower.conjugateArmLength};
        }
        return SecondRoller{follower.conjugateDistance, follower.conjugateRadius};
    }
    /// @brief The project's second roller; none without a follower or for another closure.
    [[nodiscard]] static std::optional<SecondRoller> of(const Project& project) {
        return project.follower ? of(*project.follower) : std::nullopt;
    }
};

/// @brief The tolerance a project's second plate is fitted within: its motion design's, else
/// 0.001 mm (a drawing's default, export/dxf.h).
[[nodiscard]] inline double conjugateTolerance(const Project& project) {
    return project.design ? project.design->tolerance : 1e-3;
}

/// @brief The second plate and how well it holds the second roller.
struct ConjugatePlate {
    ArcFit fit;  ///< the plate's G1 arcs, counter-clockwise round the cam
    /// The same arcs as a contour table (design/synthesis.h contourOfArcs): the second plate,
    /// for every check, drawing and export a contour has.
    std::vector<SegmentSpec> contour;
    /// The same arcs as a path of lines and arcs (for drawings: export/dxf.h PLATE_2).
    ToolPath path;
    /// The play between the second roller and the fitted plate over the turn, with the first
    /// roller on the first plate: distance from the roller's centre to the arcs less its radius
    /// (mm): the largest gap and the deepest interference (negative), and where (rad).
    double maxPlay = 0.0, maxPlayAt = 0.0;
    double minPlay = 0.0, minPlayAt = 0.0;
    /// The largest pressure angle at the second roller over the turn (rad, signed as
    /// ConjugatePoint::pressureAngle; the largest magnitude), and the cam angle (rad).
    double maxPressureAngle = 0.0, maxPressureAt = 0.0;
    /// The plate's tightest arcs, convex and concave (closure/groove.h PathBends: the arc's
    /// radius), exact for what is milled. `phi` is here the cam angle in the middle of the
    /// stretch the arc stands for and `point` where the second roller touches the plate then,
    /// not its polar angle (the second plate is touched across the centre from the first).
    PathBends bends;
};

/// @brief The second roller's centre and the second plate's point at cam angle φ, with the
/// plate's derivative by φ: exact, from `first` (a translating roller on the first plate).
struct ConjugatePoint {
    Eigen::Vector2d centre{0.0, 0.0};
    /// A yoke's D − s: how far the second roller's centre is beyond the first's foot (+∞ on a
    /// bell crank).
    double behind = 0.0;
    /// cross(P, P') of the centre's path: positive where it runs counter-clockwise round the
    /// cam centre, as the plate must.
    double roundCentre = 0.0;
    Eigen::Vector2d plate{0.0, 0.0};
    Eigen::Vector2d plateTangent{1.0, 0.0};
    /// 1 − ρ₂·κ of the centre's path: where it is not positive the plate folds (undercut).
    double spread = 1.0;
    /// The plate's radius of curvature at the contact (mm, positive where it bends round the
    /// cam centre, +∞ where straight): the centre path's 1/κ less ρ₂.
    double rhoPlate = 0.0;
    /// The pressure angle at the second roller (rad): from the direction its centre moves when
    /// it leaves its plate (a yoke's: −u, along the line towards the cam; a bell crank's:
    /// across the second arm) to the contact normal (from the plate to the roller's centre),
    /// counter-clockwise positive.
    double pressureAngle = 0.0;
};
[[nodiscard]] ConjugatePoint conjugatePoint(const FollowerModel& first, const SecondRoller& yoke,
                                            double phi);
/// @brief The same from the first follower's coordinate q(φ) (s in mm, or ψ in rad) and its
/// first two derivatives by φ (per rad), `first` its spec: what a sampled turn holds
/// (FollowerTurn's s, v/ω, a/ω²).
[[nodiscard]] ConjugatePoint conjugatePointOf(double phi, const std::array<double, 3>& sPhi,
                                              const FollowerSpec& first, const SecondRoller& yoke);

/// @brief How many equal steps of the turn conjugateProblems checks the second roller at.
inline constexpr int kConjugateCheckSamples = 3600;

/// @brief Why the second plate for `yoke` behind `first` cannot be made, each at its key: a
/// first follower that is not a roller, a second roller, distance or arm that is not a
/// positive length, a distance that does not put the second roller beyond the cam centre at
/// every angle, a second roller that does not run round the cam centre with the cam (a plate
/// that is not a cam), a plate that folds (its roller too large for the path's bend) —
/// checked at kConjugateCheckSamples angles. Empty: conjugatePlate can fit it. Part of the one
/// verdict (evaluation/evaluation.h), so cheap: about 0.1 µs … 4 µs an angle (arcs … splines).
[[nodiscard]] Diagnostics conjugateProblems(const FollowerModel& first, const SecondRoller& yoke);

/// @brief The second plate for `yoke` behind the translating roller `first`, fitted within
/// `toleranceMm`, and its play over the turn measured at `samples` angles. Errors:
/// conjugateProblems', a fit that cannot meet the tolerance. None returned once `cancel` reads
/// true.
[[nodiscard]] Result<ConjugatePlate> conjugatePlate(const FollowerModel& first,
                                                    const SecondRoller& yoke, double toleranceMm,
                                                    int samples = 7200,
                                                    const std::atomic<bool>* cancel = nullptr);

/// @brief The second plate of `project` on `contour` (its compiled contour), when its follower
/// is a conjugate pair: the follower placed on the contour and conjugatePlate within
/// conjugateTolerance. None for another closure (or once `cancel` reads true); errors: why the
/// follower cannot ride the contour or the plate cannot be made. What every export of a pair
/// asks (the CLI's and the window's).
[[nodiscard]] Result<std::optional<ConjugatePlate>> secondPlateOf(
    const Project& project, const Contour& contour, const std::atomic<bool>* cancel = nullptr);

/// @brief The second plate as a contour of its own (its fitted arcs compiled), to be milled or
/// checked as any cam is.
[[nodiscard]] Result<Contour> plateContour(const ConjugatePlate& plate);

}  // namespace cam
