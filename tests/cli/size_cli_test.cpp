// camwright-cli size: the smallest base radius of a design, written back with --out, checked
// end to end — the sized project synthesised and analysed meets the limit it was sized for.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace cam {
namespace {

using Json = nlohmann::json;

const std::string kDesign =
    std::string(CAMWRIGHT_EXAMPLES) + "/synthesised-cycloidal-roller.cam.json";

TEST(CliSize, TheSizedDesignMeetsItsLimitAndABitSmallerOneDoesNot) {
    test::TempDir dir;
    const std::string sized = dir.file("sized.cam.json");
    const auto run = test::runCli({"size", kDesign, "--out", sized});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json r = Json::parse(run.out);
    const double base = r["base_radius_mm"];
    EXPECT_LT(base, r["was_mm"].get<double>());
    EXPECT_EQ(r["limit_deg"], 30.0);
    // The binding check is at its limit; the other one within it.
    const std::string binding = r["binding"];
    ASSERT_TRUE(binding == "pressure_angle_rise" || binding == "pressure_angle_return") << binding;
    const double rise = r["pressure_angle_rise_deg"], fall = r["pressure_angle_return_deg"];
    EXPECT_NEAR(binding == "pressure_angle_rise" ? rise : fall, 30.0, 1e-6);
    EXPECT_LE(std::max(rise, fall), 30.0 + 1e-9);
    // NEW is the project with that base radius, nothing else changed.
    Json original = Json::parse(test::readFile(kDesign));
    const Json written = Json::parse(test::readFile(sized));
    EXPECT_EQ(written["design"]["base_radius"].get<double>(), base);
    original["design"]["base_radius"] = base;
    EXPECT_EQ(written["design"], original["design"]);
    EXPECT_EQ(written["follower"], original["follower"]);

    // Synthesised, its follower's largest pressure angle (analyze, on the arc table) is the
    // limit, to the arc fit's tolerance.
    const std::string cam = dir.file("cam.cam.json");
    const auto made = test::runCli({"synthesize", sized, "--out", cam});
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const auto analyzed = test::runCli({"analyze", cam});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json report = Json::parse(analyzed.out);
    const Json p = report["follower"]["pressure_angle"];
    // synthesize states the jerk cost: an acceleration jump at every joint that is not C2.
    const Json synthesis = Json::parse(made.out);
    int notC2 = 0;
    for (const Json& j : report["joints"]) notC2 += j["continuity"] != "C2" ? 1 : 0;
    EXPECT_GT(notC2, 0);
    EXPECT_EQ(synthesis["acceleration_jumps"], notC2);
    EXPECT_EQ(synthesis["jerk"], "unbounded at each acceleration jump");
    EXPECT_GT(synthesis["max_acceleration_jump"].get<double>(), 0.0);
    EXPECT_NEAR(p["max"]["value_deg"].get<double>(), 30.0, 0.05);

    // 10 % smaller, the same design is over its limit: the synthesised cam says so.
    Json smaller = written;
    smaller["design"]["base_radius"] = 0.9 * base;
    const std::string small = dir.file("small.cam.json");
    test::writeText(small, smaller.dump());
    const std::string smallCam = dir.file("small-cam.cam.json");
    ASSERT_EQ(test::runCli({"synthesize", small, "--out", smallCam}).exitCode, 0);
    const auto over = test::runCli({"analyze", smallCam});
    ASSERT_EQ(over.exitCode, 0) << over.err;
    EXPECT_GT(Json::parse(over.out)["follower"]["pressure_angle"]["max"]["value_deg"].get<double>(),
              30.1);
}

TEST(CliSize, AMinimumRadiusCanBindAndBadInputIsNamed) {
    const auto run = test::runCli({"size", kDesign, "--min-radius", "20"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json r = Json::parse(run.out);
    EXPECT_EQ(r["binding"], "convex_radius");
    EXPECT_NEAR(r["min_convex_radius_mm"].get<double>(), 20.0, 1e-6);
    EXPECT_FALSE(r.contains("out"));

    const auto negative = test::runCli({"size", kDesign, "--min-radius", "-1"});
    EXPECT_EQ(negative.exitCode, 2);
    EXPECT_NE(negative.err.find("--min-radius"), std::string::npos) << negative.err;
    const auto notANumber = test::runCli({"size", kDesign, "--min-radius", "nan"});
    EXPECT_EQ(notANumber.exitCode, 2);
    const std::string noDesign = std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json";
    const auto none = test::runCli({"size", noDesign});
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("design"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(CliSize, TheBestOffsetGivesASmallerCamWhoseRiseAndReturnBothMeetTheLimit) {
    // The bundled roller rises by a cycloid and returns by a modified sine: an offset lets a
    // smaller cam meet 30° on both. Checked end to end: the sized project synthesised and
    // analysed on its arc table has both phases at the limit, to the fit's tolerance.
    test::TempDir dir;
    const std::string sized = dir.file("sized.cam.json");
    const auto plain = test::runCli({"size", kDesign});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const auto run = test::runCli({"size", kDesign, "--best-offset", "--out", sized});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json r = Json::parse(run.out);
    const double base = r["base_radius_mm"], offset = r["offset_mm"];
    EXPECT_LT(base, Json::parse(plain.out)["base_radius_mm"].get<double>() - 0.5);
    EXPECT_EQ(r["offset_was_mm"], 0.0);
    EXPECT_NEAR(r["pressure_angle_rise_deg"].get<double>(), 30.0, 1e-3);
    EXPECT_NEAR(r["pressure_angle_return_deg"].get<double>(), 30.0, 1e-3);
    // The edge of the feasible region: no offset it lists allows a smaller cam.
    ASSERT_EQ(r["feasible_edge"].size(), 41U);
    for (const Json& point : r["feasible_edge"]) {
        ASSERT_TRUE(point["base_radius_mm"].is_number()) << point.dump();
        EXPECT_GE(point["base_radius_mm"].get<double>(), base - 1e-9) << point.dump();
    }
    // NEW has both; sizing it again at that offset finds the same base radius.
    const Json written = Json::parse(test::readFile(sized));
    EXPECT_EQ(written["design"]["base_radius"].get<double>(), base);
    EXPECT_EQ(written["follower"]["offset"].get<double>(), offset);
    const auto again = test::runCli({"size", sized});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NEAR(Json::parse(again.out)["base_radius_mm"].get<double>(), base, 1e-8);

    const std::string cam = dir.file("cam.cam.json");
    const auto made = test::runCli({"synthesize", sized, "--out", cam});
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const auto analyzed = test::runCli({"analyze", cam});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json p = Json::parse(analyzed.out)["follower"]["pressure_angle"];
    // (This cam is small, 3.3 mm with an 8 mm roller: the 0.001 mm fit moves α by up to 0.07°;
    // at no offset rise and return differ by 3°.)
    EXPECT_NEAR(p["rise"]["value_deg"].get<double>(), 30.0, 0.1);
    EXPECT_NEAR(p["return"]["value_deg"].get<double>(), 30.0, 0.1);

    // A swinging arm has no offset: refused, naming the option and the one that suits it,
    // nothing written; and a translating follower has no pivot.
    const std::string arm = std::string(CAMWRIGHT_EXAMPLES) + "/swinging-arm-cam.cam.json";
    const std::string armOut = dir.file("arm.cam.json");
    const auto refused = test::runCli({"size", arm, "--best-offset", "--out", armOut});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("--best-offset"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("--best-pivot"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(armOut));
    const auto noPivot = test::runCli({"size", kDesign, "--best-pivot", "--out", armOut});
    EXPECT_EQ(noPivot.exitCode, 2);
    EXPECT_NE(noPivot.err.find("--best-pivot"), std::string::npos) << noPivot.err;
    const auto both = test::runCli({"size", arm, "--best-pivot", "--best-offset"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(armOut));
}

TEST(CliSize, TheBestPivotGivesASmallerArmCamThatMeetsTheLimitOnRiseAndReturn) {
    // The bundled arm (pivot 70 mm out, arm 60 mm, limit 45°) needs 11.41 mm at its own pivot.
    // Moving the pivot along its line lets a smaller cam meet 45° on both phases (core_tests
    // SizingArm.* check the number against pressure angles computed from math.md §7 alone);
    // here end to end: written, synthesised and analysed on its arc table.
    test::TempDir dir;
    const std::string arm = std::string(CAMWRIGHT_EXAMPLES) + "/swinging-arm-cam.cam.json";
    const std::string sized = dir.file("sized.cam.json");
    const auto plain = test::runCli({"size", arm});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const auto run = test::runCli({"size", arm, "--best-pivot", "--out", sized});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json r = Json::parse(run.out);
    const double base = r["base_radius_mm"], distance = r["pivot_distance_mm"];
    EXPECT_LT(base, Json::parse(plain.out)["base_radius_mm"].get<double>() - 5.0);
    EXPECT_EQ(r["pivot_was_mm"], Json::array({70.0, 0.0}));
    EXPECT_EQ(r["pivot_mm"], Json::array({distance, 0.0}));
    EXPECT_FALSE(r.contains("offset_mm"));
    EXPECT_NEAR(r["pressure_angle_rise_deg"].get<double>(), 45.0, 1e-3);
    EXPECT_NEAR(r["pressure_angle_return_deg"].get<double>(), 45.0, 1e-3);
    // The region: 41 pivot distances; where radii pass, from the smallest to the largest, and
    // none smaller than the answer.
    ASSERT_EQ(r["feasible_edge"].size(), 41U);
    int feasible = 0;
    for (const Json& point : r["feasible_edge"]) {
        ASSERT_TRUE(point.contains("pivot_distance_mm")) << point.dump();
        if (point["base_radius_mm"].is_null()) {
            EXPECT_TRUE(point["largest_base_radius_mm"].is_null()) << point.dump();
            continue;
        }
        ++feasible;
        EXPECT_GE(point["base_radius_mm"].get<double>(), base - 1e-9) << point.dump();
        EXPECT_GT(point["largest_base_radius_mm"].get<double>(),
                  point["base_radius_mm"].get<double>())
            << point.dump();
    }
    EXPECT_GT(feasible, 5);
    const Json written = Json::parse(test::readFile(sized));
    EXPECT_EQ(written["design"]["base_radius"].get<double>(), base);
    EXPECT_EQ(written["follower"]["pivot"], Json::array({distance, 0.0}));
    EXPECT_EQ(written["follower"]["arm_length"].get<double>(), 60.0);

    // The cam is small (2.8 mm with a 6 mm roller): at the design's 0.001 mm the arcs move α
    // by 0.16°, so synthesised at 1e-5 mm, where they move it by < 0.003°.
    const std::string cam = dir.file("cam.cam.json");
    const auto made = test::runCli({"synthesize", sized, "--out", cam, "--tolerance", "1e-5"});
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const auto analyzed = test::runCli({"analyze", cam});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json p = Json::parse(analyzed.out)["follower"]["pressure_angle"];
    EXPECT_NEAR(p["rise"]["value_deg"].get<double>(), 45.0, 0.01);
    EXPECT_NEAR(p["return"]["value_deg"].get<double>(), 45.0, 0.01);
}

}  // namespace
}  // namespace cam
