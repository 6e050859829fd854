// The time-optimal planner's two passes over N grid points (items = grid points), on the issue's
// reference path (line, tangent 90° arc, line) and on the six-lobe contour offset by 2 mm (all
// arcs). Target: at least 20 million grid points per second.

#include <benchmark/benchmark.h>

#include <cstdlib>

#include "contour/contour.h"
#include "io/project_json.h"
#include "timing/machining_time.h"

namespace {

cam::ToolPath referencePath() {
    cam::ToolPath p;
    p.segments.push_back(cam::PathSegment::line({0, 0, 0}, {100, 0, 0}));
    p.segments.push_back(cam::PathSegment::arc({100, 20}, 20, -M_PI / 2, M_PI / 2, 0));
    p.segments.push_back(cam::PathSegment::line({120, 20, 0}, {120, 120, 0}));
    return p;
}

cam::ToolPath sixLobePath() {
    auto p = cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json");
    if (!p.ok()) std::abort();
    return cam::toolPathFromContour(cam::Contour::build(p.value()).value(), 2.0).value();
}

cam::MachineLimits limits() {
    cam::MachineLimits lim;
    lim.accel = {500, 250, 100};
    lim.vmax = {200, 150, 50};
    return lim;
}

void run(benchmark::State& state, const cam::ToolPath& path) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const cam::MachineLimits lim = limits();
    for (auto _ : state) {
        const auto profile = cam::optimalProfile(path, lim, n);
        benchmark::DoNotOptimize(profile.timeS);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_TimingOptimal(benchmark::State& state) { run(state, referencePath()); }
void BM_TimingOptimalSixLobe(benchmark::State& state) { run(state, sixLobePath()); }

BENCHMARK(BM_TimingOptimal)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TimingOptimalSixLobe)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
