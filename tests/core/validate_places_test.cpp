// Problems in the contour carry their place as data (segment, field, point, axis); the text
// location is derived from it. The table marks cells from the data, never by parsing the text.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "project/validate.h"

namespace cam {
namespace {

/// Four quarter-circle Béziers about the origin (radius 20), counter-clockwise: a valid closed
/// contour whose points the tests then break one at a time.
Project splineCircle() {
    const double R = 20.0, k = 4.0 / 3.0 * std::tan(M_PI / 8.0) * R;
    Project p;
    for (int q = 0; q < 4; ++q) {
        const double a = M_PI / 2 * q, b = a + M_PI / 2;
        const Eigen::Vector2d u(std::cos(a), std::sin(a)), v(std::cos(b), std::sin(b));
        const CubicBezier curve{{R * u, R * u + k * v, R * v + k * u, R * v}};
        p.contour.push_back(SegmentSpec{curve, 90.0 * q, 90.0 * q + 90.0});
    }
    return p;
}

const Diagnostic* find(const Diagnostics& all, const std::string& location) {
    for (const Diagnostic& d : all) {
        if (d.location == location) return &d;
    }
    return nullptr;
}

TEST(ValidationPlaces, ABezierPointCoordinateIsLocatedAsData) {
    Project p = splineCircle();
    ASSERT_TRUE(validateProject(p).empty()) << validateProject(p).front().text();
    std::get<CubicBezier>(p.contour[2].shape).p[2].x() = 2e6;  // beyond the 1e6 mm limit
    const Diagnostics problems = validateProject(p);
    const Diagnostic* d = find(problems, "contour[2].points[2][0]");
    ASSERT_NE(d, nullptr) << problems.front().text();
    EXPECT_EQ(d->place, Place(SegmentPlace{2, SegmentPart::Points, 2, 0}));
    EXPECT_EQ(locationText(d->place), d->location);
}

TEST(ValidationPlaces, AHermiteTangentCoordinateIsLocatedAsData) {
    Project p = splineCircle();
    const CubicBezier b = std::get<CubicBezier>(p.contour[1].shape);
    HermiteCurve h = HermiteCurve::of(b);
    h.t1.y() = std::numeric_limits<double>::quiet_NaN();
    p.contour[1].shape = h;
    const Diagnostics problems = validateProject(p);
    const Diagnostic* d = find(problems, "contour[1].t1[1]");
    ASSERT_NE(d, nullptr) << problems.front().text();
    EXPECT_EQ(d->segmentFields(), (std::vector<SegmentPlace>{{1, SegmentPart::T1, -1, 1}}));
}

TEST(ValidationPlaces, AGapNamesBothSidesOfTheJoint) {
    Project p = splineCircle();
    p.contour[3].phiStartDeg = 271.0;
    const Diagnostics problems = validateProject(p);
    const Diagnostic* d = find(problems, "contour[2]/contour[3]");
    ASSERT_NE(d, nullptr) << problems.front().text();
    EXPECT_EQ(d->place, Place(JointPlace{2, 3}));
    EXPECT_EQ(d->segmentFields(),
              (std::vector<SegmentPlace>{{2, SegmentPart::PhiEnd}, {3, SegmentPart::PhiStart}}));
}

TEST(ValidationPlaces, EveryPlaceSpellsItsLocation) {
    EXPECT_EQ(locationText(SegmentPlace{7}), "contour[7]");
    EXPECT_EQ(locationText(SegmentPlace{7, SegmentPart::Center, -1, 1}), "contour[7].center[1]");
    EXPECT_EQ(locationText(SegmentPlace{7, SegmentPart::Radius}), "contour[7].radius");
    EXPECT_EQ(locationText(SegmentPlace{0, SegmentPart::Points, 3}), "contour[0].points[3]");
    EXPECT_EQ(locationText(SegmentPlace{0, SegmentPart::P0, -1, 0}), "contour[0].p0[0]");
    EXPECT_EQ(locationText(SegmentPlace{12, SegmentPart::PhiEnd}), "contour[12].phi_end");
    EXPECT_EQ(locationText(JointPlace{12, 0}), "contour[12]/contour[0]");
}

TEST(ResultValue, ReadingAnEmptyResultAbortsWithAMessage) {
    const Result<int> empty(Diagnostics{{"somewhere", "went wrong"}});
    EXPECT_DEATH((void)empty.value(), "Result::value\\(\\) read without a value");
}

// Numbers in messages: at most ten significant digits, so round-off never shows
// (215.60000000000002 reads 215.6), while what a user typed reads as typed; never "-0".
TEST(MessageNumbers, HaveAtMostTenSignificantDigitsAndNoRoundOff) {
    EXPECT_EQ(formatNumber(215.60000000000002), "215.6");
    EXPECT_EQ(formatNumber(0.1 + 0.2), "0.3");
    EXPECT_EQ(formatNumber(12.5), "12.5");
    EXPECT_EQ(formatNumber(-2.0), "-2");
    EXPECT_EQ(formatNumber(-0.0), "0");
    EXPECT_EQ(formatNumber(1e-300), "1e-300");
    EXPECT_EQ(formatNumber(4.840705970012345), "4.84070597");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::quiet_NaN()), "NaN");
    // A message the validation writes with a computed window: no 17-digit tail.
    Project p;
    p.contour = {SegmentSpec{Arc{{0.0, 0.0}, 20.0, Branch::Outer}, 0.0, 0.1 + 0.2},
                 SegmentSpec{Arc{{0.0, 0.0}, 20.0, Branch::Outer}, 0.5, 360.0}};
    const Diagnostics d = validateProject(p);
    ASSERT_FALSE(d.empty());
    bool named = false;
    for (const Diagnostic& m : d) {
        EXPECT_EQ(m.text().find("0.30000000000000004"), std::string::npos) << m.text();
        named = named || m.text().find("0.3") != std::string::npos;
    }
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace cam
