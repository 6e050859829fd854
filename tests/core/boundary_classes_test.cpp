// Boundary classes (VDI 2143: rest, constant velocity, reversal, movement) and Suggest, checked
// by hand: the classes a design's neighbours demand, the laws Suggest picks for each pair of
// classes (CODESYS SoftMotion's table, design/boundary_classes.h), the joints they make
// continuous, and where a suggested law has a closed form (a quartic turn, an inclined sine),
// its values against it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "core/test_projects.h"
#include "design/boundary_classes.h"
#include "design/motion_design.h"

namespace cam {
namespace {

using test::designSegment;

std::string letters(const std::vector<SegmentClasses>& classes) {
    std::string out;
    for (const SegmentClasses& c : classes) {
        out += boundaryClassLetter(c.start);
        out += boundaryClassLetter(c.end);
        out += ' ';
    }
    return out;
}

TEST(BoundaryClasses, AreWhatTheNeighboursDemand) {
    // The cycloidal cam of math.md: every joint at rest.
    const auto cycloidal = boundaryClasses(test::cycloidalDesign());
    ASSERT_TRUE(cycloidal.ok());
    EXPECT_EQ(letters(cycloidal.value()), "RR RR RR RR ");
    // A line between two cycloids: the cycloids' ends at rest demand rest of the line, the
    // line's constant velocity demands it of the cycloids; a harmonic rise and return meet at
    // a reversal (v = 0, a = −π²/2·Δ/h² ≠ 0).
    DesignSpec d = test::cycloidalDesign();
    d.segments = {designSegment(MotionLawType::Cycloidal, 60.0, 5.0),
                  designSegment(MotionLawType::ConstantVelocity, 120.0, 10.0),
                  designSegment(MotionLawType::Cycloidal, 180.0, 15.0),
                  designSegment(MotionLawType::Harmonic, 270.0, 20.0),
                  designSegment(MotionLawType::Harmonic, 360.0, 0.0)};
    const auto classes = boundaryClasses(d);
    ASSERT_TRUE(classes.ok());
    // Segment 0 starts where the last harmonic ends (v = 0, a = π²/2·20/h² ≠ 0: reversal) and
    // ends where the line starts (constant velocity); the line between cycloids, at rest.
    EXPECT_EQ(letters(classes.value()), "UG RR GU RU UR ");
    // The same design, built: the line's joints are refused at the cycloids' laws, which must
    // change (a line is the requirement).
    const auto built = MotionDesign::build(d);
    ASSERT_FALSE(built.ok());
    ASSERT_EQ(built.errors().size(), 2u);
    EXPECT_EQ(built.errors()[0].location, "design.segments[0].law");
    EXPECT_EQ(built.errors()[1].location, "design.segments[2].law");
    EXPECT_NE(built.errors()[0].message.find("constant velocity at its end"), std::string::npos)
        << built.errors()[0].message;
}

TEST(Suggest, FillsADwellLineDwellCycleWithPoly5sAndAModifiedSine) {
    // Dwell, a rise to a line of 10 mm over 80° (1/8 mm per degree), a rise to a dwell, a
    // return.
    DesignSpec d = test::cycloidalDesign();
    d.segments = {designSegment(MotionLawType::Dwell, 60.0, 0.0),
                  designSegment(MotionLawType::Cycloidal, 120.0, 5.0),
                  designSegment(MotionLawType::ConstantVelocity, 200.0, 15.0),
                  designSegment(MotionLawType::Cycloidal, 260.0, 20.0),
                  designSegment(MotionLawType::Dwell, 300.0, 20.0),
                  designSegment(MotionLawType::Cycloidal, 360.0, 0.0)};
    ASSERT_FALSE(MotionDesign::build(d).ok());
    const auto suggested = suggestLaws(d);
    ASSERT_TRUE(suggested.ok());
    const DesignSpec& s = suggested.value();
    // Rest → constant velocity and back: poly5 with the line's 1/8 mm/° and a = 0 (by hand).
    EXPECT_EQ(s.segments[1].law, MotionLawType::Poly5);
    EXPECT_EQ(s.segments[1].v0, 0.0);
    EXPECT_EQ(s.segments[1].a0, 0.0);
    EXPECT_NEAR(s.segments[1].v1, 0.125, 1e-15);
    EXPECT_NEAR(s.segments[1].a1, 0.0, 1e-15);
    EXPECT_EQ(s.segments[3].law, MotionLawType::Poly5);
    EXPECT_NEAR(s.segments[3].v0, 0.125, 1e-15);
    EXPECT_EQ(s.segments[3].v1, 0.0);
    // Rest → rest: the modified sine, symmetric.
    EXPECT_EQ(s.segments[5].law, MotionLawType::ModifiedSine);
    EXPECT_EQ(s.segments[5].lambda, 0.5);
    // The dwells and the line stay; the lifts and angles too.
    for (std::size_t k : {0u, 2u, 4u}) EXPECT_EQ(s.segments[k], d.segments[k]) << k;
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
        EXPECT_EQ(s.segments[k].toDeg, d.segments[k].toDeg);
        EXPECT_EQ(s.segments[k].lift, d.segments[k].lift);
    }
    // Now every joint is continuous in velocity and acceleration.
    const auto built = MotionDesign::build(s);
    ASSERT_TRUE(built.ok()) << built.errors().front().text();
    EXPECT_TRUE(built.value().jumps().empty()) << built.value().jumps().front().text();
    EXPECT_EQ(letters(boundaryClasses(built.value())), "RR RG GG GR RR RR ");
}

TEST(Suggest, TurnsARiseIntoAReturnAtAReversal) {
    // A rise of 10 mm over 90° straight into a return over 90°: both suggested, they meet at
    // v = 0 with a = 6(Δ₂/h₂² − Δ₁/h₁²) = −120/h², which for equal stretches makes each poly5
    // the quartic turn y = Δ(4u³ − 3u⁴) (its c5 vanishes: 6Δ − (a0 − a1)h²/2 = 0).
    DesignSpec d = test::cycloidalDesign();
    d.segments = {designSegment(MotionLawType::Dwell, 90.0, 0.0),
                  designSegment(MotionLawType::Cycloidal, 180.0, 10.0),
                  designSegment(MotionLawType::Cycloidal, 270.0, 0.0),
                  designSegment(MotionLawType::Dwell, 360.0, 0.0)};
    const auto suggested = suggestLaws(d);
    ASSERT_TRUE(suggested.ok());
    const DesignSpec& s = suggested.value();
    const double h = 90.0;  // degrees
    EXPECT_EQ(s.segments[1].law, MotionLawType::Poly5);
    EXPECT_EQ(s.segments[1].v1, 0.0);
    EXPECT_NEAR(s.segments[1].a1, -120.0 / (h * h), 1e-15);
    EXPECT_EQ(s.segments[2].law, MotionLawType::Poly5);
    EXPECT_NEAR(s.segments[2].a0, -120.0 / (h * h), 1e-15);
    const auto built = MotionDesign::build(s);
    ASSERT_TRUE(built.ok()) << built.errors().front().text();
    EXPECT_TRUE(built.value().jumps().empty());
    EXPECT_EQ(letters(boundaryClasses(built.value())), "RR RU UR RR ");
    for (int i = 0; i <= 90; ++i) {
        const double u = i / 90.0;
        const double quartic = 10.0 * (4.0 * u * u * u - 3.0 * u * u * u * u);
        EXPECT_NEAR(built.value().liftAt(degToRad(90.0 + 90.0 * u))[0], quartic, 1e-12) << u;
        EXPECT_NEAR(built.value().liftAt(degToRad(270.0 - 90.0 * u))[0], quartic, 1e-12) << u;
    }
}

TEST(Suggest, JoinsTwoLinesOfOneVelocityByAnInclinedSine) {
    // Lines of 0.1 mm/° before and after a stretch of 60° that rises 8 mm (0.1333 mm/°): the
    // inclined sine with v0 = 0.1, whose lift is y0 + Δ(x − (1 − vn) sin 2πx / 2π) with
    // vn = 0.1·60/8 = 0.75 (VDI 2143's geneigte Sinuslinie).
    DesignSpec d = test::cycloidalDesign();
    d.segments = {designSegment(MotionLawType::Dwell, 30.0, 0.0),
                  designSegment(MotionLawType::Cycloidal, 90.0, 6.0),
                  designSegment(MotionLawType::ConstantVelocity, 150.0, 12.0),
                  designSegment(MotionLawType::Cycloidal, 210.0, 20.0),
                  designSegment(MotionLawType::ConstantVelocity, 250.0, 24.0),
                  designSegment(MotionLawType::Cycloidal, 300.0, 28.0),
                  designSegment(MotionLawType::Cycloidal, 360.0, 0.0)};
    const auto suggested = suggestLaws(d);
    ASSERT_TRUE(suggested.ok());
    const DesignSpec& s = suggested.value();
    ASSERT_EQ(s.segments[3].law, MotionLawType::InclinedSine);
    EXPECT_NEAR(s.segments[3].v0, 0.1, 1e-15);
    const auto built = MotionDesign::build(s);
    ASSERT_TRUE(built.ok()) << built.errors().front().text();
    EXPECT_TRUE(built.value().jumps().empty()) << built.value().jumps().front().text();
    EXPECT_EQ(letters(boundaryClasses(built.value())), "RR RG GG GG GG GU UR ");
    const double vn = 0.1 * 60.0 / 8.0;
    for (int i = 0; i <= 60; ++i) {
        const double x = i / 60.0;
        const double y = 12.0 + 8.0 * (x - (1.0 - vn) * std::sin(kTwoPi * x) / kTwoPi);
        EXPECT_NEAR(built.value().liftAt(degToRad(150.0 + 60.0 * x))[0], y, 1e-12) << x;
    }
    // Suggesting one segment leaves the others as they are.
    const auto one = suggestLaws(d, 3);
    ASSERT_TRUE(one.ok());
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
        if (k != 3) {
            EXPECT_EQ(one.value().segments[k], d.segments[k]) << k;
        }
    }
    EXPECT_EQ(one.value().segments[3], s.segments[3]);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(Suggest, AStretchThatComesBackWhereItStartedStaysAPoly5) {
    // A poly5 out and back (lift 10 → 10) that leaves at 0.05 mm/°, where the dwell before it
    // rests: no normalised law rises by nothing, so Suggest keeps poly5 and gives it the
    // dwells' rest at both ends.
    DesignSpec d = test::cycloidalDesign();
    d.segments[1] = designSegment(MotionLawType::Poly5, 180.0, 10.0);
    d.segments[1].v0 = 0.05;
    ASSERT_FALSE(MotionDesign::build(d).ok());
    const auto suggested = suggestLaws(d, 1);
    ASSERT_TRUE(suggested.ok());
    const DesignSegmentSpec& s = suggested.value().segments[1];
    EXPECT_EQ(s.law, MotionLawType::Poly5);
    EXPECT_EQ(s.v0, 0.0);
    EXPECT_EQ(s.a0, 0.0);
    EXPECT_EQ(s.v1, 0.0);
    EXPECT_EQ(s.a1, 0.0);
    const auto built = MotionDesign::build(suggested.value());
    ASSERT_TRUE(built.ok()) << built.errors().front().text();
    // All zero at both ends from 10 to 10: the poly5 is the constant 10 (its c1 … c5 vanish).
    for (double deg : {120.0, 150.0, 179.0}) {
        EXPECT_EQ(built.value().liftAt(degToRad(deg))[0], 10.0) << deg;
    }
}

}  // namespace
}  // namespace cam
