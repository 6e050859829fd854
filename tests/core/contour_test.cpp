// Window lookup and compilation of the contour from the document.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/test_projects.h"

namespace cam {
namespace {

TEST(Contour, LooksUpWindowsStartingAtANegativeAngle) {
    const auto c = Contour::build(test::splitCircle(3.0, 20.0, {-30.0, 60.0, 200.0, 330.0}));
    ASSERT_TRUE(c.ok());
    const Contour& contour = c.value();
    EXPECT_DOUBLE_EQ(contour.phiBegin(), degToRad(-30.0));
    // [start, end): a boundary belongs to the window it starts.
    EXPECT_EQ(contour.segmentAt(degToRad(-30.0)), 0u);
    EXPECT_EQ(contour.segmentAt(degToRad(0.0)), 0u);
    EXPECT_EQ(contour.segmentAt(degToRad(59.999)), 0u);
    EXPECT_EQ(contour.segmentAt(degToRad(60.0)), 1u);
    EXPECT_EQ(contour.segmentAt(degToRad(200.0)), 2u);
    EXPECT_EQ(contour.segmentAt(degToRad(329.999)), 2u);
    EXPECT_EQ(contour.segmentAt(degToRad(330.0)), 0u);
    // Any number of turns, either direction.
    EXPECT_EQ(contour.segmentAt(degToRad(100.0 + 720.0)), 1u);
    EXPECT_EQ(contour.segmentAt(degToRad(100.0 - 1080.0)), 1u);
    EXPECT_EQ(contour.segmentAt(degToRad(-40.0)), 2u);  // = 320°
}

TEST(Contour, NormalizeStaysInOneTurn) {
    const auto c = Contour::build(test::splitCircle(3.0, 20.0, {10.0, 200.0, 370.0}));
    ASSERT_TRUE(c.ok());
    for (double deg = -2000.0; deg < 2000.0; deg += 7.3) {
        const double x = c.value().normalize(degToRad(deg));
        EXPECT_GE(x, degToRad(10.0));
        EXPECT_LT(x, degToRad(370.0));
        EXPECT_NEAR(std::remainder(x - degToRad(deg), kTwoPi), 0.0, 1e-12);
    }
}

TEST(Contour, BuildRefusesAnInvalidDocumentWithLocatedErrors) {
    Project p = test::splitCircle(3.0, 20.0, {0.0, 180.0, 360.0});
    std::get<Arc>(p.contour[1].shape).radius = -2.0;
    const auto c = Contour::build(p);
    ASSERT_FALSE(c.ok());
    EXPECT_EQ(c.errors().front().location, "contour[1].radius");
    EXPECT_EQ(c.errors().front().message, "must be > 0 (got -2)");
}

TEST(Contour, SingleSegmentCoversTheTurn) {
    const auto c = Contour::build(test::splitCircle(0.0, 10.0, {0.0, 360.0}));
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.value().segmentAt(5.0), 0u);
    EXPECT_DOUBLE_EQ(c.value().evaluate(1.234).r, 10.0);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(Contour, AnOpenJointCanBeCompiledOnRequestButIsNeverSilentlyValid) {
    Project p = test::splitCircle(3.0, 20.0, {0.0, 180.0, 360.0});
    std::get<Arc>(p.contour[1].shape).radius = 21.0;  // both joints open by about 1 mm
    const auto strict = Contour::build(p);
    ASSERT_FALSE(strict.ok());
    EXPECT_EQ(strict.errors().front().location, "contour[0]/contour[1]");
    const auto lenient = Contour::build(p, ValidationOptions{.checkJoints = false});
    ASSERT_TRUE(lenient.ok());
    const Arc wider{{3.0, 0.0}, 21.0, Branch::Outer};
    EXPECT_DOUBLE_EQ(lenient.value().evaluate(degToRad(270.0)).r,
                     wider.evaluate(degToRad(270.0)).r);
    // Everything else is still checked.
    std::get<Arc>(p.contour[1].shape).radius = -1.0;
    EXPECT_FALSE(Contour::build(p, ValidationOptions{.checkJoints = false}).ok());
}

}  // namespace
}  // namespace cam
