// Fit windows: boundaries move to where the neighbours meet, checked against constructions
// whose meeting points are known in closed form, against the validator's own verdict, and
// against the seed's Table 1 as it is printed.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <random>

#include "common/angles.h"
#include "common/tolerances.h"
#include "contour/fit_windows.h"
#include "io/project_json.h"
#include "project/validate.h"
#include "test_support.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

const std::vector<SegmentSpec>& contourOf(const Result<FittedWindows>& fitted) {
    return fitted.value().contour;
}

Diagnostics problemsOf(const std::vector<SegmentSpec>& contour) {
    Project p;
    p.contour = contour;
    return validateProject(p);
}

std::size_t countCode(const Diagnostics& d, DiagnosticCode code) {
    return static_cast<std::size_t>(
        std::count_if(d.begin(), d.end(), [code](const Diagnostic& x) { return x.code == code; }));
}

/// The polar angles (deg) of the two intersections of two circles, in closed form by Heron's
/// formula in Kahan's stable arrangement (not the construction fitWindows uses): the triangle
/// c1, c2, p has sides r1, r2 and d; its height over the side d is 2·area/d.
std::array<double, 2> intersectionAnglesDeg(const Vec& c1, double r1, const Vec& c2, double r2) {
    using L = long double;
    const L dx = static_cast<L>(c2.x()) - c1.x(), dy = static_cast<L>(c2.y()) - c1.y();
    const L d = std::sqrt(dx * dx + dy * dy);
    std::array<L, 3> s{static_cast<L>(r1), static_cast<L>(r2), d};
    std::sort(s.begin(), s.end(), std::greater<>());
    const L a = s[0], b = s[1], c = s[2];
    const L area = std::sqrt((a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c))) / 4;
    const L height = 2 * area / d;
    // The foot of the height from c1, signed along c1 → c2 (law of cosines).
    const L along = (d * d + static_cast<L>(r1) * r1 - static_cast<L>(r2) * r2) / (2 * d);
    const L ex = dx / d, ey = dy / d;
    std::array<double, 2> out{};
    for (int side = 0; side < 2; ++side) {
        const L sign = side == 0 ? 1 : -1;
        const L px = c1.x() + along * ex - sign * height * ey;
        const L py = c1.y() + along * ey + sign * height * ex;
        out[static_cast<std::size_t>(side)] = static_cast<double>(std::atan2(py, px) * 180 / M_PIl);
    }
    return out;
}

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
        EXPECT_NEAR(contourOf(fitted)[k].phiEndDeg, expected[k], 1e-5) << k;
    }
    EXPECT_NEAR(contourOf(fitted).back().phiEndDeg, 360.0, 1e-6);
    EXPECT_TRUE(fitted.value().moves.empty());  // the example's circles touch exactly
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty());
}

TEST(FitWindows, LeavesAFittingContourAsItIs) {
    // The example's circles overlap by 3.4e-8 mm (its numbers have ten digits): nothing moves,
    // and the windows, which the example holds from the exact tangent points, stay within
    // 3e-8° (the tangent point of the circles as they are).
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    const auto fitted = fitWindows(p.value().contour);
    ASSERT_TRUE(fitted.ok());
    EXPECT_TRUE(fitted.value().moves.empty());
    for (std::size_t k = 0; k < p.value().contour.size(); ++k) {
        EXPECT_NEAR(contourOf(fitted)[k].phiEndDeg, p.value().contour[k].phiEndDeg, 1e-7) << k;
        EXPECT_EQ(fitted.value().joints[k].meeting, k + 1 == p.value().contour.size()
                                                        ? JointMeeting::SameCurve
                                                        : JointMeeting::Tangent)
            << k;
    }
}

TEST(FitWindows, MovesLineEndsToTheirIntersections) {
    // A square from four lines whose end points overshoot: fitting puts them on the corners.
    std::vector<SegmentSpec> c(4);
    const Vec corners[] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    for (int k = 0; k < 4; ++k) {
        const Vec a = corners[k], b = corners[(k + 1) % 4];
        c[k].shape = Line{a + 0.2 * (a - b), b + 0.1 * (b - a)};  // 20 %, 10 % beyond corners
        c[k].phiStartDeg = -40.0 + 90.0 * k;
        c[k].phiEndDeg = 50.0 + 90.0 * k;
    }
    c[3].phiEndDeg = 320.0;
    const auto fitted = fitWindows(c);
    ASSERT_TRUE(fitted.ok());
    for (int k = 0; k < 4; ++k) {
        const Line& line = *contourOf(fitted)[k].as<Line>();
        EXPECT_NEAR((line.from - corners[k]).norm(), 0.0, 1e-12) << k;
        EXPECT_NEAR((line.to - corners[(k + 1) % 4]).norm(), 0.0, 1e-12) << k;
        EXPECT_NEAR(contourOf(fitted)[k].phiStartDeg, -45.0 + 90.0 * k, 1e-12) << k;
    }
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty())
        << problemsOf(contourOf(fitted)).front().text();
}

TEST(FitWindows, NamesAJointWhoseNeighboursDoNotMeetWithTheirDistance) {
    std::vector<SegmentSpec> c(2);
    c[0] = {Arc{{0, 0}, 10, Branch::Outer}, 0, 180};
    c[1] = {Arc{{0, 0}, 12, Branch::Outer}, 180, 360};
    const auto fitted = fitWindows(c);
    ASSERT_FALSE(fitted.ok());
    const Diagnostic& d = fitted.errors().front();
    EXPECT_EQ(d.location, "contour[0]/contour[1]");
    EXPECT_EQ(d.code, DiagnosticCode::WindowsSegmentsDoNotMeet);
    // Concentric circles: they miss each other by the difference of their radii.
    ASSERT_EQ(d.args.size(), 1u);
    EXPECT_DOUBLE_EQ(std::get<double>(d.args[0]), 2.0);
    EXPECT_NE(d.message.find("miss each other by 2 mm"), std::string::npos) << d.message;
}

/// The bundled six-lobe cam (whose circles touch to ten digits) with segment k changed.
std::vector<SegmentSpec> exampleWith(std::size_t k, const std::function<void(Arc&)>& change) {
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    std::vector<SegmentSpec> c = p.value().contour;
    change(*c[k].as<Arc>());
    return c;
}

TEST(FitWindows, ARoundingOverlapPutsTheJointAtTheTrueIntersection) {
    // Lobe 3 typed 2e-6 mm too large overlaps both its notches by 2e-6 mm; at the old
    // boundaries (the tangent points) the rays meet the circles 4e-6 mm apart.
    const auto c = exampleWith(3, [](Arc& a) { a.radius += 2e-6; });
    ASSERT_EQ(countCode(problemsOf(c), DiagnosticCode::JointGap), 2u);
    const auto fitted = fitWindows(c);
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    EXPECT_TRUE(fitted.value().moves.empty());  // an overlap moves nothing
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty())
        << problemsOf(contourOf(fitted)).front().text();
    for (std::size_t k : {2u, 3u}) {
        const Arc& a = *c[k].as<Arc>();
        const Arc& b = *c[k + 1].as<Arc>();
        EXPECT_EQ(fitted.value().joints[k].meeting, JointMeeting::Crossing) << k;
        const auto angles = intersectionAnglesDeg(a.center, a.radius, b.center, b.radius);
        // The two intersections lie 0.008° apart, either side of the tangent point; the joint
        // is at the one nearer the boundary as it was.
        const double at = contourOf(fitted)[k].phiEndDeg;
        const double nearest =
            std::abs(angles[0] - at) < std::abs(angles[1] - at) ? angles[0] : angles[1];
        EXPECT_NEAR(at, nearest, 1e-9) << k;
        EXPECT_GT(std::abs(angles[0] - angles[1]), 5e-3) << k;
        EXPECT_LT(std::abs(angles[0] - angles[1]), 2e-2) << k;
        EXPECT_NEAR(nearest, c[k].phiEndDeg, 0.05) << k;
    }
    // The others still touch: their tangent points stay.
    EXPECT_EQ(fitted.value().joints[1].meeting, JointMeeting::Tangent);
}

TEST(FitWindows, AMissWithinTheTypingToleranceMovesTheLaterCircleAlongTheLineOfCentres) {
    // Lobe 3 moved 3e-6 mm towards notch 4: it misses notch 2 (before it) and still overlaps
    // notch 4 after the move.
    const auto c = exampleWith(3, [](Arc& a) { a.center += 3e-6 * Vec(-1, 0); });
    ASSERT_GE(countCode(problemsOf(c), DiagnosticCode::JointGap), 1u);
    const auto fitted = fitWindows(c);
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty())
        << problemsOf(contourOf(fitted)).front().text();
    const auto& moves = fitted.value().moves;
    ASSERT_EQ(moves.size(), 1u);
    // Lobe 3, the later circle of joint 2, moves onto the circle of centres about notch 2's:
    // c3' = c2 + (R2 + R3)·(c3 − c2)/|c3 − c2|.
    EXPECT_EQ(moves[0].segment, 3u);
    EXPECT_EQ(moves[0].neighbour, 2u);
    const Arc& n2 = *c[2].as<Arc>();
    const Arc& l3 = *c[3].as<Arc>();
    const Vec expected = n2.center + (n2.radius + l3.radius) * (l3.center - n2.center).normalized();
    const Arc& moved = std::get<Arc>(moves[0].after);
    EXPECT_NEAR((moved.center - expected).norm(), 0.0, 1e-12);
    EXPECT_EQ(moved.radius, l3.radius);
    EXPECT_NEAR(moves[0].distanceMm, (l3.center - n2.center).norm() - (n2.radius + l3.radius),
                1e-15);
    EXPECT_LE(moves[0].distanceMm, 3e-6);
    EXPECT_EQ(fitted.value().joints[2].meeting, JointMeeting::Tangent);
    // Listed: where the centre was and where it is now.
    ASSERT_EQ(fitted.value().notes.size(), 1u);
    const Diagnostic& note = fitted.value().notes[0];
    EXPECT_EQ(note.severity, Severity::Info);
    EXPECT_EQ(note.code, DiagnosticCode::WindowsCircleMoved);
    EXPECT_EQ(note.location, "contour[3].center");
    EXPECT_NE(note.message.find("touches contour[2]"), std::string::npos) << note.message;
    EXPECT_NE(note.message.find("typing tolerance of 1e-05 mm"), std::string::npos);
}

TEST(FitWindows, ACircleThatMissesBothNeighboursTakesTheSmallestChangeForBoth) {
    // Lobe 3 typed 4e-6 mm too small misses both its notches by 4e-6 mm. Its centre alone
    // would have to move 4e-6/cos 83.8° = 3.7e-5 mm (the lines of centres meet at 167.6°);
    // by symmetry the smallest change is the radius back by 4e-6 mm, the centre where it is.
    const auto c = exampleWith(3, [](Arc& a) { a.radius -= 4e-6; });
    ASSERT_EQ(countCode(problemsOf(c), DiagnosticCode::JointGap), 2u);
    const auto fitted = fitWindows(c);
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty())
        << problemsOf(contourOf(fitted)).front().text();
    ASSERT_EQ(fitted.value().moves.size(), 1u);
    const Arc& was = *c[3].as<Arc>();
    const Arc& now = *contourOf(fitted)[3].as<Arc>();
    const Arc& n2 = *c[2].as<Arc>();
    const Arc& n4 = *c[4].as<Arc>();
    EXPECT_NEAR((now.center - was.center).norm(), 0.0, 1e-12);
    EXPECT_NEAR(now.radius - was.radius, (was.center - n2.center).norm() - (n2.radius + was.radius),
                1e-12);
    EXPECT_NEAR((now.center - n2.center).norm(), n2.radius + now.radius, 1e-12);
    EXPECT_NEAR((now.center - n4.center).norm(), n4.radius + now.radius, 1e-12);
    EXPECT_EQ(fitted.value().joints[2].meeting, JointMeeting::Tangent);
    EXPECT_EQ(fitted.value().joints[3].meeting, JointMeeting::Tangent);
    const Diagnostic& note = fitted.value().notes[0];
    EXPECT_EQ(note.code, DiagnosticCode::WindowsCircleResized);
    EXPECT_EQ(note.location, "contour[3]");
    EXPECT_NE(note.message.find("touches both contour[2] and contour[4]"), std::string::npos)
        << note.message;
    EXPECT_EQ(fitted.value().moves[0].alsoNeighbour, std::optional<std::size_t>(4));
}

TEST(FitWindows, AMissBeyondTheTypingToleranceIsNamedWithItsDistance) {
    const auto c = exampleWith(3, [](Arc& a) { a.radius -= 3e-5; });
    const auto fitted = fitWindows(c);
    ASSERT_FALSE(fitted.ok());
    ASSERT_EQ(fitted.errors().size(), 2u);  // both joints of the lobe
    for (std::size_t i = 0; i < 2; ++i) {
        const Diagnostic& d = fitted.errors()[i];
        const std::size_t k = 2 + i;
        EXPECT_EQ(d.location,
                  "contour[" + std::to_string(k) + "]/contour[" + std::to_string(k + 1) + "]");
        ASSERT_EQ(d.code, DiagnosticCode::WindowsSegmentsDoNotMeet);
        const Arc& a = *c[k].as<Arc>();
        const Arc& b = *c[k + 1].as<Arc>();
        EXPECT_NEAR(std::get<double>(d.args[0]),
                    (b.center - a.center).norm() - (a.radius + b.radius), 1e-15);
        EXPECT_NEAR(std::get<double>(d.args[0]), 3e-5, 1e-7);
    }
}

/// A stadium: arcs of radius 10 about (±5, 0) joined by the lines y = ±10, tangent to both.
std::vector<SegmentSpec> stadium(double topLineY) {
    const double a = radToDeg(std::atan2(10.0, 5.0));
    std::vector<SegmentSpec> c(4);
    c[0] = {Arc{{5, 0}, 10, Branch::Outer}, -a, a};
    c[1] = {Line{{5, topLineY}, {-5, topLineY}}, a, 180.0 - a};
    c[2] = {Arc{{-5, 0}, 10, Branch::Outer}, 180.0 - a, 180.0 + a};
    c[3] = {Line{{-5, -10}, {5, -10}}, 180.0 + a, 360.0 - a};
    return c;
}

TEST(FitWindows, ALineThatMissesByATypingSlipMovesAcrossOntoTheCircle) {
    ASSERT_TRUE(problemsOf(stadium(10.0)).empty());
    const auto fitted = fitWindows(stadium(10.0 + 3e-6));
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    ASSERT_EQ(fitted.value().moves.size(), 1u);
    EXPECT_EQ(fitted.value().moves[0].segment, 1u);
    EXPECT_NEAR(fitted.value().moves[0].distanceMm, 3e-6, 1e-15);
    const Line& top = *contourOf(fitted)[1].as<Line>();
    // Tangent to both arcs: the line y = 10, from (5, 10) to (−5, 10).
    EXPECT_NEAR((top.from - Vec(5, 10)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((top.to - Vec(-5, 10)).norm(), 0.0, 1e-12);
    EXPECT_TRUE(problemsOf(contourOf(fitted)).empty())
        << problemsOf(contourOf(fitted)).front().text();
    EXPECT_EQ(fitted.value().notes[0].code, DiagnosticCode::WindowsLineMoved);

    const auto far = fitWindows(stadium(10.0 + 3e-5));
    ASSERT_FALSE(far.ok());
    EXPECT_EQ(far.errors().front().location, "contour[0]/contour[1]");
    EXPECT_NEAR(std::get<double>(far.errors().front().args[0]), 3e-5, 1e-12);
}

// --- The seed's Table 1 as printed (seed 000; math.md §3) -------------------------------------

/// Table 1 of seed 000 with its 8-digit numbers as printed: outer (lobe) centres in the first
/// two columns, inner (notch) centres in the last two, the notch at 0° split into its first
/// and last row. The radii are those math.md §3 derives from the seed's Table 2:
/// R_lobe = 29 − d1, R_notch = d2 − d1. `thirdLobeY` and `firstNotchX` are the two typos.
std::vector<SegmentSpec> seedTable1(double thirdLobeY, double firstNotchX) {
    const double d1 = 20.89681945, d2 = 25.73752542;
    const double rLobe = 29.0 - d1, rNotch = d2 - d1;
    const Vec lobes[] = {{18.09718091, 10.44841227}, {0.0, 20.89681945},
                         {-18.09717651, thirdLobeY}, {-18.09717681, -10.4484099},
                         {0.0, -20.89681986},        {18.09717686, -10.44840993}};
    const Vec notches[] = {{firstNotchX, 0.0},          {12.86876268, 22.28935079},
                           {-12.86876268, 22.28935079}, {-25.73752542, 0.0},
                           {-12.8687635, -22.28935221}, {12.86876362, -22.28935242},
                           {25.73752722, 0.0}};
    // The windows a designer types from math.md §3: tangent at 30° ± 20.31° + k·60°.
    std::vector<SegmentSpec> c;
    double start = 0.0;
    for (int k = 0; k < 6; ++k) {
        const double mid = 30.0 + 60.0 * k;
        c.push_back({Arc{notches[k], rNotch, Branch::Inner}, start, mid - 20.31});
        c.push_back({Arc{lobes[k], rLobe, Branch::Outer}, mid - 20.31, mid + 20.31});
        start = mid + 20.31;
    }
    c.push_back({Arc{notches[6], rNotch, Branch::Inner}, start, 360.0});
    return c;
}

constexpr double kPrintedThirdLobeY = -18.09717651;  // typo: a copy of its x
constexpr double kPrintedFirstNotchX = 25.74;        // typo: d2 = 25.73752542 rounded away
/// The typos fixed: the third lobe mirrors the first (d1·sin 30° = 10.448409725, to 8 digits);
/// the first notch at d2 as the fifth row and math.md print it.
constexpr double kFixedThirdLobeY = 10.44840972;
constexpr double kFixedFirstNotchX = 25.73752542;

/// The windows at the point on the line of centres where the circles would touch (the foot of
/// their radical line), as Fit Windows put them before it knew better; the split notch at 0°.
std::vector<SegmentSpec> windowsAtLineOfCentres(std::vector<SegmentSpec> c) {
    const std::size_t n = c.size();
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const Arc& a = *c[k].as<Arc>();
        const Arc& b = *c[k + 1].as<Arc>();
        const double d = (b.center - a.center).norm();
        const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d);
        const Vec foot = a.center + along * (b.center - a.center) / d;
        const double deg = radToDeg(std::atan2(foot.y(), foot.x()));
        c[k].phiEndDeg = c[k + 1].phiStartDeg = deg < 0.0 ? deg + 360.0 : deg;
    }
    return c;
}

TEST(FitWindowsSeedTable, TypedWithItsTwoTyposFixedItBecomesValidWithOneFit) {
    const std::vector<SegmentSpec> typed = seedTable1(kFixedThirdLobeY, kFixedFirstNotchX);
    EXPECT_FALSE(problemsOf(typed).empty());
    // The issue: with the joints on the lines of centres, 8 of the 13 joints stay open by
    // 1.3e-6 to 2.3e-6 mm, beyond the validator's 1e-6 mm; nothing else is wrong.
    const Diagnostics onCentreLines = problemsOf(windowsAtLineOfCentres(typed));
    EXPECT_EQ(countCode(onCentreLines, DiagnosticCode::JointGap), 8u);
    EXPECT_EQ(onCentreLines.size(), 8u);
    for (const Diagnostic& d : onCentreLines) {
        EXPECT_GT(std::get<double>(d.args[1]), 1.2e-6) << d.text();
        EXPECT_LT(std::get<double>(d.args[1]), 2.3e-6) << d.text();
    }

    const auto fitted = fitWindows(typed);
    ASSERT_TRUE(fitted.ok()) << fitted.errors().front().text();
    const FittedWindows& f = fitted.value();
    // The validator's own verdict on the result.
    const Diagnostics after = problemsOf(f.contour);
    EXPECT_TRUE(after.empty()) << after.front().text();
    // No circle changed by more than the typing tolerance: against the circles themselves.
    EXPECT_GT(f.largestMoveMm(), 0.0);
    EXPECT_LE(f.largestMoveMm(), kTypingToleranceMm);
    std::size_t changed = 0;
    for (std::size_t k = 0; k < typed.size(); ++k) {
        const Arc& was = *typed[k].as<Arc>();
        const Arc& now = *f.contour[k].as<Arc>();
        EXPECT_EQ(now.branch, was.branch) << k;
        const double change = (now.center - was.center).norm() + std::abs(now.radius - was.radius);
        EXPECT_LE(change, kTypingToleranceMm) << k;
        changed += change > 0.0;
    }
    // Each change listed once, with how far the circle moved.
    ASSERT_EQ(f.moves.size(), changed);
    ASSERT_EQ(f.notes.size(), changed);
    for (const SegmentMove& m : f.moves) {
        const Arc& was = *typed[m.segment].as<Arc>();
        const Arc& now = *f.contour[m.segment].as<Arc>();
        EXPECT_DOUBLE_EQ(m.distanceMm,
                         (now.center - was.center).norm() + std::abs(now.radius - was.radius))
            << m.segment;
        // A moved circle touches its neighbour exactly (a piece of the split notch is the
        // other piece's circle).
        const Arc& other = *f.contour[m.neighbour].as<Arc>();
        if (m.tookNeighboursCurve) {
            EXPECT_EQ(now.center, other.center) << m.segment;
        } else {
            EXPECT_NEAR((now.center - other.center).norm(), now.radius + other.radius, 1e-12)
                << m.segment;
        }
    }
    // Every joint: the two circles touch (within the typing tolerance; the joint then at the
    // tangent point, which the validator accepted above) or cross, and then the joint is at
    // one of their intersections in closed form.
    const std::size_t n = f.contour.size();
    std::size_t crossings = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Arc& a = *f.contour[k].as<Arc>();
        const Arc& b = *f.contour[(k + 1) % n].as<Arc>();
        const double at = f.joints[k].angleDeg;
        switch (f.joints[k].meeting) {
            case JointMeeting::SameCurve:
                EXPECT_EQ(a.center, b.center) << k;
                EXPECT_EQ(a.radius, b.radius) << k;
                break;
            case JointMeeting::Tangent:
                EXPECT_NEAR((b.center - a.center).norm(), a.radius + b.radius, kTypingToleranceMm)
                    << k;
                break;
            case JointMeeting::Crossing: {
                ++crossings;
                const auto angles = intersectionAnglesDeg(a.center, a.radius, b.center, b.radius);
                EXPECT_NEAR(
                    std::min(std::abs(wrapDeg(angles[0] - at)), std::abs(wrapDeg(angles[1] - at))),
                    0.0, 1e-9)
                    << k;
                break;
            }
            case JointMeeting::SplineEnd:
                ADD_FAILURE() << k;
        }
        // Tangent at 30° ± 20.30859° + k·60° (math.md §3) to within the rounding.
        const double mid = 30.0 + 60.0 * static_cast<double>(k / 2);
        const double expected = k == n - 1 ? 360.0 : mid + (k % 2 == 0 ? -20.30859 : 20.30859);
        EXPECT_NEAR(f.contour[k].phiEndDeg, expected, 0.01) << k;
    }
    std::cout << "[ seed table ] " << changed << " circles changed, the largest by "
              << f.largestMoveMm() << " mm; " << crossings << " joints at intersections\n";
    for (const Diagnostic& d : f.notes) std::cout << "  " << d.text() << "\n";
}

TEST(FitWindowsSeedTable, AsPrintedItCannotBeFittedAndTheJointsAreNamedWithTheirGaps) {
    // With the typo in the third lobe, that circle lies 28.9 mm from both its notches.
    const std::vector<SegmentSpec> printed = seedTable1(kPrintedThirdLobeY, kFixedFirstNotchX);
    const auto fitted = fitWindows(printed);
    ASSERT_FALSE(fitted.ok());
    ASSERT_EQ(fitted.errors().size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const Diagnostic& d = fitted.errors()[i];
        const std::size_t k = 4 + i;
        EXPECT_EQ(d.location,
                  "contour[" + std::to_string(k) + "]/contour[" + std::to_string(k + 1) + "]");
        const Arc& a = *printed[k].as<Arc>();
        const Arc& b = *printed[k + 1].as<Arc>();
        EXPECT_NEAR(std::get<double>(d.args[0]),
                    (b.center - a.center).norm() - (a.radius + b.radius), 1e-12);
    }
    // The other typo alone: the first notch 2.5e-3 mm off misses lobe 1 (by 1.4e-3 mm) and
    // is too far from its other half to be one circle with it.
    const auto notch = fitWindows(seedTable1(kFixedThirdLobeY, kPrintedFirstNotchX));
    ASSERT_FALSE(notch.ok());
    EXPECT_EQ(notch.errors().front().code, DiagnosticCode::WindowsSegmentsDoNotMeet);
    EXPECT_GT(std::get<double>(notch.errors().front().args[0]), kTypingToleranceMm);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(FitWindowsSeedTable, AnyRoundingOfTheCentresToSixDecimalsFitsWithinTheTolerance) {
    // Every centre coordinate of the example off by up to ±1e-6 mm, as six decimals leave them
    // (the seed prints eight): each draw must become valid, no circle changed by more than the
    // typing tolerance.
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    std::mt19937 random(29);
    std::uniform_real_distribution<double> slip(-1e-6, 1e-6);
    double largest = 0.0;
    int crossings = 0, moved = 0;
    for (int draw = 0; draw < 500; ++draw) {
        std::vector<SegmentSpec> c = p.value().contour;
        for (std::size_t k = 0; k + 1 < c.size(); ++k) {
            c[k].as<Arc>()->center += Vec(slip(random), slip(random));
        }
        c.back().as<Arc>()->center = c.front().as<Arc>()->center + Vec(slip(random), 0.0);
        const auto fitted = fitWindows(c);
        ASSERT_TRUE(fitted.ok()) << draw << ": " << fitted.errors().front().text();
        const Diagnostics after = problemsOf(fitted.value().contour);
        ASSERT_TRUE(after.empty()) << draw << ": " << after.front().text();
        ASSERT_LE(fitted.value().largestMoveMm(), kTypingToleranceMm) << draw;
        largest = std::max(largest, fitted.value().largestMoveMm());
        moved += static_cast<int>(fitted.value().moves.size());
        for (const FittedJoint& j : fitted.value().joints) {
            crossings += j.meeting == JointMeeting::Crossing;
        }
    }
    std::cout << "[ rounding ] largest change " << largest << " mm, " << moved
              << " circles changed, " << crossings << " joints at intersections in 500 draws\n";
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(FitWindows, ASplineWithANaNInItIsNeitherMovedNorACrash) {
    // A NaN makes a segment unequal to itself: Fit Windows once took that for a move and read
    // the spline as a line (std::bad_variant_access, found by app_tests RandomEdits). It must
    // leave the spline alone; the NaN is validation's to report.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<SegmentSpec> contour{
        SegmentSpec{Arc{{0.0, 0.0}, 20.0, Branch::Outer}, 0.0, 180.0},
        SegmentSpec{HermiteCurve{{-20.0, 0.0}, {0.0, -30.0}, {20.0, 0.0}, {nan, 30.0}}, 180.0,
                    360.0}};
    const auto fitted = fitWindows(contour);  // must return, whatever it says
    if (fitted.ok()) {
        EXPECT_TRUE(fitted.value().moves.empty());
    } else {
        EXPECT_FALSE(fitted.errors().empty());
    }
}

}  // namespace
}  // namespace cam
