// Fit windows: boundaries move to where the neighbours meet, checked against constructions
// whose meeting points are known in closed form.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/fit_windows.h"
#include "io/project_json.h"
#include "project/validate.h"
#include "test_support.h"

namespace cam {
namespace {

TEST(FitWindows, RestoresTheSixLobeBoundariesFromRoughGuesses) {
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    std::vector<SegmentSpec> rough = p.value().contour;
    // Round every boundary to whole degrees, the way a designer might first type them.
    for (std::size_t k = 0; k + 1 < rough.size(); ++k) {
        const double r = std::round(rough[k].phiEndDeg);
        rough[k].phiEndDeg = r;
        rough[k + 1].phiStartDeg = r;
    }
    const auto fitted = fitWindows(rough);
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    // Neighbouring arcs are tangent at 30° ± 20.30859° + k·60° (math.md §3).
    const double expected[] = {9.69141, 50.30859, 69.69141};
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(fitted.value()[k].phiEndDeg, expected[k], 1e-5) << k;
    }
    EXPECT_NEAR(fitted.value().back().phiEndDeg, 360.0, 1e-6);
    Project fixed = p.value();
    fixed.contour = fitted.value();
    EXPECT_TRUE(validateProject(fixed).empty());
}

TEST(FitWindows, MovesLineEndsToTheirIntersections) {
    // A square from four lines whose end points overshoot: fitting puts them on the corners.
    std::vector<SegmentSpec> c(4);
    const Eigen::Vector2d corners[] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    for (int k = 0; k < 4; ++k) {
        const Eigen::Vector2d a = corners[k], b = corners[(k + 1) % 4];
        c[k].shape = Line{a + 0.2 * (a - b), b + 0.1 * (b - a)};  // 20 %, 10 % beyond corners
        c[k].phiStartDeg = -40.0 + 90.0 * k;
        c[k].phiEndDeg = 50.0 + 90.0 * k;
    }
    c[3].phiEndDeg = 320.0;
    const auto fitted = fitWindows(c);
    ASSERT_TRUE(fitted.ok());
    for (int k = 0; k < 4; ++k) {
        const Line& line = *fitted.value()[k].as<Line>();
        EXPECT_NEAR((line.from - corners[k]).norm(), 0.0, 1e-12) << k;
        EXPECT_NEAR((line.to - corners[(k + 1) % 4]).norm(), 0.0, 1e-12) << k;
        EXPECT_NEAR(fitted.value()[k].phiStartDeg, -45.0 + 90.0 * k, 1e-12) << k;
    }
    Project p;
    p.contour = fitted.value();
    EXPECT_TRUE(validateProject(p).empty()) << validateProject(p).front().text();
}

TEST(FitWindows, NamesAJointWhoseNeighboursDoNotMeet) {
    std::vector<SegmentSpec> c(2);
    c[0] = {Arc{{0, 0}, 10, Branch::Outer}, 0, 180};
    c[1] = {Arc{{0, 0}, 12, Branch::Outer}, 180, 360};
    const auto fitted = fitWindows(c);
    ASSERT_FALSE(fitted.ok());
    EXPECT_EQ(fitted.errors().front().location, "contour[0]/contour[1]");
}

}  // namespace
}  // namespace cam
