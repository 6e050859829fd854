// camwright-cli state against an independent 50-digit reference (tests/reference/
// polar_reference.py, derivatives by mpmath.diff) on cams the engine was never tuned on:
// both arc branches, lines, windows from negative angles and past 360°, omega as rad/s, rpm
// and period, clockwise turning, lengths in metres and angles in radians.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

TEST(CliReference, StateAgreesWithTheHighPrecisionReferenceToOneBillionth) {
    namespace fs = std::filesystem;
    int cams = 0, states = 0;
    for (const auto& entry : fs::directory_iterator(test::dataPath("reference"))) {
        const std::string path = entry.path().string();
        if (!path.ends_with(".expected.json")) continue;
        const std::string project = path.substr(0, path.size() - 14) + ".cam.json";
        const auto expected = nlohmann::json::parse(test::readFile(path));
        ++cams;
        for (const auto& e : expected) {
            const double t = e.at("t");
            char tText[32];
            std::snprintf(tText, sizeof tText, "%.17g", t);
            const auto run = test::runCli({"state", project, "--t", tText});
            SCOPED_TRACE(entry.path().filename().string() + " t=" + tText);
            ASSERT_EQ(run.exitCode, 0) << run.err;
            const auto got = nlohmann::json::parse(run.out);
            EXPECT_EQ(got.at("segment"), e.at("segment"));
            EXPECT_TRUE(relClose(got.at("phi_deg"), e.at("phi_deg"), 1e-12, 1.0));
            // Components that are exactly zero in the reference get a floor of 1e-9 of the
            // magnitude they belong to.
            const std::pair<const char*, const char*> fields[] = {
                {"r", "r"},     {"v_r", "v"}, {"v_phi", "v"}, {"v", "v"},     {"a_r", "a"},
                {"a_phi", "a"}, {"a", "a"},   {"j_r", "j"},   {"j_phi", "j"}, {"j", "j"}};
            for (const auto& [key, magnitude] : fields) {
                EXPECT_TRUE(relClose(got.at(key), e.at(key), 1e-9, e.at(magnitude))) << key;
            }
            ++states;
        }
    }
    EXPECT_GE(cams, 6);
    EXPECT_GE(states, 60);
}

TEST(CliReference, SixLobeExampleAgreesWithMathMdTable) {
    // math.md §3: t = 0.37 s on the bundled example.
    const auto run =
        test::runCli({"state", test::examplePath("six-lobe-arc-cam.cam.json"), "--t", "0.37"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto s = nlohmann::json::parse(run.out);
    EXPECT_TRUE(relClose(s.at("r"), 28.897219241, 1e-9));
    EXPECT_TRUE(relClose(s.at("v_r"), -61.829076850, 1e-9));
    EXPECT_TRUE(relClose(s.at("v_phi"), 453.916458381, 1e-9));
    EXPECT_TRUE(relClose(s.at("a_r"), -25873.4168380, 1e-9));
    EXPECT_TRUE(relClose(s.at("a_phi"), -1942.4177361, 1e-9));
    EXPECT_EQ(s.at("segment"), 11);  // 333° lies in 309.69° .. 350.31°
}

}  // namespace
}  // namespace cam
