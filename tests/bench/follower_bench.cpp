// The follower over one full turn of the six-lobe cam (issue "Followers", point 7): a roller of
// 2 mm with 3 mm offset; s, v, a, j, the pressure angle and both radii of curvature at n equal
// time steps into arrays (sampleFollowerTurn). Compare with BM_KinematicsTurn of the same run
// (target: within 2×).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <vector>

#include "common/angles.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "follower/follower_turn.h"
#include "io/project_json.h"

namespace {

/// The six-lobe example with a roller of 2 mm: offset 3 mm on a line, or (arm) on a swinging
/// arm from a pivot 60 mm out, 50 mm long.
struct RollerCam {
    cam::Contour contour;
    double omega = 0.0;
    cam::FollowerSpec spec;
};

RollerCam rollerCam(bool arm) {
    auto project =
        cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json");
    if (!project.ok()) std::abort();
    cam::FollowerSpec spec;
    spec.type = cam::FollowerType::Roller;
    spec.radius = 2.0;
    spec.offset = 3.0;
    if (arm) {
        spec.offset = 0.0;
        spec.motion = cam::FollowerMotion::Oscillating;
        spec.pivot = {60.0, 0.0};
        spec.armLength = 50.0;
    }
    return {cam::Contour::build(project.value()).value(), project.value().motion.omegaRadS(), spec};
}

void BM_FollowerTurn(benchmark::State& state) {
    const RollerCam setup = rollerCam(state.range(1) == 1);
    const cam::FollowerModel model = cam::FollowerModel::build(setup.contour, setup.spec).value();
    const auto n = static_cast<std::size_t>(state.range(0));
    cam::FollowerTurn turn;
    cam::sampleFollowerTurn(model, setup.omega, n, turn);  // first touch outside the timing
    for (auto _ : state) {
        cam::sampleFollowerTurn(model, setup.omega, n, turn);
        benchmark::DoNotOptimize(turn.rhoPitch.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}
BENCHMARK(BM_FollowerTurn)
    ->ArgNames({"", "arm"})
    ->Args({1000, 0})
    ->Args({100000, 0})
    ->Args({1000000, 0})
    ->Args({100000, 1})
    ->Unit(benchmark::kMillisecond);

// FollowerModel::at() one angle at a time (what the CLI's state, the contour view's marker and
// the design checks' refinement call): the cost of one exact evaluation without the batch.
void BM_FollowerAt(benchmark::State& state) {
    const RollerCam setup = rollerCam(false);
    const cam::Contour& contour = setup.contour;
    const cam::FollowerModel model = cam::FollowerModel::build(contour, setup.spec).value();
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<double> s(n);
    const double step = cam::kTwoPi / static_cast<double>(n);
    for (auto _ : state) {
        for (std::size_t k = 0; k < n; ++k) {
            s[k] = model.at(contour.phiBegin() + step * static_cast<double>(k), setup.omega).s;
        }
        benchmark::DoNotOptimize(s.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}
BENCHMARK(BM_FollowerAt)->Arg(100000)->Unit(benchmark::kMillisecond);

// The design checks of one turn (analyzeFollower at its default 7200 samples, every extreme
// refined): what the app's engine adds to a computation when the project has a follower.
// Arg 0: the translating roller of BM_FollowerTurn; 1: the same roller on its swinging arm.
void BM_FollowerChecks(benchmark::State& state) {
    const RollerCam setup = rollerCam(state.range(0) == 1);
    const cam::Contour& contour = setup.contour;
    const cam::FollowerSpec& spec = setup.spec;
    const double omega = setup.omega;
    for (auto _ : state) {
        const cam::FollowerModel model = cam::FollowerModel::build(contour, spec).value();
        const cam::FollowerAnalysis checks = cam::analyzeFollower(model, omega, contour.phiBegin());
        benchmark::DoNotOptimize(checks.pressure.max.value);
    }
}
BENCHMARK(BM_FollowerChecks)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
