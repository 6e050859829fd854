// Kinematics of one full turn of the six-lobe cam into every array of SampledTurn.
// Compare with tests/bench/numpy_baseline.py, run in the same session (see docs/performance.md).

#include <benchmark/benchmark.h>

#include <cstdlib>

#include "contour/contour.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"

namespace {

cam::Contour sixLobe(double* omega) {
    auto p = cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json");
    if (!p.ok()) std::abort();
    *omega = p.value().motion.omegaRadS();
    return cam::Contour::build(p.value()).value();
}

void BM_KinematicsTurn(benchmark::State& state) {
    double omega = 0.0;
    const cam::Contour contour = sixLobe(&omega);
    const auto n = static_cast<std::size_t>(state.range(0));
    cam::SampledTurn turn;
    cam::sampleTurn(contour, omega, n, turn);  // first touch of the pages outside the timing
    for (auto _ : state) {
        cam::sampleTurn(contour, omega, n, turn);
        benchmark::DoNotOptimize(turn.j.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}
BENCHMARK(BM_KinematicsTurn)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
