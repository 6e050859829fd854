// The cam table's interpolation error (export/cam_table.h) against the error theory of the
// interpolants it models, on a motion whose derivatives are known in closed form: the slave
// y = sin(θ) with θ the master angle in radians, so d^k y/dθ_deg^k = (π/180)^k sin(θ + kπ/2).

#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "export/cam_table.h"

// Its own namespace: the unity build puts it beside other core tests.
namespace cam::cam_table_test {
namespace {

constexpr double kPerDeg = kPi / 180.0;

CamMotion sine() {
    return {[](double deg) {
                const double t = deg * kPerDeg;
                return std::array<double, 4>{std::sin(t), kPerDeg * std::cos(t),
                                             -kPerDeg * kPerDeg * std::sin(t),
                                             -kPerDeg * kPerDeg * kPerDeg * std::cos(t)};
            },
            false, CamTableSource::Law};
}

/// The quintic Hermite interpolant's error at the middle of a step h: f⁽⁶⁾ t³(1−t)³h⁶/6! with
/// t = 1/2, i.e. |f⁽⁶⁾| h⁶/46080 (the error of Hermite interpolation with triple nodes).
double quinticMidpointError(double stepDeg) { return std::pow(kPerDeg * stepDeg, 6) / 46080.0; }

// Fact: with 36 and 72 points the quintic dialects' worst position error is the Hermite error
// term at an interval's middle where |sin| is largest (within 1%), and it shrinks as h⁶.
TEST(CamTableInterpolation, TheQuinticsErrorIsHermitesErrorTerm) {
    for (const std::size_t n : {36u, 72u}) {
        CamTableOptions options;
        options.points = n;
        options.dialect = CamTableDialect::Beckhoff;
        const auto report = camTableReport(sine(), options);
        ASSERT_TRUE(report.ok());
        const double step = 360.0 / static_cast<double>(n);
        // The middles nearest 90°: 90 ± step/2 (n = 36, 72 have a knot at 90°).
        const double peak = std::sin((90.0 - step / 2.0) * kPerDeg);
        EXPECT_NEAR(report.value().positionError, quinticMidpointError(step) * peak,
                    0.01 * quinticMidpointError(step))
            << n;
        EXPECT_STREQ(report.value().interpolation, "quintic");
    }
}

// Fact: a C2 cubic spline through the points stays within 5/384·h⁴·max|f⁗| of the function
// (Hall and Meyer's bound for complete and periodic splines) and not far below it (the
// spline does not reproduce the sine); the Kollmorgen (periodic) and Rockwell (clamped,
// REAL values) splines are both within it, Rockwell adding a REAL's rounding.
TEST(CamTableInterpolation, TheSplinesKeepHallAndMeyersBound) {
    for (const auto dialect : {CamTableDialect::Kollmorgen, CamTableDialect::Rockwell}) {
        CamTableOptions options;
        options.points = 36;
        options.dialect = dialect;
        const auto report = camTableReport(sine(), options);
        ASSERT_TRUE(report.ok());
        const double h = 10.0 * kPerDeg;
        const double bound = 5.0 / 384.0 * std::pow(h, 4);
        EXPECT_LE(report.value().positionError, bound + 1e-7);
        EXPECT_GT(report.value().positionError, 0.1 * bound);
    }
}

// Fact: --tolerance's point count is the smallest that meets it: from the error term, the
// quintic needs h ≤ 180/π·(46080·T)^(1/6); the count found is the first N = 360/h beyond it
// (±1 for where the worst middle falls), and one point fewer does not meet T.
TEST(CamTableInterpolation, TheToleranceGivesTheFewestPoints) {
    CamTableOptions options;
    options.dialect = CamTableDialect::Codesys;
    for (const double tolerance : {1e-6, 1e-9}) {
        const auto n = camTablePointsFor(sine(), options, tolerance);
        ASSERT_TRUE(n.has_value());
        const double step = std::pow(46080.0 * tolerance, 1.0 / 6.0) / kPerDeg;
        EXPECT_NEAR(static_cast<double>(*n), std::ceil(360.0 / step), 1.0) << tolerance;
        options.points = *n - 1;
        EXPECT_GT(camTableReport(sine(), options).value().positionError, tolerance);
        options.points = *n;
        EXPECT_LE(camTableReport(sine(), options).value().positionError, tolerance);
    }
    EXPECT_FALSE(camTablePointsFor(sine(), options, 1e-300).has_value());
}

// Fact: the characteristics are the sine's extremes and where they occur (every 0.01°).
TEST(CamTableInterpolation, TheCharacteristicsAreTheMotionsExtremes) {
    CamTableOptions options;
    const auto report = camTableReport(sine(), options);
    ASSERT_TRUE(report.ok());
    const CamCharacteristics& c = report.value().characteristics;
    EXPECT_DOUBLE_EQ(c.positionMax.value, 1.0);
    EXPECT_DOUBLE_EQ(c.positionMax.atDeg, 90.0);
    EXPECT_DOUBLE_EQ(c.positionMin.atDeg, 270.0);
    EXPECT_DOUBLE_EQ(c.velocityMax.value, kPerDeg);
    EXPECT_DOUBLE_EQ(c.velocityMax.atDeg, 0.0);
    EXPECT_DOUBLE_EQ(c.accelerationMin.atDeg, 90.0);
    EXPECT_NEAR(c.jerkMax.value, std::pow(kPerDeg, 3), 1e-18);
    EXPECT_DOUBLE_EQ(c.jerkMax.atDeg, 180.0);
}

}  // namespace
}  // namespace cam::cam_table_test
