#pragma once
/// @file
/// @brief The follower placed on the cam profile by contact (math.md §7): knife edge, roller and
/// flat face on a translating line with offset e; knife and roller on a swinging arm. s (or the
/// arm angle ψ) and its first three derivatives are exact to rounding: closed form on arcs,
/// lines and the roller's circles round the joints; on splines the contact condition is
/// differentiated (follower/jet.h). The swinging arm is in follower_arm.cpp.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/angles.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "project/project.h"

namespace cam {

/// @brief The follower at one cam angle. Frame: the cam frame of math.md §1; the follower's line
/// of motion is {e·n + s·u} with u = (cos φ, sin φ), n = (−sin φ, cos φ). A swinging arm's
/// pivot is the project's pivot A turned by φ, and its angle ψ is measured in the follower frame
/// (the cam frame at φ = 0) from +x, counter-clockwise.
struct FollowerState {
    double phi = 0.0;  ///< rad
    /// The follower's coordinate q and dq/dφ, d²q/dφ², d³q/dφ³: q = s (mm; the support function
    /// for the flat face) on a translating line, q = ψ (rad) on a swinging arm.
    std::array<double, 4> sPhi{};
    double s = 0.0;  ///< q: mm along the line from its foot e·n, or ψ in rad
    double v = 0.0;  ///< dq/dt (ω constant): mm/s, or the arm's angular speed in rad/s
    double a = 0.0;  ///< mm/s² or rad/s²
    double j = 0.0;  ///< mm/s³ or rad/s³
    /// Knife: the tip; roller: its centre; flat face: where the face crosses the line of motion.
    Eigen::Vector2d center{0.0, 0.0};
    Eigen::Vector2d contact{0.0, 0.0};  ///< the touching point of the profile
    Eigen::Vector2d normal{1.0, 0.0};   ///< the contact normal, out of the cam
    double pressureAngle = 0.0;         ///< rad; positive while the follower rises
    /// mm at the contact point, positive where convex; +∞ on a straight stretch.
    double rhoProfile = 0.0;
    /// mm at the centre (the profile's for knife and flat); +∞ on a straight stretch.
    double rhoPitch = 0.0;
    std::size_t segment = 0;  ///< the contour segment touched (its end: the joint)
};

/// @brief A follower on one contour, ready to be evaluated at any angle.
class FollowerModel {
public:
    /// @brief Places `spec` on `contour`. Errors (located "follower.…" or "contour[k]"): a
    /// roller not narrower than a concave arc it must enter; a swinging arm whose pivot comes
    /// inside the cam, or whose arm cannot touch the cam at some angle.
    [[nodiscard]] static Result<FollowerModel> build(const Contour& contour,
                                                     const FollowerSpec& spec);

    /// @brief The follower at cam angle φ (any real) turning at ω rad/s.
    [[nodiscard]] FollowerState at(double phi, double omega) const;
    /// @brief Translating: the smallest s over one turn (lift = s − minS()), to rounding.
    [[nodiscard]] double minS() const { return m_minRank; }
    /// @brief The lift and its φ-derivatives (per rad): s − min s in mm, or on a swinging arm
    /// the angle swung away from the cam from its closest position, in degrees.
    [[nodiscard]] std::array<double, 4> liftPhi(const FollowerState& state) const;
    [[nodiscard]] double lift(const FollowerState& state) const { return liftOf(state.s); }
    /// @brief The lift and its time derivatives (per s, s², s³) in the lift's unit and sense:
    /// mm, or on a swinging arm degrees swung away from the cam. `q` is FollowerState::s and
    /// `v`, `a`, `j` its time derivatives (FollowerState::v, a, j).
    [[nodiscard]] std::array<double, 4> liftMotion(double q, double v, double a, double j) const;
    [[nodiscard]] std::array<double, 4> liftMotion(const FollowerState& state) const {
        return liftMotion(state.s, state.v, state.a, state.j);
    }
    /// @brief The lift at the follower's coordinate q (FollowerState::s).
    [[nodiscard]] double liftOf(double q) const;
    [[nodiscard]] bool oscillating() const { return m_spec.motion == FollowerMotion::Oscillating; }
    /// @brief +1 when the arm swings away from the cam with growing ψ ("ccw"), −1 ("cw");
    /// +1 on a translating line.
    [[nodiscard]] double awaySign() const {
        return oscillating() && m_spec.arm == ArmSide::Cw ? -1.0 : 1.0;
    }
    [[nodiscard]] const FollowerSpec& spec() const { return m_spec; }

    /// @brief One piece of the curve the follower point runs on: the profile (knife), its
    /// offset by the roller radius (roller: arcs, lines, splines and a circle round every
    /// joint) or the profile's convex parts and corners (flat face).
    struct Piece {
        enum class Kind { Circle, Line, Spline, Vertex } kind = Kind::Circle;
        std::size_t segment = 0;
        // Circle: centre, radius of the pitch circle, span from angle `start` by `sweep` (signed,
        // 2π for a whole circle), `convex` when the cam lies on the centre's side. Vertex: the
        // outward normals it holds run from `start` by `sweep`.
        Eigen::Vector2d center{0.0, 0.0};
        double radius = 0.0;
        double start = 0.0;
        double sweep = 0.0;
        Eigen::Vector2d from{1.0, 0.0}, to{1.0, 0.0};  ///< unit directions at start and end
        bool convex = true;
        // Line: from q0 to q1 (offset), outward unit normal m.
        Eigen::Vector2d q0{0.0, 0.0}, q1{0.0, 0.0}, m{0.0, 0.0};
        // Spline: power-basis coefficients of p(τ), τ in [tLow, tHigh]; `orientation` +1 when
        // τ runs with the contour, −1 against it.
        std::array<Eigen::Vector2d, 4> coeff{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                             Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
        double tLow = 0.0, tHigh = 1.0;
        double orientation = 1.0;
        /// How far past its ends the piece still counts (rad for a circle, a fraction of the
        /// length for a line, τ for a spline): rounding, and at a joint that is tangent within
        /// kTangentToleranceDeg the gap the small break leaves between the neighbours' offsets
        /// (no corner circle is put there).
        double slack = 1e-9;
    };

private:
    friend class FollowerTurnSampler;  // follower_turn.cpp: the batch path walks the pieces
    struct Candidate;
    /// The pieces that can hold the contact at φ: a bin of the turn (see buildIndex).
    [[nodiscard]] std::span<const std::uint32_t> piecesAt(double phi) const;
    /// Sorts every piece into the bins of the cam angles at which the follower can touch it,
    /// so that one evaluation looks at a handful of pieces, not all of them.
    void buildIndex();
    /// The cam angles (unwrapped, lo ≤ hi) at which the follower can touch a piece.
    [[nodiscard]] std::vector<std::pair<double, double>> reach(const Piece& piece) const;

    /// u = (cos φ, sin φ) is passed in: one sincos per evaluation.
    void crossings(double phi, const Eigen::Vector2d& u, std::vector<Candidate>& out) const;
    void supports(double phi, const Eigen::Vector2d& u, std::vector<Candidate>& out) const;
    void armContacts(double phi, std::vector<Candidate>& out) const;  // follower_arm.cpp
    [[nodiscard]] double armRank(const Piece& piece, double phi) const;
    [[nodiscard]] Candidate best(double phi) const;
    /// best(phi).rank without the derivatives (an arm's contact found in doubles alone).
    [[nodiscard]] double rankAt(double phi) const;
    [[nodiscard]] Candidate best(double phi, const Eigen::Vector2d& u) const;
    [[nodiscard]] FollowerState armState(double phi, double omega, const Candidate& c) const;
    /// follower_arm.cpp: a pivot that comes inside the cam; why the arm finds no contact at φ.
    [[nodiscard]] Diagnostics checkPivot(const Contour& contour) const;
    [[nodiscard]] Diagnostics armUnreachable(const Contour& contour, double phi) const;

    FollowerSpec m_spec;
    std::vector<Piece> m_pieces;
    double m_phiBegin = 0.0;
    /// The smallest rank over the turn: s on a line, the arm's angle from the line pivot → cam
    /// centre on a swinging arm (rad, growing away from the cam).
    double m_minRank = 0.0;
    double m_pivotDirection = 0.0;  ///< β: the follower-frame angle from the pivot to the centre
    /// Bins of equal width over [m_phiBegin, m_phiBegin + 2π): bin b's pieces are
    /// m_binPieces[m_binOffsets[b] … m_binOffsets[b + 1]).
    double m_binWidth = kTwoPi;
    std::vector<std::uint32_t> m_binOffsets;
    std::vector<std::uint32_t> m_binPieces;
};

}  // namespace cam
