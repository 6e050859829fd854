// Issue 9 in the app: a machining request with a hopeless seed step must neither block the
// worker (a new request got no result, closing the window hung) nor go unexplained, and a time
// whose refinement stopped short is shown as an estimate.

#include <gtest/gtest.h>

#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <filesystem>
#include <fstream>
#include <memory>

#include "app_test_support.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "timing/machining_time.h"
#include "toolpath/tool_path.h"
#include "views/machining_panel.h"

namespace cam {
namespace {

/// One circle of radius 100 m: a 628 m tool path. With a seed step of 1e-6 mm (which the
/// project's validation allows) the seed method would walk 3e11 steps, hours in the old worker,
/// which never polled its cancel flag there.
constexpr const char* kCircle = R"({
  "format": "camwright", "version": 1, "name": "circle",
  "units": {"length": "mm", "angle": "deg"}, "motion": {"period_s": 1.0},
  "contour": [{"type": "arc", "center": [0, 0], "radius": 100000, "branch": "outer",
               "phi_start": 0, "phi_end": 360}],
  "machining": {"axis_accel": [500, 500, 200], "feed_max": 100, "tool_radius": 2.0, "step": %1}
})";

Project circle(const char* step) {
    auto p = parseProject(QString::fromUtf8(kCircle).arg(step).toStdString());
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.errors().front().text());
    return p.value();
}

/// Waits for the newest request's machining times (or the timeout).
bool waitForTiming(const ComputeEngine& engine, int timeoutMs) {
    return test::processEventsUntil(
        [&] {
            const auto& t = engine.latestTiming();
            return t && t->generation == engine.latestGeneration();
        },
        timeoutMs);
}

constexpr int kPromptMs = test::kSanitized ? 30000 : 5000;

// Fact: the hopeless step is refused at once with a message naming machining.step, a request
// that follows gets its times, one that supersedes it at once gets them too, and the engine is
// destroyed without waiting. The old worker walked the steps without polling its cancel flag.
TEST(MachiningHostile, AHopelessStepIsAnsweredAndNeverHoldsUpTheNextRequest) {
    QElapsedTimer destroyed;
    {
        ComputeEngine engine;
        engine.setCoalesceMs(0);
        engine.request(circle("1e-6"), PlotAxis::Angle, true);
        ASSERT_TRUE(waitForTiming(engine, kPromptMs)) << "no answer to the hopeless request";
        const TimingOutcomePtr refused = engine.latestTiming();
        ASSERT_EQ(refused->errors.size(), 1u);
        EXPECT_EQ(refused->errors.front().location, "machining.step");
        EXPECT_NE(refused->errors.front().message.find("at most 10000000"), std::string::npos)
            << refused->errors.front().text();

        engine.request(circle("1"), PlotAxis::Angle, true);
        ASSERT_TRUE(waitForTiming(engine, kPromptMs)) << "the next request got no times";
        const TimingOutcomePtr good = engine.latestTiming();
        ASSERT_TRUE(good->errors.empty()) << good->errors.front().text();
        // The circle offset by the 2 mm tool, 2π·100002 mm, at the feed of 100 mm/s with its
        // two ramps (F/a each; the centripetal F²/R = 0.1 mm/s² does not bind): L/F + F/a.
        const double length = 2.0 * M_PI * 100002.0;
        EXPECT_TRUE(test::relClose(good->lengthMm, length, 1e-12));
        EXPECT_TRUE(test::relClose(good->timesS[2], length / 100.0 + 100.0 / 500.0, 1e-9));
        EXPECT_TRUE(test::relClose(good->timesS[1], length / 100.0 + 100.0 / 500.0, 1e-9));

        // Superseded at once: the newer request is answered.
        engine.request(circle("1e-6"), PlotAxis::Angle, true);
        engine.request(circle("2"), PlotAxis::Angle, true);
        ASSERT_TRUE(waitForTiming(engine, kPromptMs)) << "the superseding request got no times";
        EXPECT_TRUE(engine.latestTiming()->errors.empty());

        engine.request(circle("1e-6"), PlotAxis::Angle, true);
        destroyed.start();
    }
    EXPECT_LT(destroyed.elapsed(), test::kSanitized ? 3000 : 500);
}

std::string writeTemp(const std::string& name, const std::string& text) {
    const auto p = std::filesystem::temp_directory_path() / ("camwright_app_" + name);
    std::ofstream(p) << text;
    return p.string();
}

// Fact: the window shows the refusal in the machining panel and closes at once (the old window
// hung on close, waiting for the worker).
TEST(MachiningHostile, TheWindowExplainsTheStepAndClosesAtOnce) {
    const std::string path =
        writeTemp("hopeless.cam.json", QString::fromUtf8(kCircle).arg("1e-6").toStdString());
    QElapsedTimer closed;
    {
        MainWindow window;
        ASSERT_TRUE(window.loadFile(QString::fromStdString(path)).isEmpty());
        window.show();
        window.findChild<QDockWidget*>("machiningDock")->show();
        ASSERT_TRUE(waitForTiming(*window.engine(), kPromptMs));
        const auto* status = window.machiningPanel()->findChild<QLabel*>("machiningStatus");
        ASSERT_NE(status, nullptr);
        EXPECT_TRUE(status->text().contains("Machining, step: ")) << status->text().toStdString();
        window.close();
        closed.start();
    }
    EXPECT_LT(closed.elapsed(), test::kSanitized ? 3000 : 500);
}

// Fact: a time whose refinement stopped at the grid limit is shown as an estimate ("≈") with a
// note naming the method and its estimated error. The outcome is the core's, for the six-lobe
// path planned with room for only 20,000 grid points (its 13 arcs need more).
TEST(MachiningHostile, AnUnconvergedTimeIsShownAsAnEstimate) {
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::dataPath("app/six-lobe-machining.cam.json")))
            .isEmpty());
    window.show();
    window.findChild<QDockWidget*>("machiningDock")->show();
    ASSERT_TRUE(waitForTiming(*window.engine(), kPromptMs));
    auto outcome = std::make_shared<TimingOutcome>(*window.engine()->latestTiming());
    ASSERT_TRUE(outcome->errors.empty());
    EXPECT_EQ(outcome->converged, (std::array<bool, 3>{true, true, true}));
    const Project& p = window.document()->project();
    const ToolPath path =
        toolPathFromContour(Contour::build(p).value(), p.machining->toolRadius).value();
    const TimingResult cramped =
        machiningTime(path, limitsFromProject(*p.machining), TimingMethod::Optimal, nullptr, 20'000)
            .value();
    ASSERT_FALSE(cramped.converged);
    outcome->timesS[2] = cramped.timeS;
    outcome->converged[2] = false;
    outcome->convergence[2] = cramped.convergence;
    window.machiningPanel()->setOutcome(outcome);
    const QString times = window.machiningPanel()->timesText();
    // A time has 6 significant digits and an error estimate 3 (widgets/quantity_format.h).
    EXPECT_TRUE(times.contains("≈ " + QLocale().toString(cramped.timeS, 'g', 6) + " s"))
        << times.toStdString();
    const auto* status = window.machiningPanel()->findChild<QLabel*>("machiningStatus");
    ASSERT_NE(status, nullptr);
    EXPECT_TRUE(status->text().contains("Not converged")) << status->text().toStdString();
    // Three digits, the exponent written "E" in every language (widgets/number_format.h).
    EXPECT_TRUE(
        status->text().contains(QLocale().toString(cramped.convergence, 'g', 3).replace('e', 'E')))
        << status->text().toStdString();
}

}  // namespace
}  // namespace cam
