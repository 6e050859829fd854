// Construction help (construction/tangents.h): common tangents of two circles, a tangent line
// between two arcs of the contour, a tangent arc through a point. Every number is checked
// against a closed form derived here or against geometry computed here (tangency, distances,
// polar derivatives, the project's validation), never against the implementation's output.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/angles.h"
#include "construction/tangents.h"
#include "core/contour_geometry.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "geometry/planar.h"
#include "project/validate.h"
#include "test_support.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;
using test::arc;
using test::arcOf;
using test::expectValid;
using test::line;
using test::lineOf;
using test::polar;
using test::tangentOn;
using test::validate;

using test::contains;

void expectNear(const Vec& actual, const Vec& expected, double tol) {
    EXPECT_NEAR((actual - expected).norm(), 0.0, tol)
        << "(" << actual.x() << ", " << actual.y() << ") vs (" << expected.x() << ", "
        << expected.y() << ")";
}

/// Every joint of the contour is G1: the polar tangents of both sides agree.
void expectG1(const std::vector<SegmentSpec>& c, double tol) {
    for (std::size_t k = 0; k < c.size(); ++k) {
        const SegmentSpec& left = c[k];
        const SegmentSpec& right = c[(k + 1) % c.size()];
        EXPECT_NEAR((tangentOn(left, left.phiEndDeg) - tangentOn(right, right.phiStartDeg)).norm(),
                    0.0, tol)
            << "joint after contour[" << k << "]";
    }
}

/// A line is tangent to a circle at t: t on the circle, the line perpendicular to the radius.
void expectTangentAt(const Vec& t, const Vec& otherEnd, const Vec& center, double radius) {
    EXPECT_NEAR((t - center).norm(), radius, 1e-12 * radius);
    EXPECT_NEAR((t - center).normalized().dot((otherEnd - t).normalized()), 0.0, 1e-12);
}

/// The error is located at the joint left/right, as data too.
void expectAtJoint(const Diagnostic& d, std::size_t left, std::size_t right) {
    EXPECT_EQ(d.location,
              "contour[" + std::to_string(left) + "]/contour[" + std::to_string(right) + "]");
    EXPECT_EQ(d.place, Place(JointPlace{left, right}));
    const std::vector<SegmentPlace> fields = d.segmentFields();
    ASSERT_EQ(fields.size(), 2u);
    EXPECT_EQ(fields[0], (SegmentPlace{left, SegmentPart::PhiEnd}));
    EXPECT_EQ(fields[1], (SegmentPlace{right, SegmentPart::PhiStart}));
}

// ---- the lobe cam: base circle R20 at the origin, nose R6 at (0, 24) ----
//
// Outer tangents, derived: c1 = (0, 0), R1 = 20, c2 = (0, 24), R2 = 6, d = 24. An outer tangent
// touches both circles on the same side; with m the unit normal there, t_i = c_i + R_i·m, and
// the line t1 t2 is perpendicular to m: m·(t2 − t1) = m·(c2 − c1) + (R2 − R1) = 24·m_y − 14 = 0.
// So m = (±cos θ, sin θ) with sin θ = (R1 − R2)/d = 14/24, cos θ = √(24² − 14²)/24 = √380/24,
// and t1 = 20·(±cos θ, sin θ), t2 = (0, 24) + 6·(±cos θ, sin θ). Inner tangents would need
// d > R1 + R2 = 26: the circles overlap, there are none.
//
// Which of the two joins the contour: it runs counter-clockwise, base → nose on the right
// (x > 0): from t1 = 20·(cos θ, sin θ) up and left to t2, direction ∝ (−sin θ, cos θ) — the
// base circle's own direction of travel at t1 (perp of t1), the polar angle growing
// (cross(t1, t2 − t1) = 20·|t2 − t1| > 0); nose → base on the left (x < 0), mirrored. Both
// tangent points are on the far side of their circles (outer branch).

const double kSinTheta = 14.0 / 24.0;
const double kCosTheta = std::sqrt(380.0) / 24.0;
const Vec kNoseCenter(0.0, 24.0);

Vec baseTangent(double side) { return 20.0 * Vec(side * kCosTheta, kSinTheta); }
Vec noseTangent(double side) { return kNoseCenter + 6.0 * Vec(side * kCosTheta, kSinTheta); }

std::vector<SegmentSpec> roughLobe() {
    return {arc({0, 0}, 20, Branch::Outer, -90.0, 90.0),
            arc(kNoseCenter, 6, Branch::Outer, 90.0, 270.0)};
}

TEST(TangentLines, LobeCamHasTwoOuterTangentsInClosedForm) {
    const auto t = circleTangentLines(Arc{{0, 0}, 20}, Arc{kNoseCenter, 6});
    ASSERT_EQ(t.size(), 2u);
    // First the one touching the base circle left of the line from its centre to the nose's.
    for (std::size_t i = 0; i < 2; ++i) {
        const double side = i == 0 ? -1.0 : 1.0;
        EXPECT_EQ(t[i].kind, TangentKind::Outer);
        expectNear(t[i].onA, baseTangent(side), 1e-12);
        expectNear(t[i].onB, noseTangent(side), 1e-12);
    }
    // From the nose's side the same two lines, the other way round.
    const auto back = circleTangentLines(Arc{kNoseCenter, 6}, Arc{{0, 0}, 20});
    ASSERT_EQ(back.size(), 2u);
    expectNear(back[0].onA, noseTangent(1.0), 1e-12);
    expectNear(back[0].onB, baseTangent(1.0), 1e-12);
}

TEST(TangentLines, DisjointCirclesHaveFourTangentsInClosedForm) {
    // c_a = (0, 0), R_a = 11, c_b = (0, 25), R_b = 4, d = 25. Outer (as for the lobe):
    // sin θ = (R_a − R_b)/d = 7/25, cos θ = 24/25, t_i = c_i + R_i·(±cos θ, sin θ). Inner: the
    // line separates the circles, t_a = c_a + R_a·m, t_b = c_b − R_b·m, and
    // m·(t_b − t_a) = 25·m_y − (R_a + R_b) = 0: sin θ = (R_a + R_b)/d = 15/25, cos θ = 20/25.
    const double ra = 11.0, rb = 4.0;
    const Vec cb(0.0, 25.0);
    struct Expected {
        Vec a, b;
        TangentKind kind;
    };
    const Vec outerLeft(-24.0 / 25.0, 7.0 / 25.0), outerRight(24.0 / 25.0, 7.0 / 25.0);
    const Vec innerLeft(-20.0 / 25.0, 15.0 / 25.0), innerRight(20.0 / 25.0, 15.0 / 25.0);
    const Expected expected[] = {
        {ra * outerLeft, cb + rb * outerLeft, TangentKind::Outer},
        {ra * outerRight, cb + rb * outerRight, TangentKind::Outer},
        {ra * innerLeft, cb - rb * innerLeft, TangentKind::Inner},
        {ra * innerRight, cb - rb * innerRight, TangentKind::Inner},
    };
    const auto t = circleTangentLines(Arc{{0, 0}, ra}, Arc{cb, rb});
    ASSERT_EQ(t.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(t[i].kind, expected[i].kind);
        expectNear(t[i].onA, expected[i].a, 1e-12);
        expectNear(t[i].onB, expected[i].b, 1e-12);
    }
    // Moved and turned rigidly (a rotation keeps left and right): the same tangents, moved.
    const double angle = 0.7;
    Eigen::Matrix2d rot;
    rot << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    const Vec shift(3.0, -2.0);
    const Arc a{shift, ra}, b{shift + rot * cb, rb};
    const auto moved = circleTangentLines(a, b);
    ASSERT_EQ(moved.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(moved[i].kind, expected[i].kind);
        expectNear(moved[i].onA, shift + rot * expected[i].a, 1e-12);
        expectNear(moved[i].onB, shift + rot * expected[i].b, 1e-12);
        expectTangentAt(moved[i].onA, moved[i].onB, a.center, ra);
        expectTangentAt(moved[i].onB, moved[i].onA, b.center, rb);
    }
}

TEST(TangentLines, OneCircleInsideTheOtherHasNone) {
    EXPECT_TRUE(circleTangentLines(Arc{{0, 0}, 10}, Arc{{1, 2}, 3}).empty());
    EXPECT_TRUE(circleTangentLines(Arc{{1, 2}, 3}, Arc{{0, 0}, 10}).empty());
    EXPECT_TRUE(circleTangentLines(Arc{{0, 0}, 10}, Arc{{0, 0}, 5}).empty());   // concentric
    EXPECT_TRUE(circleTangentLines(Arc{{4, 1}, 10}, Arc{{4, 1}, 10}).empty());  // the same
    EXPECT_TRUE(circleTangentLines(Arc{{0, 0}, 0}, Arc{{30, 0}, 5}).empty());   // no circle
    EXPECT_TRUE(circleTangentLines(Arc{{0, 0}, NAN}, Arc{{30, 0}, 5}).empty());
}

TEST(TangentLines, TouchingCirclesGiveOnlyTheRealTangents) {
    // From outside: (0, 0) R3 and (5, 0) R2, d = 5 = R_a + R_b. Outer: m·e = (3 − 2)/5 with
    // e = (1, 0), so m = (1/5, ±√24/5), t_a = 3·m, t_b = (5, 0) + 2·m; the inner pair merges
    // into the tangent x = 3 at the contact point (3, 0).
    {
        const auto t = circleTangentLines(Arc{{0, 0}, 3}, Arc{{5, 0}, 2});
        ASSERT_EQ(t.size(), 3u);
        const Vec left(0.2, std::sqrt(24.0) / 5.0), right(0.2, -std::sqrt(24.0) / 5.0);
        EXPECT_EQ(t[0].kind, TangentKind::Outer);
        expectNear(t[0].onA, 3.0 * left, 1e-12);
        expectNear(t[0].onB, Vec(5, 0) + 2.0 * left, 1e-12);
        EXPECT_EQ(t[1].kind, TangentKind::Outer);
        expectNear(t[1].onA, 3.0 * right, 1e-12);
        expectNear(t[1].onB, Vec(5, 0) + 2.0 * right, 1e-12);
        EXPECT_EQ(t[2].kind, TangentKind::Inner);
        expectNear(t[2].onA, Vec(3, 0), 1e-12);
        EXPECT_EQ(t[2].onA, t[2].onB);
    }
    // From inside: (0, 0) R5 and (2, 0) R3, d = 2 = R_a − R_b: one outer tangent, x = 5, at
    // the contact point (5, 0); no inner one. Either way round, and turned by 90°.
    for (const auto& [a, b, contact] : {std::tuple{Arc{{0, 0}, 5}, Arc{{2, 0}, 3}, Vec(5, 0)},
                                        std::tuple{Arc{{2, 0}, 3}, Arc{{0, 0}, 5}, Vec(5, 0)},
                                        std::tuple{Arc{{0, 0}, 5}, Arc{{0, -2}, 3}, Vec(0, -5)}}) {
        const auto t = circleTangentLines(a, b);
        ASSERT_EQ(t.size(), 1u);
        EXPECT_EQ(t[0].kind, TangentKind::Outer);
        expectNear(t[0].onA, contact, 1e-12);
        EXPECT_EQ(t[0].onA, t[0].onB);
    }
    // Intersecting: only the outer pair, all finite.
    for (const CircleTangent& t : circleTangentLines(Arc{{0, 0}, 5}, Arc{{3, 0}, 4})) {
        EXPECT_EQ(t.kind, TangentKind::Outer);
        EXPECT_TRUE(std::isfinite(t.onA.x()) && std::isfinite(t.onA.y()));
        EXPECT_TRUE(std::isfinite(t.onB.x()) && std::isfinite(t.onB.y()));
    }
    EXPECT_EQ(circleTangentLines(Arc{{0, 0}, 5}, Arc{{3, 0}, 4}).size(), 2u);
}

// ---- a tangent line at a joint ----

TEST(TangentLineJoint, LobeCamClosesWithTwoTangentLines) {
    const auto first = tangentLineJoint(roughLobe(), 1);
    ASSERT_TRUE(first.ok()) << first.errors().front().text();
    ASSERT_EQ(first.value().choices.size(), 1u);
    const TangentLineChoice& right = first.value().choices.front();
    EXPECT_EQ(right.kind, TangentKind::Outer);
    EXPECT_EQ(right.lineIndex, 1u);
    expectNear(right.tangentPoint1, baseTangent(1.0), 1e-12);
    expectNear(right.tangentPoint2, noseTangent(1.0), 1e-12);
    ASSERT_EQ(right.contour.size(), 3u);

    // The wrap-around joint is now nose (contour[2]) → base (contour[0]).
    const auto second = tangentLineJoint(right.contour, 0);
    ASSERT_TRUE(second.ok()) << second.errors().front().text();
    ASSERT_EQ(second.value().choices.size(), 1u);
    const TangentLineChoice& left = second.value().choices.front();
    EXPECT_EQ(left.kind, TangentKind::Outer);
    EXPECT_EQ(left.lineIndex, 3u);  // appended: the base circle stays first
    expectNear(left.tangentPoint1, noseTangent(-1.0), 1e-12);
    expectNear(left.tangentPoint2, baseTangent(-1.0), 1e-12);

    const std::vector<SegmentSpec>& c = left.contour;
    ASSERT_EQ(c.size(), 4u);
    ASSERT_EQ(c[0].type(), SegmentType::Arc);
    ASSERT_EQ(c[1].type(), SegmentType::Line);
    ASSERT_EQ(c[2].type(), SegmentType::Arc);
    ASSERT_EQ(c[3].type(), SegmentType::Line);
    EXPECT_EQ(arcOf(c[0]), (Arc{{0, 0}, 20, Branch::Outer}));
    EXPECT_EQ(arcOf(c[2]), (Arc{kNoseCenter, 6, Branch::Outer}));
    expectNear(lineOf(c[1]).from, baseTangent(1.0), 1e-12);
    expectNear(lineOf(c[1]).to, noseTangent(1.0), 1e-12);
    expectNear(lineOf(c[3]).from, noseTangent(-1.0), 1e-12);
    expectNear(lineOf(c[3]).to, baseTangent(-1.0), 1e-12);

    // Windows from the closed form: θ = asin(14/24); the nose tangent points at ±x lie at the
    // polar angles ψ = atan2(24 + 6 sin θ, 6 cos θ) and 180° − ψ.
    const double theta = radToDeg(std::asin(kSinTheta));
    const double psi = radToDeg(std::atan2(24.0 + 6.0 * kSinTheta, 6.0 * kCosTheta));
    const double windows[4][2] = {
        {-180.0 - theta, theta}, {theta, psi}, {psi, 180.0 - psi}, {180.0 - psi, 180.0 - theta}};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(c[i].phiStartDeg, windows[i][0], 1e-12) << i;
        EXPECT_NEAR(c[i].phiEndDeg, windows[i][1], 1e-12) << i;
    }
    expectValid(c);
    expectG1(c, 1e-12);
}

TEST(TangentLineJoint, EachBranchCombinationAdmitsExactlyOneTangent) {
    // Two circles off the rotation centre, at 0° and 90°: whatever branches the arcs follow,
    // exactly one of the four common tangents runs counter-clockwise with its ends on them —
    // counted here with the checks of the brief written independently: cross(t_a, t_b − t_a)
    // > 0, and |t| equal to the branch's r on the ray through t.
    const Arc a0{{10, 0}, 3}, b0{{0, 10}, 2};
    const auto all = circleTangentLines(a0, b0);
    ASSERT_EQ(all.size(), 4u);
    for (Branch ba : {Branch::Outer, Branch::Inner}) {
        for (Branch bb : {Branch::Outer, Branch::Inner}) {
            SCOPED_TRACE(std::to_string(int(ba)) + "/" + std::to_string(int(bb)));
            const Arc a{a0.center, a0.radius, ba}, b{b0.center, b0.radius, bb};
            auto onBranch = [](const Arc& arc, const Vec& p) {
                return std::abs(arc.evaluate(std::atan2(p.y(), p.x())).r - p.norm()) < 1e-9;
            };
            int fitting = 0;
            Vec fitA, fitB;
            for (const CircleTangent& t : all) {
                if (cross(t.onA, t.onB - t.onA) > 0.0 && onBranch(a, t.onA) && onBranch(b, t.onB)) {
                    ++fitting;
                    fitA = t.onA;
                    fitB = t.onB;
                }
            }
            EXPECT_EQ(fitting, 1);
            const std::vector<SegmentSpec> c = {SegmentSpec{a, -30.0, 45.0},
                                                SegmentSpec{b, 45.0, 330.0}};
            const auto r = tangentLineJoint(c, 1);
            ASSERT_TRUE(r.ok()) << r.errors().front().text();
            ASSERT_EQ(r.value().choices.size(), 1u);
            const TangentLineChoice& choice = r.value().choices.front();
            expectNear(choice.tangentPoint1, fitA, 1e-12);
            expectNear(choice.tangentPoint2, fitB, 1e-12);
            // The line continues both arcs: G1 at its two joints, windows contiguous.
            const auto& out = choice.contour;
            ASSERT_EQ(out.size(), 3u);
            EXPECT_NEAR(
                (tangentOn(out[0], out[0].phiEndDeg) - tangentOn(out[1], out[1].phiStartDeg))
                    .norm(),
                0.0, 1e-12);
            EXPECT_NEAR(
                (tangentOn(out[1], out[1].phiEndDeg) - tangentOn(out[2], out[2].phiStartDeg))
                    .norm(),
                0.0, 1e-12);
            EXPECT_EQ(out[0].phiEndDeg, out[1].phiStartDeg);
            EXPECT_EQ(out[1].phiEndDeg, out[2].phiStartDeg);
            EXPECT_EQ(out[0].phiStartDeg, -30.0);
            EXPECT_EQ(out[2].phiEndDeg, 330.0);
        }
    }
}

TEST(TangentLineJoint, RefusesANeighbourThatIsNotAnArc) {
    const std::vector<SegmentSpec> c = {line({20, 0}, {0, 20}, 0.0),
                                        arc({0, 0}, 20, Branch::Outer, 90.0, 360.0)};
    const auto r = tangentLineJoint(c, 1);
    ASSERT_FALSE(r.ok());
    expectAtJoint(r.errors().front(), 0, 1);
    EXPECT_TRUE(contains(r.errors().front().message, "contour[0] is a line"))
        << r.errors().front().message;
    const auto wrap = tangentLineJoint(c, 0);
    ASSERT_FALSE(wrap.ok());
    expectAtJoint(wrap.errors().front(), 1, 0);

    EXPECT_EQ(tangentLineJoint(c, 2).errors().front().location, "contour");
    EXPECT_EQ(tangentLineJoint({c[1]}, 0).errors().front().location, "contour");
}

TEST(TangentLineJoint, SaysWhyTheCirclesHaveNoTangent) {
    const auto inside = tangentLineJoint(
        {arc({0, 0}, 20, Branch::Outer, -90.0, 90.0), arc({1, 2}, 5, Branch::Outer, 90.0, 270.0)},
        1);
    ASSERT_FALSE(inside.ok());
    expectAtJoint(inside.errors().front(), 0, 1);
    EXPECT_TRUE(contains(inside.errors().front().message,
                         "the circle of contour[1] lies inside that of contour[0]"))
        << inside.errors().front().message;

    const auto same = tangentLineJoint(
        {arc({0, 0}, 20, Branch::Outer, 0.0, 180.0), arc({0, 0}, 20, Branch::Outer, 180.0, 360.0)},
        0);
    ASSERT_FALSE(same.ok());
    expectAtJoint(same.errors().front(), 1, 0);
    EXPECT_TRUE(contains(same.errors().front().message, "same circle"))
        << same.errors().front().message;

    // Touching from inside at (0, 20): the only tangent has no length.
    const auto touching = tangentLineJoint(
        {arc({0, 0}, 20, Branch::Outer, -90.0, 90.0), arc({0, 5}, 15, Branch::Outer, 90.0, 270.0)},
        1);
    ASSERT_FALSE(touching.ok());
    expectAtJoint(touching.errors().front(), 0, 1);
    EXPECT_TRUE(contains(touching.errors().front().message, "the circles touch at (0, 20)"))
        << touching.errors().front().message;
}

TEST(TangentLineJoint, SaysWhyEachTangentIsDropped) {
    // The lobe with a nose on the inner branch: the right outer tangent touches the nose on
    // its far side, the left one runs clockwise.
    auto lobe = roughLobe();
    std::get<Arc>(lobe[1].shape).branch = Branch::Inner;
    const auto r = tangentLineJoint(lobe, 1);
    ASSERT_FALSE(r.ok());
    expectAtJoint(r.errors().front(), 0, 1);
    const std::string& m = r.errors().front().message;
    EXPECT_TRUE(contains(m, "no tangent line fits")) << m;
    EXPECT_TRUE(contains(m, "runs clockwise around the rotation centre")) << m;
    EXPECT_TRUE(contains(m,
                         "touches contour[1] on the far side of its circle, but the arc "
                         "follows the near side (inner branch)"))
        << m;
}

TEST(TangentLineJoint, RefusesAWindowThatWouldBeReversed) {
    // The nose's window ends at 70°, before the tangent point on it (ψ ≈ 79.95°).
    const std::vector<SegmentSpec> c = {arc({0, 0}, 20, Branch::Outer, -90.0, 60.0),
                                        arc(kNoseCenter, 6, Branch::Outer, 60.0, 70.0),
                                        arc({0, 0}, 20, Branch::Outer, 70.0, 270.0)};
    const auto r = tangentLineJoint(c, 1);
    ASSERT_FALSE(r.ok());
    expectAtJoint(r.errors().front(), 0, 1);
    const std::string& m = r.errors().front().message;
    EXPECT_TRUE(contains(m, "the window of contour[1] would be empty or reversed")) << m;
    EXPECT_TRUE(contains(m, "its end 70°")) << m;
}

// ---- an arc through a point ----

/// A wedge: the base circle R20 from −90° to 90°, then (0, 20) → (−20, 0) → (0, −20).
std::vector<SegmentSpec> wedge() {
    const SegmentSpec base = arc({0, 0}, 20, Branch::Outer, -90.0, 90.0);
    const SegmentSpec up = line({0, 20}, {-20, 0}, 90.0);
    const SegmentSpec down = line({-20, 0}, {0, -20}, up.phiEndDeg);
    return {base, up, down};
}

/// The new arc starts at T tangent to `travel` and passes through P (checked here).
void expectTangentArc(const ArcThroughPointResult& r, const Vec& t, const Vec& travel,
                      const Vec& p) {
    const Vec dir = travel.normalized();
    EXPECT_NEAR((r.center - t).dot(dir), 0.0, 1e-12);  // centre on the normal at T
    EXPECT_NEAR((r.center - t).norm(), r.radius, 1e-12);
    EXPECT_NEAR((r.center - p).norm(), r.radius, 1e-12);
    const SegmentSpec& s = r.contour[r.arcIndex];
    ASSERT_EQ(s.type(), SegmentType::Arc);
    EXPECT_EQ(arcOf(s).center, r.center);
    EXPECT_EQ(arcOf(s).radius, r.radius);
    // The ray meets the new arc at T at its start and at P at its end.
    expectNear(arcOf(s).evaluate(degToRad(s.phiStartDeg)).r *
                   Vec(std::cos(degToRad(s.phiStartDeg)), std::sin(degToRad(s.phiStartDeg))),
               t, 1e-12);
    expectNear(arcOf(s).evaluate(degToRad(s.phiEndDeg)).r *
                   Vec(std::cos(degToRad(s.phiEndDeg)), std::sin(degToRad(s.phiEndDeg))),
               p, 1e-12);
    // The same direction of travel at T: the arc's polar tangent there is `travel`.
    EXPECT_NEAR((tangentOn(s, s.phiStartDeg) - dir).norm(), 0.0, 1e-12);
}

TEST(TangentArcThroughPoint, FromAnArcMatchesTheClosedFormAndValidates) {
    const auto c = wedge();
    expectValid(c);
    // T = (0, 20), running left; the circle tangent to y = 20 at T has its centre (0, 20 − R);
    // through P = (−10, 15): 10² + (R − 5)² = R², R = 12.5, centre (0, 7.5). It turns left
    // (outer branch) and holds the origin.
    const Vec p(-10, 15);
    const auto r = arcThroughPoint(c, 0, p);
    ASSERT_TRUE(r.ok()) << r.errors().front().text();
    const ArcThroughPointResult& a = r.value();
    EXPECT_EQ(a.arcIndex, 1u);
    expectNear(a.center, Vec(0, 7.5), 1e-12);
    EXPECT_NEAR(a.radius, 12.5, 1e-12);
    expectTangentArc(a, Vec(0, 20), Vec(-1, 0), p);
    ASSERT_EQ(a.contour.size(), 4u);
    EXPECT_EQ(arcOf(a.contour[1]).branch, Branch::Outer);
    EXPECT_EQ(a.contour[1].phiStartDeg, 90.0);
    EXPECT_NEAR(a.contour[1].phiEndDeg, 180.0 - radToDeg(std::atan(1.5)), 1e-12);
    // The line after it now starts at P; its end and the rest are untouched.
    EXPECT_EQ(lineOf(a.contour[2]).from, p);
    EXPECT_EQ(lineOf(a.contour[2]).to, Vec(-20, 0));
    EXPECT_EQ(a.contour[2].phiStartDeg, a.contour[1].phiEndDeg);
    EXPECT_EQ(a.contour[2].phiEndDeg, c[1].phiEndDeg);
    EXPECT_EQ(a.contour[0], c[0]);
    EXPECT_EQ(a.contour[3], c[2]);
    expectValid(a.contour);
}

TEST(TangentArcThroughPoint, AfterTheLastRowTheFirstWindowStartsATurnBack) {
    const auto c = wedge();
    // T = (0, −20) at the end of the last line, running (1, −1)/√2; P on the base circle at
    // −60°, so the base arc, whose start moves to −60°, meets the new arc there.
    const Vec p = 20.0 * Vec(std::cos(degToRad(-60.0)), std::sin(degToRad(-60.0)));
    const auto r = arcThroughPoint(c, 2, p);
    ASSERT_TRUE(r.ok()) << r.errors().front().text();
    const ArcThroughPointResult& a = r.value();
    EXPECT_EQ(a.arcIndex, 3u);  // appended: the base circle stays first
    ASSERT_EQ(a.contour.size(), 4u);
    expectTangentArc(a, Vec(0, -20), Vec(1, -1), p);
    EXPECT_EQ(arcOf(a.contour[3]).branch, Branch::Outer);  // it turns left
    EXPECT_EQ(a.contour[3].phiStartDeg, 270.0);
    EXPECT_NEAR(a.contour[3].phiEndDeg, 300.0, 1e-12);
    EXPECT_EQ(a.contour[0].phiStartDeg, a.contour[3].phiEndDeg - 360.0);
    EXPECT_EQ(a.contour[0].phiEndDeg, 90.0);
    expectValid(a.contour);
}

TEST(TangentArcThroughPoint, FromASplineUsesItsEndTangent) {
    // A quarter circle R20 as a Bézier (handles κ·R, κ = 4/3·tan(22.5°)): it ends at (0, 20)
    // along P3 − P2 = (−κ·20, 0), as the arc does; the same arc as from the arc (centre (0, 7.5),
    // R = 12.5) follows.
    const double kappa = 4.0 / 3.0 * std::tan(degToRad(22.5));
    SegmentSpec quarter{
        CubicBezier{{Vec(20, 0), Vec(20, 20 * kappa), Vec(20 * kappa, 20), Vec(0, 20)}}};
    std::tie(quarter.phiStartDeg, quarter.phiEndDeg) = lineWindowDeg(quarter, 0.0);
    std::vector<SegmentSpec> c = {quarter};
    for (const auto& [from, to] :
         {std::pair{Vec(0, 20), Vec(-20, 0)}, std::pair{Vec(-20, 0), Vec(0, -20)},
          std::pair{Vec(0, -20), Vec(20, 0)}}) {
        c.push_back(line(from, to, c.back().phiEndDeg));
    }
    expectValid(c);
    const Vec p(-10, 15);
    const auto r = arcThroughPoint(c, 0, p);
    ASSERT_TRUE(r.ok()) << r.errors().front().text();
    expectNear(r.value().center, Vec(0, 7.5), 1e-12);
    EXPECT_NEAR(r.value().radius, 12.5, 1e-12);
    expectTangentArc(r.value(), Vec(0, 20), Vec(-1, 0), p);
    expectValid(r.value().contour);

    // A tilted end handle: the centre lies on the normal to P3 − P2 = (−8, −2) at (0, 20).
    std::get<CubicBezier>(c[0].shape).p[2] = Vec(8, 22);
    const auto tilted = arcThroughPoint(c, 0, p);
    ASSERT_TRUE(tilted.ok()) << tilted.errors().front().text();
    expectTangentArc(tilted.value(), Vec(0, 20), Vec(-8, -2), p);
}

TEST(TangentArcThroughPoint, RefusesAPointOnTheTangent) {
    const auto r = arcThroughPoint(wedge(), 0, Vec(-10, 20));
    ASSERT_FALSE(r.ok());
    expectAtJoint(r.errors().front(), 0, 1);
    EXPECT_TRUE(contains(r.errors().front().message, "the point is on the tangent: use a line"))
        << r.errors().front().message;
}

TEST(TangentArcThroughPoint, RefusesAPointOnTheOtherBranch) {
    // P above the tangent y = 20: the circle through T = (0, 20) and P = (−20, 32.5) tangent
    // there has its centre (0, 20 + R), 20² + (R − 12.5)² = R², R = 22.25: the arc turns right
    // (inner branch, the near side), but P lies on its far side.
    const auto r = arcThroughPoint(wedge(), 0, Vec(-20, 32.5));
    ASSERT_FALSE(r.ok());
    expectAtJoint(r.errors().front(), 0, 1);
    const std::string& m = r.errors().front().message;
    EXPECT_TRUE(contains(m, "far side of the circle (centre (0, 42.25), radius 22.25 mm)")) << m;
    EXPECT_TRUE(contains(m, "inner branch")) << m;
}

TEST(TangentArcThroughPoint, RefusesAPointBehindTheEndPoint) {
    // The same kind of circle through P = (10, 25): centre (0, 32.5), R = 12.5, and P is on
    // its near side, but right of T: the arc leaving T to the left reaches it only over the
    // far side.
    const auto behind = arcThroughPoint(wedge(), 0, Vec(10, 25));
    ASSERT_FALSE(behind.ok());
    expectAtJoint(behind.errors().front(), 0, 1);
    EXPECT_TRUE(contains(behind.errors().front().message, "behind the end point of contour[0]"))
        << behind.errors().front().message;

    // P = (10, 15) lies on the outer circle (0, 7.5) R12.5 that holds the origin: the arc
    // reaches it at 56.3° + 360°, beyond the end 180° of the next segment.
    const auto beyond = arcThroughPoint(wedge(), 0, Vec(10, 15));
    ASSERT_FALSE(beyond.ok());
    expectAtJoint(beyond.errors().front(), 0, 1);
    EXPECT_TRUE(contains(beyond.errors().front().message,
                         "not before the end 180° of contour[1], whose window would be empty"))
        << beyond.errors().front().message;

    EXPECT_FALSE(arcThroughPoint(wedge(), 0, Vec(0, 20)).ok());  // T itself
    EXPECT_EQ(arcThroughPoint(wedge(), 3, Vec(1, 1)).errors().front().location, "contour");
}

}  // namespace
}  // namespace cam
