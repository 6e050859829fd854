// The follower over one full turn of the six-lobe cam (issue "Followers", point 7): a roller of
// 2 mm with 3 mm offset; s, v, a, j, the pressure angle and both radii of curvature at n equal
// angle steps into arrays. Compare with BM_KinematicsTurn of the same run (target: within 2×).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <vector>

#include "common/angles.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "io/project_json.h"

namespace {

struct FollowerTurn {
    std::vector<double> s, v, a, j, pressureAngle, rhoProfile, rhoPitch;
    void resize(std::size_t n) {
        for (auto* column : {&s, &v, &a, &j, &pressureAngle, &rhoProfile, &rhoPitch})
            column->resize(n);
    }
};

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
    const cam::Contour& contour = setup.contour;
    const double omega = setup.omega;
    const cam::FollowerModel model = cam::FollowerModel::build(contour, setup.spec).value();
    const auto n = static_cast<std::size_t>(state.range(0));
    FollowerTurn turn;
    turn.resize(n);
    const double step = cam::kTwoPi / static_cast<double>(n);
    for (auto _ : state) {
        for (std::size_t k = 0; k < n; ++k) {
            const cam::FollowerState f =
                model.at(contour.phiBegin() + step * static_cast<double>(k), omega);
            turn.s[k] = f.s;
            turn.v[k] = f.v;
            turn.a[k] = f.a;
            turn.j[k] = f.j;
            turn.pressureAngle[k] = f.pressureAngle;
            turn.rhoProfile[k] = f.rhoProfile;
            turn.rhoPitch[k] = f.rhoPitch;
        }
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
        benchmark::DoNotOptimize(checks.pressureRise.value);
    }
}
BENCHMARK(BM_FollowerChecks)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
