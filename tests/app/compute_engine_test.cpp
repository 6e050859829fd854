// The compute engine: latest request wins, stale results are never shown, results match an
// independent computation of the same snapshot.

#include <gtest/gtest.h>

#include "app_test_support.h"
#include "common/angles.h"
#include "engine/compute_engine.h"

namespace cam {
namespace {

Project heavyExample(double period) {
    Project p = test::loadExample();
    p.samplesPerTurn = 200'000;  // a few ms per computation: long enough to be superseded
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
    test::processEventsUntil([] { return false; }, 300);  // anything late would arrive now
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown.front(), 100u);

    // The result is the computation of the last snapshot, value for value.
    const ComputeResultPtr& r = engine.latestResult();
    EXPECT_DOUBLE_EQ(r->project->motion.value, lastPeriod);
    const Contour contour = Contour::build(heavyExample(lastPeriod)).value();
    SampledTurn expected;
    sampleTurn(contour, kTwoPi / lastPeriod, 200'000, expected);
    ASSERT_EQ(r->turn.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); k += 997) {
        EXPECT_EQ(r->turn.r[k], expected.r[k]);
        EXPECT_EQ(r->turn.aR[k], expected.aR[k]);
        EXPECT_EQ(r->turn.jPhi[k], expected.jPhi[k]);
    }
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
