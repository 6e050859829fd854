// Motion laws and designs (math.md §8), checked against math.md's table of Cv, Ca, Cj (found
// here by dense sampling, not taken from the code; for a law math.md does not list, against its
// closed form), central differences of y, v and a, the boundary values a poly5 is asked for, and
// the cycloidal cam of math.md §8 by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "common/angles.h"
#include "core/test_projects.h"
#include "design/motion_design.h"
#include "design/motion_law.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

/// A normalised law's reference values: one row per law of LawShape::Normalised.
struct Table {
    MotionLawType law;
    double cv, ca, cj;  // as math.md §8 gives them, or the closed form (cj < 0: not given)
    double digits;      // the table's last digit (0: a closed form)
    double v0, v1;      // y'(0), y'(1)
    double a0, a1;      // y''(0), y''(1)
};

const double kHalfPi2 = kPi * kPi / 2.0;

const Table kTable[] = {
    // Harmonic: y = (1 − cos πx)/2, so y''(0) = π²/2 and y''(1) = −π²/2.
    {MotionLawType::Harmonic, 1.5708, 4.9348, -1.0, 1e-4, 0, 0, kHalfPi2, -kHalfPi2},
    {MotionLawType::Cycloidal, 2.0, 6.2832, 39.478, 1e-3, 0, 0, 0, 0},
    {MotionLawType::ModifiedTrapezoid, 2.0, 4.8881, 61.43, 1e-2, 0, 0, 0, 0},
    {MotionLawType::ModifiedSine, 1.7596, 5.5280, 69.47, 1e-2, 0, 0, 0, 0},
    {MotionLawType::Poly345, 1.875, 5.7735, 60.0, 1e-4, 0, 0, 0, 0},
    {MotionLawType::Poly4567, 2.1875, 7.5132, 52.5, 1e-4, 0, 0, 0, 0},
    // Not in math.md: y = x, y' = 1, y'' = y''' = 0, at speed at both ends.
    {MotionLawType::ConstantVelocity, 1.0, 0.0, 0.0, 0.0, 1, 1, 0, 0},
    // At their default parameters (an end velocity of 0; b = d = 0.25) the inclined sine is
    // the cycloid and SCCA the modified trapezoid: math.md's rows of those. Their other
    // parameters: motion_law_reference_test.cpp.
    {MotionLawType::InclinedSine, 2.0, 6.2832, 39.478, 1e-3, 0, 0, 0, 0},
    {MotionLawType::Scca, 2.0, 4.8881, 61.43, 1e-2, 0, 0, 0, 0},
};

/// max |f| over [0, 1]: 200 001 samples, the best refined by golden sections.
double sampledMax(const std::function<double(double)>& f) {
    constexpr int n = 200000;
    int best = 0;
    for (int i = 1; i <= n; ++i) {
        if (std::abs(f(static_cast<double>(i) / n)) > std::abs(f(static_cast<double>(best) / n)))
            best = i;
    }
    double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
    for (int it = 0; it < 100; ++it) {
        const double a = lo + (hi - lo) / 3.0, b = hi - (hi - lo) / 3.0;
        (std::abs(f(a)) < std::abs(f(b)) ? lo : hi) = std::abs(f(a)) < std::abs(f(b)) ? a : b;
    }
    return std::max({std::abs(f(0.5 * (lo + hi))), std::abs(f(static_cast<double>(best) / n))});
}

TEST(MotionLaw, EveryNormalisedLawHasAReferenceRow) {
    // The table below is read from the laws' table, so a new law cannot go untested.
    for (const MotionLawKind& kind : motionLaws()) {
        const bool listed =
            std::ranges::any_of(kTable, [&](const Table& row) { return row.law == kind.type; });
        EXPECT_EQ(listed, kind.shape == LawShape::Normalised) << kind.name;
    }
}

TEST(MotionLaw, CharacteristicValuesAreThoseOfMathMdsTable) {
    for (const Table& row : kTable) {
        const std::string name(lawName(row.law));
        const double cv = sampledMax([&](double x) { return normalisedLaw(row.law, x).v; });
        // Inside the interval: harmonic's acceleration jumps at its ends, not its jerk's size.
        const double ca = sampledMax([&](double x) { return normalisedLaw(row.law, x).a; });
        const double cj = sampledMax([&](double x) { return normalisedLaw(row.law, x).j; });
        EXPECT_NEAR(cv, row.cv, row.digits / 2 + 1e-12) << name;
        EXPECT_NEAR(ca, row.ca, row.digits / 2 + 1e-12) << name;
        if (row.cj >= 0.0) {
            EXPECT_NEAR(cj, row.cj, row.digits / 2 + 1e-12) << name;
        }
        // The closed forms the app shows agree with the sampling.
        const LawCoefficients c = lawCoefficients(row.law);
        EXPECT_TRUE(relClose(c.cv, cv, 1e-9)) << name;
        EXPECT_TRUE(relClose(c.ca, ca, 1e-9)) << name;
        EXPECT_TRUE(relClose(c.cj, cj, 1e-9)) << name;
    }
}

TEST(MotionLaw, RisesFromZeroToOneWithTheEndConditionsOfItsRow) {
    for (const Table& row : kTable) {
        const std::string name(lawName(row.law));
        const LawPoint start = normalisedLaw(row.law, 0.0), end = normalisedLaw(row.law, 1.0);
        EXPECT_NEAR(start.y, 0.0, 1e-15) << name;
        EXPECT_NEAR(end.y, 1.0, 1e-14) << name;
        EXPECT_NEAR(start.v, row.v0, 1e-14) << name;
        EXPECT_NEAR(end.v, row.v1, 1e-13) << name;
        EXPECT_NEAR(start.a, row.a0, 1e-13) << name;
        EXPECT_NEAR(end.a, row.a1, 1e-12) << name;
        // Symmetric rises: y(1 − x) = 1 − y(x).
        for (double x = 0.013; x < 1.0; x += 0.0731) {
            EXPECT_NEAR(normalisedLaw(row.law, 1.0 - x).y, 1.0 - normalisedLaw(row.law, x).y, 1e-14)
                << name << " " << x;
        }
    }
    EXPECT_EQ(normalisedLaw(MotionLawType::Dwell, 0.4).y, 0.0);
}

TEST(MotionLaw, DerivativesAreThoseOfTheLawItself) {
    // Central differences of y, v and a, including just either side of the piece boundaries of
    // the modified laws (1/8, 3/8, 5/8, 7/8), where y, v and a must also be continuous.
    constexpr double h = 1e-5;
    for (const Table& row : kTable) {
        const std::string name(lawName(row.law));
        const auto at = [&](double x) { return normalisedLaw(row.law, x); };
        for (double x : {0.01, 0.1, 0.124, 0.126, 0.2, 0.374, 0.376, 0.5, 0.624, 0.626, 0.77, 0.874,
                         0.876, 0.95}) {
            const LawPoint p = at(x), lo = at(x - h), hi = at(x + h);
            EXPECT_NEAR(p.v, (hi.y - lo.y) / (2 * h), 1e-7) << name << x;
            EXPECT_NEAR(p.a, (hi.v - lo.v) / (2 * h), 1e-6) << name << x;
            EXPECT_NEAR(p.j, (hi.a - lo.a) / (2 * h), 1e-4) << name << x;
        }
        for (double b : {0.125, 0.375, 0.625, 0.875}) {
            const LawPoint l = at(b - 1e-13), r = at(b + 1e-13);
            EXPECT_NEAR(l.y, r.y, 1e-12) << name << b;
            EXPECT_NEAR(l.v, r.v, 1e-11) << name << b;
            EXPECT_NEAR(l.a, r.a, 1e-10) << name << b;
        }
    }
}

TEST(MotionLaw, NamesReadBack) {
    for (std::size_t k = 0; k < kMotionLawCount; ++k) {
        const auto law = static_cast<MotionLawType>(k);
        EXPECT_EQ(lawFromName(lawName(law)), law);
    }
    EXPECT_EQ(lawFromName("modified-trapezoid"), MotionLawType::ModifiedTrapezoid);
    EXPECT_EQ(lawFromName("line"), MotionLawType::ConstantVelocity);
    EXPECT_FALSE(lawFromName("sinus"));
}

TEST(MotionLaw, Poly5MeetsItsBoundaryValues) {
    std::uint64_t state = 7;
    const auto random = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / 9007199254740992.0 * 2.0 - 1.0;
    };
    for (int i = 0; i < 50; ++i) {
        const double h = 0.3 + 2.0 * std::abs(random()), y0 = 10 * random(), y1 = 10 * random();
        const double v0 = 5 * random(), a0 = 20 * random(), v1 = 5 * random(), a1 = 20 * random();
        const Poly5Law law(h, y0, y1, v0, a0, v1, a1);
        const LawPoint s = law.at(0.0), e = law.at(1.0);
        EXPECT_TRUE(relClose(s.y, y0, 1e-12, 1.0));
        EXPECT_TRUE(relClose(e.y, y1, 1e-12, 10.0));
        EXPECT_TRUE(relClose(s.v, v0, 1e-12, 1.0));
        EXPECT_TRUE(relClose(e.v, v1, 1e-11, 10.0));
        EXPECT_TRUE(relClose(s.a, a0, 1e-12, 1.0));
        EXPECT_TRUE(relClose(e.a, a1, 1e-11, 100.0));
        // Derivatives with respect to x = x0 + u·h.
        const double u = 0.37, du = 1e-6;
        EXPECT_NEAR(law.at(u).v, (law.at(u + du).y - law.at(u - du).y) / (2 * du * h),
                    1e-6 * (1 + std::abs(law.at(u).v)));
    }
    // At rest at both ends it is poly345, scaled.
    const Poly5Law rest(2.0, 1.0, 4.0, 0.0, 0.0, 0.0, 0.0);
    for (double u = 0.0; u <= 1.0; u += 0.05) {
        EXPECT_NEAR(rest.at(u).y, 1.0 + 3.0 * normalisedLaw(MotionLawType::Poly345, u).y, 1e-13);
    }
}

TEST(MotionDesign, TheCycloidalCamOfMathMd) {
    const auto design = MotionDesign::build(test::cycloidalDesign());
    ASSERT_TRUE(design.ok()) << design.errors().front().text();
    const MotionDesign& m = design.value();
    const double h = degToRad(120.0);
    // By hand: s = 10·(x − sin 2πx / 2π); at 60° x = ½, s = 5, s' = 10·2/h (Cv = 2).
    EXPECT_NEAR(m.liftAt(degToRad(60.0))[0], 5.0, 1e-13);
    EXPECT_NEAR(m.liftAt(degToRad(60.0))[1], 20.0 / h, 1e-12);
    EXPECT_NEAR(m.liftAt(degToRad(30.0))[0], 10.0 * (0.25 - 1.0 / kTwoPi), 1e-13);
    EXPECT_NEAR(m.liftAt(degToRad(30.0))[2], 10.0 * kTwoPi / (h * h), 1e-10);
    EXPECT_EQ(m.liftAt(degToRad(150.0))[0], 10.0);
    EXPECT_NEAR(m.liftAt(degToRad(240.0))[0], 5.0, 1e-13);
    EXPECT_NEAR(m.liftAt(degToRad(240.0))[1], -20.0 / h, 1e-12);
    EXPECT_EQ(m.liftAt(degToRad(330.0))[0], 0.0);
    EXPECT_TRUE(m.jumps().empty()) << m.jumps().front().text();
    // Any real angle: whole turns either way.
    for (double deg : {17.0, 133.0, 250.5}) {
        const auto a = m.liftAt(degToRad(deg)), b = m.liftAt(degToRad(deg) + 3 * kTwoPi),
                   c = m.liftAt(degToRad(deg) - 2 * kTwoPi);
        EXPECT_NEAR(a[0], b[0], 1e-12);
        EXPECT_NEAR(a[1], c[1], 1e-11);
    }
    // Derivatives against central differences.
    constexpr double d = 1e-6;
    for (double deg = 2.5; deg < 360.0; deg += 11.0) {  // off the joints (jerk jumps there)
        const double phi = degToRad(deg);
        const auto p = m.liftAt(phi), lo = m.liftAt(phi - d), hi = m.liftAt(phi + d);
        EXPECT_NEAR(p[1], (hi[0] - lo[0]) / (2 * d), 1e-7) << deg;
        EXPECT_NEAR(p[2], (hi[1] - lo[1]) / (2 * d), 1e-6) << deg;
        EXPECT_NEAR(p[3], (hi[2] - lo[2]) / (2 * d), 1e-4) << deg;
    }
    EXPECT_EQ(m.segmentAt(degToRad(119.0)), 0u);
    EXPECT_EQ(m.segmentAt(degToRad(121.0)), 1u);
    EXPECT_EQ(m.segmentAt(degToRad(359.0)), 3u);
}

TEST(MotionDesign, AHarmonicRiseBetweenDwellsJumpsInAcceleration) {
    DesignSpec d = test::cycloidalDesign();
    d.segments[0].law = MotionLawType::Harmonic;
    const auto m = MotionDesign::build(d);
    ASSERT_TRUE(m.ok());
    // y'' = ±π²/2 at the ends: the lift's acceleration jumps by Δ·π²/(2h²) per rad², in the
    // message per degree².
    ASSERT_EQ(m.value().jumps().size(), 2u);
    EXPECT_EQ(m.value().jumps()[0].location, "design.segments[0]/design.segments[1]");
    EXPECT_EQ(m.value().jumps()[1].location, "design.segments[3]/design.segments[0]");
    EXPECT_EQ(m.value().jumps()[0].severity, Severity::Info);
    const double h = degToRad(120.0), perDeg2 = std::pow(kPi / 180.0, 2);
    const double jump = 10.0 * kPi * kPi / (2 * h * h) * perDeg2;
    const std::string& message = m.value().jumps()[1].message;
    const auto to = message.find(" to ");
    ASSERT_NE(to, std::string::npos) << message;
    // The message rounds to kMessageDigits = 10 significant digits.
    EXPECT_TRUE(relClose(std::stod(message.substr(to + 4)), jump, 1e-9)) << message;
    EXPECT_EQ(m.value().jumps()[0].message.find("velocity"), std::string::npos);
}

TEST(MotionDesign, AConstantVelocityRiseBetweenDwellsIsALawThatCannotMeetItsClasses) {
    // Dwell 0–60°, a line up 10 mm to 180°, dwell to 240°, a line back down to 360°: each line
    // starts and ends at constant velocity where its dwells are at rest, so its velocity would
    // jump by 10/120 mm per degree at each of the four joints — a corner in the cam, an
    // impulse in the servo. Refused at each line's law, with both velocities.
    DesignSpec d = test::cycloidalDesign();
    d.segments = {{MotionLawType::Dwell, 60.0, 0.0},
                  {MotionLawType::ConstantVelocity, 180.0, 10.0},
                  {MotionLawType::Dwell, 240.0, 10.0},
                  {MotionLawType::ConstantVelocity, 360.0, 0.0}};
    const auto built = MotionDesign::build(d);
    ASSERT_FALSE(built.ok());
    const double perDeg = 10.0 / 120.0;
    struct Expected {
        std::string location;
        double own, other;
    };
    const Expected expected[] = {{"design.segments[1].law", perDeg, 0.0},
                                 {"design.segments[1].law", perDeg, 0.0},
                                 {"design.segments[3].law", -perDeg, 0.0},
                                 {"design.segments[3].law", -perDeg, 0.0}};
    ASSERT_EQ(built.errors().size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        const Diagnostic& e = built.errors()[k];
        EXPECT_EQ(e.code, DiagnosticCode::DesignBoundaryMismatch) << e.text();
        EXPECT_EQ(e.location, expected[k].location) << e.text();
        ASSERT_EQ(e.args.size(), 5u) << e.text();
        EXPECT_EQ(std::get<std::string>(e.args[1]), "rest") << e.text();
        EXPECT_NEAR(std::get<double>(e.args[3]), expected[k].own, 1e-15) << e.text();
        EXPECT_NEAR(std::get<double>(e.args[4]), expected[k].other, 1e-15) << e.text();
    }
    // The lift itself is the straight line, by hand: s = 10·(φ − 60°)/120°, s' = 10/h per rad.
    const auto lenient = MotionDesign::buildIgnoringJoints(d);
    ASSERT_TRUE(lenient.ok());
    const MotionDesign& m = lenient.value();
    const double h = degToRad(120.0);
    EXPECT_NEAR(m.liftAt(degToRad(90.0))[0], 2.5, 1e-13);
    EXPECT_NEAR(m.liftAt(degToRad(90.0))[1], 10.0 / h, 1e-12);
    EXPECT_EQ(m.liftAt(degToRad(90.0))[2], 0.0);
    EXPECT_NEAR(m.liftAt(degToRad(300.0))[0], 5.0, 1e-13);
    EXPECT_NEAR(m.liftAt(degToRad(300.0))[1], -10.0 / h, 1e-12);
    const LawCoefficients c = m.coefficients(1);
    EXPECT_EQ(c.cv, 1.0);
    EXPECT_EQ(c.ca, 0.0);
    EXPECT_EQ(c.cj, 0.0);
}

TEST(MotionDesign, EveryProblemHasItsPlace) {
    struct Case {
        std::function<void(DesignSpec&)> edit;
        std::string location, says;
    };
    const Case cases[] = {
        {[](DesignSpec& d) { d.segments.clear(); }, "design.segments", "at least one"},
        {[](DesignSpec& d) { d.baseRadius = 0.0; }, "design.base_radius", "> 0"},
        {[](DesignSpec& d) { d.tolerance = -1.0; }, "design.tolerance", "> 0"},
        {[](DesignSpec& d) { d.segments[2].toDeg = 170.0; }, "design.segments[2].to_deg", "180"},
        {[](DesignSpec& d) { d.segments[0].toDeg = 0.0; }, "design.segments[0].to_deg", "0°"},
        {[](DesignSpec& d) { d.segments[3].toDeg = 350.0; }, "design.segments[3].to_deg", "360"},
        {[](DesignSpec& d) { d.segments[1].lift = 9.0; }, "design.segments[1].lift", "dwell"},
        {[](DesignSpec& d) { d.segments[0].lift = 0.0; }, "design.segments[0].lift", "dwell"},
        {[](DesignSpec& d) { d.segments[2].lift = d.segments[3].lift = 1.0; },
         "design.segments[3].lift", "return"},
        {[](DesignSpec& d) { d.segments[0].lift = std::nan(""); }, "design.segments[0].lift",
         "finite"},
    };
    for (const Case& c : cases) {
        DesignSpec d = test::cycloidalDesign();
        c.edit(d);
        const auto m = MotionDesign::build(d);
        ASSERT_FALSE(m.ok()) << c.location;
        bool found = false;
        std::string all;
        for (const Diagnostic& e : m.errors()) {
            all += e.text() + "\n";
            found =
                found || (e.location == c.location && e.message.find(c.says) != std::string::npos);
        }
        EXPECT_TRUE(found) << c.location << " / " << c.says << "\n" << all;
    }
}

TEST(MotionDesign, Poly5SlopesArePerDegree) {
    // A poly5 return whose end slope is −0.01 mm/° and end acceleration 0.002 mm/°².
    DesignSpec d = test::cycloidalDesign();
    d.segments[2] = {MotionLawType::Poly5, 300.0, 0.0, 0.0, 0.0, -0.01, 0.002};
    const auto m = MotionDesign::buildIgnoringJoints(d);
    ASSERT_TRUE(m.ok());
    const auto end = m.value().liftAt(degToRad(300.0) - 1e-12);
    EXPECT_NEAR(end[1] * kPi / 180.0, -0.01, 1e-10);
    EXPECT_NEAR(end[2] * std::pow(kPi / 180.0, 2), 0.002, 1e-9);
    // …which the dwell after it, at rest, cannot take: refused at the poly5's law.
    const auto refused = MotionDesign::build(d);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.errors().front().location, "design.segments[2].law");
    EXPECT_NE(refused.errors().front().message.find("-0.01"), std::string::npos)
        << refused.errors().front().message;
    const LawCoefficients c = m.value().coefficients(0);
    EXPECT_EQ(c.cv, 2.0);
}

}  // namespace
}  // namespace cam
