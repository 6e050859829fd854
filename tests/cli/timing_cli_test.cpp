// camwright-cli timing: output contract, consistency of --detail, and every bad input class.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/project_json.h"
#include "spline/teach_in.h"
#include "test_support.h"
#include "timing_reference.h"
#include "toolpath/biarc.h"

namespace cam {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
    return test::writeTestTempFile("camwright_timing", name, text);
}

// The issue's reference path as a point list: the bulge tan(π/8) makes the 90° arc.
const std::string kReferenceCsv =
    "x,y,z,bulge\n0,0,0,0\n100,0,0,0.41421356237309503\n120,20,0,0\n120,120,0\n";
const std::vector<std::string> kLimits{"--accel", "500,250,100", "--vmax", "200,150,50"};

nlohmann::json timing(std::vector<std::string> args) {
    const auto r = test::runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

TEST(CliTiming, ThreeMethodsOnTheReferencePath) {
    const std::string csv = writeTemp("reference.csv", kReferenceCsv);
    auto args = [&](const char* method) {
        std::vector<std::string> a{"timing", "--path", csv, "--method", method};
        a.insert(a.end(), kLimits.begin(), kLimits.end());
        return a;
    };
    const auto optimal = timing(args("optimal"));
    const auto exact = timing(args("exact-stop"));
    const auto seed = timing(args("seed"));
    EXPECT_EQ(optimal.at("method"), "optimal");
    EXPECT_EQ(optimal.at("segments"), 3);
    EXPECT_NEAR(optimal.at("length_mm").get<double>(), 200.0 + 10.0 * M_PI, 1e-9);
    // Published: TOPP-RA and Kunz–Stilman 2.18356 s; stopping at both joints 2.8075 s.
    EXPECT_NEAR(optimal.at("time_s").get<double>(), 2.18356, 3e-5);
    EXPECT_NEAR(exact.at("time_s").get<double>(), 2.8075, 1e-4);
    // The analytic optimum 2.325 − √2/10 (timing_test.cpp), to the refinement's tolerance.
    EXPECT_TRUE(
        test::relClose(optimal.at("time_s").get<double>(), 2.325 - std::sqrt(2.0) / 10.0, 1e-6));
    EXPECT_TRUE(test::onRefinedGrid(optimal.at("grid_points").get<std::size_t>(), 1));
    EXPECT_LE(optimal.at("convergence").get<double>(), 1e-6);  // the refinement's criterion
    EXPECT_EQ(optimal.at("converged"), true);
    EXPECT_EQ(exact.at("converged"), true);
    EXPECT_FALSE(optimal.contains("warning"));
    EXPECT_FALSE(seed.contains("converged"));  // the seed has no grid
    // The seed, from the wording of math.md §6 (timing_reference.h) on the same three pieces:
    // the line along x, the quarter arc R = 20 around (100, 20), the line along y. It charges
    // each step at its end speed and so comes out below exact stop (TimingSeed tests).
    MachineLimits limits;
    limits.accel = {500, 250, 100};
    limits.vmax = {200, 150, 50};
    const std::vector<test::RefPiece> pieces{
        test::RefPiece::line({0, 0, 0}, {100, 0, 0}),
        test::RefPiece::arc({100, 20}, 20, -M_PI / 2, M_PI / 2, 0),
        test::RefPiece::line({120, 20, 0}, {120, 120, 0})};
    EXPECT_TRUE(
        test::relClose(seed.at("time_s").get<double>(), test::seedReference(pieces, limits), 1e-9));
    EXPECT_LT(seed.at("time_s").get<double>(), exact.at("time_s").get<double>());
}

TEST(CliTiming, DetailAddsUpAndSpeedsMatchAtTheJoints) {
    const std::string csv = writeTemp("reference.csv", kReferenceCsv);
    std::vector<std::string> a{"timing", "--path", csv, "--method", "optimal", "--detail"};
    a.insert(a.end(), kLimits.begin(), kLimits.end());
    const auto r = timing(a);
    const auto& detail = r.at("detail");
    ASSERT_EQ(detail.size(), 3u);
    double sum = 0.0;
    for (std::size_t k = 0; k < detail.size(); ++k) {
        sum += detail[k].at("time_s").get<double>();
        if (k > 0) {
            EXPECT_DOUBLE_EQ(detail[k].at("entry_speed").get<double>(),
                             detail[k - 1].at("exit_speed").get<double>());
        }
    }
    EXPECT_NEAR(sum, r.at("time_s").get<double>(), 1e-12);
    EXPECT_EQ(detail[0].at("entry_speed"), 0.0);
    EXPECT_EQ(detail[2].at("exit_speed"), 0.0);
    // Entering the arc the y axis carries the centripetal v²/R <= 250: v = sqrt(250·20).
    EXPECT_NEAR(detail[0].at("exit_speed").get<double>(), std::sqrt(5000.0), 1e-6);
    // First line by hand: 0 → 200 mm/s (0.4 s), cruise 25 mm (0.125 s), 200 → 70.71 (0.2586 s).
    EXPECT_NEAR(detail[0].at("time_s").get<double>(), 0.4 + 0.125 + (200 - std::sqrt(5000.0)) / 500,
                1e-6);
}

TEST(CliTiming, TheMethodIsOptimalUnlessAnotherIsAskedFor) {
    std::string text = test::readFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    text.insert(text.rfind('}'), R"(, "machining": {"axis_accel": [500, 500, 200], "feed_max": 100,
        "tool_radius": 2.0, "step": 1.0})");
    const std::string project = writeTemp("six-lobe-default.cam.json", text);
    const auto byDefault = timing({"timing", project});
    EXPECT_EQ(byDefault.at("method"), "optimal");
    EXPECT_EQ(byDefault, timing({"timing", project, "--method", "optimal"}));
    EXPECT_NE(byDefault.at("time_s"),
              timing({"timing", project, "--method", "exact-stop"}).at("time_s"));
}

TEST(CliTiming, ProjectMachiningSectionAndOverrides) {
    std::string text = test::readFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    text.insert(text.rfind('}'), R"(, "machining": {"axis_accel": [500, 500, 200], "feed_max": 100,
        "tool_radius": 2.0, "step": 1.0})");
    const std::string project = writeTemp("six-lobe.cam.json", text);
    const auto optimal = timing({"timing", project, "--method", "optimal"});
    const auto exact = timing({"timing", project, "--method", "exact-stop"});
    const auto seed = timing({"timing", project, "--method", "seed"});
    EXPECT_EQ(optimal.at("segments"), 13);  // 13 tangent arcs offset by 2 mm: no corner arcs
    // The same path built in the test from the arcs' data, timed by the independent reference
    // (timing_reference.h) with the project's limits: a = (500, 500, 200), feed 100, no vmax.
    const Contour contour =
        Contour::build(loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json")).value())
            .value();
    const std::vector<test::RefPiece> pieces = test::offsetArcContour(contour, 2.0);
    std::vector<bool> tangent(pieces.size(), true);
    tangent[0] = false;  // the path starts (and ends) at rest at φ = 0
    MachineLimits limits;
    limits.accel = {500, 500, 200};
    limits.feedMax = 100;
    double length = 0.0;
    for (const test::RefPiece& p : pieces) length += p.length();
    EXPECT_NEAR(optimal.at("length_mm").get<double>(), length, 1e-9);
    EXPECT_TRUE(test::relClose(optimal.at("time_s").get<double>(),
                               test::referenceOptimal(pieces, tangent, limits, 1e-3), 1e-5));
    EXPECT_TRUE(test::relClose(exact.at("time_s").get<double>(),
                               test::referenceExactStop(pieces, limits, 1e-3), 1e-5));
    EXPECT_TRUE(
        test::relClose(seed.at("time_s").get<double>(), test::seedReference(pieces, limits), 1e-9));
    // Never slower than stopping at every joint, never faster than the feed allows.
    EXPECT_LE(optimal.at("time_s").get<double>(), exact.at("time_s").get<double>());
    EXPECT_GT(optimal.at("time_s").get<double>(), length / 100.0);
    // --feed 20 overrides the project's 100. Curvature limits this path below 100 mm/s
    // (√(500·2.84) ≈ 38 mm/s in the notches), so 20 mm/s binds everywhere but in the two ramps
    // at the ends: about length/20 + 20/500 s, the trapezoid with a = 500 (the ramps run along
    // the notch, mostly on the y axis; the curvature shifts them by 1e-5 relative), and exactly
    // the reference's.
    const auto slow = timing({"timing", project, "--method", "optimal", "--feed", "20"});
    limits.feedMax = 20;
    const double slowReference = test::referenceOptimal(pieces, tangent, limits, 1e-3);
    EXPECT_TRUE(test::relClose(slowReference, length / 20.0 + 20.0 / 500.0, 1e-4));
    EXPECT_TRUE(test::relClose(slow.at("time_s").get<double>(), slowReference, 1e-5));
    EXPECT_GE(slow.at("time_s").get<double>(), slow.at("length_mm").get<double>() / 20.0);
}

TEST(CliTiming, BadInputGetsTheDocumentedExitCodeAndLocation) {
    const std::string csv = writeTemp("reference.csv", kReferenceCsv);
    const std::string badCsv = writeTemp("bad.csv", "0,0,0\n10,abc,0\n");
    const std::string climbing = writeTemp("climb.csv", "0,0,0,0.5\n10,0,3\n");
    const std::string repeated = writeTemp("repeat.csv", "0,0,0\n0,0,0\n5,0,0\n");
    const std::string example = test::examplePath("six-lobe-arc-cam.cam.json");
    struct Case {
        std::vector<std::string> args;
        int exit;
        std::string where;
    };
    const std::vector<Case> cases{
        {{"timing", "--path", csv, "--method", "", "--accel", "1,1,1"}, 1, "--method"},
        {{"timing", "--path", csv, "--method", "fastest", "--accel", "1,1,1"}, 1, "--method"},
        {{"timing", "--method", "seed", "--accel", "1,1,1"}, 1, "PROJECT or --path"},
        {{"timing", example, "--path", csv, "--method", "seed"}, 1, "PROJECT or --path"},
        {{"timing", "--path", csv, "--method", "seed"}, 1, "--accel"},
        {{"timing", example, "--method", "seed"}, 1, "--accel"},
        {{"timing", "--path", csv, "--method", "seed", "--accel", "1,x,1"}, 2, "--accel"},
        {{"timing", "--path", csv, "--method", "seed", "--accel", "1,-1,1"}, 2, "--accel"},
        {{"timing", "--path", csv, "--method", "seed", "--accel", "1"}, 2, "--accel"},
        {{"timing", "--path", csv, "--method", "seed", "--accel", "1,1,1", "--feed", "0"},
         2,
         "--feed"},
        {{"timing", "--path", csv, "--method", "seed", "--accel", "1,1,1", "--step", "nan"},
         2,
         "--step"},
        {{"timing", "--path", badCsv, "--method", "seed", "--accel", "1,1,1"}, 2, "line 2"},
        {{"timing", "--path", climbing, "--method", "seed", "--accel", "1,1,1"}, 2, "point[0]"},
        {{"timing", "--path", repeated, "--method", "seed", "--accel", "1,1,1"}, 2, "point[1]"},
        {{"timing", "--path", "/nonexistent.csv", "--method", "seed", "--accel", "1,1,1"},
         2,
         "/nonexistent.csv"},
    };
    for (const Case& c : cases) {
        const auto r = test::runCli(c.args);
        SCOPED_TRACE(nlohmann::json(c.args).dump());
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, c.exit) << r.err;
        EXPECT_NE(r.err.find(c.where), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
    }
}

TEST(CliTiming, AToolWiderThanANotchCannotBeComputed) {
    std::string text = test::readFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    text.insert(text.rfind('}'), R"(, "machining": {"axis_accel": [500, 500], "feed_max": 100,
        "tool_radius": 6.0})");
    const auto r =
        test::runCli({"timing", writeTemp("wide-tool.cam.json", text), "--method", "optimal"});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("contour[0]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("degenerates"), std::string::npos) << r.err;
}

// The dwell arc at the bottom of the notch is trimmed from both of its concave corners; a 3 mm
// tool would need more than all of it (tool_path_test.cpp works out the limit, 1.374 mm). The
// old code wrapped the arc to a near-full circle and reported a 130 mm path with exit 0.
TEST(CliTiming, AnArcTrimmedAwayAtItsConcaveCornersCannotBeComputed) {
    const std::string project = test::dataPath("timing/notch-dwell.cam.json");
    for (const char* method : {"seed", "exact-stop", "optimal"}) {
        SCOPED_TRACE(method);
        const auto r = test::runCli({"timing", project, "--method", method});
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, 3) << r.err;
        EXPECT_EQ(r.err.rfind("camwright-cli: " + project +
                                  ": contour[2]: the tool radius 3 mm is "
                                  "too large here",
                              0),
                  0u)
            << r.err;
        EXPECT_EQ(r.out, "");
    }
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(CliTiming, TeachInPointsAsAnOpenSplinePath) {
    const std::string knots = writeTemp("knots.csv", "0,0,0\n30,20,0\n60,5,0\n90,25,0\n");
    const std::vector<std::string> limits{"--accel", "500,500,200", "--feed", "150", "--detail"};
    auto run = [&](const char* method) {
        std::vector<std::string> a{"timing", "--path",   knots, "--spline",
                                   "oval",   "--method", method};
        a.insert(a.end(), limits.begin(), limits.end());
        return timing(a);
    };
    const auto optimal = run("optimal"), exact = run("exact-stop");
    // The spline the CLI builds (the oval rule, tested in teach_in_test.cpp) and its biarcs.
    const std::vector<Eigen::Vector2d> points{{0, 0}, {30, 20}, {60, 5}, {90, 25}};
    const auto spline = splineThroughPoints(points, false, HandleRule::Oval).value();
    ASSERT_EQ(spline.size(), 3u);
    const ToolPath biarcs = toolPathFromSpline(spline, kSplineToleranceMm);
    // Biarcs: tangent arc pairs, at least one pair per Bézier piece.
    EXPECT_EQ(optimal.at("segments").get<std::size_t>(), biarcs.segments.size());
    EXPECT_EQ(biarcs.segments.size() % 2, 0u);
    EXPECT_GE(biarcs.segments.size(), 6u);
    // Their length is the spline's (within 0.1 µm everywhere): ∫|B'(t)| dt by Simpson's rule on
    // 4096 intervals per piece, B' = 3[(1−t)²(P1−P0) + 2t(1−t)(P2−P1) + t²(P3−P2)].
    double length = 0.0;
    for (const CubicBezier& b : spline) {
        auto speed = [&](double t) {
            return (3.0 * ((1 - t) * (1 - t) * (b.p[1] - b.p[0]) +
                           2 * t * (1 - t) * (b.p[2] - b.p[1]) + t * t * (b.p[3] - b.p[2])))
                .norm();
        };
        const int n = 4096;
        double sum = speed(0.0) + speed(1.0);
        for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * speed(i / double(n));
        length += sum / (3.0 * n);
    }
    EXPECT_TRUE(test::relClose(optimal.at("length_mm").get<double>(), length, 1e-6));
    // Times: the independent reference on the same biarcs, through which the optimal plan keeps
    // its speed (all joints tangent) and exact stop stops at each.
    std::vector<test::RefPiece> pieces;
    for (const PathSegment& p : biarcs.segments) {
        pieces.push_back(p.kind == PathSegment::Kind::Arc
                             ? test::RefPiece::arc(p.center, p.radius, p.startAngle, p.sweep, 0)
                             : test::RefPiece::line(p.start, p.end));
    }
    std::vector<bool> tangent(pieces.size(), true);
    tangent[0] = false;
    MachineLimits machine;
    machine.accel = {500, 500, 200};
    machine.feedMax = 150;
    EXPECT_TRUE(test::relClose(optimal.at("time_s").get<double>(),
                               test::referenceOptimal(pieces, tangent, machine, 1e-3), 1e-5));
    EXPECT_TRUE(test::relClose(exact.at("time_s").get<double>(),
                               test::referenceExactStop(pieces, machine, 1e-3), 1e-5));
    EXPECT_LT(optimal.at("time_s").get<double>(), 0.5 * exact.at("time_s").get<double>());
    EXPECT_GT(optimal.at("time_s").get<double>(), optimal.at("length_mm").get<double>() / 150.0);
    const auto bad = test::runCli(
        {"timing", "--path", knots, "--spline", "bogus", "--method", "optimal", "--accel", "1,1"});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("--spline"), std::string::npos);
}

}  // namespace
}  // namespace cam
