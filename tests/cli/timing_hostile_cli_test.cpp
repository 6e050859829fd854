// camwright-cli timing under hostile input (issue 9): option values out of the ranges where the
// arithmetic is sound, a seed step tiny against the path, extreme bulges, and the refinement's
// honesty. Exit codes and messages as cli.md documents them; times against closed forms and the
// independent reference of timing_reference.h.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"
#include "timing_reference.h"

namespace cam {
namespace {

std::string writeHostileTemp(const std::string& name, const std::string& text) {
    return test::writeTestTempFile("camwright_hostile", name, text);
}

/// A point list of the issue's arcs: (10k, 0, 0) with bulge `bulge` (or ±bulge in turn).
std::string arcsCsv(int count, double bulge, bool alternate) {
    std::ostringstream out;
    for (int k = 0; k <= count; ++k) {
        out << 10 * k << ",0,0," << (alternate && k % 2 == 1 ? -bulge : bulge) << "\n";
    }
    return out.str();
}

/// Every number in the document is finite (nlohmann writes a non-finite double as null).
bool allFinite(const nlohmann::json& j) {
    if (j.is_null()) return false;
    if (j.is_number()) return std::isfinite(j.get<double>());
    if (j.is_object() || j.is_array()) {
        for (const auto& item : j) {
            if (!allFinite(item)) return false;
        }
    }
    return true;
}

// Fact: machine limits given as options are refused outside the ranges the project's validation
// has (accelerations 1e-6 to 1e12 mm/s², speeds 1e-6 to 1e9 mm/s, the step 1e-6 to 1e6 mm),
// exit 2 naming the option, the range and the value. --accel 1e-320 (a denormal) used to print
// "time_s": null with exit 0; --step 1e-12 hung the seed method.
TEST(CliTimingHostile, OptionsOutsideTheirRangesAreRefused) {
    const std::string line = writeHostileTemp("line.csv", "0,0,0\n100,0,0\n");
    struct Case {
        std::vector<std::string> options;
        std::string message;
    };
    const std::vector<Case> cases{
        {{"--accel", "1e-320,1,1"}, "--accel: must be between 1e-06 and 1e+12 mm/s² (got 1e-320)"},
        {{"--accel", "500,2e12"}, "--accel: must be between 1e-06 and 1e+12 mm/s² (got 2e+12)"},
        {{"--accel", "500,500", "--vmax", "100,1e10"},
         "--vmax: must be between 1e-06 and 1000000000 mm/s (got 1e+10)"},
        {{"--accel", "500,500", "--feed", "1e-7"},
         "--feed: must be between 1e-06 and 1000000000 mm/s (got 1e-07)"},
        {{"--accel", "500,500", "--step", "1e-12"},
         "--step: must be between 1e-06 and 1000000 mm (got 1e-12)"},
        {{"--accel", "500,500", "--step", "1e7"},
         "--step: must be between 1e-06 and 1000000 mm (got 10000000)"},
    };
    for (const Case& c : cases) {
        for (const char* method : {"seed", "exact-stop", "optimal"}) {
            std::vector<std::string> args{"timing", "--path", line, "--method", method};
            args.insert(args.end(), c.options.begin(), c.options.end());
            SCOPED_TRACE(nlohmann::json(args).dump());
            const auto r = test::runCli(args);
            EXPECT_EQ(r.exitCode, 2) << r.err;
            EXPECT_EQ(r.err, "camwright-cli: " + c.message + "\n");
            EXPECT_EQ(r.out, "");
        }
    }
}

// Fact: a step that is valid but tiny against the path is refused at once, naming the step, the
// limit of 1e7 steps and the smallest step that would do (100 mm / 1e7 = 1e-5 mm); a project's
// own step is named machining.step in its file. Both used to walk for minutes.
// Issue 27 point 7: the plunge 0,0,0 → 0,0,−5 with --accel 500,500 --vmax 100,100,5 printed
// "time_s": 0.0 by the seed method, exit 0 (z, left out of --accel, counted as infinitely
// quick). Two values of --accel are for a path in a plane; one that moves along z is refused as
// a bad argument value (cli.md: exit 2), naming the option, the axis and where the path moves
// it, by every method. With AZ given the times are the closed form: exact stop along z with
// a = 200, v = 5 over 5 mm is L/v + v/a = 1.025 s (v²/a = 0.125 mm <= 5 mm), optimal the same
// for one line from rest to rest, the seed the reference of timing_reference.h.
TEST(CliTimingHostile, APlungeNeedsTheZAccelerationLimit) {
    const std::string plunge = writeHostileTemp("plunge.csv", "0,0,0\n0,0,-5\n");
    for (const char* method : {"seed", "exact-stop", "optimal"}) {
        SCOPED_TRACE(method);
        for (const char* vmax : {"100,100,5", "100,100"}) {
            const auto r = test::runCli({"timing", "--path", plunge, "--accel", "500,500", "--vmax",
                                         vmax, "--method", method});
            EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
            EXPECT_EQ(r.err,
                      "camwright-cli: --accel: gives no limit for the z axis, along which the path "
                      "moves (segment 0, from point[0] to point[1]): give all three, AX,AY,AZ\n");
            EXPECT_TRUE(r.out.empty()) << r.out;
        }
        const auto r = test::runCli({"timing", "--path", plunge, "--accel", "500,500,200", "--vmax",
                                     "100,100,5", "--method", method});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const double time = nlohmann::json::parse(r.out).at("time_s").get<double>();
        if (std::string(method) == "seed") {
            MachineLimits lim;
            lim.accel = {500, 500, 200};
            lim.vmax = {100, 100, 5};
            lim.feedMax = kUnlimited;
            EXPECT_TRUE(test::relClose(
                time, test::seedReference(test::RefPiece::line({0, 0, 0}, {0, 0, -5}), lim),
                1e-12));
            EXPECT_GT(time, 0.0);
        } else {
            EXPECT_TRUE(test::relClose(time, 1.025, 1e-6)) << time;
        }
    }
    // A path in a plane still needs only two.
    const std::string flat = writeHostileTemp("plane-z2.csv", "0,0,2\n100,0,2\n");
    const auto r =
        test::runCli({"timing", "--path", flat, "--accel", "500,500", "--method", "exact-stop"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // A triangle along x: 2·√(100/500) s.
    EXPECT_TRUE(test::relClose(nlohmann::json::parse(r.out).at("time_s").get<double>(),
                               2.0 * std::sqrt(0.2), 1e-12));
}

TEST(CliTimingHostile, AStepTinyAgainstThePathIsRefusedAtOnce) {
    const std::string line = writeHostileTemp("line.csv", "0,0,0\n100,0,0\n");
    const auto r = test::run(
        CAMWRIGHT_CLI,
        {"timing", "--path", line, "--method", "seed", "--accel", "500,500", "--step", "5e-6"},
        test::kSanitized ? 60 : 10);
    EXPECT_EQ(r.signal, 0) << "killed: the seed walk did not end";
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(r.err,
              "camwright-cli: --step: 5e-06 mm makes 20000000 steps on this 100 mm path; the seed "
              "method takes at most 10000000: a step of at least 1e-05 mm\n");
    EXPECT_EQ(r.out, "");

    std::string text = test::readFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    text.insert(text.rfind('}'), R"(, "machining": {"axis_accel": [500, 500, 200], "feed_max": 100,
        "tool_radius": 2.0, "step": 1e-6})");
    const std::string project = writeHostileTemp("tiny-step.cam.json", text);
    const auto p = test::run(CAMWRIGHT_CLI, {"timing", project, "--method", "seed"},
                             test::kSanitized ? 60 : 10);
    EXPECT_EQ(p.signal, 0) << "killed: the seed walk did not end";
    EXPECT_EQ(p.exitCode, 3) << p.err;
    EXPECT_EQ(p.err.rfind("camwright-cli: " + project + ": machining.step: 1e-06 mm makes ", 0), 0u)
        << p.err;
    // The other methods do not walk steps: the same project is timed.
    const auto optimal = test::runCli({"timing", project, "--method", "optimal"});
    EXPECT_EQ(optimal.exitCode, 0) << optimal.err;
}

// Fact: bulge 1e-300 is a straight segment (|bulge| <= 1e-9), timed as the line: 10 mm along
// x with a = 500: 2·sqrt(10/500) s for exact stop and optimal. Bulge 1e300 (NaN before) and 1e9
// on a 10 mm chord are circles of 2.5e300 and 2.5e9 mm: refused, exit 2, at the point.
TEST(CliTimingHostile, ExtremeBulges) {
    const std::string flat = writeHostileTemp("flat.csv", "0,0,0,1e-300\n10,0,0\n");
    for (const char* method : {"exact-stop", "optimal"}) {
        const auto r =
            test::runCli({"timing", "--path", flat, "--method", method, "--accel", "500,500"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_TRUE(test::relClose(j.at("time_s").get<double>(), 2.0 * std::sqrt(0.02), 1e-12))
            << method;
        EXPECT_EQ(j.at("length_mm").get<double>(), 10.0);
    }
    for (const char* bulge : {"1e300", "1e9", "-1e9", "1.7e308"}) {
        const std::string huge =
            writeHostileTemp("huge.csv", std::string("0,0,0,") + bulge + "\n10,0,0\n");
        const auto r = test::run(
            CAMWRIGHT_CLI, {"timing", "--path", huge, "--method", "seed", "--accel", "500,500"},
            test::kSanitized ? 60 : 10);
        SCOPED_TRACE(bulge);
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find(huge + ": point[0]: the arc (bulge "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("a path must stay within 1000000 mm"), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
    }
}

// Hostile point lists: extreme bulges and coordinates, denormal and tiny arcs.
const std::vector<std::string> kHostilePaths{
    "0,0,0,1e-300\n10,0,0\n", "0,0,0,1e300\n10,0,0\n",
    "0,0,0,1e9\n1e-3,0,0\n",  "0,0,0,4.9e-324\n10,0,0\n",
    "0,0,0,-1\n1e-6,0,0\n",   "-1e6,-1e6,-1e6\n1e6,1e6,1e6\n",
    "0,0,0,2e-9\n1e6,0,0\n",  "0,0,0,1\n1e-6,0,0,1\n2e-6,0,0\n",
};

// One test per point list, so each stays within the time limit under the sanitizers (the tiny
// arcs with accelerations 1e12 and 1e-6 converge at 4 million grid points: 0.4 s in the release
// build, 23 s under ASan).
class CliTimingHostilePath : public ::testing::TestWithParam<std::size_t> {};

// Fact: whatever the input, timing prints only finite numbers with exit 0, or nothing with
// exit 2 or 3. Hostile values at and beyond every edge (denormal, huge and negative limits;
// tiny steps) on each hostile path.
TEST_P(CliTimingHostilePath, NoOutputEverHoldsANonFiniteNumber) {
    const std::size_t c = GetParam();
    const std::vector<std::vector<std::string>> options{
        {"--accel", "1e-320,1,1"},
        {"--accel", "1e-6,1e-6,1e-6"},
        {"--accel", "1e12,1e12", "--vmax", "1e9,1e9", "--feed", "1e9"},
        {"--accel", "1e12,1e-6", "--feed", "1e-6"},
        {"--accel", "1e300,1"},
        {"--accel", "500,500", "--step", "1e-6"},
    };
    const std::string csv = writeHostileTemp("any" + std::to_string(c) + ".csv", kHostilePaths[c]);
    int printed = 0;
    for (const auto& opts : options) {
        for (const char* method : {"seed", "exact-stop", "optimal"}) {
            std::vector<std::string> args{"timing", "--path", csv, "--method", method, "--detail"};
            args.insert(args.end(), opts.begin(), opts.end());
            SCOPED_TRACE(kHostilePaths[c] + " " + nlohmann::json(args).dump());
            const auto r = test::run(CAMWRIGHT_CLI, args, test::kSanitized ? 100 : 30);
            ASSERT_EQ(r.signal, 0) << "killed";
            if (r.exitCode == 0) {
                ++printed;
                EXPECT_TRUE(allFinite(nlohmann::json::parse(r.out))) << r.out;
            } else {
                EXPECT_TRUE(r.exitCode == 2 || r.exitCode == 3) << r.exitCode << r.err;
                EXPECT_EQ(r.out, "");
            }
        }
    }
    // Not vacuous: every path but the bulge of 1e300 (beyond 1e6 mm) is timed by all three
    // methods under the three sound limit sets (1e-6; 1e12 with 1e9; 1e12 with 1e-6). The
    // workspace diagonal moves along z, which the last two leave without a limit: refused
    // (issue 27), so only the first times it.
    if (c == 1) {
        EXPECT_EQ(printed, 0);
    } else if (c == 5) {
        EXPECT_EQ(printed, 3);
    } else {
        EXPECT_GE(printed, 9);
    }
}

INSTANTIATE_TEST_SUITE_P(Paths, CliTimingHostilePath,
                         ::testing::Range<std::size_t>(0, kHostilePaths.size()));

// Fact (the issue's reproduction, at 2,000 arcs): every joint of (10k, 0, 0, 0.5) is a corner,
// so optimal equals exact stop, 2000 times one arc from rest to rest by the independent
// reference (R = 6.25 around (5, 3.75), from atan2(−3.75, −5) through 4·atan(0.5)); both say
// "converged": true. The old code stopped its global doubling at 2^24 points with convergence
// 2.8e-6, no flag and no warning.
TEST(CliTimingHostile, TheIssuesArcsConvergeAndOptimalEqualsExactStop) {
    const int count = test::kSanitized ? 300 : 2000;
    const std::string csv = writeHostileTemp("issue-arcs.csv", arcsCsv(count, 0.5, false));
    MachineLimits lim;
    lim.accel = {500, 500, kUnlimited};
    const double one = test::referenceTime(
        {test::RefPiece::arc({5, 3.75}, 6.25, std::atan2(-3.75, -5.0), 4.0 * std::atan(0.5), 0)},
        lim, 1e-3);
    double times[2] = {0.0, 0.0};
    int m = 0;
    for (const char* method : {"exact-stop", "optimal"}) {
        const auto r = test::run(
            CAMWRIGHT_CLI, {"timing", "--path", csv, "--method", method, "--accel", "500,500"},
            test::kSanitized ? 300 : 60);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        SCOPED_TRACE(method);
        times[m++] = j.at("time_s").get<double>();
        EXPECT_TRUE(test::relClose(times[m - 1], count * one, 1e-6));
        EXPECT_LE(j.at("convergence").get<double>(), 1e-6);
        EXPECT_EQ(j.value("converged", false), true);
        EXPECT_FALSE(j.contains("warning"));
    }
    EXPECT_LE(times[1], times[0] * (1.0 + 1e-6));
}

// Fact: a smooth stretch that needs more grid points than one plan may hold (34,000 tangent
// arcs of bulge ±0.5, some hundreds of intervals each, against 2^24 points) is reported as
// "converged": false with a warning that names the limit and the estimated error, exit 0.
TEST(CliTimingHostile, ARefinementStoppedShortSaysSo) {
    if (test::kSanitized) GTEST_SKIP() << "34,000 arcs take minutes under the sanitizers";
    const std::string csv = writeHostileTemp("chain.csv", arcsCsv(34'000, 0.5, true));
    const auto r = test::run(
        CAMWRIGHT_CLI, {"timing", "--path", csv, "--method", "optimal", "--accel", "500,500"}, 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.value("converged", true), false);
    EXPECT_LE(j.at("grid_points").get<std::size_t>(), std::size_t{1} << 24);
    const double estimate = j.at("convergence").get<double>();
    EXPECT_GT(estimate, 0.0);
    const std::string warning = j.value("warning", std::string());
    EXPECT_NE(warning.find("not converged"), std::string::npos) << warning;
    EXPECT_NE(warning.find("16777216 points"), std::string::npos) << warning;
    EXPECT_TRUE(allFinite(j));
}

}  // namespace
}  // namespace cam
