// Splines as tool paths: biarcs within tolerance (measured from the arcs back to the curve, the
// other direction from the fitter's own check), tangent throughout, exact ends; a spline contour
// offset by ρ grows by 2πρ; the planner does not stop at the smooth joints.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "spline/teach_in.h"
#include "timing/machining_time.h"
#include "toolpath/biarc.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

const CubicBezier kCurve{{Vec(0, 0), Vec(12, 14), Vec(25, -6), Vec(36, 8)}};  // an S-curve

void expectTangentChain(const std::vector<PathSegment>& segs, double tol = 1e-9) {
    for (std::size_t i = 0; i + 1 < segs.size(); ++i) {
        EXPECT_LT((segs[i].end - segs[i + 1].start).norm(), 1e-9) << i;
        EXPECT_GT(segs[i].tangent(segs[i].length()).dot(segs[i + 1].tangent(0.0)), 1.0 - tol) << i;
    }
}

TEST(Biarc, FollowsTheCurveWithinToleranceAndStaysTangent) {
    for (double tol : {1e-1, 1e-3, 1e-5}) {
        const auto segs = biarcsOf(kCurve, tol);
        ASSERT_GE(segs.size(), 2u);
        expectTangentChain(segs);
        EXPECT_LT((segs.front().start.head<2>() - kCurve.p[0]).norm(), 1e-12);
        EXPECT_LT((segs.back().end.head<2>() - kCurve.p[3]).norm(), 1e-12);
        EXPECT_GT(segs.front().tangent(0.0).head<2>().dot(kCurve.derivative(0.0, 1).normalized()),
                  1.0 - 1e-12);
        // Every point of the arcs lies within the tolerance of the curve (dense search).
        // Nearest point on the curve: a coarse grid, then ternary search around the best sample.
        auto distanceToCurve = [](const Vec& p) {
            int bestJ = 0;
            double best = 1e300;
            for (int j = 0; j <= 2000; ++j) {
                const double d = (kCurve.point(j / 2000.0) - p).squaredNorm();
                if (d < best) best = d, bestJ = j;
            }
            double lo = std::max(0.0, (bestJ - 1) / 2000.0),
                   hi = std::min(1.0, (bestJ + 1) / 2000.0);
            for (int it = 0; it < 100; ++it) {
                const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
                if ((kCurve.point(a) - p).squaredNorm() < (kCurve.point(b) - p).squaredNorm()) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            return (kCurve.point(0.5 * (lo + hi)) - p).norm();
        };
        double worst = 0.0;
        for (const PathSegment& s : segs) {
            for (int i = 0; i <= 20; ++i) {
                worst = std::max(worst, distanceToCurve(s.point(s.length() * i / 20.0).head<2>()));
            }
        }
        EXPECT_LE(worst, tol * 1.05) << tol;
    }
}

TEST(Biarc, SplineContourOffsetGrowsByTwoPiRhoAndIsTangentThroughout) {
    const std::vector<Vec> knots{{20, 0}, {14, 15}, {-3, 22}, {-18, 9}, {-16, -12}, {5, -19}};
    Project p;
    p.contour = contourThroughPoints(knots, HandleRule::Oval).value();
    const Contour c = Contour::build(p).value();
    const auto zero = toolPathFromContour(c, 0.0);
    const auto offset = toolPathFromContour(c, 1.5);
    ASSERT_TRUE(zero.ok() && offset.ok());
    expectTangentChain(zero.value().segments, 1e-8);
    expectTangentChain(offset.value().segments, 1e-8);
    EXPECT_NEAR(offset.value().length() - zero.value().length(), kTwoPi * 1.5, 1e-3);
}

TEST(Biarc, ThePlannerRunsThroughTheSmoothJointsOfASplinePath) {
    const std::vector<Vec> knots{{0, 0}, {30, 20}, {60, 5}, {90, 25}};
    const ToolPath path =
        toolPathFromSpline(splineThroughPoints(knots, false, HandleRule::Oval).value(), 1e-3);
    MachineLimits lim;
    lim.accel = {500, 500, 200};
    lim.feedMax = 150;
    const auto optimal = machiningTime(path, lim, TimingMethod::Optimal);
    const auto exact = machiningTime(path, lim, TimingMethod::ExactStop);
    ASSERT_TRUE(optimal.ok() && exact.ok());
    EXPECT_LT(optimal.value().timeS, 0.8 * exact.value().timeS);
    const auto& segs = optimal.value().segments;
    EXPECT_EQ(segs.front().entrySpeed, 0.0);
    EXPECT_EQ(segs.back().exitSpeed, 0.0);
    for (std::size_t i = 1; i < segs.size(); ++i) EXPECT_GT(segs[i].entrySpeed, 1.0) << i;
}

}  // namespace
}  // namespace cam
