// r(phi) of arcs and lines, and every analytic derivative against a central finite difference
// of the derivative one order below, on both arc branches and on lines, at many angles.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

/// Central difference of f at x with step h: error O(h²·f''').
template <class F>
double centralDiff(const F& f, double x, double h) {
    return (f(x + h) - f(x - h)) / (2.0 * h);
}

/// Checks r', r'', r''' against central differences of r, r', r'' at phi.
template <class Eval>
void expectDerivativesMatchFiniteDifferences(const Eval& eval, double phi, double scale) {
    const double h = 1e-5;
    const PolarDerivatives d = eval(phi);
    const double fd1 = centralDiff([&](double p) { return eval(p).r; }, phi, h);
    const double fd2 = centralDiff([&](double p) { return eval(p).dr; }, phi, h);
    const double fd3 = centralDiff([&](double p) { return eval(p).d2r; }, phi, h);
    // Truncation ~h²·(next derivative) ≈ 1e-10·scale; rounding ~1e-16·scale/h ≈ 1e-11·scale.
    EXPECT_TRUE(relClose(d.dr, fd1, 1e-7, scale)) << "r' at phi=" << phi;
    EXPECT_TRUE(relClose(d.d2r, fd2, 1e-7, scale)) << "r'' at phi=" << phi;
    EXPECT_TRUE(relClose(d.d3r, fd3, 1e-7, scale)) << "r''' at phi=" << phi;
}

struct ArcCase {
    Eigen::Vector2d center;
    double radius;
    Branch branch;
    double phiLo, phiHi;  // degrees inside which the ray meets the circle well away from tangency
};

class ArcDerivatives : public ::testing::TestWithParam<ArcCase> {};

TEST_P(ArcDerivatives, AgreeWithFiniteDifferences) {
    const ArcCase& c = GetParam();
    const Arc arc{c.center, c.radius, c.branch};
    for (int i = 0; i <= 40; ++i) {
        const double phi = degToRad(c.phiLo + (c.phiHi - c.phiLo) * i / 40.0);
        const double scale = arc.evaluate(phi).r;
        expectDerivativesMatchFiniteDifferences([&](double p) { return arc.evaluate(p); }, phi,
                                                scale);
    }
}

INSTANTIATE_TEST_SUITE_P(
    BothBranches, ArcDerivatives,
    ::testing::Values(
        // Origin outside the circle (seed lobes/notches), both branches. The ray meets the
        // circle within ±asin(R/|c|) of the centre's angle; the windows stay 2–3° inside that,
        // away from the tangent rays where r' grows without bound.
        ArcCase{{18.09717650199676, 10.448409724999998}, 8.10318055, Branch::Outer, 10, 50},
        ArcCase{{18.09717650199676, 10.448409724999998}, 8.10318055, Branch::Inner, 10, 50},
        ArcCase{{25.73752542, 0.0}, 4.84070597, Branch::Inner, -8, 8},
        ArcCase{{-30.0, 12.0}, 9.0, Branch::Outer, 145, 171},
        ArcCase{{-30.0, 12.0}, 9.0, Branch::Inner, 145, 171},
        // origin inside the circle: the outer branch is defined all the way round
        ArcCase{{3.0, -2.0}, 40.0, Branch::Outer, -180, 180},
        ArcCase{{0.0, 0.0}, 12.5, Branch::Outer, 0, 360}));

TEST(Arc, MatchesEccentricCircleClosedForm) {
    // Centre (e, 0), radius R > e: r = e·cosφ + sqrt(R² - e²·sin²φ), and by direct
    // differentiation r' = -e·sinφ - e²·sin2φ/(2q), r'' = -e·cosφ - e²·cos2φ/q - e⁴·sin²2φ/(4q³).
    const double e = 7.0, rad = 25.0;
    const Arc arc{{e, 0.0}, rad, Branch::Outer};
    for (int i = 0; i < 72; ++i) {
        const double phi = degToRad(5.0 * i + 0.3);
        const double q = std::sqrt(rad * rad - e * e * std::sin(phi) * std::sin(phi));
        const double r = e * std::cos(phi) + q;
        const double r1 = -e * std::sin(phi) - e * e * std::sin(2 * phi) / (2 * q);
        const double r2 = -e * std::cos(phi) - e * e * std::cos(2 * phi) / q -
                          std::pow(e, 4) * std::pow(std::sin(2 * phi), 2) / (4 * q * q * q);
        const PolarDerivatives d = arc.evaluate(phi);
        EXPECT_TRUE(relClose(d.r, r, 1e-14, rad));
        EXPECT_TRUE(relClose(d.dr, r1, 1e-13, rad));
        EXPECT_TRUE(relClose(d.d2r, r2, 1e-13, rad));
    }
}

TEST(Arc, InnerBranchIsTheNearIntersection) {
    const Arc outer{{30.0, 0.0}, 5.0, Branch::Outer};
    const Arc inner{{30.0, 0.0}, 5.0, Branch::Inner};
    EXPECT_DOUBLE_EQ(outer.evaluate(0.0).r, 35.0);
    EXPECT_DOUBLE_EQ(inner.evaluate(0.0).r, 25.0);
    // Both intersection points lie on the circle at every angle inside the window.
    for (double deg = -9.0; deg <= 9.0; deg += 1.5) {
        const double phi = degToRad(deg);
        for (const Arc& a : {outer, inner}) {
            const Eigen::Vector2d p =
                a.evaluate(phi).r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
            EXPECT_NEAR((p - a.center).norm(), 5.0, 1e-12);
        }
    }
}

struct LineCase {
    Eigen::Vector2d from, to;
};

class LineDerivatives : public ::testing::TestWithParam<LineCase> {};

TEST_P(LineDerivatives, AgreeWithFiniteDifferencesAndLieOnTheLine) {
    const Line line{GetParam().from, GetParam().to};
    const double a0 = std::atan2(line.from.y(), line.from.x());
    double a1 = std::atan2(line.to.y(), line.to.x());
    if (a1 < a0) a1 += kTwoPi;
    for (int i = 0; i <= 30; ++i) {
        const double phi = a0 + (a1 - a0) * i / 30.0;
        const PolarDerivatives d = line.evaluate(phi);
        const Eigen::Vector2d p = d.r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
        const Eigen::Vector2d ab = line.to - line.from;
        const double cross = ab.x() * (p - line.from).y() - ab.y() * (p - line.from).x();
        EXPECT_NEAR(cross / ab.norm(), 0.0, 1e-12);  // on the line
        expectDerivativesMatchFiniteDifferences([&](double x) { return line.evaluate(x); }, phi,
                                                d.r);
    }
}

INSTANTIATE_TEST_SUITE_P(Lines, LineDerivatives,
                         ::testing::Values(LineCase{{20.0, -5.0}, {20.0, 15.0}},
                                           LineCase{{16.2, 11.7}, {5.3, 23.6}},
                                           LineCase{{-10.0, -3.0}, {-2.0, -12.0}},
                                           LineCase{{30.0, 30.0}, {-30.0, 31.0}}));

}  // namespace
}  // namespace cam
