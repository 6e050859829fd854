// Polar kinematics: the formulas of math.md §2 against finite differences of the follower's
// Cartesian motion, and the sampled turn against the state at each instant.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "core/test_projects.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"
#include "test_support.h"

namespace cam {
namespace {

using test::sixLobe;

using test::relClose;

TEST(Kinematics, PolarComponentsMatchFiniteDifferencesOfTheCartesianMotion) {
    // The follower point is P(t) = r(ωt)·(cos ωt, sin ωt). Differentiate P numerically in the
    // fixed frame and project onto the radial and tangential unit vectors: an independent route
    // to v, a and jerk that does not use the polar formulas.
    const Contour contour = sixLobe();
    const double omega = 5.0 * kPi;
    auto position = [&](double t) {
        const double phi = omega * t;
        const double r = contour.evaluate(phi).r;
        return Eigen::Vector2d(r * std::cos(phi), r * std::sin(phi));
    };
    const double h = 2e-6;
    for (double t : {0.013, 0.05, 0.101, 0.15, 0.222, 0.31, 0.37}) {
        const KinematicState s = stateAt(contour, omega, t);
        const Eigen::Vector2d p0 = position(t), pp = position(t + h), pm = position(t - h);
        const Eigen::Vector2d pp2 = position(t + 2 * h), pm2 = position(t - 2 * h);
        const Eigen::Vector2d vel = (pp - pm) / (2 * h);
        const Eigen::Vector2d acc = (pp - 2 * p0 + pm) / (h * h);
        const Eigen::Vector2d jerk = (pp2 - 2 * pp + 2 * pm - pm2) / (2 * h * h * h);
        const Eigen::Vector2d er(std::cos(s.phi), std::sin(s.phi)), ephi(-er.y(), er.x());
        EXPECT_TRUE(relClose(s.motion.vR, vel.dot(er), 1e-6, s.motion.v)) << "t=" << t;
        EXPECT_TRUE(relClose(s.motion.vPhi, vel.dot(ephi), 1e-6, s.motion.v)) << "t=" << t;
        EXPECT_TRUE(relClose(s.motion.aR, acc.dot(er), 1e-4, s.motion.a)) << "t=" << t;
        EXPECT_TRUE(relClose(s.motion.aPhi, acc.dot(ephi), 1e-4, s.motion.a)) << "t=" << t;
        EXPECT_TRUE(relClose(s.motion.jR, jerk.dot(er), 1e-2, s.motion.j)) << "t=" << t;
        EXPECT_TRUE(relClose(s.motion.jPhi, jerk.dot(ephi), 1e-2, s.motion.j)) << "t=" << t;
        EXPECT_NEAR(s.motion.v, std::hypot(s.motion.vR, s.motion.vPhi), 1e-12 * s.motion.v);
    }
}

TEST(Kinematics, CentredCircleIsUniformCircularMotion) {
    const Contour c = Contour::build(test::splitCircle(0.0, 10.0, {0.0, 360.0})).value();
    const double omega = 3.0;
    const KinematicState s = stateAt(c, omega, 0.7);
    EXPECT_NEAR(s.motion.vR, 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.motion.vPhi, 30.0);
    EXPECT_DOUBLE_EQ(s.motion.aR, -90.0);  // centripetal r·ω²
    EXPECT_NEAR(s.motion.aPhi, 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.motion.jPhi, -270.0);  // -r·ω³
}

void expectSampledMatchesState(const Contour& contour, double omega, std::size_t n) {
    SampledTurn turn;
    sampleTurn(contour, omega, n, turn);
    ASSERT_EQ(turn.size(), n);
    const double period = kTwoPi / std::abs(omega);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = period * static_cast<double>(k) / static_cast<double>(n);
        const KinematicState s = stateAt(contour, omega, t);
        ASSERT_TRUE(relClose(turn.t[k], t, 1e-14, period)) << k;
        ASSERT_EQ(static_cast<std::size_t>(turn.segment[k]), s.segment) << "k=" << k;
        const double tol = 1e-11;
        ASSERT_TRUE(relClose(turn.r[k], s.polar.r, tol)) << k;
        ASSERT_TRUE(relClose(turn.x[k], s.polar.r * std::cos(s.phi), tol, s.polar.r)) << k;
        ASSERT_TRUE(relClose(turn.y[k], s.polar.r * std::sin(s.phi), tol, s.polar.r)) << k;
        ASSERT_TRUE(relClose(turn.vR[k], s.motion.vR, tol, s.motion.v)) << k;
        ASSERT_TRUE(relClose(turn.vPhi[k], s.motion.vPhi, tol)) << k;
        ASSERT_TRUE(relClose(turn.aR[k], s.motion.aR, tol, s.motion.a)) << k;
        ASSERT_TRUE(relClose(turn.aPhi[k], s.motion.aPhi, tol, s.motion.a)) << k;
        ASSERT_TRUE(relClose(turn.a[k], s.motion.a, tol)) << k;
        ASSERT_TRUE(relClose(turn.jR[k], s.motion.jR, 1e-9, s.motion.j)) << k;
        ASSERT_TRUE(relClose(turn.jPhi[k], s.motion.jPhi, 1e-9, s.motion.j)) << k;
        ASSERT_TRUE(relClose(turn.j[k], s.motion.j, 1e-9)) << k;
    }
}

TEST(SampledTurn, EverySampleEqualsTheStateAtItsInstant) {
    expectSampledMatchesState(sixLobe(), 5.0 * kPi, 3600);
    expectSampledMatchesState(sixLobe(), 5.0 * kPi, 5003);  // not a multiple of the block size
}

TEST(SampledTurn, ClockwiseAndNegativeWindowStart) {
    const Contour c =
        Contour::build(test::splitCircle(4.0, 25.0, {-30.0, 10.0, 10.5, 200.0, 330.0})).value();
    expectSampledMatchesState(c, -7.0, 2000);
    expectSampledMatchesState(c, 7.0, 2000);
}

TEST(SampledTurn, TinyAndOddCounts) {
    const Contour c = sixLobe();
    for (std::size_t n : {1u, 2u, 3u, 17u, 1025u}) expectSampledMatchesState(c, 5.0 * kPi, n);
}

TEST(SampledTurn, ReusesStorageAcrossSizes) {
    const Contour c = sixLobe();
    SampledTurn turn;
    sampleTurn(c, 1.0, 5000, turn);
    sampleTurn(c, 1.0, 100, turn);
    EXPECT_EQ(turn.size(), 100u);
    EXPECT_EQ(turn.segment.size(), 100u);
    EXPECT_DOUBLE_EQ(turn.r[0], stateAt(c, 1.0, 0.0).polar.r);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(SampledTurn, StopsWhenCancelledAndCompletesOtherwise) {
    const Contour c = Contour::build(test::splitCircle(0.0, 10.0, {0.0, 360.0})).value();
    SampledTurn turn;
    std::atomic<bool> cancel{true};
    EXPECT_FALSE(sampleTurn(c, 1.0, 1'000'000, turn, &cancel));
    cancel = false;
    EXPECT_TRUE(sampleTurn(c, 1.0, 1'000'000, turn, &cancel));
    EXPECT_DOUBLE_EQ(turn.r.back(), 10.0);
    EXPECT_TRUE(sampleTurn(c, 1.0, 10, turn));
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(SampledTurn, ChunksAreTheWholeTurn) {
    // A big turn is computed in chunks of bounded memory by the app. Chunks that start and end
    // on block boundaries (or at the end) hold exactly the whole turn's samples; any others
    // only differ in the last bit (the vector loop and its scalar remainder round differently).
    const Contour sixLobeCam = sixLobe();
    const Contour clockwise =
        Contour::build(test::splitCircle(4.0, 25.0, {-30.0, 10.0, 10.5, 200.0, 330.0})).value();
    for (const auto& [contour, omega] :
         {std::pair{&sixLobeCam, 5.0 * kPi}, std::pair{&clockwise, -7.0}}) {
        const std::size_t n = 10'007;
        SampledTurn whole, chunk;
        ASSERT_TRUE(sampleTurn(*contour, omega, n, whole));
        for (const auto& [first, count] : {std::pair<std::size_t, std::size_t>{0, 1},
                                           {0, 1024},
                                           {1024, 3000},
                                           {5 * kSampleBlock, n - 5 * kSampleBlock},
                                           {1000, 3000},
                                           {n - 1, 1}}) {
            ASSERT_TRUE(sampleTurnRange(*contour, omega, n, first, count, chunk));
            ASSERT_EQ(chunk.size(), count);
            const bool aligned = first % kSampleBlock == 0 &&
                                 ((first + count) % kSampleBlock == 0 || first + count == n);
            const auto same = [&](double a, double b, double scale) {
                return aligned ? a == b : static_cast<bool>(relClose(a, b, 1e-14, scale));
            };
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t k = first + i;
                ASSERT_EQ(chunk.t[i], whole.t[k]) << k;
                ASSERT_EQ(chunk.phi[i], whole.phi[k]) << k;
                ASSERT_EQ(chunk.segment[i], whole.segment[k]) << k;
                ASSERT_TRUE(same(chunk.r[i], whole.r[k], whole.r[k])) << k;
                ASSERT_TRUE(same(chunk.x[i], whole.x[k], whole.r[k])) << k;
                ASSERT_TRUE(same(chunk.vPhi[i], whole.vPhi[k], whole.v[k])) << k;
                ASSERT_TRUE(same(chunk.a[i], whole.a[k], whole.a[k])) << k;
                ASSERT_TRUE(same(chunk.jR[i], whole.jR[k], whole.j[k])) << k;
            }
        }
    }
}

TEST(SampledTurn, AlignedChunksOfALongTurnAreItsSamplesBitForBit) {
    // Segments of tens of thousands of samples, which the loop goes through in pieces between
    // two polls of the cancel flag: those pieces end on the turn's own grid, not a chunk's, so
    // a chunk that starts inside a segment still splits it where the whole turn does (split
    // 16,384 samples after where each started, they differed in the last bit, and the app's
    // two halves of a turn differed from the turn in one piece).
    const Contour sixLobeCam = sixLobe();
    for (const double omega : {5.0 * kPi, -5.0 * kPi}) {
        const std::size_t n = 1'000'003;
        SampledTurn whole, chunk;
        ASSERT_TRUE(sampleTurn(sixLobeCam, omega, n, whole));
        for (const auto& [first, count] :
             {std::pair<std::size_t, std::size_t>{50 * kSampleBlock, 64 * kSampleBlock},
              {488 * kSampleBlock, 64 * kSampleBlock},
              {200 * kSampleBlock, n - 200 * kSampleBlock}}) {
            ASSERT_TRUE(sampleTurnRange(sixLobeCam, omega, n, first, count, chunk));
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t k = first + i;
                ASSERT_EQ(chunk.segment[i], whole.segment[k]) << k;
                ASSERT_EQ(chunk.r[i], whole.r[k]) << k;
                ASSERT_EQ(chunk.x[i], whole.x[k]) << k;
                ASSERT_EQ(chunk.vR[i], whole.vR[k]) << k;
                ASSERT_EQ(chunk.vPhi[i], whole.vPhi[k]) << k;
                ASSERT_EQ(chunk.aR[i], whole.aR[k]) << k;
                ASSERT_EQ(chunk.a[i], whole.a[k]) << k;
                ASSERT_EQ(chunk.jR[i], whole.jR[k]) << k;
                ASSERT_EQ(chunk.j[i], whole.j[k]) << k;
            }
        }
    }
}

}  // namespace
}  // namespace cam
