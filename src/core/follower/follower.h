#pragma once
/// @file
/// @brief The follower placed on the cam profile by contact (math.md §7): knife edge, roller and
/// flat face on a translating line with offset e. s and its first three derivatives are exact to
/// rounding: closed form on arcs, lines and the roller's circles round the joints; on splines
/// the contact condition is differentiated (follower/jet.h).

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "project/project.h"

namespace cam {

/// @brief The follower at one cam angle. Frame: the cam frame of math.md §1; the follower's line
/// of motion is {e·n + s·u} with u = (cos φ, sin φ), n = (−sin φ, cos φ).
struct FollowerState {
    double phi = 0.0;  ///< rad
    /// s, ds/dφ, d²s/dφ², d³s/dφ³ (mm, mm/rad, …). For the flat face s is the support function.
    std::array<double, 4> sPhi{};
    double s = 0.0;  ///< mm, along the line from its foot e·n
    double v = 0.0;  ///< mm/s (ω constant)
    double a = 0.0;  ///< mm/s²
    double j = 0.0;  ///< mm/s³
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
    /// roller not narrower than a concave arc it must enter.
    [[nodiscard]] static Result<FollowerModel> build(const Contour& contour,
                                                     const FollowerSpec& spec);

    /// @brief The follower at cam angle φ (any real) turning at ω rad/s.
    [[nodiscard]] FollowerState at(double phi, double omega) const;
    /// @brief The smallest s over one turn (lift = s − minS()), to rounding.
    [[nodiscard]] double minS() const { return m_minS; }
    [[nodiscard]] const FollowerSpec& spec() const { return m_spec; }

    /// @brief One piece of the curve the follower point runs on: the profile (knife), its
    /// offset by the roller radius (roller: arcs, lines, splines and a circle round every
    /// joint) or the profile's convex parts and corners (flat face).
    struct Piece {
        enum class Kind { Circle, Line, Spline, Vertex } kind = Kind::Circle;
        std::size_t segment = 0;
        // Circle: centre, radius of the pitch circle, span from angle `start` by `sweep` (signed,
        // 2π for a whole circle), `convex` when the cam lies on the centre's side.
        Eigen::Vector2d center{0.0, 0.0};
        double radius = 0.0;
        double start = 0.0;
        double sweep = 0.0;
        bool convex = true;
        // Line: from q0 to q1 (offset), outward unit normal m.
        Eigen::Vector2d q0{0.0, 0.0}, q1{0.0, 0.0}, m{0.0, 0.0};
        // Spline: power-basis coefficients of p(τ), τ in [tLow, tHigh]; `orientation` +1 when
        // τ runs with the contour, −1 against it.
        std::array<Eigen::Vector2d, 4> coeff{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                             Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
        double tLow = 0.0, tHigh = 1.0;
        double orientation = 1.0;
    };

private:
    struct Candidate;
    void crossings(double phi, std::vector<Candidate>& out) const;
    void supports(double phi, std::vector<Candidate>& out) const;
    [[nodiscard]] Candidate best(double phi) const;

    FollowerSpec m_spec;
    std::vector<Piece> m_pieces;
    double m_phiBegin = 0.0;
    double m_minS = 0.0;
};

}  // namespace cam
