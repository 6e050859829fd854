// Cancellation of the machining-time computations: a flag set from another thread while a long
// computation runs must stop it, with the error {"", "cancelled"}, within a bound far below the
// computation's own duration. The workloads take 0.3–3 s each uncancelled on the development
// machine (a 5-million-step seed walk, an 8-million-point plan); the bound is 100 ms, so a
// loop that does not poll fails by an order of magnitude, while a polling one answers in about
// a millisecond and has ample room for a loaded machine.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <iostream>
#include <string>
#include <thread>

#include "common/angles.h"
#include "core/test_projects.h"
#include "io/project_json.h"
#include "test_support.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"

namespace cam {
namespace {

using test::errorsOf;

using Clock = std::chrono::steady_clock;

/// How long a call may go on after its flag was set (sanitizers slow everything down several
/// times; a loop that does not poll still overshoots by seconds).
constexpr double kHonouredWithinMs = test::kSanitized ? 500.0 : 100.0;
/// When the flag is set, after the call started: long enough that the call is well under way.
constexpr auto kSetAfter = std::chrono::milliseconds(20);
/// For the 8-million-point plans: after their memory is set up (some tens of ms), inside the
/// passes themselves (together some hundreds of ms).
constexpr auto kSetInThePasses = std::chrono::milliseconds(100);

bool isCancelled(const Diagnostics& errors) {
    return errors.size() == 1 && errors.front().location.empty() &&
           errors.front().message == "cancelled";
}

struct CancelRun {
    bool cancelled = false;  ///< the call reported {"", "cancelled"}
    double lateMs = 0.0;     ///< how long it ran on after the flag was set
};

/// Runs `call` with a flag that another thread sets `setAfter` after the start.
CancelRun cancelWhileRunning(const std::function<Diagnostics(const std::atomic<bool>*)>& call,
                             std::chrono::milliseconds setAfter = kSetAfter) {
    std::atomic<bool> flag{false};
    const Clock::time_point start = Clock::now();
    Clock::time_point setAt;
    std::thread setter([&] {
        std::this_thread::sleep_until(start + setAfter);
        setAt = Clock::now();
        flag.store(true);
    });
    const Diagnostics errors = call(&flag);
    const Clock::time_point end = Clock::now();
    setter.join();
    CancelRun run;
    run.cancelled = isCancelled(errors);
    run.lateMs = std::chrono::duration<double, std::milli>(end - setAt).count();
    std::cout << "[ info ] cancelled " << run.cancelled << ", returned " << run.lateMs
              << " ms after the flag was set\n";
    return run;
}

MachineLimits limits() {
    MachineLimits lim;
    lim.accel = {500, 250, 100};
    lim.vmax = {200, 150, 50};
    lim.feedMax = 100;
    return lim;
}

/// One 100 m line: with 0.01 mm steps (the most the seed method takes, kMaxSeedSteps = 1e7 over
/// the path), the seed walks 5 million steps to its middle.
ToolPath longLine() { return ToolPath{{PathSegment::line({0, 0, 0}, {1e5, 0, 0})}}; }

/// The reference path: line, tangent quarter arc, line.
ToolPath referencePath() {
    return ToolPath{{PathSegment::line({0, 0, 0}, {100, 0, 0}),
                     PathSegment::arc({100, 20}, 20, -kPi / 2, kPi / 2, 0),
                     PathSegment::line({120, 20, 0}, {120, 120, 0})}};
}

TEST(TimingCancel, SeedStopsWithinOneLongSegment) {
    MachineLimits lim = limits();
    lim.seedStep = 0.01;
    const ToolPath path = longLine();
    const CancelRun run = cancelWhileRunning([&](const std::atomic<bool>* cancel) {
        return errorsOf(machiningTime(path, lim, TimingMethod::Seed, cancel));
    });
    EXPECT_TRUE(run.cancelled);
    EXPECT_LT(run.lateMs, kHonouredWithinMs);
}

TEST(TimingCancel, SeedProfileStopsWithinOneLongSegment) {
    MachineLimits lim = limits();
    lim.seedStep = 0.01;
    const ToolPath path = longLine();
    const CancelRun run = cancelWhileRunning([&](const std::atomic<bool>* cancel) {
        return errorsOf(timingProfile(path, lim, TimingMethod::Seed, 4000, cancel));
    });
    EXPECT_TRUE(run.cancelled);
    EXPECT_LT(run.lateMs, kHonouredWithinMs);
}

// One plan on 2^23 grid points: the passes themselves must poll, not only the refinement
// between them.
TEST(TimingCancel, OptimalPlanStopsWithinAPass) {
    const ToolPath path = referencePath();
    const CancelRun run = cancelWhileRunning(
        [&](const std::atomic<bool>* cancel) {
            return errorsOf(timingProfile(path, limits(), TimingMethod::Optimal, 1u << 23, cancel));
        },
        kSetInThePasses);
    EXPECT_TRUE(run.cancelled);
    EXPECT_LT(run.lateMs, kHonouredWithinMs);
}

TEST(TimingCancel, ExactStopPlanStopsWithinAPass) {
    const ToolPath arc{{PathSegment::arc({0, 0}, 1000, 0, 6, 0)}};
    const CancelRun run = cancelWhileRunning(
        [&](const std::atomic<bool>* cancel) {
            return errorsOf(
                timingProfile(arc, limits(), TimingMethod::ExactStop, 1u << 23, cancel));
        },
        kSetInThePasses);
    EXPECT_TRUE(run.cancelled);
    EXPECT_LT(run.lateMs, kHonouredWithinMs);
}

/// 100 000 lines with a corner (a 3D kink) at every joint: the optimal plan's refinement keeps
/// doubling, and every pass covers at least 200 000 grid points.
ToolPath zigzag() {
    ToolPath path;
    Eigen::Vector3d p{0, 0, 0};
    for (int k = 0; k < 100'000; ++k) {
        const Eigen::Vector3d q = p + Eigen::Vector3d(1.0, k % 2 == 0 ? 1.0 : -1.0, 0.5);
        path.segments.push_back(PathSegment::line(p, q));
        p = q;
    }
    return path;
}

/// 2000 half circles of radius 10 in a row: exact stop plans each arc on its own refined grid.
ToolPath arches() {
    ToolPath path;
    for (int k = 0; k < 2000; ++k) {
        path.segments.push_back(PathSegment::arc({20.0 * k + 10.0, 0}, 10, kPi, -kPi, 0));
    }
    return path;
}

TEST(TimingCancel, RefinedPlansStopOnTime) {
    const ToolPath lines = zigzag(), arcs = arches();
    const CancelRun optimal = cancelWhileRunning([&](const std::atomic<bool>* cancel) {
        return errorsOf(machiningTime(lines, limits(), TimingMethod::Optimal, cancel));
    });
    EXPECT_TRUE(optimal.cancelled);
    EXPECT_LT(optimal.lateMs, kHonouredWithinMs);
    const CancelRun exact = cancelWhileRunning([&](const std::atomic<bool>* cancel) {
        return errorsOf(machiningTime(arcs, limits(), TimingMethod::ExactStop, cancel));
    });
    EXPECT_TRUE(exact.cancelled);
    EXPECT_LT(exact.lateMs, kHonouredWithinMs);
}

// A flag already set: the tool path and every method answer "cancelled" without computing.
TEST(TimingCancel, APresetFlagCancelsEveryStep) {
    const std::atomic<bool> cancel{true};
    const Contour contour =
        Contour::build(loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value())
            .value();
    EXPECT_TRUE(isCancelled(errorsOf(toolPathFromContour(contour, 2.0, &cancel))));
    for (TimingMethod method :
         {TimingMethod::Seed, TimingMethod::ExactStop, TimingMethod::Optimal}) {
        SCOPED_TRACE(timingMethodName(method));
        EXPECT_TRUE(
            isCancelled(errorsOf(machiningTime(referencePath(), limits(), method, &cancel))));
        EXPECT_TRUE(
            isCancelled(errorsOf(timingProfile(referencePath(), limits(), method, 4000, &cancel))));
    }
}

}  // namespace
}  // namespace cam
