// Joint continuity and extremes, checked against closed forms and one-sided evaluations.

#include <gtest/gtest.h>

#include <limits>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "core/test_projects.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

Contour loadContour(const std::string& path, double* omega = nullptr) {
    auto p = loadProjectFile(path);
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.errors().front().text());
    if (omega) *omega = p.value().motion.omegaRadS();
    return Contour::build(p.value()).value();
}

TEST(JointAnalysis, SixLobeJointsAreTangentWithAJumpInRadialAcceleration) {
    double omega = 0.0;
    const Contour c = loadContour(test::examplePath("six-lobe-arc-cam.cam.json"), &omega);
    const ContourAnalysis a = analyzeContour(c, omega);
    ASSERT_EQ(a.joints.size(), 13u);
    for (const JointAnalysis& j : a.joints) {
        if (j.left == 12) {
            // contour[12] → contour[0] is the notch at 0° split in two: the same circle.
            EXPECT_EQ(j.continuity, Continuity::C2);
            EXPECT_NEAR(j.jumpAR, 0.0, 1e-6);
            continue;
        }
        EXPECT_EQ(j.continuity, Continuity::C1) << "joint after " << j.left;
        EXPECT_LT(j.gapMm, 1e-6);
        EXPECT_LT(j.tangentBreakDeg, 1e-5);
        // The jump is a_r just right of the joint minus just left, evaluated one-sidedly.
        const double eps = 1e-9;
        const double right = polarMotion(c.segment(j.right).evaluate(j.phi + eps), omega).aR;
        const double left = polarMotion(c.segment(j.left).evaluate(j.phi - eps), omega).aR;
        EXPECT_TRUE(relClose(j.jumpAR, right - left, 1e-5)) << "joint after " << j.left;
        EXPECT_GT(std::abs(j.jumpAR), 1e4);  // lobe (convex) to notch (concave): a large jump
    }
}

TEST(JointAnalysis, CornerHasTangentBreakOfItsGeometry) {
    // Square of half-width 10 from four lines: at each corner the tangent turns by 90°.
    Project p;
    p.motion = {SpeedUnit::PeriodS, 1.0};
    const Eigen::Vector2d corners[] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    for (int k = 0; k < 4; ++k) {
        SegmentSpec s{Line{corners[k], corners[(k + 1) % 4]}};
        s.phiStartDeg = -45.0 + 90.0 * k;
        s.phiEndDeg = 45.0 + 90.0 * k;
        p.contour.push_back(s);
    }
    const auto c = Contour::build(p);
    ASSERT_TRUE(c.ok()) << c.errors().front().text();
    const ContourAnalysis a = analyzeContour(c.value(), kTwoPi);
    ASSERT_EQ(a.joints.size(), 4u);
    for (const JointAnalysis& j : a.joints) {
        EXPECT_EQ(j.continuity, Continuity::C0);
        EXPECT_NEAR(j.tangentBreakDeg, 90.0, 1e-9);
        EXPECT_LT(j.gapMm, 1e-12);
        // r = 10/cos(φ - θn): r' jumps from +10·√2 to -10·√2 at a corner.
        EXPECT_NEAR(j.jumpDr, -20.0 * std::sqrt(2.0), 1e-9);
    }
    // The joints alone (what the window computes on every edit) are the same, corner by corner.
    const std::vector<JointAnalysis> joints = analyzeJoints(c.value(), kTwoPi);
    ASSERT_EQ(joints.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(joints[k].left, k);
        EXPECT_EQ(joints[k].phi, a.joints[k].phi);
        EXPECT_EQ(joints[k].tangentBreakDeg, a.joints[k].tangentBreakDeg);
        EXPECT_EQ(joints[k].continuity, a.joints[k].continuity);
    }
    // r ranges from 10 (edge midpoints) to 10·√2 (corners).
    const auto& r = a.extremes.front();
    ASSERT_EQ(r.quantity, Quantity::R);
    EXPECT_NEAR(r.min.value, 10.0, 1e-12);
    EXPECT_NEAR(r.max.value, 10.0 * std::sqrt(2.0), 1e-12);
}

TEST(Extremes, SixLobeRadiusExtremesSitAtLobeTipsAndNotchBottoms) {
    double omega = 0.0;
    const Contour c = loadContour(test::examplePath("six-lobe-arc-cam.cam.json"), &omega);
    const ContourAnalysis a = analyzeContour(c, omega);
    const QuantityExtremes& r = a.extremes.at(0);
    EXPECT_TRUE(relClose(r.max.value, 29.0, 1e-12));
    EXPECT_TRUE(relClose(r.min.value, 20.89681945, 1e-12));
    // Tips at 30° + k·60°, bottoms at k·60°: the angle is found to ~1e-5° (r is flat there).
    EXPECT_NEAR(std::remainder(radToDeg(r.max.phi) - 30.0, 60.0), 0.0, 1e-4);
    EXPECT_NEAR(std::remainder(radToDeg(r.min.phi), 60.0), 0.0, 1e-4);
}

TEST(Extremes, TheBoundedSearchFindsWhatSearchingEverySegmentFinds) {
    // Searching finely only where a coarse look says a segment's extreme could win changes no
    // extreme, to the bit: against searching every segment, on every bundled example, on the
    // seed's table, and on the six-lobe cam split into 1,300 windows (neighbours nearly tie).
    std::vector<std::string> paths;
    for (const char* name :
         {"six-lobe-arc-cam.cam.json", "roller-lobe-cam.cam.json", "spline-egg-cam.cam.json",
          "swinging-arm-cam.cam.json", "synthesised-cycloidal-roller.cam.json"}) {
        paths.push_back(test::examplePath(name));
    }
    std::vector<std::pair<std::string, Contour>> contours;
    double omega = 1.0;
    for (const std::string& path : paths) contours.emplace_back(path, loadContour(path, &omega));
    Project split = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value();
    std::vector<SegmentSpec> pieces;
    for (const SegmentSpec& spec : split.contour) {
        for (int k = 0; k < 100; ++k) {
            SegmentSpec piece = spec;
            const double w = spec.phiEndDeg - spec.phiStartDeg;
            piece.phiStartDeg = spec.phiStartDeg + w * k / 100;
            piece.phiEndDeg = k == 99 ? spec.phiEndDeg : spec.phiStartDeg + w * (k + 1) / 100;
            pieces.push_back(piece);
        }
    }
    split.contour = pieces;
    contours.emplace_back("six lobes split", Contour::build(split).value());
    for (const auto& [name, contour] : contours) {
        const ContourAnalysis bounded = analyzeContour(contour, 3.7);
        const ContourAnalysis every =
            analyzeContour(contour, 3.7, nullptr, ContourSearch::EverySegment);
        ASSERT_EQ(bounded.extremes.size(), every.extremes.size());
        for (std::size_t q = 0; q < every.extremes.size(); ++q) {
            const QuantityExtremes& b = bounded.extremes[q];
            const QuantityExtremes& e = every.extremes[q];
            const std::string what = name + " " + quantityName(e.quantity);
            EXPECT_EQ(b.min.value, e.min.value) << what;
            EXPECT_EQ(b.min.phi, e.min.phi) << what;
            EXPECT_EQ(b.min.segment, e.min.segment) << what;
            EXPECT_EQ(b.max.value, e.max.value) << what;
            EXPECT_EQ(b.max.phi, e.max.phi) << what;
            EXPECT_EQ(b.max.segment, e.max.segment) << what;
        }
    }
}

TEST(Extremes, MatchABruteForceSearchOverADenseSampleAndTheWindowEnds) {
    // Brute force: 200,000 samples plus each segment's one-sided values at both window ends
    // (the a_r and jerk extremes of this cam sit exactly at joints).
    double omega = 0.0;
    const Contour c = loadContour(test::examplePath("six-lobe-arc-cam.cam.json"), &omega);
    const ContourAnalysis a = analyzeContour(c, omega);
    SampledTurn turn;
    sampleTurn(c, omega, 200000, turn);
    for (const QuantityExtremes& e : a.extremes) {
        double lo = 1e300, hi = -1e300;
        auto take = [&](const PolarDerivatives& d, const PolarMotion& m) {
            const double v = quantityValue(e.quantity, d, m);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        };
        for (std::size_t k = 0; k < turn.size(); ++k) {
            PolarMotion m;
            m.vR = turn.vR[k], m.v = turn.v[k], m.aR = turn.aR[k], m.a = turn.a[k];
            m.jR = turn.jR[k], m.j = turn.j[k];
            take({turn.r[k], 0, 0, 0}, m);
        }
        for (const ContourSegment& seg : c.segments()) {
            for (double phi : {seg.phiStart, seg.phiEnd}) {
                const PolarDerivatives d = seg.evaluate(phi);
                take(d, polarMotion(d, omega));
            }
        }
        const double scale = std::max(std::abs(lo), std::abs(hi));
        EXPECT_LE(e.min.value, lo + 1e-12 * scale) << quantityName(e.quantity);
        EXPECT_GE(e.max.value, hi - 1e-12 * scale) << quantityName(e.quantity);
        // Between grid points a smooth extremum differs from the best sample by O(Δφ²).
        EXPECT_TRUE(relClose(e.min.value, lo, 1e-7, scale)) << quantityName(e.quantity);
        EXPECT_TRUE(relClose(e.max.value, hi, 1e-7, scale)) << quantityName(e.quantity);
    }
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(JointClassification, ANaNMeasureNeverPassesItsTest) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // A NaN gap (a ray that misses a curve at the joint) used to fall through every `>` test
    // and come out C2, the best a joint can be.
    EXPECT_EQ(kinematicContinuity(nan, 0.0, 0.0), Continuity::None);
    EXPECT_EQ(kinematicContinuity(0.0, nan, 0.0), Continuity::C0);
    EXPECT_EQ(kinematicContinuity(0.0, 0.0, nan), Continuity::C1);
    EXPECT_EQ(kinematicContinuity(0.0, 0.0, 0.0), Continuity::C2);
    EXPECT_EQ(geometricContinuity(Continuity::C2, nan, 0.0), Continuity::G1);
    EXPECT_EQ(geometricContinuity(Continuity::C1, 0.0, nan), Continuity::C1);
    EXPECT_EQ(geometricContinuity(Continuity::C2, 0.0, 0.0), Continuity::C2);
    // The boundaries themselves still pass.
    EXPECT_EQ(kinematicContinuity(kJointToleranceMm, kTangentToleranceDeg, kCurvatureToleranceRel),
              Continuity::C2);
}

TEST(Analysis, ReturnsAtOnceWhenCancelled) {
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    const Contour c = Contour::build(p.value()).value();
    const std::atomic<bool> cancel{true};
    const ContourAnalysis cancelled = analyzeContour(c, 1.0, &cancel);
    EXPECT_TRUE(cancelled.joints.empty());
    EXPECT_TRUE(cancelled.extremes.empty());
    const std::atomic<bool> go{false};
    const ContourAnalysis full = analyzeContour(c, 1.0, &go);
    EXPECT_EQ(full.joints.size(), 13u);
    EXPECT_EQ(full.extremes.size(), kAllQuantities.size());
}

}  // namespace
}  // namespace cam
