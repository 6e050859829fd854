// camwright-cli never prints a non-finite number with exit 0 (issue 9 point 3). The inputs that
// printed null or -nan at 612d090 are refused with their place, the instant far out keeps its
// angle, and projects at the very edges of the sound ranges (project-format.md) print finite
// numbers from every command.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>

#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

using test::runCli;
using test::TempDir;

using test::contains;

using test::writeText;

/// A circle about (e, 0) split into two arcs, with the motion and radius given as JSON text.
std::string splitCircleJson(const std::string& motion, const std::string& e,
                            const std::string& radius) {
    return R"({"format": "camwright", "version": 1, "motion": )" + motion +
           R"(, "contour": [
  {"type": "arc", "center": [)" +
           e + ", 0], \"radius\": " + radius +
           R"(, "branch": "outer", "phi_start": 0, "phi_end": 180},
  {"type": "arc", "center": [)" +
           e + ", 0], \"radius\": " + radius +
           R"(, "branch": "outer", "phi_start": 180, "phi_end": 360}]})";
}

/// The lens of issue 9: an arc about (20, 0) of radius 10 on [-end, end] (the ray touches it at
/// ±30°), closed by a circle about the origin through its end points.
std::string lensJson(double endDeg) {
    const double phi = endDeg * std::numbers::pi / 180.0;
    const double mu = 20.0 * std::cos(phi);
    const double r = mu + std::sqrt(std::max(0.0, mu * mu - 300.0));
    char text[512];
    std::snprintf(text, sizeof text,
                  R"({"format": "camwright", "version": 1, "motion": {"period_s": 1}, "contour": [
  {"type": "arc", "center": [20, 0], "radius": 10, "branch": "outer", "phi_start": %.17g, "phi_end": %.17g},
  {"type": "arc", "center": [0, 0], "radius": %.17g, "branch": "outer", "phi_start": %.17g, "phi_end": %.17g}]})",
                  -endDeg, endDeg, r, endDeg, 360.0 - endDeg);
    return text;
}

/// Any token a non-finite number prints as, in JSON (null), CSV (nan, inf) or C (-nan).
bool printsNonFinite(const std::string& out) {
    static const std::regex token(R"((^|[^A-Za-z_])(null|-?nan|-?inf)([^A-Za-z_]|$))",
                                  std::regex::icase);
    // null where cli.md says a value may be missing (none of its kind), never for a number
    // that failed: a dwell the motion does not have, a curve that never bends one way.
    static const std::regex missing(
        R"re(^\s*"(rise|return|dwell|min_convex|min_concave|pressure_angle_rise_deg|pressure_angle_return_deg|min_convex_radius_mm)": null,?$)re");
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        if (std::regex_search(line, missing)) continue;
        if (std::regex_search(line, token)) return true;
    }
    return false;
}

TEST(CliFiniteOutput, TheInputsThatPrintedNanAreRefusedWithTheirPlace) {
    const TempDir dir;
    struct Case {
        const char* name;
        std::string text;
        const char* where;
        const char* says;
    };
    const std::vector<Case> cases{
        {"period", splitCircleJson(R"({"period_s": 1e-308})", "5", "20"), "motion.period_s",
         "between 1e-05 and 10000000 s"},
        {"radius", splitCircleJson(R"({"period_s": 1})", "1e-301", "1e-300"), "contour[0].radius",
         "at least 1e-06 mm"},
        {"tangent", lensJson(30.0), "contour[0].phi_start", "only grazes"},
    };
    for (const Case& c : cases) {
        const std::string path = dir.file(std::string(c.name) + ".cam.json");
        writeText(path, c.text);
        for (const std::vector<std::string>& args : {std::vector<std::string>{"validate", path},
                                                     {"state", path, "--t", "0.25"},
                                                     {"sample", path, "--samples", "16"},
                                                     {"analyze", path}}) {
            const auto r = runCli(args);
            EXPECT_EQ(r.exitCode, 2) << c.name << " " << args[0] << ": " << r.out << r.err;
            EXPECT_TRUE(contains(r.err, c.where)) << c.name << " " << args[0] << ": " << r.err;
            EXPECT_TRUE(contains(r.err, c.says)) << c.name << " " << args[0] << ": " << r.err;
            EXPECT_FALSE(printsNonFinite(r.out)) << c.name << " " << args[0] << ": " << r.out;
        }
    }
}

TEST(CliFiniteOutput, AFilletBelowTheSmallestRadiusIsRefused) {
    const TempDir dir;
    const std::string square = dir.file("square.cam.json");
    writeText(square, R"({"format": "camwright", "version": 1, "motion": {"period_s": 1},
      "contour": [{"type": "line", "from": [10, -10], "to": [10, 10]},
                  {"type": "line", "from": [10, 10], "to": [-10, 10]},
                  {"type": "line", "from": [-10, 10], "to": [-10, -10]},
                  {"type": "line", "from": [-10, -10], "to": [10, -10]}]})");
    const std::string out = dir.file("rounded.cam.json");
    // At 612d090 radius 1e-9 wrote a project whose new joint analysed as null, "C2".
    auto r = runCli({"fillet", square, "--joint", "1", "--radius", "1e-9", "--out", out});
    EXPECT_EQ(r.exitCode, 3) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "radius 1e-09 mm is too small")) << r.err;
    EXPECT_TRUE(contains(r.err, "at least 1e-06 mm")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    // The smallest radius itself rounds the corner, and the result analyses finite.
    r = runCli({"fillet", square, "--joint", "1", "--radius", "1e-6", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"analyze", out});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(printsNonFinite(r.out)) << r.out;
}

TEST(CliFiniteOutput, AnInstantFarOutKeepsItsAngleAndOneTooFarIsRefused) {
    // The six-lobe example turns once in 0.4 s; 1e14 s is exactly 2.5e14 turns, so the state is
    // that of t = 0: on contour[0], an inner-branch arc about (25.73752542, 0) of radius
    // 4.84070597, at φ = 0: r = 25.73752542 − 4.84070597. (612d090 printed 21.805.)
    const std::string example = test::examplePath("six-lobe-arc-cam.cam.json");
    auto r = runCli({"state", example, "--t", "1e14"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto state = nlohmann::json::parse(r.out);
    EXPECT_NEAR(state["r"].get<double>(), 25.73752542 - 4.84070597, 1e-9);
    EXPECT_EQ(state["segment"].get<int>(), 0);
    // 1e16 s is 2.5e16 turns: a double cannot resolve the angle there (its spacing is 4 turns).
    r = runCli({"state", example, "--t", "1e16"});
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_TRUE(contains(r.err, "--t")) << r.err;
    EXPECT_TRUE(contains(r.err, "turns")) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(CliFiniteOutput, ProjectsAtTheEdgesOfTheRangesPrintFiniteNumbersFromEveryCommand) {
    const TempDir dir;
    const std::vector<std::pair<std::string, std::string>> projects{
        {"fastest", splitCircleJson(R"({"omega_rad_s": 1e6})", "5", "20")},
        {"slowest", splitCircleJson(R"({"period_s": 1e7})", "5", "20")},
        {"smallest", splitCircleJson(R"({"rpm": -1e7})", "1e-7", "1e-6")},
        {"largest", splitCircleJson(R"({"omega_rad_s": 1e6})", "0", "1e6")},
        {"near-tangent", lensJson(30.0 - 1e-8)},
    };
    for (const auto& [name, text] : projects) {
        const std::string path = dir.file(name + ".cam.json");
        writeText(path, text);
        for (const std::vector<std::string>& args : {std::vector<std::string>{"validate", path},
                                                     {"state", path, "--t", "1e-3"},
                                                     {"state", path, "--t", "-12345.678"},
                                                     {"sample", path, "--samples", "720"},
                                                     {"analyze", path}}) {
            const auto r = runCli(args);
            EXPECT_EQ(r.exitCode, 0) << name << " " << args[0] << ": " << r.err;
            EXPECT_FALSE(printsNonFinite(r.out)) << name << " " << args[0];
            EXPECT_FALSE(r.out.empty()) << name << " " << args[0];
        }
    }
}

}  // namespace
}  // namespace cam
