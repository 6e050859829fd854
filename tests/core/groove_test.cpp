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
#include "core/test_projects.h"

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

}  // namespace
}  // namespace cam
