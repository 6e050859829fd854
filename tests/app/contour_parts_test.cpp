// The contour view's parts that need no window: snapping a point in mm
// (views/contour_snapping.h) and where the follower's glyph is drawn
// (views/follower_glyph.h). Every expectation is worked out by hand or by plane geometry
// (a follower on a circle), not read from the code under test.

#include <gtest/gtest.h>

#include <qcustomplot.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/follower_geometry.h"
#include "follower/follower.h"
#include "views/contour_snapping.h"
#include "views/follower_glyph.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;
using test::normalOf;
using test::unit;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ContourSnapping, TheGridStepIsTheSmallestOneTwoFiveStepOfAtLeastTheMinimum) {
    EXPECT_EQ(gridStepFor(0.13).value(), 0.2);
    EXPECT_EQ(gridStepFor(0.2).value(), 0.2);  // exactly the minimum is enough
    EXPECT_EQ(gridStepFor(0.21).value(), 0.5);
    EXPECT_EQ(gridStepFor(0.6).value(), 1.0);
    EXPECT_EQ(gridStepFor(7.0).value(), 10.0);
    EXPECT_EQ(gridStepFor(30.0).value(), 50.0);
    EXPECT_EQ(gridStepFor(0.0042).value(), 0.005);
    // No sensible minimum (a plot of no size): 1 mm.
    for (double nonsense : {0.0, -3.0, kNaN, std::numeric_limits<double>::infinity()}) {
        EXPECT_EQ(gridStepFor(nonsense).value(), 1.0) << nonsense;
    }
    // Multiples are the decimals, not products that pick up rounding: 3 × 0.1 is 0.3.
    const GridStep tenth = gridStepFor(0.08);
    EXPECT_EQ(tenth.value(), 0.1);
    EXPECT_EQ(tenth.multiple(3.0), 0.3);
    EXPECT_EQ(tenth.round(0.27), 0.3);
    EXPECT_EQ(gridStepFor(0.15).round(-0.71), -0.8);
}

TEST(ContourSnapping, TheNearestPointWithinTheToleranceWins) {
    const std::vector<Vec> candidates{{0.0, 0.0}, {10.0, 4.0}, {10.5, 4.0}};
    // (10.3, 4.1) is 0.316 from (10, 4) and 0.224 from (10.5, 4).
    const Snapped s = snapPoint({10.3, 4.1}, candidates, 0.5, gridStepFor(1.0), Qt::NoModifier);
    EXPECT_EQ(s.target, SnapTarget::Point);
    EXPECT_EQ(s.candidate, 2);
    EXPECT_EQ(s.point, Vec(10.5, 4.0));
    EXPECT_EQ(s.keptAxis, -1);

    // A point exactly at the tolerance counts: (3, 4) is 5 from the origin.
    const std::vector<Vec> far{{3.0, 4.0}};
    EXPECT_EQ(snapPoint({0.0, 0.0}, far, 5.0, gridStepFor(1.0), Qt::NoModifier).point,
              Vec(3.0, 4.0));
    // At equal distances the later candidate wins.
    const std::vector<Vec> tie{{1.0, 0.0}, {-1.0, 0.0}};
    const Snapped t = snapPoint({0.0, 0.0}, tie, 2.0, gridStepFor(1.0), Qt::NoModifier);
    EXPECT_EQ(t.candidate, 1);
    EXPECT_EQ(t.point, Vec(-1.0, 0.0));
}

TEST(ContourSnapping, AwayFromEveryPointItLandsOnTheGrid) {
    // 10.37 / 0.2 = 51.85 → 52 steps; −4.12 / 0.2 = −20.6 → −21 steps.
    const std::vector<Vec> candidates{{0.0, 0.0}, {10.0, -4.0}, {kNaN, kNaN}};
    const Snapped s = snapPoint({10.37, -4.12}, candidates, 0.1, gridStepFor(0.2), Qt::NoModifier);
    EXPECT_EQ(s.target, SnapTarget::Grid);
    EXPECT_EQ(s.candidate, -1);
    EXPECT_EQ(s.point, Vec(10.4, -4.2));
    // No candidates at all: the grid too.
    EXPECT_EQ(snapPoint({0.74, 0.76}, {}, 0.1, gridStepFor(0.5), Qt::NoModifier).point,
              Vec(0.5, 1.0));
}

TEST(ContourSnapping, AltPlacesFreelyAndShiftKeepsTheAxisMovedLessAlong) {
    const std::vector<Vec> candidates{{5.3, 1.7}};
    const Vec origin(1.0, 1.0);
    // Alt: where it is, even on a candidate.
    const Snapped free =
        snapPoint({5.31, 1.72}, candidates, 1.0, gridStepFor(1.0), Qt::AltModifier);
    EXPECT_EQ(free.target, SnapTarget::Nothing);
    EXPECT_EQ(free.point, Vec(5.31, 1.72));

    // Shift, moved mostly along x: snapped to the grid (5, 2), then y back to the origin's.
    const Snapped alongX =
        snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin);
    EXPECT_EQ(alongX.point, Vec(5.0, 1.0));
    EXPECT_EQ(alongX.keptAxis, 1);
    // Mostly along y: x stays.
    const Snapped alongY =
        snapPoint({1.4, 6.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin);
    EXPECT_EQ(alongY.point, Vec(1.0, 7.0));
    EXPECT_EQ(alongY.keptAxis, 0);
    // As far along both: y stays.
    EXPECT_EQ(snapPoint({3.0, 3.0}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier, origin).point,
              Vec(3.0, 1.0));
    // Shift with Alt: unsnapped, one axis kept. Shift without an origin: no axis kept.
    EXPECT_EQ(snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier | Qt::AltModifier,
                        origin)
                  .point,
              Vec(5.4, 1.0));
    const Snapped noOrigin = snapPoint({5.4, 1.6}, {}, 0.1, gridStepFor(1.0), Qt::ShiftModifier);
    EXPECT_EQ(noOrigin.point, Vec(5.0, 2.0));
    EXPECT_EQ(noOrigin.keptAxis, -1);
}

TEST(ContourSnapping, ADraggedLengthSnapsToTheGridUnlessAlt) {
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.5), Qt::NoModifier), 12.5);
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.02), Qt::NoModifier), 12.34);
    EXPECT_EQ(snapLength(12.34, gridStepFor(0.5), Qt::AltModifier), 12.34);
}

FollowerModel modelOn(const Contour& contour, const FollowerSpec& spec) {
    auto model = FollowerModel::build(contour, spec);
    EXPECT_TRUE(model.ok());
    return std::move(model).value();
}

void expectNear(const Vec& actual, const Vec& expected, double tolerance, const char* what) {
    EXPECT_LE((actual - expected).norm(), tolerance)
        << what << ": (" << actual.x() << ", " << actual.y() << ") not (" << expected.x() << ", "
        << expected.y() << ")";
}

TEST(ContourFollowerGlyph, ARollerOnACircleSitsOnTheRayAtRPlusRho) {
    // A translating roller without offset on a circle of radius R about the cam's centre: its
    // centre lies on the ray at R + ρ, it touches the circle at R, the normal points along the
    // ray, and the line of motion runs out along the ray from the centre.
    const double R = 20.0, rho = 5.0;
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = rho;
    const FollowerModel model = modelOn(test::disc({0.0, 0.0}, R), spec);
    for (const double phi : {0.0, 0.7, 2.9, -1.2}) {
        const auto glyph = followerGlyphAt(model, phi, 1.0);
        ASSERT_TRUE(glyph) << phi;
        const Vec u = unit(phi);
        expectNear(glyph->center, (R + rho) * u, 1e-9, "centre");
        ASSERT_TRUE(glyph->rollerRadius);
        EXPECT_EQ(*glyph->rollerRadius, rho);
        expectNear(glyph->contact, R * u, 1e-9, "contact");
        // The arrow: 0.12 of the centre's distance, from the contact outwards along the ray.
        expectNear(glyph->normalTip, (R + 0.12 * (R + rho)) * u, 1e-9, "normal tip");
        // The line of motion from the centre past the roller by a quarter of that distance.
        expectNear(glyph->guideStart, (R + rho) * u, 1e-9, "guide start");
        expectNear(glyph->guideEnd, (R + rho + rho + 0.25 * (R + rho)) * u, 1e-9, "guide end");
        EXPECT_FALSE(glyph->pivot);
        EXPECT_FALSE(glyph->face);
    }
}

TEST(ContourFollowerGlyph, AFlatFaceLiesAcrossTheLineOfMotionAndHoldsTheContact) {
    // A flat face on a circle of radius 20 about (5, 0), at φ = 90°: the face touches the top of
    // the circle, (5, 20); it crosses the line of motion (the y axis) at (0, 20). The contact
    // is 5 from the line (|ds/dφ| = |c·n| = 5), so the face reaches 1.3 · 5 = 6.5 either side.
    FollowerSpec spec;
    spec.type = FollowerType::Flat;
    const FollowerModel model = modelOn(test::disc({5.0, 0.0}, 20.0), spec);
    const double phi = M_PI / 2.0;
    const auto glyph = followerGlyphAt(model, phi, 1.0);
    ASSERT_TRUE(glyph);
    expectNear(glyph->contact, {5.0, 20.0}, 1e-9, "contact");
    expectNear(glyph->center, {0.0, 20.0}, 1e-9, "centre");
    ASSERT_TRUE(glyph->face);
    expectNear((*glyph->face)[0], {6.5, 20.0}, 1e-9, "face, one end");
    expectNear((*glyph->face)[1], {-6.5, 20.0}, 1e-9, "face, other end");
    EXPECT_FALSE(glyph->rollerRadius);
    EXPECT_FALSE(glyph->pivot);
    // The line of motion: along the ray (no contact circle), 0.25 · 20 beyond the face.
    expectNear(glyph->guideStart, {0.0, 20.0}, 1e-9, "guide start");
    expectNear(glyph->guideEnd, {0.0, 25.0}, 1e-9, "guide end");

    // Where the contact is on the line, the face keeps a tenth of the distance either side:
    // a hand-made state at φ = 0, the face crossing at (30, 0), ds/dφ = 0.
    FollowerState state;
    state.center = {30.0, 0.0};
    state.contact = {30.0, 0.0};
    const auto narrow = followerGlyphShape(spec, state, 0.0);
    ASSERT_TRUE(narrow && narrow->face);
    expectNear((*narrow->face)[0], {30.0, -3.0}, 1e-12, "narrow face, one end");
    expectNear((*narrow->face)[1], {30.0, 3.0}, 1e-12, "narrow face, other end");
}

TEST(ContourFollowerGlyph, ASwingingArmRunsFromThePivotTurnedWithTheCam) {
    // A knife on an arm of 40 about (50, 0) in the follower frame, on a circle of radius 20:
    // the pivot turns with φ, the arm reaches from it to the knife's tip on the circle.
    const double R = 20.0;
    FollowerSpec spec = test::armSpec(FollowerType::Knife, 0.0, {50.0, 0.0}, 40.0, ArmSide::Ccw);
    const FollowerModel model = modelOn(test::disc({0.0, 0.0}, R), spec);
    for (const double phi : {0.0, 1.0, 4.0}) {
        const auto glyph = followerGlyphAt(model, phi, 1.0);
        ASSERT_TRUE(glyph) << phi;
        ASSERT_TRUE(glyph->pivot);
        expectNear(*glyph->pivot, 50.0 * unit(phi), 1e-9, "pivot");
        expectNear(glyph->guideStart, 50.0 * unit(phi), 1e-9, "arm start");
        EXPECT_NEAR((glyph->guideEnd - glyph->guideStart).norm(), 40.0, 1e-9) << phi;
        EXPECT_NEAR(glyph->guideEnd.norm(), R, 1e-9) << phi;  // the knife on the circle
        expectNear(glyph->contact, glyph->guideEnd, 1e-9, "contact at the tip");
        // The normal: the circle's radius through the contact, outwards, 0.12 · R long.
        expectNear(glyph->normalTip, glyph->contact * (1.0 + 0.12), 1e-9, "normal tip");
        EXPECT_FALSE(glyph->rollerRadius);
        EXPECT_FALSE(glyph->face);
    }
    // A pivot off the axis turns too: (10, 45) at φ = 90° is (−45, 10).
    FollowerSpec offAxis = spec;
    offAxis.pivot = {10.0, 45.0};
    FollowerState state;
    state.center = {-20.0, 0.0};
    const auto turned = followerGlyphShape(offAxis, state, M_PI / 2.0);
    ASSERT_TRUE(turned && turned->pivot);
    expectNear(*turned->pivot, {-45.0, 10.0}, 1e-12, "turned pivot");
}

TEST(ContourFollowerGlyph, NoContactDrawsNothing) {
    FollowerSpec spec;
    FollowerState state;
    state.center = {kNaN, kNaN};
    EXPECT_FALSE(followerGlyphShape(spec, state, 0.3));
}

TEST(ContourFollowerGlyph, ThePlotItemsShowTheShapeAndHideWithoutOne) {
    QCustomPlot plot;
    FollowerGlyph glyph(&plot, plot.layer("main"));
    EXPECT_FALSE(glyph.markers().shown);
    // A roller of 5 at (25, 0) touching at (20, 0), drawn by hand.
    FollowerGlyphShape roller;
    roller.center = {25.0, 0.0};
    roller.rollerRadius = 5.0;
    roller.guideStart = {25.0, 0.0};
    roller.guideEnd = {36.25, 0.0};
    roller.contact = {20.0, 0.0};
    roller.normalTip = {23.0, 0.0};
    glyph.show(roller);
    FollowerMarkers m = glyph.markers();
    EXPECT_TRUE(m.shown);
    EXPECT_FALSE(m.pivotShown);
    EXPECT_EQ(m.center, QPointF(25.0, 0.0));
    EXPECT_EQ(m.rollerRadius, 5.0);
    EXPECT_EQ(m.contact, QPointF(20.0, 0.0));
    EXPECT_EQ(m.normalTip, QPointF(23.0, 0.0));
    // An arm's pivot is shown with it.
    FollowerGlyphShape arm = roller;
    arm.pivot = Vec(0.0, 50.0);
    glyph.show(arm);
    m = glyph.markers();
    EXPECT_TRUE(m.pivotShown);
    EXPECT_EQ(m.pivot, QPointF(0.0, 50.0));
    // A translating knife's follower point is where it touches, not the far end of its
    // line of motion.
    FollowerGlyphShape knife;
    knife.center = {20.0, 0.0};
    knife.guideStart = {20.0, 0.0};
    knife.guideEnd = {31.25, 0.0};
    knife.contact = {20.0, 0.0};
    knife.normalTip = {23.0, 0.0};
    glyph.show(knife);
    m = glyph.markers();
    EXPECT_EQ(m.center, QPointF(20.0, 0.0));
    EXPECT_EQ(m.rollerRadius, 0.0);
    glyph.show(std::nullopt);
    m = glyph.markers();
    EXPECT_FALSE(m.shown);
    EXPECT_FALSE(m.pivotShown);
    EXPECT_EQ(m.rollerRadius, 0.0);
}

}  // namespace
}  // namespace cam
