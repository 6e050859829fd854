// The forces the motion design's law itself asks for (evaluation/design_curves.h, lawForces):
// the bundled spring-loaded roller cam's cycloidal rise, h = 10 mm over β = 120°, in closed
// form: s = h(φ/β − sin(2πφ/β)/2π), s' = h/β (1 − cos(2πφ/β)), s'' = 2πh/β² sin(2πφ/β); the
// load by math.md §9 (0.8 kg, 5 N·s/m, 3 N/mm, 40 N at 300 rpm) and, for the radial roller of
// 8 mm on a base circle of 40 mm, tan α = s' / (48 + s). And the window's summary of the
// forces (evaluateForces) is the one `camwright-cli analyze` reports: the same function.

#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "evaluation/design_curves.h"
#include "evaluation/evaluation.h"
#include "evaluation/force_evaluation.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

TEST(DesignForces, TheLawsLoadOnTheRiseIsTheCycloidsClosedForm) {
    auto loaded = loadProjectFile(test::examplePath("spring-loaded-roller-cam.cam.json"));
    ASSERT_TRUE(loaded.ok());
    const Project& project = loaded.value();
    const ProjectEvaluation evaluation = evaluateProject(project);
    ASSERT_EQ(evaluation.status, EvaluationStatus::Computed);
    constexpr std::size_t n = 3600;
    DesignEvaluation design;
    ASSERT_TRUE(evaluateDesign(project, evaluation, n, design));
    ASSERT_EQ(design.lawForces.size(), n + 1);
    const double omega = 300.0 * kTwoPi / 60.0;
    ASSERT_NEAR(evaluation.omega, omega, 1e-12);
    const double h = 10.0, beta = degToRad(120.0);
    int checked = 0;
    for (std::size_t k = 1; k < 1200; k += 7) {
        const double phi = kTwoPi * static_cast<double>(k) / n;
        const double x = kTwoPi * phi / beta;
        const double s = h * (phi / beta - std::sin(x) / kTwoPi);
        const double s1 = h / beta * (1.0 - std::cos(x));
        const double s2 = kTwoPi * h / (beta * beta) * std::sin(x);
        const double load =
            0.8 * s2 * 1e-3 * omega * omega + 5.0 * s1 * 1e-3 * omega + 3.0 * s + 40.0;
        EXPECT_NEAR(design.lawForces.load[k], load, 1e-9 * std::abs(load)) << k;
        const double alpha = std::atan(s1 / (48.0 + s));
        EXPECT_NEAR(design.lawForces.normal[k], load / std::cos(alpha), 1e-9 * std::abs(load)) << k;
        // The power balance: T·ω = load · ds/dt.
        EXPECT_NEAR(design.lawForces.torque[k], load * s1 * 1e-3, 1e-9) << k;
        ++checked;
    }
    EXPECT_GT(checked, 150);
    // Without dynamics there are none.
    Project bare = project;
    bare.dynamics.reset();
    DesignEvaluation none;
    ASSERT_TRUE(evaluateDesign(bare, evaluateProject(bare), n, none));
    EXPECT_EQ(none.lawForces.size(), 0u);
}

TEST(DesignForces, TheSummaryIsFoundOnTheProjectsSamples) {
    auto loaded = loadProjectFile(test::examplePath("spring-loaded-roller-cam.cam.json"));
    ASSERT_TRUE(loaded.ok());
    Project project = loaded.value();
    project.samplesPerTurn = 5000;
    const ProjectEvaluation evaluation = evaluateProject(project);
    ASSERT_TRUE(evaluation.follower);
    ForceEvaluation forces;
    ASSERT_TRUE(evaluateForces(project, *evaluation.follower, evaluation.omega, forces));
    EXPECT_EQ(forces.turn.size(), 5000u);
    EXPECT_EQ(forces.forces.size(), 5000u);
    EXPECT_EQ(forces.model.mass, 0.8);
    // The largest normal force is refined between samples: no sample exceeds it, and the one
    // nearest it is within the curve's change over half a step.
    double largest = 0.0;
    for (const double v : forces.forces.normal) largest = std::max(largest, v);
    EXPECT_GE(forces.summary.maxNormal, largest);
    EXPECT_LT(forces.summary.maxNormal - largest, 1e-3 * largest);
    const std::atomic<bool> cancelled{true};
    ForceEvaluation stopped;
    EXPECT_FALSE(
        evaluateForces(project, *evaluation.follower, evaluation.omega, stopped, &cancelled));
}

}  // namespace
}  // namespace cam
