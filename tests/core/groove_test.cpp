// A groove's flanks (closure/groove.h), checked against geometric facts that do not depend on
// the code: the offsets of a circle are circles about its centre, so the flanks of an arc table
// are arc tables whose radii differ by the roller radius and by twice it plus the clearance;
// every point of the outer flank lies the roller radius plus the clearance from the pitch curve
// and twice the roller radius plus the clearance from the inner flank (measured here by brute
// force over the sampled curves); a concave stretch tighter than that is refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "closure/groove.h"
#include "common/angles.h"
#include "core/follower_geometry.h"
#include "core/test_projects.h"
#include "evaluation/evaluation.h"
#include "evaluation/force_evaluation.h"

namespace cam {
namespace {

using test::sixLobe;

/// Points along a path, `perPiece` per segment.
std::vector<Eigen::Vector2d> sample(const ToolPath& path, int perPiece) {
    std::vector<Eigen::Vector2d> points;
    for (const PathSegment& s : path.segments) {
        for (int k = 0; k < perPiece; ++k) {
            const Eigen::Vector3d p = s.point(s.length() * (k + 0.5) / perPiece);
            points.emplace_back(p.x(), p.y());
        }
    }
    return points;
}

double nearest(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& curve) {
    double best = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& q : curve) best = std::min(best, (p - q).norm());
    return best;
}

TEST(Groove, AnEccentricCircleHasConcentricCirclesForFlanks) {
    Project p;
    p.motion = {SpeedUnit::PeriodS, 1.0};
    p.contour.push_back(SegmentSpec{Arc{{5.0, 0.0}, 30.0, Branch::Outer}, 0.0, 360.0});
    const auto contour = Contour::build(p);
    ASSERT_TRUE(contour.ok());
    const auto groove = grooveFlanks(contour.value(), 5.0, 0.3);
    ASSERT_TRUE(groove.ok()) << groove.errors().front().text();
    ASSERT_EQ(groove.value().pitch.segments.size(), 1u);
    ASSERT_EQ(groove.value().outer.segments.size(), 1u);
    const PathSegment& pitch = groove.value().pitch.segments[0];
    const PathSegment& outer = groove.value().outer.segments[0];
    EXPECT_EQ(pitch.kind, PathSegment::Kind::Arc);
    EXPECT_EQ(outer.kind, PathSegment::Kind::Arc);
    EXPECT_NEAR(pitch.radius, 35.0, 1e-12);
    EXPECT_NEAR(outer.radius, 40.3, 1e-12);
    EXPECT_NEAR((outer.center - Eigen::Vector2d(5.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(outer.sweep), kTwoPi, 1e-12);
}

TEST(Groove, TheSixLobeCamsOuterFlankKeepsItsDistanceFromBothCurves) {
    const Contour contour = sixLobe();
    const double rho = 1.0, clearance = 0.2;
    const auto groove = grooveFlanks(contour, rho, clearance);
    ASSERT_TRUE(groove.ok()) << groove.errors().front().text();
    // Arc for arc: a lobe (convex) grows by 2ρ + c, a notch (concave) shrinks by it; the
    // centres stay. The six-lobe cam's joints are tangent: no corner arcs.
    const auto& outer = groove.value().outer.segments;
    ASSERT_EQ(outer.size(), contour.size());
    for (std::size_t k = 0; k < contour.size(); ++k) {
        const ContourSegment& s = contour.segment(k);
        ASSERT_EQ(s.type, SegmentType::Arc);
        const bool lobe = s.arc.branch == Branch::Outer;
        EXPECT_NEAR(outer[k].radius, s.arc.radius + (lobe ? 1.0 : -1.0) * (2 * rho + clearance),
                    1e-9)
            << k;
        EXPECT_NEAR((outer[k].center - s.arc.center).norm(), 0.0, 1e-12) << k;
    }
    // Brute force, independent of the offset rule: the outer flank's points against dense
    // samples of the pitch curve and of the profile r(φ) itself.
    const std::vector<Eigen::Vector2d> pitch = sample(groove.value().pitch, 4000);
    std::vector<Eigen::Vector2d> profile;
    for (int k = 0; k < 200000; ++k) {
        const double phi = kTwoPi * k / 200000.0;
        const double r = contour.evaluate(phi).r;
        profile.emplace_back(r * std::cos(phi), r * std::sin(phi));
    }
    for (const Eigen::Vector2d& p : sample(groove.value().outer, 40)) {
        EXPECT_NEAR(nearest(p, pitch), rho + clearance, 2e-4);
        EXPECT_NEAR(nearest(p, profile), 2 * rho + clearance, 2e-4);
    }
}

TEST(Groove, ANotchTighterThanTheGrooveIsRefusedByName) {
    const Contour contour = sixLobe();
    // The notches have radius 4.8407…: a 2 mm roller with 1 mm clearance needs 5 mm.
    const auto groove = grooveFlanks(contour, 2.0, 1.0);
    ASSERT_FALSE(groove.ok());
    std::size_t notches = 0;
    for (std::size_t k = 0; k < contour.size(); ++k) {
        if (contour.segment(k).arc.branch == Branch::Inner) ++notches;
    }
    ASSERT_EQ(groove.errors().size(), notches);
    for (const Diagnostic& d : groove.errors()) {
        EXPECT_EQ(d.code, DiagnosticCode::GrooveOuterFlankUndercut);
        const auto* place = std::get_if<SegmentPlace>(&d.place);
        ASSERT_NE(place, nullptr);
        const ContourSegment& s = contour.segment(place->segment);
        EXPECT_EQ(s.arc.branch, Branch::Inner);
        EXPECT_EQ(std::get<double>(d.args.at(2)), s.arc.radius);
        EXPECT_NE(d.text().find("2 mm with 1 mm clearance"), std::string::npos) << d.text();
    }
    // With room to spare it is made.
    EXPECT_TRUE(grooveFlanks(contour, 2.0, 0.8).ok());
}

TEST(Groove, ANegativeClearanceOrRadiusIsRefusedAtItsField) {
    const Contour contour = sixLobe();
    const auto groove = grooveFlanks(contour, 1.0, -0.1);
    ASSERT_FALSE(groove.ok());
    EXPECT_EQ(groove.errors().front().location, "follower.groove_clearance_mm");
    const auto nan = grooveFlanks(contour, std::nan(""), 0.1);
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.errors().front().location, "follower.radius");
}

TEST(GrooveLands, AnEccentricCirclesFlanksComeNearestAndFarthestOnItsAxis) {
    // Closed form: a circle of radius R about (E, 0) comes to R − E from the centre at 180° and
    // reaches R + E at 0°; the outer flank is the circle R + 2ρ + c about the same centre.
    const double E = 5.0, R = 30.0, rho = 5.0, c = 0.3;
    const auto groove = grooveFlanks(test::disc({E, 0.0}, R), rho, c);
    ASSERT_TRUE(groove.ok());
    const GrooveLands lands = grooveLands(groove.value(), 25.5, 45.0);
    EXPECT_NEAR(lands.innerMost.radius, R - E, 1e-12);
    EXPECT_NEAR(lands.innerMost.phi, kPi, 1e-12);
    EXPECT_NEAR(lands.outerMost.radius, R + 2 * rho + c + E, 1e-12);
    EXPECT_NEAR(std::abs(std::remainder(lands.outerMost.phi, kTwoPi)), 0.0, 1e-12);
    // 25 < 25.5: the groove cuts into the bore's land; 45.3 > 45: into the rim's.
    EXPECT_FALSE(lands.innerKept());
    EXPECT_FALSE(lands.outerKept());
    const GrooveLands roomy = grooveLands(groove.value(), 24.9, 45.4);
    EXPECT_TRUE(roomy.innerKept());
    EXPECT_TRUE(roomy.outerKept());
    const GrooveLands unchecked = grooveLands(groove.value(), std::nullopt, std::nullopt);
    EXPECT_TRUE(unchecked.innerKept());
    EXPECT_TRUE(unchecked.outerKept());
}

TEST(GrooveLands, TheSixLobeCamsExtremesAgreeWithADenseSampling) {
    const Contour contour = sixLobe();
    const auto groove = grooveFlanks(contour, 1.0, 0.2);
    ASSERT_TRUE(groove.ok());
    const GrooveLands lands = grooveLands(groove.value(), std::nullopt, std::nullopt);
    // r(φ) itself for the inner flank; dense points of the outer flank.
    double nearestR = 1e300;
    for (int k = 0; k < 400000; ++k) {
        nearestR = std::min(nearestR, contour.evaluate(kTwoPi * k / 400000.0).r);
    }
    double farthest = 0.0;
    for (const Eigen::Vector2d& p : sample(groove.value().outer, 20000)) {
        farthest = std::max(farthest, p.norm());
    }
    // Sampling can only miss the extreme, by at most (spacing)²/(2·radius): well below 1e-6.
    EXPECT_LE(lands.innerMost.radius, nearestR + 1e-12);
    EXPECT_NEAR(lands.innerMost.radius, nearestR, 1e-6);
    EXPECT_GE(lands.outerMost.radius, farthest - 1e-12);
    EXPECT_NEAR(lands.outerMost.radius, farthest, 1e-6);
    EXPECT_NEAR(lands.innerMost.point.norm(), lands.innerMost.radius, 1e-12);
    EXPECT_NEAR(contour.evaluate(lands.innerMost.phi).r, lands.innerMost.radius, 1e-9);
}

TEST(GrooveBends, TheOuterFlanksTightestArcsAreTheProfilesGrownAndShrunkByTheWidth) {
    // The six-lobe cam's arcs, read from the contour: lobes (convex) grow by w = 2ρ + c on the
    // outer flank, notches (concave) shrink by it.
    const Contour contour = sixLobe();
    const double rho = 1.0, c = 0.2, w = 2 * rho + c;
    double lobe = 1e300, notch = 1e300;
    for (std::size_t k = 0; k < contour.size(); ++k) {
        const ContourSegment& s = contour.segment(k);
        (s.arc.branch == Branch::Outer ? lobe : notch) =
            std::min(s.arc.branch == Branch::Outer ? lobe : notch, s.arc.radius);
    }
    const auto groove = grooveFlanks(contour, rho, c);
    ASSERT_TRUE(groove.ok());
    const PathBends outer = pathBends(groove.value().outer);
    ASSERT_TRUE(outer.minConvex && outer.minConcave);
    EXPECT_NEAR(outer.minConvex->radius, lobe + w, 1e-9);
    EXPECT_NEAR(outer.minConcave->radius, notch - w, 1e-9);
    // Its place is on the flank, at the polar angle it names.
    EXPECT_NEAR(std::atan2(outer.minConcave->point.y(), outer.minConcave->point.x()),
                std::remainder(outer.minConcave->phi, kTwoPi), 1e-12);
    const PathBends inner = pathBends(groove.value().inner);
    EXPECT_NEAR(inner.minConvex->radius, lobe, 1e-12);
    EXPECT_NEAR(inner.minConcave->radius, notch, 1e-12);
    // A disc bends one way only.
    const auto disc = grooveFlanks(test::disc({5.0, 0.0}, 30.0), 5.0, 0.3);
    ASSERT_TRUE(disc.ok());
    EXPECT_NEAR(pathBends(disc.value().outer).minConvex->radius, 40.3, 1e-12);
    EXPECT_FALSE(pathBends(disc.value().outer).minConcave);
}

TEST(GrooveRoller, InTheGrooveOfAnEccentricDiscItSitsWhereTheClosedFormPutsIt) {
    // A roller on an offset line in the groove of a disc of radius R about c. In the cam frame
    // at angle φ the line runs along u(φ), offset e along n(φ); the centre x = s·u + e·n lies
    // on the circle of radius R + ρ about c (on the inner flank) or R + ρ + c (pressed on the
    // outer flank): s = u·c + √(Rc² − (e − n·c)²).
    const Eigen::Vector2d centre(-6.0, 4.0);
    const double R = 25.0, rho = 4.0, clearance = 0.25, e = -7.0;
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.offset = e;
    spec.radius = rho;
    spec.closure = Closure::Groove;
    spec.grooveClearance = clearance;
    const Contour contour = test::disc(centre, R);
    const auto inner = FollowerModel::build(contour, spec);
    const auto wide = FollowerModel::build(contour, outerFlankRoller(spec));
    ASSERT_TRUE(inner.ok());
    ASSERT_TRUE(wide.ok());
    const auto sOf = [&](double phi, double radius) {
        const Eigen::Vector2d u = test::unit(phi), n = test::normalOf(phi);
        const double side = e - n.dot(centre);
        return u.dot(centre) + std::sqrt(radius * radius - side * side);
    };
    for (double deg = 0.5; deg < 360.0; deg += 7.3) {
        const double phi = degToRad(deg);
        const FollowerState onInner = inner.value().at(phi, 1.0);
        EXPECT_NEAR(onInner.s, sOf(phi, R + rho), 1e-11) << deg;
        const FollowerState onOuter = onOuterFlank(wide.value().at(phi, 1.0), rho, clearance);
        EXPECT_NEAR(onOuter.s, sOf(phi, R + rho + clearance), 1e-11) << deg;
        // The outer contact is on the outer flank, the circle R + 2ρ + c, ρ from the centre,
        // across the roller from the inner flank; its normal points back into the groove.
        EXPECT_NEAR((onOuter.contact - centre).norm(), R + 2 * rho + clearance, 1e-11) << deg;
        EXPECT_NEAR((onOuter.contact - onOuter.center).norm(), rho, 1e-12) << deg;
        const Eigen::Vector2d towardsCentre = (centre - onOuter.contact).normalized();
        EXPECT_NEAR((onOuter.normal - towardsCentre).norm(), 0.0, 1e-12) << deg;
        EXPECT_NEAR(onOuter.rhoProfile, R + 2 * rho + clearance, 1e-9) << deg;
        // The same line of force: the pressure angle from the closed form's slope, both ways.
        const double side = e - test::normalOf(phi).dot(centre);
        EXPECT_NEAR(std::abs(std::sin(onOuter.pressureAngle)),
                    std::abs(side) / (R + rho + clearance), 1e-9)
            << deg;
    }
}

TEST(GrooveEvaluation, AGroovedProjectCarriesItsFlanksAndAnUndercutMakesItInvalid) {
    Project p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value();
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = 2.0;
    spec.closure = Closure::Groove;
    spec.grooveClearance = 0.8;
    p.follower = spec;
    const ProjectEvaluation fine = evaluateProject(p);
    ASSERT_EQ(fine.status, EvaluationStatus::Computed)
        << (fine.problems.empty() ? "" : fine.problems.front().text());
    ASSERT_TRUE(fine.groove);
    EXPECT_EQ(fine.groove->outer.segments.size(), fine.contour->size());
    // 1 mm more clearance and the notches (radius 4.84 mm) are tighter than 2ρ + c = 5 mm.
    p.follower->grooveClearance = 1.0;
    const ProjectEvaluation undercut = evaluateProject(p);
    EXPECT_EQ(undercut.status, EvaluationStatus::Invalid);
    EXPECT_FALSE(undercut.groove);
    EXPECT_FALSE(undercut.follower);
    ASSERT_FALSE(undercut.problems.empty());
    EXPECT_EQ(undercut.problems.front().code, DiagnosticCode::GrooveOuterFlankUndercut);
    // A spring-closed roller has no groove.
    p.follower->closure = Closure::Spring;
    EXPECT_FALSE(evaluateProject(p).groove);
}

TEST(GrooveForces, TheRollerCrossesToTheOuterFlankWhereTheClosedFormsLoadTurnsNegative) {
    // A radial roller in the groove of an eccentric disc, driven by inertia alone: the load is
    // m·s''·ω², s(φ) = u·c + √((R + ρ)² − (n·c)²) in closed form. It turns negative, and the
    // outer flank takes it, exactly where s'' changes sign; the outer flank (the circle
    // R + 2ρ + c) wraps round the roller: 1/R' = 1/ρ − 1/(R + 2ρ + c).
    const Eigen::Vector2d centre(6.0, 0.0);
    const double R = 25.0, rho = 4.0, clearance = 0.3, mass = 0.5, omega = 20.0;
    const double width = 2 * rho + clearance, b = 10.0, E = 210000.0, nu = 0.3;
    Project p;
    p.motion = {SpeedUnit::OmegaRadS, omega};
    p.contour.push_back(SegmentSpec{Arc{centre, R, Branch::Outer}, 0.0, 360.0});
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = rho;
    spec.closure = Closure::Groove;
    spec.grooveClearance = clearance;
    p.follower = spec;
    DynamicsSpec d;
    d[DynamicsKey::MassKg] = mass;
    d[DynamicsKey::ContactWidthMm] = b;
    d[DynamicsKey::CamModulusMpa] = E;
    d[DynamicsKey::CamPoisson] = nu;
    d[DynamicsKey::FollowerModulusMpa] = E;
    d[DynamicsKey::FollowerPoisson] = nu;
    p.dynamics = d;
    const ProjectEvaluation e = evaluateProject(p);
    ASSERT_EQ(e.status, EvaluationStatus::Computed);
    ForceEvaluation forces;
    ASSERT_TRUE(evaluateForces(p, *e.follower, e.omega, forces));
    ASSERT_TRUE(forces.model.grooved());

    // The closed form: s(φ) and s''(φ) by a central difference of order 4 (to ~1e-9 mm).
    const auto s = [&](double phi) {
        const Eigen::Vector2d u = test::unit(phi), n = test::normalOf(phi);
        const double side = n.dot(centre);
        return u.dot(centre) + std::sqrt((R + rho) * (R + rho) - side * side);
    };
    const auto s2 = [&](double phi) {
        const double h = 1e-3;
        return (-s(phi - 2 * h) + 16 * s(phi - h) - 30 * s(phi) + 16 * s(phi + h) -
                s(phi + 2 * h)) /
               (12 * h * h);
    };
    // Its sign changes, found by bisection on the closed form alone.
    std::vector<double> roots;
    const int n = 3600;
    for (int k = 0; k < n; ++k) {
        double a = kTwoPi * k / n, c = kTwoPi * (k + 1) / n;
        if ((s2(a) < 0) == (s2(c) < 0)) continue;
        const bool negativeAtA = s2(a) < 0;
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + c);
            ((s2(m) < 0) == negativeAtA ? a : c) = m;
        }
        roots.push_back(0.5 * (a + c));
    }
    ASSERT_EQ(roots.size(), 2u);
    const ForceSummary& summary = forces.summary;
    ASSERT_EQ(summary.liftOff.size(), 1u);
    // The crossover into the outer flank and back: where s'' turns negative and positive.
    const double into = std::remainder(summary.liftOff[0][0], kTwoPi);
    const double back = std::remainder(summary.liftOff[0][1], kTwoPi);
    bool matchedInto = false, matchedBack = false;
    for (const double r : roots) {
        const bool turnsNegative = s2(r + 1e-4) < 0;
        if (std::abs(std::remainder(r - into, kTwoPi)) < 1e-7) matchedInto = turnsNegative;
        if (std::abs(std::remainder(r - back, kTwoPi)) < 1e-7) matchedBack = !turnsNegative;
    }
    EXPECT_TRUE(matchedInto) << into;
    EXPECT_TRUE(matchedBack) << back;

    // Each flank's largest stress against a dense search of the closed form: the normal force
    // m·|s''|·ω²/cos α (N; s'' in mm → m) on 1/R' of the flank carrying it.
    const double eStar = 1.0 / (2 * (1 - nu * nu) / E);
    double innerPeak = 0.0, outerPeak = 0.0;
    for (int k = 0; k < 200000; ++k) {
        const double phi = kTwoPi * k / 200000;
        const double side = test::normalOf(phi).dot(centre);
        const double cosAlpha = std::sqrt(1 - side * side / ((R + rho) * (R + rho)));
        const double normal = mass * s2(phi) * 1e-3 * omega * omega / cosAlpha;
        const double curvature = normal >= 0 ? 1 / rho + 1 / R : 1 / rho - 1 / (R + width);
        const double p = std::sqrt(std::abs(normal) * eStar * curvature / (kPi * b));
        (normal >= 0 ? innerPeak : outerPeak) = std::max(normal >= 0 ? innerPeak : outerPeak, p);
    }
    ASSERT_TRUE(summary.maxStress && summary.maxStressSecond && summary.maxNormalSecond);
    EXPECT_NEAR(*summary.maxStress, innerPeak, 1e-6 * innerPeak);
    EXPECT_NEAR(*summary.maxStressSecond, outerPeak, 1e-6 * outerPeak);
}

}  // namespace
}  // namespace cam
