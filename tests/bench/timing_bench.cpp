// The time-optimal planner's two passes over N grid points (items = grid points), on the issue's
// reference path (line, tangent 90° arc, line) and on the six-lobe contour offset by 2 mm (all
// arcs). Target: at least 20 million grid points per second.
// And the refined methods on paths of N arcs (items = segments; issue 9): exact stop and
// optimal on the issue's arcs ((10k, 0, 0) with bulge 0.5, a corner at every joint, so every arc
// is planned alone), and optimal on a smooth chain (bulges ±0.5 in turn: one stretch).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <vector>

#include "contour/contour.h"
#include "io/project_json.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"

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

cam::ToolPath issueArcs(int count, bool alternate) {
    std::vector<cam::PathPoint> points;
    for (int k = 0; k <= count; ++k) {
        points.push_back({{10.0 * k, 0, 0}, alternate && k % 2 == 1 ? -0.5 : 0.5});
    }
    return cam::toolPathFromPoints(points).value();
}

void runRefined(benchmark::State& state, cam::TimingMethod method, bool alternate) {
    const cam::ToolPath path = issueArcs(static_cast<int>(state.range(0)), alternate);
    const cam::MachineLimits lim = limits();
    bool converged = true;
    for (auto _ : state) {
        const auto r = cam::machiningTime(path, lim, method);
        if (!r.ok()) std::abort();
        converged = r.value().converged;
        benchmark::DoNotOptimize(r.value().timeS);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.counters["converged"] = converged ? 1 : 0;
}

void BM_TimingExactStopArcs(benchmark::State& state) {
    runRefined(state, cam::TimingMethod::ExactStop, false);
}
void BM_TimingOptimalArcs(benchmark::State& state) {
    runRefined(state, cam::TimingMethod::Optimal, false);
}
void BM_TimingOptimalSmoothChain(benchmark::State& state) {
    runRefined(state, cam::TimingMethod::Optimal, true);
}

BENCHMARK(BM_TimingExactStopArcs)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kSecond);
BENCHMARK(BM_TimingOptimalArcs)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kSecond);
BENCHMARK(BM_TimingOptimalSmoothChain)
    ->Arg(1'000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kSecond);

BENCHMARK(BM_TimingOptimal)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TimingOptimalSixLobe)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
