// Design from motion (issue "Design from motion", point 8): math.md §8's cycloidal cam (radial
// knife, Rb 40 mm, cycloidal rise of 10 mm over 0–120°, dwell, return over 180–300°, dwell)
// synthesised into an arc table — the exact profile, the fit and the follower placed on the
// result to measure the price of arcs. Target: under 20 ms at 0.001 mm.

#include <benchmark/benchmark.h>

#include <cstdlib>

#include "design/synthesis.h"

namespace {

cam::Project cycloidalCam() {
    cam::Project p;
    p.motion = {cam::SpeedUnit::Rpm, 60.0};
    cam::DesignSpec d;
    d.baseRadius = 40.0;
    d.segments = {{cam::MotionLawType::Cycloidal, 120.0, 10.0},
                  {cam::MotionLawType::Dwell, 180.0, 10.0},
                  {cam::MotionLawType::Cycloidal, 300.0, 0.0},
                  {cam::MotionLawType::Dwell, 360.0, 0.0}};
    p.design = d;
    return p;
}

// Arg: the tolerance in µm.
void BM_Synthesize(benchmark::State& state) {
    const cam::Project project = cycloidalCam();
    const double tolerance = static_cast<double>(state.range(0)) * 1e-3;
    std::size_t segments = 0;
    for (auto _ : state) {
        const auto made = cam::synthesize(project, tolerance);
        if (!made.ok()) std::abort();
        segments = made.value().report.segments;
        benchmark::DoNotOptimize(segments);
    }
    state.counters["arcs"] = static_cast<double>(segments);
}
BENCHMARK(BM_Synthesize)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
