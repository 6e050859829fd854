#pragma once
// Segments built and measured in the tests' own terms, independently of the implementation:
// arcs and lines with their windows, r(φ) from each curve's own formula (math.md §1), points
// and unit tangents of the polar curve, the project's validation of a bare contour.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <tuple>
#include <variant>
#include <vector>

#include "common/angles.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "project/validate.h"

namespace cam::test {

/// The polar angle of p, degrees in (−180, 180].
inline double polarDeg(const Eigen::Vector2d& p) { return radToDeg(std::atan2(p.y(), p.x())); }

inline const Arc& arcOf(const SegmentSpec& s) { return std::get<Arc>(s.shape); }
inline const Line& lineOf(const SegmentSpec& s) { return std::get<Line>(s.shape); }

/// A line with the window its end points give, starting near nearDeg.
inline SegmentSpec line(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double nearDeg) {
    SegmentSpec s{Line{from, to}};
    std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, nearDeg);
    return s;
}

inline SegmentSpec arc(const Eigen::Vector2d& center, double radius, Branch branch, double startDeg,
                       double endDeg) {
    return SegmentSpec{Arc{center, radius, branch}, startDeg, endDeg};
}

/// r(φ) and its derivatives of an arc or a line, from their own formulas.
inline PolarDerivatives polar(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    return s.type() == SegmentType::Arc ? arcOf(s).evaluate(phi) : lineOf(s).evaluate(phi);
}

/// Where the follower ray at φ meets the segment (arc or line).
inline Eigen::Vector2d pointOn(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    return polar(s, phiDeg).r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
}

/// Unit tangent dp/dφ of the segment's polar curve p = r·u: r'·u + r·u'.
inline Eigen::Vector2d tangentOn(const SegmentSpec& s, double phiDeg) {
    const double phi = degToRad(phiDeg);
    const PolarDerivatives d = polar(s, phiDeg);
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), u1(-std::sin(phi), std::cos(phi));
    return (d.dr * u + d.r * u1).normalized();
}

/// The project validation of a project holding nothing but this contour.
inline Diagnostics validate(const std::vector<SegmentSpec>& contour) {
    Project p;
    p.contour = contour;
    return validateProject(p);
}

/// The contour validates without a single message (the first one is shown otherwise).
inline void expectValid(const std::vector<SegmentSpec>& contour) {
    const Diagnostics d = validate(contour);
    EXPECT_TRUE(d.empty()) << d.front().text();
}

}  // namespace cam::test
