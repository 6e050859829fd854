// The forces of one turn (issue 30, point 2): the six-lobe cam under BM_FollowerTurn's roller
// (2 mm, offset 3 mm) with a full dynamics section (mass, spring, preload, load, damping,
// steel on steel): the forces of a turn sampled at n instants (forcesOfTurn over
// sampleFollowerTurn's columns). Target: BM_ForcesTurn/1000000 within 1.5× of
// BM_FollowerTurn/1000000, the sampling itself.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <vector>

#include "contour/contour.h"
#include "follower/follower.h"
#include "follower/follower_turn.h"
#include "forces/forces.h"
#include "io/project_json.h"
#include "steel_dynamics.h"

namespace {

void BM_ForcesTurn(benchmark::State& state) {
    auto project =
        cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json");
    if (!project.ok()) std::abort();
    const cam::Contour contour = cam::Contour::build(project.value()).value();
    const double omega = project.value().motion.omegaRadS();
    cam::FollowerSpec spec;
    spec.type = cam::FollowerType::Roller;
    spec.radius = 2.0;
    spec.offset = 3.0;
    const cam::FollowerModel model = cam::FollowerModel::build(contour, spec).value();
    const cam::ForceModel forces = cam::ForceModel::of(cam::test::steelOnSteelDynamics(), spec);
    const auto n = static_cast<std::size_t>(state.range(0));
    cam::FollowerTurn turn;
    cam::ForceTurn out;
    cam::sampleFollowerTurn(model, omega, n, turn);
    cam::forcesOfTurn(forces, model, turn, omega, out);  // first touch outside the timing
    for (auto _ : state) {
        cam::forcesOfTurn(forces, model, turn, omega, out);
        benchmark::DoNotOptimize(out.stress.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}
BENCHMARK(BM_ForcesTurn)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace
