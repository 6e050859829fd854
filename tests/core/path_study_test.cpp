// The path study: on a cubic the central difference of the positions differs from x' by exactly
// h²/6·x''' (x''' is constant), and the second difference equals x'' (x'''' = 0) — the O(h²)
// agreement the seed compares, in closed form.

#include <gtest/gtest.h>

#include "spline/path_study.h"
#include "spline/teach_in.h"

namespace cam {
namespace {

TEST(PathStudy, DifferenceQuotientsDifferByTheClosedFormOfTheirError) {
    const std::vector<Eigen::Vector2d> knots{{0, 0}, {10, 8}, {22, 3}, {30, 12}};
    const auto spline = splineThroughPoints(knots, false, HandleRule::Oval);
    ASSERT_TRUE(spline.ok());
    for (int samples : {20, 80}) {
        const PathStudy s = studyPath(spline.value(), samples);
        const double h = s.step;
        ASSERT_EQ(s.t.size(), 3u * static_cast<std::size_t>(samples + 1));
        for (std::size_t i = 0; i < s.t.size(); ++i) {
            const std::size_t piece = i / static_cast<std::size_t>(samples + 1);
            const Eigen::Vector2d third = spline.value()[piece].derivative(0.0, 3);
            EXPECT_NEAR(s.quotient[PathStudy::DX][i] - s.analytic[PathStudy::DX][i],
                        h * h / 6.0 * third.x(), 1e-9);
            EXPECT_NEAR(s.quotient[PathStudy::DY][i] - s.analytic[PathStudy::DY][i],
                        h * h / 6.0 * third.y(), 1e-9);
            EXPECT_NEAR(s.quotient[PathStudy::DDX][i], s.analytic[PathStudy::DDX][i], 1e-7);
            EXPECT_NEAR(s.quotient[PathStudy::DDY][i], s.analytic[PathStudy::DDY][i], 1e-7);
            EXPECT_EQ(s.quotient[PathStudy::X][i], s.analytic[PathStudy::X][i]);
        }
    }
}

}  // namespace
}  // namespace cam
