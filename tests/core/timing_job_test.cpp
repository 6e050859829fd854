// The machining-time pipeline (timing_job.h) that the CLI and the app share: the tool path, the
// methods in the order asked, the profile, located errors and cancellation. Values are checked
// against hand-worked geometry and closed forms; the pipeline's results are also required to be
// exactly those of its documented steps.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "common/angles.h"
#include "io/project_json.h"
#include "test_support.h"
#include "timing/timing_job.h"

namespace cam {
namespace {

/// The square ±10 as four lines, tool radius 1.5, a = 500 mm/s² on x and y, feed 100 mm/s.
constexpr const char* kSquare = R"({
  "format": "camwright", "version": 1, "name": "square",
  "units": {"length": "mm", "angle": "deg"}, "motion": {"period_s": 1.0},
  "contour": [
    {"type": "line", "from": [10, -10], "to": [10, 10], "phi_start": -45, "phi_end": 45},
    {"type": "line", "from": [10, 10], "to": [-10, 10], "phi_start": 45, "phi_end": 135},
    {"type": "line", "from": [-10, 10], "to": [-10, -10], "phi_start": 135, "phi_end": 225},
    {"type": "line", "from": [-10, -10], "to": [10, -10], "phi_start": 225, "phi_end": 315}
  ],
  "machining": {"axis_accel": [500, 500, 200], "feed_max": 100, "tool_radius": 1.5, "step": 1}
})";

Project squareProject() {
    auto p = parseProject(kSquare);
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.errors().front().text());
    return p.value();
}

const std::vector<TimingMethod> kAll{TimingMethod::ExactStop, TimingMethod::Seed,
                                     TimingMethod::Optimal};

TEST(TimingJob, ContourToolPathMethodsAndProfile) {
    const Project project = squareProject();
    const Contour contour = Contour::build(project).value();
    TimingJob job = timingJobFor(*project.machining, kAll);
    EXPECT_EQ(job.toolRadiusMm, 1.5);
    EXPECT_EQ(job.limits.accel, Eigen::Vector3d(500, 500, 200));
    EXPECT_EQ(job.limits.feedMax, 100.0);
    job.profileMethod = TimingMethod::ExactStop;
    job.profilePoints = 1000;
    const auto timed = timeContour(contour, job);
    ASSERT_TRUE(timed.ok()) << timed.errors().front().text();
    const TimedPath& t = timed.value();

    // The offset square: four sides of 20 mm and four quarter circles of the tool radius.
    ASSERT_EQ(t.path.segments.size(), 8u);
    EXPECT_NEAR(t.path.length(), 80.0 + kTwoPi * 1.5, 1e-9);
    // One result per method, in the order asked.
    ASSERT_EQ(t.results.size(), 3u);
    for (std::size_t m = 0; m < 3; ++m) EXPECT_EQ(t.results[m].method, kAll[m]);
    // Exact stop on each 20 mm side: v²/a = 100²/500 = 20 mm, so the ramp up and down just
    // meet: 20/100 + 100/500 = 0.4 s.
    for (std::size_t k = 0; k < 8; k += 2) {
        EXPECT_NEAR(t.results[0].segments[k].timeS, 0.4, 1e-12) << k;
    }
    // The profile of the method asked: it runs over the whole path and ends at rest.
    ASSERT_TRUE(t.profile.has_value());
    EXPECT_NEAR(t.profile->s.back(), 80.0 + kTwoPi * 1.5, 1e-9);
    EXPECT_EQ(t.profile->speed.back(), 0.0);

    // And it is exactly its steps, the tool path and then machiningTime / timingProfile.
    const ToolPath path = toolPathFromContour(contour, 1.5).value();
    for (std::size_t m = 0; m < 3; ++m) {
        EXPECT_EQ(t.results[m].timeS, machiningTime(path, job.limits, kAll[m]).value().timeS);
    }
    const TimingProfile profile =
        timingProfile(path, job.limits, TimingMethod::ExactStop, 1000).value();
    EXPECT_EQ(t.profile->s, profile.s);
    EXPECT_EQ(t.profile->speed, profile.speed);

    job.profileMethod.reset();
    EXPECT_FALSE(timeContour(contour, job).value().profile.has_value());
}

TEST(TimingJob, AGivenPathIgnoresTheToolRadius) {
    // Two 20 mm lines at a right angle: both rest to rest, 0.4 s each (see above).
    TimingJob job = timingJobFor(*squareProject().machining, {TimingMethod::Optimal});
    const ToolPath corner{
        {PathSegment::line({0, 0, 0}, {20, 0, 0}), PathSegment::line({20, 0, 0}, {20, 20, 0})}};
    const auto timed = timePath(corner, job);
    ASSERT_TRUE(timed.ok());
    EXPECT_EQ(timed.value().path.segments.size(), 2u);
    EXPECT_TRUE(test::relClose(timed.value().results.front().timeS, 0.8, 1e-6));
}

TEST(TimingJob, ErrorsAreLocated) {
    // A tool too large for the notch's dwell arc (tool_path_test.cpp): the tool path's error.
    const Project notch = loadProjectFile(test::dataPath("timing/notch-dwell.cam.json")).value();
    const auto tooLarge =
        timeContour(Contour::build(notch).value(), timingJobFor(*notch.machining, kAll));
    ASSERT_FALSE(tooLarge.ok());
    EXPECT_EQ(tooLarge.errors().front().location, "contour[2]");
    // Limits that cannot be planned with: machiningTime's error.
    TimingJob job = timingJobFor(*squareProject().machining, kAll);
    job.limits.accel[1] = 0.0;
    const auto noAccel = timeContour(Contour::build(squareProject()).value(), job);
    ASSERT_FALSE(noAccel.ok());
    EXPECT_EQ(noAccel.errors().front().location, "accel[1]");
}

TEST(TimingJob, APresetCancelFlagCancels) {
    const std::atomic<bool> cancel{true};
    const Project project = squareProject();
    TimingJob job = timingJobFor(*project.machining, kAll);
    job.profileMethod = TimingMethod::Optimal;
    const auto timed = timeContour(Contour::build(project).value(), job, &cancel);
    ASSERT_FALSE(timed.ok());
    ASSERT_EQ(timed.errors().size(), 1u);
    EXPECT_EQ(timed.errors().front().location, "");
    EXPECT_EQ(timed.errors().front().message, "cancelled");
}

}  // namespace
}  // namespace cam
