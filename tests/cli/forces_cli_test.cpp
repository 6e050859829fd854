// camwright-cli state and analyze with a project's dynamics (cli.md `forces`, math.md §9): the
// eccentric disc of math.md §9, whose numbers core_tests Forces.* check against the closed
// form, here end to end from the file; and a project without dynamics prints no forces.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace cam {
namespace {

using Json = nlohmann::json;

const std::string kDisc = test::dataPath("forces/eccentric-disc.cam.json");

TEST(CliForces, StateAt17DegreesPrintsMathSection9sForces) {
    // 300 rpm: 17° is at t = 17/360 · 0.2 s.
    const auto run = test::runCli({"state", kDisc, "--t", "0.009444444444444445"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json s = Json::parse(run.out);
    ASSERT_NEAR(s["phi_deg"].get<double>(), 17.0, 1e-9);
    const Json& f = s["forces"];
    EXPECT_NEAR(f["axial_N"].get<double>(), 41.36032, 5e-6);
    EXPECT_NEAR(f["normal_N"].get<double>(), 41.39096, 5e-6);
    EXPECT_NEAR(f["torque_Nm"].get<double>(), -0.0680766, 5e-8);
    EXPECT_NEAR(f["contact_stress_MPa"].get<double>(), 141.6274, 5e-5);
    // P = T·ω at 300 rpm; the side force F_n·sin α with tan α = s'/s of the closed form.
    EXPECT_NEAR(f["power_W"].get<double>(), f["torque_Nm"].get<double>() * 10.0 * M_PI, 1e-12);
    const double phi = 17.0 * M_PI / 180.0,
                 d = std::sqrt(38.0 * 38.0 - 25.0 * std::sin(phi) * std::sin(phi));
    const double sv = 5.0 * std::cos(phi) + d;
    const double s1 = -5.0 * std::sin(phi) - 25.0 * std::sin(phi) * std::cos(phi) / d;
    EXPECT_NEAR(f["lateral_N"].get<double>(),
                f["normal_N"].get<double>() * std::sin(std::atan(s1 / sv)), 1e-9);
    EXPECT_GT(f["contact_half_width_mm"].get<double>(), 0.0);
    EXPECT_FALSE(f.contains("moment_Nm"));
}

TEST(CliForces, AnalyzeReportsTheTurnsJumpSpeedPreloadAndPeaks) {
    const auto run = test::runCli({"analyze", kDisc});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json f = Json::parse(run.out)["forces"];
    // The valley's bottom, refined between samples (math.md prints 1197.46, its value at 8°).
    EXPECT_NEAR(f["jump_speed_rpm"].get<double>(), 1197.4486, 1e-3);
    EXPECT_NEAR(f["jump_speed_at_deg"].get<double>(), 8.34, 0.01);
    EXPECT_TRUE(f["lift_off_deg"].empty());
    EXPECT_TRUE(f["jumps_at_joints"].empty());  // one circle: no joint
    EXPECT_EQ(f["allowable_contact_stress_MPa"].get<double>(), 900.0);
    EXPECT_NEAR(f["contact_stress_ratio"].get<double>(),
                f["max_contact_stress_MPa"].get<double>() / 900.0, 1e-15);
    // The largest stress is where the normal force is largest (the radii are constant).
    EXPECT_NEAR(f["max_contact_stress_at_deg"].get<double>(), f["max_normal_at_deg"].get<double>(),
                1e-3);
    EXPECT_NEAR(f["peak_power_W"].get<double>(), f["peak_torque_Nm"].get<double>() * 10.0 * M_PI,
                1e-9);
    for (const char* key : {"min_preload_N", "max_normal_N", "rms_torque_Nm"}) {
        EXPECT_TRUE(f[key].is_number()) << key;
    }
}

TEST(CliForces, AProjectWithoutDynamicsPrintsNoForces) {
    const std::string example = test::examplePath("six-lobe-arc-cam.cam.json");
    const auto state = test::runCli({"state", example, "--t", "0.1"});
    ASSERT_EQ(state.exitCode, 0) << state.err;
    EXPECT_FALSE(Json::parse(state.out).contains("forces"));
    const auto analyze = test::runCli({"analyze", example});
    ASSERT_EQ(analyze.exitCode, 0) << analyze.err;
    EXPECT_FALSE(Json::parse(analyze.out).contains("forces"));
}

TEST(CliForces, AKnifeEdgeHasNoContactStressAndAFastCamLeavesIt) {
    // The disc's profile under a knife at 3000 rpm: no Hertz contact, and the roller-less
    // follower leaves the cam around the top of its rise.
    test::TempDir dir;
    std::string text = test::readFile(kDisc);
    const auto replace = [&text](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("\"rpm\": 300", "\"rpm\": 3000");
    replace(R"({ "type": "roller", "radius": 8 })", R"({ "type": "knife" })");
    const std::string fast = dir.file("fast.cam.json");
    test::writeFileWithMode(fast, text, 0644);
    const auto run = test::runCli({"analyze", fast});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json f = Json::parse(run.out)["forces"];
    EXPECT_TRUE(f["max_contact_stress_MPa"].is_null());
    EXPECT_TRUE(f["contact_stress_ratio"].is_null());
    ASSERT_FALSE(f["lift_off_deg"].empty());
    EXPECT_LT(f["jump_speed_rpm"].get<double>(), 3000.0);
    const auto state = test::runCli({"state", fast, "--t", "0"});
    ASSERT_EQ(state.exitCode, 0) << state.err;
    EXPECT_TRUE(Json::parse(state.out)["forces"]["contact_stress_MPa"].is_null());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

std::vector<std::string> cells(const std::string& line) {
    std::vector<std::string> out(1);
    for (const char c : line) {
        if (c == ',') {
            out.emplace_back();
        } else {
            out.back() += c;
        }
    }
    return out;
}

TEST(CliForces, TheCsvExportAddsTheForcesColumnsThatStatePrints) {
    test::TempDir dir;
    const std::string csv = dir.file("disc.csv");
    const auto run = test::runCli({"export", kDisc, "--format", "csv", "--out", csv});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::istringstream in(test::readFile(csv));
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = cells(line);
    const std::vector<std::string> forces{"axial_N",   "normal_N", "lateral_N",
                                          "torque_Nm", "power_W",  "contact_stress_MPa"};
    ASSERT_GE(header.size(), forces.size());
    EXPECT_EQ(std::vector<std::string>(header.end() - 6, header.end()), forces);
    // Row 170 of 3600 is 17°: the same numbers as `state` there (core_tests check those
    // against the closed form).
    for (int k = 0; k <= 170; ++k) std::getline(in, line);
    const std::vector<std::string> row = cells(line);
    ASSERT_EQ(row.size(), header.size());
    ASSERT_NEAR(std::stod(row[1]), 17.0, 1e-9);
    const auto state = test::runCli({"state", kDisc, "--t", row[0]});
    ASSERT_EQ(state.exitCode, 0) << state.err;
    const Json f = Json::parse(state.out)["forces"];
    const std::size_t first = header.size() - 6;
    EXPECT_NEAR(std::stod(row[first + 0]), f["axial_N"].get<double>(), 1e-9);
    EXPECT_NEAR(std::stod(row[first + 1]), f["normal_N"].get<double>(), 1e-9);
    EXPECT_NEAR(std::stod(row[first + 2]), f["lateral_N"].get<double>(), 1e-9);
    EXPECT_NEAR(std::stod(row[first + 3]), f["torque_Nm"].get<double>(), 1e-12);
    EXPECT_NEAR(std::stod(row[first + 4]), f["power_W"].get<double>(), 1e-10);
    EXPECT_NEAR(std::stod(row[first + 5]), f["contact_stress_MPa"].get<double>(), 1e-8);
    // A project without dynamics keeps the columns it had.
    const std::string plain = dir.file("plain.csv");
    ASSERT_EQ(test::runCli({"export", test::examplePath("swinging-arm-cam.cam.json"), "--format",
                            "csv", "--out", plain})
                  .exitCode,
              0);
    EXPECT_EQ(test::readFile(plain).find("normal_N"), std::string::npos);
}

}  // namespace
}  // namespace cam
