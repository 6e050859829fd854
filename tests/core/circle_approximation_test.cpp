// Arcs as Bézier pieces: every point of every piece within the requested radial error of the
// circle (checked densely, independently of how the pieces were chosen), the classic κ values,
// and an arc of a real contour replaced without opening a joint.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "io/project_json.h"
#include "project/validate.h"
#include "spline/circle_approximation.h"
#include "test_support.h"

namespace cam {
namespace {

double worstRadialError(const ArcApproximation& a, const Eigen::Vector2d& c, double R) {
    double worst = 0.0;
    for (const CubicBezier& b : a.pieces) {
        for (int i = 0; i <= 4000; ++i) {
            worst = std::max(worst, std::abs((b.point(i / 4000.0) - c).norm() - R));
        }
    }
    return worst;
}

TEST(CircleApproximation, QuarterCircleHasTheClassicErrorAndSpeedRatio) {
    const ArcApproximation a = approximateArc({0, 0}, 10.0, 0.0, kPi / 2, 1e-2);
    ASSERT_EQ(a.pieces.size(), 1u);
    EXPECT_NEAR(a.radialErrorMm, 10.0 * 2.7253e-4, 1e-7);
    const double kappa = 4.0 / 3.0 * std::tan(kPi / 8.0);
    EXPECT_NEAR(a.speedRatio, kappa / (std::sqrt(2.0) * (0.5 - kappa / 4.0)), 1e-12);
}

TEST(CircleApproximation, MeetsAnyRequestedErrorWithTheFewestPieces) {
    const Eigen::Vector2d c(3, -2);
    for (double tol : {1e-2, 1e-4, 1e-6, 1e-8}) {
        const ArcApproximation a = approximateArc(c, 25.0, 0.3, 4.0, tol);
        EXPECT_LE(worstRadialError(a, c, 25.0), tol * 1.0001) << tol;
        EXPECT_NEAR(a.radialErrorMm, worstRadialError(a, c, 25.0), tol * 1e-3) << tol;
        // One piece fewer would not do: the error grows with the opening angle.
        if (a.pieces.size() > 1) {
            const double n = static_cast<double>(a.pieces.size()) - 1.0;
            EXPECT_GT(bezierArcRadialError(4.0 / n) * 25.0, tol) << tol;
        }
        // The pieces join end to start exactly on the circle.
        for (std::size_t i = 0; i + 1 < a.pieces.size(); ++i) {
            EXPECT_LT((a.pieces[i].p[3] - a.pieces[i + 1].p[0]).norm(), 1e-12);
        }
    }
}

TEST(CircleApproximation, ReplacesAContourArcKeepingItsJoints) {
    const Project p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value();
    for (std::size_t k : {0u, 1u, 12u}) {  // a notch, a lobe, the last piece of the notch at 0°
        ArcApproximation report;
        const auto replaced = approximateArcSegment(p.contour, k, 1e-4, &report);
        ASSERT_TRUE(replaced.ok()) << replaced.errors().front().text();
        Project q = p;
        q.contour = replaced.value();
        EXPECT_TRUE(validateProject(q).empty()) << validateProject(q).front().text();
        EXPECT_EQ(q.contour.size(), p.contour.size() + report.pieces.size() - 1);
        // r along the replaced window stays within the error of the original arc's r.
        const Contour before = Contour::build(p).value(), after = Contour::build(q).value();
        const double a = degToRad(p.contour[k].phiStartDeg), b = degToRad(p.contour[k].phiEndDeg);
        for (int i = 1; i < 200; ++i) {
            const double phi = a + (b - a) * i / 200.0;
            EXPECT_NEAR(after.evaluate(phi).r, before.evaluate(phi).r, 2e-4) << k << " " << i;
        }
    }
    EXPECT_FALSE(approximateArcSegment(p.contour, 3, 0.0).ok());
}

TEST(CircleApproximation, AnArcItsWindowMissesIsRefusedAtThatEnd) {
    // Lobe 1 (centre (18.1, 10.4), window 9.7°..50.3°) shrunk to 1 mm: the ray at 9.7° passes
    // the circle, the one at 50.3° too. At e144d2b the sweep became NaN and was cast to int.
    Project p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value();
    p.contour[1].as<Arc>()->radius = 1.0;
    const auto refused = approximateArcSegment(p.contour, 1, 1e-3);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.errors().front().text(),
              "contour[1].phi_start: the ray at the window's start does not meet the arc");
}

}  // namespace
}  // namespace cam
