// The compute engine: latest request wins, stale results are never shown, results match an
// independent computation of the same snapshot.

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QThread>
#include <algorithm>
#include <new>
#include <stdexcept>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "engine/compute_engine.h"
#include "follower/follower_analysis.h"
#include "io/project_json.h"

namespace cam {
namespace {

Project heavyExample(double period) {
    Project p = test::loadExample();
    // A few ms per computation (long enough to be superseded), and few enough samples that the
    // plotted curves keep every one of them (PlotCurves::kMaxLevelPoints).
    p.samplesPerTurn = 60'000;
    p.motion = {SpeedUnit::PeriodS, period};
    return p;
}

TEST(ComputeEngine, HundredRapidEditsGiveOneFinalResultForTheLastSnapshot) {
    ComputeEngine engine;
    engine.setCoalesceMs(0);  // submit every request at once: the worker must cope alone
    std::vector<std::uint64_t> shown;
    QObject::connect(&engine, &ComputeEngine::resultReady, [&](const ComputeResultPtr& r) {
        EXPECT_EQ(r->generation, engine.latestGeneration()) << "a stale result was shown";
        shown.push_back(r->generation);
    });
    double lastPeriod = 0.0;
    for (int i = 0; i < 100; ++i) {
        lastPeriod = 0.4 + 0.001 * i;
        engine.request(heavyExample(lastPeriod), PlotAxis::Angle);
    }
    ASSERT_TRUE(test::processEventsUntil([&] { return !shown.empty(); }));
    // The last snapshot's first picture, and the same result with its finer plot levels when
    // the first had left them out (on a loaded machine that may take longer than the picture).
    ASSERT_TRUE(test::processEventsUntil([&] { return engine.latestResult()->complete(); }));
    test::processEventsUntil([] { return false; }, 300);  // anything late would arrive now
    ASSERT_GE(shown.size(), 1u);
    ASSERT_LE(shown.size(), 2u);
    for (std::uint64_t g : shown) EXPECT_EQ(g, 100u);
    EXPECT_FALSE(engine.latestResult()->curves.partial);

    // The result is the computation of the last snapshot, value for value.
    const ComputeResultPtr& r = engine.latestResult();
    EXPECT_DOUBLE_EQ(r->project->motion.value, lastPeriod);
    const Contour contour = Contour::build(heavyExample(lastPeriod)).value();
    SampledTurn expected;
    sampleTurn(contour, kTwoPi / lastPeriod, 60'000, expected);
    // The finest level of the plotted curves holds every sample (in chunks, bit for bit).
    ASSERT_EQ(r->sampleCount, expected.size());
    const PlotLevel& finest = r->curves.levels.front();
    ASSERT_EQ(finest.samplesPerBucket, 1u);
    for (const auto& [curve, values] :
         {std::pair{Curve::AR, &expected.aR}, std::pair{Curve::JPhi, &expected.jPhi},
          std::pair{Curve::V, &expected.v}}) {
        const auto& points = finest.curves[static_cast<std::size_t>(curve)];
        for (std::size_t k = 0; k < expected.size(); k += 997) {
            const double x = radToDeg(expected.phi[k]);
            const auto at = std::lower_bound(points.begin(), points.end(), x,
                                             [](const PlotPoint& p, double v) { return p.x < v; });
            ASSERT_NE(at, points.end());
            ASSERT_EQ(at->x, x) << k;
            EXPECT_EQ(at->y, (*values)[k]) << k;
        }
    }
}

/// Every result an engine reports for one request of `p` (a first picture and its
/// refinement, or one complete result), waiting until nothing more comes.
std::vector<ComputeResultPtr> resultsOfOneRequest(const Project& p) {
    ComputeEngine engine;
    std::vector<ComputeResultPtr> shown;
    QObject::connect(&engine, &ComputeEngine::resultReady,
                     [&](const ComputeResultPtr& r) { shown.push_back(r); });
    engine.request(p, PlotAxis::Angle);
    test::processEventsUntil([&] { return shown.size() >= 2; });
    test::processEventsUntil([] { return false; }, 200);  // nothing else comes
    return shown;
}

TEST(ComputeEngine, AFirstPictureIsFollowedByTheSameResultWithEveryPlotLevel) {
    Project p = test::loadExample();
    p.samplesPerTurn = 100'000;
    const std::vector<ComputeResultPtr> shown = resultsOfOneRequest(p);
    ASSERT_EQ(shown.size(), 2u);
    const ComputeResult& first = *shown[0];
    const ComputeResult& whole = *shown[1];
    EXPECT_EQ(first.generation, 1u);
    EXPECT_EQ(whole.generation, 1u);
    // 100,000 samples: the first picture's finest buckets are 64 samples (1,563 buckets, the
    // next finer 6,250 would be more than kFirstPictureBuckets); the whole set goes down to 4.
    EXPECT_TRUE(first.curves.partial);
    EXPECT_EQ(first.curves.levels.front().samplesPerBucket, 64u);
    EXPECT_FALSE(whole.curves.partial);
    EXPECT_EQ(whole.curves.levels.front().samplesPerBucket, 4u);
    // Everything else is the same result.
    EXPECT_EQ(first.sampleCount, whole.sampleCount);
    ASSERT_EQ(first.joints.size(), whole.joints.size());
    for (std::size_t i = 0; i < first.joints.size(); ++i) {
        EXPECT_EQ(first.joints[i].phi, whole.joints[i].phi);
        EXPECT_EQ(first.joints[i].continuity, whole.joints[i].continuity);
    }
    EXPECT_EQ(first.outlines, whole.outlines);
    EXPECT_EQ(first.curves.levels.back().curves[0].size(),
              whole.curves.levels.back().curves[0].size());
}

TEST(ComputeEngine, AFirstPictureLeavesTheArmsDesignChecksToItsRefinement) {
    // A swinging arm's checks take longer than the kinematics: the first picture shows the
    // pressure-angle curve without them, the refinement adds them.
    auto loaded = loadProjectFile(test::examplePath("swinging-arm-cam.cam.json"));
    ASSERT_TRUE(loaded.ok());
    const Project p = std::move(loaded).value();
    ASSERT_TRUE(p.follower && p.follower->motion == FollowerMotion::Oscillating);
    const std::vector<ComputeResultPtr> shown = resultsOfOneRequest(p);
    ASSERT_EQ(shown.size(), 2u);
    const ComputeResult& first = *shown[0];
    const ComputeResult& whole = *shown[1];
    ASSERT_TRUE(first.ok() && first.follower);
    EXPECT_TRUE(first.followerChecksPending);
    EXPECT_FALSE(first.complete());
    EXPECT_EQ(first.followerPressureDeg.size(), ComputeResult::kFollowerCurvePoints + 1);
    EXPECT_FALSE(whole.followerChecksPending);
    EXPECT_TRUE(whole.complete());
    // The checks are those of the follower on the contour in the phases of its design, made
    // apart from the engine.
    const Contour contour = Contour::build(p).value();
    const FollowerModel model = FollowerModel::build(contour, *p.follower).value();
    const FollowerAnalysis expected =
        analyzeFollower(model, p.motion.omegaRadS(), contour.phiBegin(), kFollowerCheckSamples,
                        nullptr, phasesOf(p));
    ASSERT_TRUE(expected.pressure.rise && expected.pressure.fall);
    EXPECT_GT(expected.pressure.rise->value, 0.0);
    EXPECT_EQ(whole.followerChecks.pressure.rise->value, expected.pressure.rise->value);
    EXPECT_EQ(whole.followerChecks.pressure.rise->phi, expected.pressure.rise->phi);
    EXPECT_EQ(whole.followerChecks.pressure.fall->value, expected.pressure.fall->value);
    ASSERT_TRUE(expected.pitchCurvature.minConvex);
    EXPECT_EQ(whole.followerChecks.pitchCurvature.minConvex->value,
              expected.pitchCurvature.minConvex->value);
    EXPECT_EQ(whole.followerChecks.limitRad, expected.limitRad);
    EXPECT_EQ(whole.followerChecks.undercut.size(), expected.undercut.size());
    // The curve is the first picture's.
    EXPECT_EQ(whole.followerPressureDeg, first.followerPressureDeg);
}

TEST(ComputeEngine, WithoutAFirstPictureTheChecksComeAtOnce) {
    auto loaded = loadProjectFile(test::examplePath("swinging-arm-cam.cam.json"));
    ASSERT_TRUE(loaded.ok());
    ComputeRequest request;
    request.generation = 1;
    request.project = std::make_shared<const Project>(std::move(loaded).value());
    const std::atomic<bool> cancel{false};
    const ComputeResultPtr result = computeProject(request, cancel);
    ASSERT_TRUE(result && result->ok() && result->follower);
    EXPECT_FALSE(result->followerChecksPending);
    EXPECT_TRUE(result->complete());
    EXPECT_GT(result->followerChecks.limitRad, 0.0);
    EXPECT_EQ(refineResult(*result, cancel, nullptr), nullptr);  // nothing left to add
}

TEST(ComputeEngine, StreamingEditsShowOnlyNewerResultsAndEndOnTheLast) {
    ComputeEngine engine;  // default coalescing
    std::vector<std::uint64_t> shown;
    QObject::connect(&engine, &ComputeEngine::resultReady, [&](const ComputeResultPtr& r) {
        EXPECT_EQ(r->generation, engine.latestGeneration());
        shown.push_back(r->generation);
    });
    for (int i = 0; i < 60; ++i) {
        engine.request(heavyExample(0.4 + 0.001 * i), PlotAxis::Time);
        test::processEventsUntil([] { return false; }, 5);  // an edit every ~5 ms
    }
    ASSERT_TRUE(test::processEventsUntil([&] { return !shown.empty() && shown.back() == 60u; }));
    EXPECT_TRUE(std::is_sorted(shown.begin(), shown.end()));
    EXPECT_LT(shown.size(), 60u);  // bursts were coalesced
    EXPECT_EQ(engine.latestResult()->axis, PlotAxis::Time);
}

TEST(ComputeEngine, AnInvalidProjectGivesItsErrorsNotACrash) {
    ComputeEngine engine;
    Project p = test::loadExample();
    std::get<Arc>(p.contour[2].shape).radius = -1.0;
    engine.request(p, PlotAxis::Angle);
    ASSERT_TRUE(test::processEventsUntil([&] { return engine.latestResult() != nullptr; }));
    EXPECT_FALSE(engine.latestResult()->ok());
    EXPECT_EQ(engine.latestResult()->errors.front().location, "contour[2].radius");
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// A preparer that fails, stalls or passes, as a test needs: what the worker runs after the
/// computation, so it stands for any step that throws or ignores the cancel flag.
class ScriptedPreparer : public PlotDataPreparer {
public:
    enum class Mode { Pass, ThrowOutOfMemory, ThrowError, IgnoreCancelFor2s };
    std::atomic<Mode> mode{Mode::Pass};
    mutable std::atomic<int> calls{0};

    PreparedPlotDataPtr prepare(const ComputeResult&, const std::atomic<bool>&) const override {
        ++calls;
        switch (mode.load()) {
            case Mode::ThrowOutOfMemory:
                throw std::bad_alloc();
            case Mode::ThrowError:
                throw std::runtime_error("scripted failure");
            case Mode::IgnoreCancelFor2s:
                QThread::msleep(2000);
                return nullptr;
            case Mode::Pass:
                return nullptr;
        }
        return nullptr;
    }
    PreparedPlotDataPtr prepareTiming(const TimingOutcome&) const override { return nullptr; }
};

TEST(ComputeEngine, AComputationThatThrowsBecomesAMessageAndTheNextRequestWorks) {
    ComputeEngine engine;
    engine.setCoalesceMs(0);
    auto preparer = std::make_shared<ScriptedPreparer>();
    engine.setPlotDataPreparer(preparer);
    const auto answered = [&](std::uint64_t generation) {
        return test::processEventsUntil([&] {
            return engine.latestResult() && engine.latestResult()->generation == generation;
        });
    };
    preparer->mode = ScriptedPreparer::Mode::ThrowOutOfMemory;
    engine.request(test::loadExample(), PlotAxis::Angle);
    ASSERT_TRUE(answered(1));
    EXPECT_FALSE(engine.latestResult()->ok());
    EXPECT_TRUE(engine.latestResult()->failed());
    ASSERT_EQ(engine.latestResult()->errors.size(), 1u);
    EXPECT_NE(engine.latestResult()->errors.front().message.find("out of memory"),
              std::string::npos);

    preparer->mode = ScriptedPreparer::Mode::ThrowError;
    engine.request(test::loadExample(), PlotAxis::Angle);
    ASSERT_TRUE(answered(2));
    EXPECT_TRUE(engine.latestResult()->failed());
    EXPECT_NE(engine.latestResult()->errors.front().message.find("scripted failure"),
              std::string::npos);

    preparer->mode = ScriptedPreparer::Mode::Pass;
    engine.request(test::loadExample(), PlotAxis::Angle);
    ASSERT_TRUE(answered(3));
    EXPECT_TRUE(engine.latestResult()->ok());
    EXPECT_FALSE(engine.latestResult()->failed());
    EXPECT_EQ(preparer->calls.load(), 3);
}

TEST(ComputeEngine, DestructorReturnsWithinItsBoundEvenIfAStepIgnoresCancel) {
    auto preparer = std::make_shared<ScriptedPreparer>();
    preparer->mode = ScriptedPreparer::Mode::IgnoreCancelFor2s;
    QElapsedTimer timer;
    {
        ComputeEngine engine;
        engine.setPlotDataPreparer(preparer);
        engine.request(test::loadExample(), PlotAxis::Angle);
        ASSERT_TRUE(test::processEventsUntil([&] { return preparer->calls.load() > 0; }));
        timer.start();
    }
    EXPECT_LT(timer.elapsed(), ComputeEngine::kStopTimeoutMs + 300);
    EXPECT_GE(timer.elapsed(), ComputeEngine::kStopTimeoutMs - 50);  // it did wait first
}

Project bigExample() {
    Project p = test::loadExample();
    p.samplesPerTurn = kMaxSamplesPerTurn;  // 10,000,000
    return p;
}

TEST(ComputeEngine, DestroyingTheEngineDuringABigTurnIsQuick) {
    // Every step polls the cancel flag: sampling, envelopes, analysis.
    QElapsedTimer timer;
    {
        ComputeEngine engine;
        engine.request(bigExample(), PlotAxis::Angle);
        test::processEventsUntil([] { return false; }, 150);  // well into the computation
        timer.start();
    }
    EXPECT_LT(timer.elapsed(), 300);  // it took 650–830 ms when only the sampling polled
}

TEST(ComputeEngine, ATenMillionSampleTurnHoldsABoundedNumberOfPoints) {
    ComputeEngine engine;
    const Project p = bigExample();
    engine.request(p, PlotAxis::Angle);
    ASSERT_TRUE(test::processEventsUntil(
        [&] { return engine.latestResult() && !engine.latestResult()->curves.partial; }, 60000));
    const ComputeResult& r = *engine.latestResult();
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.sampleCount, 10'000'000u);
    EXPECT_EQ(r.curves.levels.front().samplesPerBucket, 512u);  // the finest envelope
    // The bound: per curve, the finest level at most kMaxLevelPoints and each coarser one a
    // quarter of the one before (together at most a third more), plus per level three points
    // per joint and the end point.
    const std::size_t joints = r.contour->size();
    const std::size_t perCurve =
        4 * PlotCurves::kMaxLevelPoints / 3 + r.curves.levels.size() * (3 * joints + 1);
    EXPECT_LE(r.curves.pointCount(), kCurveCount * perCurve);
    EXPECT_GT(r.curves.levels.size(), 1u);
    // Bounded, and still true: the ranges of the plots are the exact extremes the analysis
    // finds (golden-section search on each segment's own formula), here at joints.
    const ContourAnalysis analysis = analyzeContour(*r.contour, r.omega);
    const auto extreme = [&](Quantity q) {
        for (const QuantityExtremes& e : analysis.extremes) {
            if (e.quantity == q) return e;
        }
        return QuantityExtremes{};
    };
    EXPECT_NEAR(r.curves.yRanges[1].upper, extreme(Quantity::A).max.value, 1e-9 * 4e5);
    EXPECT_NEAR(r.curves.yRanges[1].lower, extreme(Quantity::AR).min.value, 1e-9 * 4e5);
    EXPECT_NEAR(r.curves.yRanges[0].upper, extreme(Quantity::V).max.value, 1e-9 * 1e3);
    // Every level keeps those extremes, in ascending x over the whole turn [0°, 360°].
    for (const PlotLevel& level : r.curves.levels) {
        const auto& a = level.curves[static_cast<std::size_t>(Curve::A)];
        double hi = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!std::isnan(a[i].y)) hi = std::max(hi, a[i].y);
            if (i > 0) {
                ASSERT_LE(a[i - 1].x, a[i].x) << level.samplesPerBucket;
            }
        }
        EXPECT_DOUBLE_EQ(hi, r.curves.yRanges[1].upper) << level.samplesPerBucket;
        EXPECT_EQ(a.front().x, 0.0);
        EXPECT_NEAR(a.back().x, 360.0, 1e-12);
    }
}

}  // namespace
}  // namespace cam
