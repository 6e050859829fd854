// camwright-cli suggest (docs/cli.md "Design from motion"): a design whose line its neighbours
// cannot meet is refused with the law's place; suggest names every segment's boundary classes,
// chooses poly5s that meet the line's velocity (checked by hand), writes a project that
// validates and synthesises; the new laws' keys read back from the file. Bad options are
// refused with their name and write nothing.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_support.h"

namespace cam {
namespace {

using Json = nlohmann::json;

// Dwell, a cycloidal rise to a line of 0.125 mm/° (10 mm over 80°), a cycloidal rise to a
// dwell, a cycloidal return: the line's joints jump in velocity.
const char* const kLineBetweenCycloids = R"({
  "format": "camwright", "version": 1, "name": "line",
  "motion": { "rpm": 60 }, "contour": [],
  "follower": { "type": "roller", "radius": 8 },
  "design": { "base_radius": 60, "tolerance": 0.001, "segments": [
    { "law": "dwell", "to_deg": 60 },
    { "law": "cycloidal", "to_deg": 120, "lift": 5 },
    { "law": "line", "to_deg": 200, "lift": 15 },
    { "law": "cycloidal", "to_deg": 260, "lift": 20 },
    { "law": "dwell", "to_deg": 300 },
    { "law": "cycloidal", "to_deg": 360, "lift": 0 } ] }
})";

TEST(CliSuggest, ALineItsNeighboursCannotMeetIsSuggestedPoly5sThatDo) {
    test::TempDir dir;
    const std::string in = dir.file("line.cam.json"), out = dir.file("suggested.cam.json");
    test::writeFileWithMode(in, kLineBetweenCycloids, 0644);
    const auto refused = test::runCli({"validate", in});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("design.segments[1].law: cycloidal cannot meet the constant "
                               "velocity at its end"),
              std::string::npos)
        << refused.err;
    const auto r = test::runCli({"suggest", in, "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json report = Json::parse(r.out);
    // The classes the neighbours demand, before: the line's at rest, the cycloids' at speed.
    const Json& before = report.at("segments");
    EXPECT_EQ(before[1].at("end_class"), "velocity");
    EXPECT_EQ(before[2].at("start_class"), "rest");
    EXPECT_EQ(before[3].at("start_class"), "velocity");
    // After: poly5 from rest to 0.125 mm/° and back, the return a modified sine (Cv 1.7596 of
    // math.md §8).
    const Json& after = report.at("suggested");
    EXPECT_EQ(after[1].at("law"), "poly5");
    EXPECT_EQ(after[3].at("law"), "poly5");
    EXPECT_EQ(after[5].at("law"), "modified-sine");
    EXPECT_NEAR(after[5].at("cv").get<double>(), 1.7596, 1e-4);
    EXPECT_EQ(after[1].at("end_class"), "velocity");
    EXPECT_EQ(after[2].at("start_class"), "velocity");
    EXPECT_EQ(report.at("changed"), Json::parse("[1, 3, 5]"));
    EXPECT_TRUE(report.at("notes").empty()) << report.at("notes");
    // The file: poly5 with the line's slope at its end, read back; it validates and
    // synthesises.
    const Json project = Json::parse(test::readFile(out));
    const Json& rise = project.at("design").at("segments")[1];
    EXPECT_EQ(rise.at("law"), "poly5");
    EXPECT_EQ(rise.at("v0"), 0.0);
    EXPECT_NEAR(rise.at("v1").get<double>(), 0.125, 1e-15);
    EXPECT_NEAR(rise.at("a1").get<double>(), 0.0, 1e-15);
    EXPECT_EQ(test::runCli({"validate", out}).exitCode, 0);
    const auto made = test::runCli({"synthesize", out, "--out", dir.file("made.cam.json")});
    EXPECT_EQ(made.exitCode, 0) << made.err;
}

TEST(CliSuggest, TheNewLawsKeysReadBackAndOthersAreRefused) {
    test::TempDir dir;
    const std::string in = dir.file("laws.cam.json");
    // Every new law once, each with its own keys; the table's points those of 3-4-5.
    test::writeFileWithMode(in, R"({
  "format": "camwright", "version": 1, "name": "laws",
  "motion": { "rpm": 60 }, "contour": [],
  "design": { "base_radius": 60, "segments": [
    { "law": "scca", "to_deg": 40, "lift": 4, "b": 0.5, "d": 0.5 },
    { "law": "modified-sine", "to_deg": 80, "lift": 8, "lambda": 0.3 },
    { "law": "poly7", "to_deg": 120, "lift": 10, "v0": 0, "a0": 0, "j0": 0, "v1": 0, "a1": 0, "j1": 0 },
    { "law": "table", "to_deg": 200, "lift": 2,
      "points": [[0, 0], [0.25, 0.103515625], [0.5, 0.5, 1.875], [0.75, 0.896484375], [1, 1]] },
    { "law": "modified-trapezoid", "to_deg": 360, "lift": 0, "lambda": 0.6 } ] }
})",
                            0644);
    const auto ok = test::runCli({"suggest", in});
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    const Json report = Json::parse(ok.out);
    // scca at b = d = 1/2 is the cycloid: Ca = 2π; the modified sine at λ = 0.3 has Ca
    // 5.5280/(2·0.3) (docs/cli.md's closed form).
    EXPECT_NEAR(report.at("segments")[0].at("ca").get<double>(), 6.283185307179586, 1e-12);
    EXPECT_NEAR(report.at("segments")[1].at("ca").get<double>(), 5.5280 / 0.6, 1e-3);
    EXPECT_EQ(report.at("segments")[3].at("law"), "table");
    // A key of another law is refused at its place.
    std::string wrong = test::readFile(in);
    wrong.replace(wrong.find(R"("lambda": 0.3)"), 13, R"("b": 0.3)");
    test::writeFileWithMode(in, wrong, 0644);
    const auto refused = test::runCli({"validate", in});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("design.segments[1].b: unknown key"), std::string::npos)
        << refused.err;
}

TEST(CliSuggest, BadInputIsNamedAndNothingIsWritten) {
    test::TempDir dir;
    const std::string in = dir.file("line.cam.json"), out = dir.file("never.cam.json");
    test::writeFileWithMode(in, kLineBetweenCycloids, 0644);
    const auto segment = test::runCli({"suggest", in, "--segment", "9", "--out", out});
    EXPECT_EQ(segment.exitCode, 2);
    EXPECT_NE(segment.err.find("--segment"), std::string::npos) << segment.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    // A table that does not end at (1, 1): named at its points.
    std::string table = kLineBetweenCycloids;
    const std::string last = R"({ "law": "cycloidal", "to_deg": 360, "lift": 0 })";
    table.replace(table.find(last), last.size(),
                  R"({ "law": "table", "to_deg": 360, "lift": 0, "points": [[0, 0], [1, 0.5]] })");
    test::writeFileWithMode(in, table, 0644);
    const auto ends = test::runCli({"suggest", in, "--out", out});
    EXPECT_EQ(ends.exitCode, 2);
    EXPECT_NE(ends.err.find("design.segments[5].points: must run from (0, 0) to (1, 1)"),
              std::string::npos)
        << ends.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace cam
