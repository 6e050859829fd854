// Sizing (issue 29): the smallest base radius of a design, and the placement that allows the
// smallest one, on the bundled examples' designs — what the dock's Smallest, Best Offset and
// Best Pivot buttons wait for. See docs/performance.md.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "design/sizing.h"
#include "io/project_json.h"

namespace {

cam::Project example(const char* name) {
    auto loaded = cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/" + name);
    if (!loaded.ok() || !loaded.value().design || !loaded.value().follower) std::abort();
    return loaded.value();
}

// The roller of synthesised-cycloidal-roller and the arm of swinging-arm-cam.
const char* const kExamples[] = {"synthesised-cycloidal-roller.cam.json",
                                 "swinging-arm-cam.cam.json"};

// Arg: 0 the translating roller, 1 the swinging arm.
void BM_SizeBaseRadius(benchmark::State& state) {
    const cam::Project p = example(kExamples[state.range(0)]);
    for (auto _ : state) {
        auto sized = cam::sizeBaseRadius(*p.design, *p.follower);
        if (!sized.ok()) std::abort();
        benchmark::DoNotOptimize(sized);
    }
}
BENCHMARK(BM_SizeBaseRadius)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Arg: 0 the roller's best offset, 1 the arm's best pivot (41 placements each).
void BM_SizePlacement(benchmark::State& state) {
    const cam::Project p = example(kExamples[state.range(0)]);
    for (auto _ : state) {
        auto sized = cam::sizePlacement(*p.design, *p.follower);
        if (!sized.ok()) std::abort();
        benchmark::DoNotOptimize(sized);
    }
}
BENCHMARK(BM_SizePlacement)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
