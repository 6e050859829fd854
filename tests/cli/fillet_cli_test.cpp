// camwright-cli fillet: a rounded corner is written as a new valid project; the radius comes
// from --radius or from V²/(vae·A); an infeasible radius is refused (exit 3) with the range.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;

/// A square of four lines, written into `dir` (each test its own folder: under ctest -j2 a
/// shared file was rewritten by one test while another read it).
std::string square(const test::TempDir& dir) {
    const std::string p = dir.file("square.cam.json");
    std::ofstream(p) << R"({"format": "camwright", "version": 1, "motion": {"period_s": 1},
      "contour": [{"type": "line", "from": [10, -10], "to": [10, 10]},
                  {"type": "line", "from": [10, 10], "to": [-10, 10]},
                  {"type": "line", "from": [-10, 10], "to": [-10, -10]},
                  {"type": "line", "from": [-10, -10], "to": [10, -10]}]})";
    return p;
}

TEST(CliFillet, RoundsASquareCornerIntoAValidProject) {
    const test::TempDir dir;
    const std::string out = dir.file("out.cam.json");
    const auto r =
        test::runCli({"fillet", square(dir), "--joint", "1", "--radius", "3", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // A 90° corner at (10, 10): the centre is 3 mm in from both sides.
    EXPECT_NEAR(j.at("center")[0].get<double>(), 7.0, 1e-12);
    EXPECT_NEAR(j.at("center")[1].get<double>(), 7.0, 1e-12);
    EXPECT_EQ(j.at("segments"), 5);
    EXPECT_EQ(test::runCli({"validate", out}).exitCode, 0);
    const auto analysis = nlohmann::json::parse(test::runCli({"analyze", out}).out);
    EXPECT_EQ(analysis.at("joints")[0].at("continuity"), "C1");  // tangent now
}

TEST(CliFillet, OutKeepsTheModeAndTheSymlinkOfAnExistingProject) {
    const test::TempDir dir;
    fs::create_directory(dir.path() / "projects");
    test::writeFileWithMode(dir.file("projects/cam.cam.json"), "old", 0600);
    fs::create_symlink("projects/cam.cam.json", dir.path() / "current.cam.json");
    const std::string out = dir.file("current.cam.json");
    const auto r =
        test::runCli({"fillet", square(dir), "--joint", "1", "--radius", "3", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(out));
    EXPECT_EQ(test::fileMode(out), 0600);
    EXPECT_EQ(test::runCli({"validate", out}).exitCode, 0);
}

TEST(CliFillet, RadiusFromSpeedAccelerationAndAdmissibleError) {
    const test::TempDir dir;
    const std::string out = dir.file("out.cam.json");
    const auto r = test::runCli({"fillet", square(dir), "--joint", "2", "--speed", "100", "--accel",
                                 "5000", "--vae", "0.5", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(r.out).at("radius_mm").get<double>(),
                     100.0 * 100.0 / (0.5 * 5000.0));
}

TEST(CliFillet, RefusesWhatCannotBeDoneAndSaysWhy) {
    const test::TempDir dir;
    const std::string out = dir.file("never.cam.json");
    const auto tooBig =
        test::runCli({"fillet", square(dir), "--joint", "1", "--radius", "25", "--out", out});
    EXPECT_EQ(tooBig.exitCode, 3);
    EXPECT_NE(tooBig.err.find("25 mm"), std::string::npos) << tooBig.err;
    EXPECT_NE(tooBig.err.find("below 20 mm"), std::string::npos) << tooBig.err;
    EXPECT_FALSE(fs::exists(out));  // nothing half-written
    const std::vector<std::pair<std::vector<std::string>, int>> usage{
        {{"fillet", square(dir), "--radius", "3", "--out", out}, 1},                  // no joint
        {{"fillet", square(dir), "--joint", "1", "--out", out}, 1},                   // no radius
        {{"fillet", square(dir), "--joint", "1", "--radius", "3"}, 1},                // no --out
        {{"fillet", square(dir), "--joint", "9", "--radius", "3", "--out", out}, 2},  // no joint 9
        {{"fillet", square(dir), "--joint", "1", "--radius", "-3", "--out", out}, 2},
        {{"fillet", square(dir), "--joint", "1", "--speed", "100", "--out", out}, 1},  // no --accel
    };
    for (const auto& [args, code] : usage) {
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, code) << nlohmann::json(args).dump() << "\n" << r.err;
        EXPECT_EQ(r.out, "");
    }
}

}  // namespace
}  // namespace cam
