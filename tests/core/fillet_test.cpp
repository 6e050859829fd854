// Switch arcs (fillets, math.md §5): every case is checked against geometry computed here,
// independently of the implementation — distances of the fillet centre, tangent points on the
// old segments, equal tangent directions, the validated result — and against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/angles.h"
#include "core/contour_geometry.h"
#include "fillet/fillet.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "project/validate.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;
using Vec = Eigen::Vector2d;
using test::arc;
using test::arcOf;
using test::expectValid;
using test::line;
using test::lineOf;
using test::pointOn;
using test::polar;
using test::polarDeg;
using test::tangentOn;
using test::validate;

/// phi (deg) shifted by whole turns into [lo, lo + 360).
double unwrapInto(double phi, double lo) {
    return lo + std::fmod(std::fmod(phi - lo, 360.0) + 360.0, 360.0);
}

double distanceToLine(const Vec& p, const SegmentSpec& l) {
    const Vec d = (lineOf(l).to - lineOf(l).from).normalized();
    const Vec w = p - lineOf(l).from;
    return std::abs(d.x() * w.y() - d.y() * w.x());
}

/// How far p lies from the segment's curve (line or circle).
double offCurve(const Vec& p, const SegmentSpec& s) {
    return s.type() == SegmentType::Line ? distanceToLine(p, s)
                                         : std::abs((p - arcOf(s).center).norm() - arcOf(s).radius);
}

/// Distance of the fillet centre from the neighbour: rho for a line; R + rho (external) or
/// |R − rho| (internal) for a circle — returned as the deviation from the nearer of the two.
double centreDeviation(const Vec& o, double rho, const SegmentSpec& s) {
    if (s.type() == SegmentType::Line) return std::abs(distanceToLine(o, s) - rho);
    const Arc& a = arcOf(s);
    const double d = (o - a.center).norm();
    return std::min(std::abs(d - (a.radius + rho)), std::abs(d - std::abs(a.radius - rho)));
}

/// Whether the ray angle phi (any turn) lies strictly inside the segment's window.
bool inWindow(const SegmentSpec& s, double phiDeg) {
    const double phi = unwrapInto(phiDeg, s.phiStartDeg);
    return phi > s.phiStartDeg && phi < s.phiEndDeg;
}

/// Signed area of the contour sampled along its windows, and whether the ray angle grows
/// from every sample to the next (the chain runs counter-clockwise around the origin).
std::pair<double, bool> sampleOrientation(const std::vector<SegmentSpec>& contour) {
    std::vector<Vec> pts;
    for (const SegmentSpec& s : contour) {
        for (int i = 0; i < 200; ++i) {
            pts.push_back(pointOn(s, s.phiStartDeg + (s.phiEndDeg - s.phiStartDeg) * i / 200.0));
        }
    }
    double area = 0.0;
    bool ccw = true;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const Vec& p = pts[i];
        const Vec& q = pts[(i + 1) % pts.size()];
        const double c = p.x() * q.y() - p.y() * q.x();
        area += 0.5 * c;
        ccw = ccw && c > 0.0;
    }
    return {area, ccw};
}

enum class Corner { Convex, Concave };

/// Checks a fillet of radius rho at `joint` of `before` with geometry computed here.
void expectValidFillet(const std::vector<SegmentSpec>& before, std::size_t joint, double rho,
                       const FilletResult& f, Corner corner) {
    SCOPED_TRACE("joint " + std::to_string(joint) + ", rho " + std::to_string(rho));
    const std::size_t n = before.size();
    ASSERT_EQ(f.contour.size(), n + 1);
    const std::size_t left = (joint + n - 1) % n;
    const std::size_t at = joint == 0 ? n : joint;  // the fillet's index in the new contour
    const std::size_t right = joint == 0 ? 0 : joint + 1;
    const SegmentSpec& oldA = before[left];
    const SegmentSpec& oldB = before[joint];
    const SegmentSpec& a = f.contour[left];
    const SegmentSpec& fil = f.contour[at];
    const SegmentSpec& b = f.contour[right];
    const double scale = f.tangentPoint1.norm();

    // The fillet segment is the circle reported.
    ASSERT_EQ(fil.type(), SegmentType::Arc);
    EXPECT_EQ(arcOf(fil).radius, rho);
    EXPECT_EQ(f.radius, rho);
    EXPECT_NEAR((arcOf(fil).center - f.center).norm(), 0.0, 1e-12 * scale);

    // Its centre lies rho from a line, R ± rho from a circle; the tangent points are on both
    // curves and on the fillet circle.
    EXPECT_LE(centreDeviation(f.center, rho, oldA), 1e-9 * scale);
    EXPECT_LE(centreDeviation(f.center, rho, oldB), 1e-9 * scale);
    EXPECT_LE(offCurve(f.tangentPoint1, oldA), 1e-9 * scale);
    EXPECT_LE(offCurve(f.tangentPoint2, oldB), 1e-9 * scale);
    EXPECT_TRUE(relClose((f.tangentPoint1 - f.center).norm(), rho, 1e-9));
    EXPECT_TRUE(relClose((f.tangentPoint2 - f.center).norm(), rho, 1e-9));

    // The tangent points are on the old segments: inside their windows, on their branch.
    const double phi1 = polarDeg(f.tangentPoint1), phi2 = polarDeg(f.tangentPoint2);
    EXPECT_TRUE(inWindow(oldA, phi1)) << phi1;
    EXPECT_TRUE(inWindow(oldB, phi2)) << phi2;
    EXPECT_NEAR((pointOn(oldA, phi1) - f.tangentPoint1).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((pointOn(oldB, phi2) - f.tangentPoint2).norm(), 0.0, 1e-9 * scale);

    // The new windows meet at the tangent points, and the fillet's branch puts its ray
    // intersections there.
    EXPECT_NEAR(std::remainder(a.phiEndDeg - phi1, 360.0), 0.0, 1e-9);
    EXPECT_NEAR(std::remainder(b.phiStartDeg - phi2, 360.0), 0.0, 1e-9);
    EXPECT_EQ(fil.phiStartDeg, a.phiEndDeg);
    EXPECT_NEAR(std::remainder(fil.phiEndDeg - b.phiStartDeg, 360.0), 0.0, 1e-12);
    EXPECT_NEAR((pointOn(fil, fil.phiStartDeg) - f.tangentPoint1).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((pointOn(fil, fil.phiEndDeg) - f.tangentPoint2).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((pointOn(a, a.phiEndDeg) - f.tangentPoint1).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((pointOn(b, b.phiStartDeg) - f.tangentPoint2).norm(), 0.0, 1e-9 * scale);

    // G1 at both new joints: the neighbour and the fillet run in the same direction.
    EXPECT_NEAR((tangentOn(a, a.phiEndDeg) - tangentOn(fil, fil.phiStartDeg)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((tangentOn(fil, fil.phiEndDeg) - tangentOn(b, b.phiStartDeg)).norm(), 0.0, 1e-9);

    // Inside the corner: a convex corner loses material (r shrinks), a concave one gains it.
    const double mid = 0.5 * (fil.phiStartDeg + fil.phiEndDeg);
    const double midOld = unwrapInto(mid, oldA.phiStartDeg);
    const double rOld = midOld < oldA.phiEndDeg ? polar(oldA, mid).r : polar(oldB, mid).r;
    const double rNew = polar(fil, mid).r;
    if (corner == Corner::Convex) {
        EXPECT_LT(rNew, rOld);
    } else {
        EXPECT_GT(rNew, rOld);
    }

    // The segments away from the joint are untouched.
    for (std::size_t i = 0; i < n; ++i) {
        if (i == left || i == joint) continue;
        const std::size_t j = joint != 0 && i >= joint ? i + 1 : i;
        EXPECT_EQ(f.contour[j], before[i]) << i;
    }

    const Diagnostics d = validate(f.contour);
    EXPECT_TRUE(d.empty()) << d.front().text();
    const auto [area, ccw] = sampleOrientation(f.contour);
    EXPECT_GT(area, 0.0);
    EXPECT_TRUE(ccw);
}

using test::contains;

// ---- contours built by hand ----

/// The square |x|, |y| <= 10: four lines, windows -45 .. 315.
std::vector<SegmentSpec> squareContour() {
    const Vec corners[] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    std::vector<SegmentSpec> c;
    double near = -45.0;
    for (int k = 0; k < 4; ++k) {
        c.push_back(line(corners[k], corners[(k + 1) % 4], near));
        near = c.back().phiEndDeg;
    }
    return c;
}

/// A "D": the chord x = h of the circle |p| = R (h = 12, R = 20), then the circle. The circle's
/// centre and the fillet centres lie on the same side of the chord.
std::vector<SegmentSpec> dShape() {
    const SegmentSpec chord = line({12, -16}, {12, 16}, 0.0);
    return {chord, arc({0, 0}, 20, Branch::Outer, chord.phiEndDeg, chord.phiStartDeg + 360.0)};
}

/// The cap below the chord y = chordY of the circle centred (0, cy), the chord run right to
/// left, then the circle. With cy above the chord the circle's centre and the fillet centres
/// lie on opposite sides of it — seed 002's "line goes inside the circle, centres in different
/// half planes", bounded by (R − h)/2 with h = cy − chordY; cy = chordY puts the centre on it.
std::vector<SegmentSpec> cap(double cy, double chordY, double radius) {
    const double x = std::sqrt(radius * radius - (chordY - cy) * (chordY - cy));
    const SegmentSpec chord = line({x, chordY}, {-x, chordY}, 0.0);
    return {chord, arc({0, cy}, radius, Branch::Outer, chord.phiEndDeg, chord.phiStartDeg + 360.0)};
}

/// Two circles of radius R centred (±e, 0): `lens` is their intersection (convex corners at
/// (0, ±√(R² − e²))), otherwise their union (a peanut with concave corners there).
std::vector<SegmentSpec> twoCircles(double e, double radius, bool lens) {
    // The lens's right side is the left circle; the union's right side is the right circle.
    const double right = lens ? -e : e;
    return {arc({right, 0}, radius, Branch::Outer, -90.0, 90.0),
            arc({-right, 0}, radius, Branch::Outer, 90.0, 270.0)};
}

// ---- rho_min ----

TEST(Fillet, MinimumSwitchRadiusIsSpeedSquaredOverErrorTimesAcceleration) {
    // 100 mm/s at 5000 mm/s² with 10 % admissible error: 1e4 / 500 = 20 mm.
    EXPECT_TRUE(relClose(minimumSwitchRadius(100.0, 5000.0, 0.1), 20.0, 1e-15));
    // 250 mm/s, 2000 mm/s², 5 %: 62500 / 100 = 625 mm.
    EXPECT_TRUE(relClose(minimumSwitchRadius(250.0, 2000.0, 0.05), 625.0, 1e-15));
    EXPECT_TRUE(relClose(minimumSwitchRadius(-30.0, 900.0, 1.0), 1.0, 1e-15));
    EXPECT_TRUE(std::isnan(minimumSwitchRadius(100.0, 0.0, 0.1)));
    EXPECT_TRUE(std::isnan(minimumSwitchRadius(100.0, 5000.0, 0.0)));
}

// ---- line–line ----

TEST(Fillet, SquareCornerHasItsCentreOnTheBisectorAtRhoRootTwo) {
    const auto sq = squareContour();
    expectValid(sq);
    const double rho = 3.0;
    // joint 1: the corner (10, 10); joint 0: the corner (10, -10), between the last and first.
    for (std::size_t joint : {std::size_t{1}, std::size_t{0}}) {
        const Vec corner = joint == 1 ? Vec(10, 10) : Vec(10, -10);
        const auto f = filletJoint(sq, joint, rho);
        ASSERT_TRUE(f.ok()) << f.errors().front().text();
        const FilletResult& r = f.value();
        // Inward along the bisector, rho·√2 from the corner; tangent points rho from it.
        EXPECT_NEAR((r.center - corner).norm(), rho * std::sqrt(2.0), 1e-12);
        EXPECT_NEAR((r.center - (corner - rho * corner.normalized() * std::sqrt(2.0))).norm(), 0.0,
                    1e-12);
        EXPECT_NEAR((r.tangentPoint1 - corner).norm(), rho, 1e-12);
        EXPECT_NEAR((r.tangentPoint2 - corner).norm(), rho, 1e-12);
        EXPECT_EQ(arcOf(r.contour[joint == 0 ? 4 : 1]).branch, Branch::Outer);
        expectValidFillet(sq, joint, rho, r, Corner::Convex);
    }
}

TEST(Fillet, AllFourSquareCornersRoundOneAfterAnother) {
    std::vector<SegmentSpec> c = squareContour();
    // Rounding a joint inserts at its index, so go from the last joint down; joint 0 appends.
    for (std::size_t joint : {3, 2, 1, 0}) {
        const auto f = filletJoint(c, joint, 4.0);
        ASSERT_TRUE(f.ok()) << joint << ": " << f.errors().front().text();
        expectValidFillet(c, joint, 4.0, f.value(), Corner::Convex);
        c = f.value().contour;
    }
    ASSERT_EQ(c.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(c[i].type(), i % 2 == 0 ? SegmentType::Line : SegmentType::Arc) << i;
    }
    // Each side keeps the 12 mm between its two fillets.
    EXPECT_NEAR((lineOf(c[0]).to - lineOf(c[0]).from).norm(), 12.0, 1e-12);
}

TEST(Fillet, SquareRangeEndsWhereTheTangentPointReachesTheNextCorner) {
    const auto sq = squareContour();
    // At a right angle the tangent points are rho from the corner: the 20 mm side bounds rho.
    const auto range = filletRange(sq, 1);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_EQ(range.value().minRadius, 1e-6);  // project-format.md: radii are at least 1e-6 mm
    EXPECT_TRUE(relClose(range.value().maxRadius, 20.0, 1e-9));
    EXPECT_TRUE(filletJoint(sq, 1, 19.99).ok());

    const auto tooLarge = filletJoint(sq, 1, 25.0);
    ASSERT_FALSE(tooLarge.ok());
    const Diagnostic& e = tooLarge.errors().front();
    EXPECT_EQ(e.location, "contour[0]/contour[1]");
    EXPECT_TRUE(contains(e.message, "25 mm")) << e.message;
    EXPECT_TRUE(contains(e.message, "20 mm")) << e.message;
    EXPECT_TRUE(contains(e.message, "tangent point would leave contour[")) << e.message;

    const auto negative = filletJoint(sq, 0, -1.0);
    ASSERT_FALSE(negative.ok());
    EXPECT_EQ(negative.errors().front().location, "contour[3]/contour[0]");
    EXPECT_TRUE(contains(negative.errors().front().message, "-1 mm"));
    EXPECT_TRUE(contains(negative.errors().front().message, "20 mm"));
}

// ---- line–arc, circle centre on the same side as the fillet centre ----

TEST(Fillet, LineIntoCircleWithCentresOnTheSameSide) {
    const auto d = dShape();
    expectValid(d);
    const double R = 20.0, h = 12.0;
    // joint 1: line → arc at (12, 16); joint 0: arc → line at (12, -16). The fillet touches
    // the circle from inside: o = (h − rho, ±√((R − rho)² − (h − rho)²)). From rho = 10 on
    // the mirror circle (−y) also touches both segments inside their windows, with an arc of
    // 270° and more; the fillet is the one at the corner asked for.
    for (auto [joint, rho] : {std::pair{std::size_t{1}, 5.0}, std::pair{std::size_t{0}, 5.0},
                              std::pair{std::size_t{1}, 12.0}, std::pair{std::size_t{0}, 12.0}}) {
        const auto f = filletJoint(d, joint, rho);
        ASSERT_TRUE(f.ok()) << f.errors().front().text();
        const FilletResult& r = f.value();
        const double y = std::sqrt((R - rho) * (R - rho) - (h - rho) * (h - rho));
        const Vec expected(h - rho, joint == 1 ? y : -y);
        EXPECT_NEAR((r.center - expected).norm(), 0.0, 1e-12);
        EXPECT_TRUE(relClose(r.center.norm(), R - rho, 1e-12));  // internal tangency
        EXPECT_TRUE(relClose(h - r.center.x(), rho, 1e-12));     // rho from the line
        expectValidFillet(d, joint, rho, r, Corner::Convex);
    }
    // The offset line x = h − rho meets the offset circle |p| = R − rho while
    // rho − h <= R − rho: rho < (R + h)/2 = 16; the tangent points stay on their segments.
    const auto range = filletRange(d, 1);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_TRUE(relClose(range.value().maxRadius, (R + h) / 2.0, 1e-9));
    EXPECT_TRUE(filletJoint(d, 1, 15.9).ok());
    const auto tooLarge = filletJoint(d, 1, 16.5);
    ASSERT_FALSE(tooLarge.ok());
    EXPECT_EQ(tooLarge.errors().front().location, "contour[0]/contour[1]");
    EXPECT_TRUE(contains(tooLarge.errors().front().message, "16.5 mm"));
    EXPECT_TRUE(contains(tooLarge.errors().front().message, "16 mm"));
}

// ---- line–arc, circle centre on the opposite side (seed 002, 2.2.1.1) ----

TEST(Fillet, LineIntoCircleWithCentresOnOppositeSidesIsBoundedByHalfOfRMinusH) {
    const double cy = 8.0, chordY = 2.0, R = 20.0, h = cy - chordY;
    const auto c = cap(cy, chordY, R);
    expectValid(c);
    const double rho = 4.0;
    // joint 1: line → arc at the left corner; joint 0: arc → line at the right corner.
    for (std::size_t joint : {std::size_t{1}, std::size_t{0}}) {
        const auto f = filletJoint(c, joint, rho);
        ASSERT_TRUE(f.ok()) << f.errors().front().text();
        const FilletResult& r = f.value();
        EXPECT_TRUE(relClose(chordY - r.center.y(), rho, 1e-12));  // below the chord, c above
        EXPECT_TRUE(relClose((r.center - Vec(0, cy)).norm(), R - rho, 1e-12));  // internal
        EXPECT_LT(joint == 1 ? r.center.x() : -r.center.x(), 0.0);              // at its own corner
        expectValidFillet(c, joint, rho, r, Corner::Convex);
    }
    const double bound = (R - h) / 2.0;  // 7 mm
    for (std::size_t joint : {std::size_t{1}, std::size_t{0}}) {
        const auto range = filletRange(c, joint);
        ASSERT_TRUE(range.ok()) << range.errors().front().text();
        EXPECT_TRUE(relClose(range.value().maxRadius, bound, 1e-9));
    }
    EXPECT_TRUE(filletJoint(c, 1, 6.99).ok());
    const auto tooLarge = filletJoint(c, 1, 7.5);
    ASSERT_FALSE(tooLarge.ok());
    EXPECT_EQ(tooLarge.errors().front().location, "contour[0]/contour[1]");
    EXPECT_TRUE(contains(tooLarge.errors().front().message, "7.5 mm"));
    EXPECT_TRUE(contains(tooLarge.errors().front().message, "7 mm"));
}

TEST(Fillet, LineThroughTheCircleCentre) {
    // h = 0: the chord y = 2 passes through the centre (0, 2); the bound is R/2.
    const double R = 10.0, rho = 2.0;
    const auto c = cap(2.0, 2.0, R);
    expectValid(c);
    const auto f = filletJoint(c, 1, rho);
    ASSERT_TRUE(f.ok()) << f.errors().front().text();
    // o = (−√((R − rho)² − rho²), 2 − rho).
    const Vec expected(-std::sqrt((R - rho) * (R - rho) - rho * rho), 2.0 - rho);
    EXPECT_NEAR((f.value().center - expected).norm(), 0.0, 1e-12);
    expectValidFillet(c, 1, rho, f.value(), Corner::Convex);
    const auto range = filletRange(c, 0);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_TRUE(relClose(range.value().maxRadius, R / 2.0, 1e-9));
}

// ---- arc–arc ----

TEST(Fillet, ArcArcConvexCornerOfALens) {
    const double e = 3.0, R = 10.0;
    const auto lens = twoCircles(e, R, true);
    expectValid(lens);
    // At rho = 6 the mirror circle (below the axis for the upper joint) touches both arcs
    // inside their windows too; the fillet is the one at the corner asked for.
    for (auto [joint, rho] : {std::pair{std::size_t{1}, 2.0}, std::pair{std::size_t{0}, 2.0},
                              std::pair{std::size_t{1}, 6.0}, std::pair{std::size_t{0}, 6.0}}) {
        const auto f = filletJoint(lens, joint, rho);
        ASSERT_TRUE(f.ok()) << f.errors().front().text();
        const FilletResult& r = f.value();
        // Internal to both circles, on the axis of symmetry: o = (0, ±√((R − rho)² − e²)).
        const double y = std::sqrt((R - rho) * (R - rho) - e * e);
        EXPECT_NEAR((r.center - Vec(0, joint == 1 ? y : -y)).norm(), 0.0, 1e-12);
        EXPECT_TRUE(relClose((r.center - Vec(e, 0)).norm(), R - rho, 1e-12));
        EXPECT_TRUE(relClose((r.center - Vec(-e, 0)).norm(), R - rho, 1e-12));
        EXPECT_EQ(arcOf(r.contour[joint == 1 ? 1 : 2]).branch, Branch::Outer);
        expectValidFillet(lens, joint, rho, r, Corner::Convex);
    }
    // The offset circles (radius R − rho, centres 2e apart) meet while rho <= R − e.
    const auto range = filletRange(lens, 1);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_TRUE(relClose(range.value().maxRadius, R - e, 1e-9));
}

TEST(Fillet, ArcArcConcaveCornerOfAPeanutTouchesFromOutside) {
    const double e = 3.0, R = 5.0, rho = 2.0;
    const auto peanut = twoCircles(e, R, false);
    expectValid(peanut);
    for (std::size_t joint : {std::size_t{1}, std::size_t{0}}) {
        const auto f = filletJoint(peanut, joint, rho);
        ASSERT_TRUE(f.ok()) << f.errors().front().text();
        const FilletResult& r = f.value();
        // Outside both circles: o = (0, ±√((R + rho)² − e²)), the notch is filled.
        const double y = std::sqrt((R + rho) * (R + rho) - e * e);
        EXPECT_NEAR((r.center - Vec(0, joint == 1 ? y : -y)).norm(), 0.0, 1e-12);
        EXPECT_TRUE(relClose((r.center - Vec(e, 0)).norm(), R + rho, 1e-12));
        EXPECT_TRUE(relClose((r.center - Vec(-e, 0)).norm(), R + rho, 1e-12));
        EXPECT_EQ(arcOf(r.contour[joint == 1 ? 1 : 2]).branch, Branch::Inner);
        expectValidFillet(peanut, joint, rho, r, Corner::Concave);
    }
    // As rho grows the fillet tends to the common tangent y = ±R and the tangent points to
    // (±e, R): nothing bounds it but the largest length a project holds.
    const auto range = filletRange(peanut, 1);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_TRUE(relClose(range.value().maxRadius, kMaxLengthMm, 1e-9));
    const auto big = filletJoint(peanut, 1, 1000.0);
    ASSERT_TRUE(big.ok()) << big.errors().front().text();
    expectValidFillet(peanut, 1, 1000.0, big.value(), Corner::Concave);
}

// ---- the rotation centre bounds a fillet ----

TEST(Fillet, AFilletMustNotCutOffTheRotationCentre) {
    // The rectangle −1 <= x <= 30, −1 <= y <= 20: the corner (−1, −1), joint 0 between the left
    // side and the bottom, lies next to the origin. Its fillet centre is (rho − 1)(1, 1); the
    // arc passes the origin when |o| = rho: rho = √2 / (√2 − 1) = 2 + √2 (the sides allow 21).
    const Vec corners[] = {{-1, -1}, {30, -1}, {30, 20}, {-1, 20}};
    std::vector<SegmentSpec> rect;
    double near = -135.0;
    for (int k = 0; k < 4; ++k) {
        rect.push_back(line(corners[k], corners[(k + 1) % 4], near));
        near = rect.back().phiEndDeg;
    }
    expectValid(rect);
    const double bound = 2.0 + std::sqrt(2.0);
    const auto range = filletRange(rect, 0);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_TRUE(relClose(range.value().maxRadius, bound, 1e-9));

    const double rho = 3.4;
    const auto f = filletJoint(rect, 0, rho);
    ASSERT_TRUE(f.ok()) << f.errors().front().text();
    EXPECT_NEAR((f.value().center - Vec(rho - 1, rho - 1)).norm(), 0.0, 1e-12);
    EXPECT_GT(f.value().center.norm(), 0.0);
    EXPECT_LT(f.value().center.norm(), rho);  // the origin stays inside the fillet circle
    expectValidFillet(rect, 0, rho, f.value(), Corner::Convex);

    const auto tooLarge = filletJoint(rect, 0, 4.0);
    ASSERT_FALSE(tooLarge.ok());
    const Diagnostic& e = tooLarge.errors().front();
    EXPECT_EQ(e.location, "contour[3]/contour[0]");
    EXPECT_TRUE(contains(e.message, "4 mm")) << e.message;
    EXPECT_TRUE(contains(e.message, "3.414213562 mm")) << e.message;
    EXPECT_TRUE(contains(e.message, "rotation centre")) << e.message;
    // The far corners are bounded by the 21 mm right side instead: at (30, −1) the second
    // tangent point leaves it, at (30, 20) the first.
    for (std::size_t joint : {std::size_t{1}, std::size_t{2}}) {
        const auto far = filletRange(rect, joint);
        ASSERT_TRUE(far.ok());
        EXPECT_TRUE(relClose(far.value().maxRadius, 21.0, 1e-9));
        const auto refused = filletJoint(rect, joint, 21.5);
        ASSERT_FALSE(refused.ok());
        const std::string& m = refused.errors().front().message;
        EXPECT_TRUE(contains(m, "21.5 mm") && contains(m, "21 mm")) << m;
        EXPECT_TRUE(contains(m, "the tangent point would leave contour[1]")) << m;
    }
}

// ---- refusals ----

TEST(Fillet, RefusesATangentJoint) {
    // One circle (origin inside) split into two arcs: both joints are already smooth.
    const std::vector<SegmentSpec> circle = {arc({2, 0}, 10, Branch::Outer, -90.0, 90.0),
                                             arc({2, 0}, 10, Branch::Outer, 90.0, 270.0)};
    expectValid(circle);
    const auto f = filletJoint(circle, 1, 1.5);
    ASSERT_FALSE(f.ok());
    const Diagnostic& e = f.errors().front();
    EXPECT_EQ(e.location, "contour[0]/contour[1]");
    EXPECT_TRUE(contains(e.message, "1.5 mm")) << e.message;
    EXPECT_TRUE(contains(e.message, "tangent")) << e.message;
    const auto range = filletRange(circle, 0);
    ASSERT_FALSE(range.ok());
    EXPECT_EQ(range.errors().front().location, "contour[1]/contour[0]");
}

TEST(Fillet, RangeStartsAtTheSmallestRadiusEvenAboveAGap) {
    // Found by the fillet fuzzer (tests/fuzz/regressions/fillet/): a huge inner arc meets a line
    // that starts 0.36 mm from the rotation centre. Radii up to ~1.4e-9 mm fit, then a gap, and
    // radii from 1e-6 mm to ~1.15 mm fit again. The scan for the largest radius started near 0,
    // stopped at the gap and reported the empty range 1e-6 .. 1.4e-9 mm; the range starts at
    // the smallest radius a project holds, so the scan starts there too.
    const std::vector<SegmentSpec> c = {
        arc({-306136.1404167459, -30846.08291410225}, 307686.18867687264, Branch::Inner, -128.0,
            -91.23040380047506),
        line({-0.007632961612482174, -0.3553867894612641}, {93.60551787574047, -131.040400923125},
             -91.23040380047506),
        line({93.60551787574047, -131.040400923125}, {106.13019436541605, -33.85252902517654},
             -54.46080760095012),
        arc({63.6192824427185, 116.51540800756763}, 156.26162075181054, Branch::Outer,
            -17.69121140142518, 19.078384798099762),
        line({213.98873159443394, 74.00984505643936}, {105.05459473054471, 154.8619438085457},
             19.078384798099762),
        line({105.05459473054471, 154.8619438085457}, {-4.4504522373502216, 97.3475408516744},
             55.8479809976247),
        line({-4.4504522373502216, 97.3475408516744}, {-112.61164903760955, 137.15825628901152},
             92.61757719714964),
        line({-112.61164903760955, 137.15825628901152}, {-46.78784717276267, 11.529636299042764},
             129.3871733966746),
        line({-46.78784717276267, 11.529636299042764},
             {-0.03847884220785364, -0.049250672100420126}, 166.15676959619952)};
    expectValid(c);
    const auto range = filletRange(c, 1);
    ASSERT_TRUE(range.ok()) << range.errors().front().text();
    EXPECT_EQ(range.value().minRadius, 1e-6);
    EXPECT_GT(range.value().maxRadius, range.value().minRadius);
    for (double rho :
         {1e-6, std::sqrt(1e-6 * range.value().maxRadius), 0.999 * range.value().maxRadius}) {
        const auto f = filletJoint(c, 1, rho);
        ASSERT_TRUE(f.ok()) << rho << ": " << f.errors().front().text();
        expectValid(f.value().contour);
    }
}

TEST(Fillet, RefusesAnInvalidContourAndAMissingJoint) {
    auto broken = squareContour();
    std::get<Line>(broken[1].shape).from = {10, 11};  // opens the joint at (10, 10)
    broken[1].phiStartDeg = lineWindowDeg(broken[1], 45.0).first;
    const auto f = filletJoint(broken, 2, 1.0);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.errors().front().location, "contour[1]/contour[2]");
    EXPECT_GE(f.errors().size(), 2u);  // followed by what validation found

    const auto missing = filletJoint(squareContour(), 4, 1.0);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.errors().front().location, "contour");
}

}  // namespace
}  // namespace cam
