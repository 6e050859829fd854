// camwright-cli fit-windows: the seed's Table 1 typed with its two typos fixed is written as a
// valid project (the validator, run apart, says so), every change listed on stderr and checked
// against the two files; as printed it is refused, naming the joints with the distances the
// file's own numbers give.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kTyped = test::dataPath("seed-table/table1-typos-fixed.cam.json");
const std::string kPrinted = test::dataPath("seed-table/table1-as-printed.cam.json");

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

double hypot(const json& a, const json& b) {
    return std::hypot(a[0].get<double>() - b[0].get<double>(),
                      a[1].get<double>() - b[1].get<double>());
}

TEST(CliFitWindows, TheSeedTableTypedWithItsTyposFixedBecomesAValidProject) {
    const test::TempDir dir;
    const std::string out = dir.file("fitted.cam.json");
    ASSERT_EQ(test::runCli({"validate", kTyped}).exitCode, 2);  // joints open by 1.8e-6..2.8e-6
    const auto r = test::runCli({"fit-windows", kTyped, "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto valid = test::runCli({"validate", out});
    EXPECT_EQ(valid.exitCode, 0) << valid.err;
    EXPECT_EQ(valid.out, "valid: 13 segments\n");

    const json report = json::parse(r.out);
    const json before = json::parse(test::readFile(kTyped)).at("contour");
    const json after = json::parse(test::readFile(out)).at("contour");
    EXPECT_EQ(report.at("segments"), 13);
    EXPECT_EQ(report.at("joints").size(), 13u);
    const json& changes = report.at("changes");
    ASSERT_FALSE(changes.empty());
    EXPECT_LE(report.at("largest_change_mm").get<double>(), 1e-5);
    // Every change on stderr, one line each, naming the segment; and in the report, where
    // each is checked against the two files.
    const std::vector<std::string> lines = linesOf(r.err);
    ASSERT_EQ(lines.size(), changes.size()) << r.err;
    double largest = 0.0;
    std::size_t changed = 0;
    for (std::size_t k = 0; k < before.size(); ++k) {
        const double change =
            hypot(before[k].at("center"), after[k].at("center")) +
            std::abs(before[k].at("radius").get<double>() - after[k].at("radius").get<double>());
        EXPECT_LE(change, 1e-5) << k;
        largest = std::max(largest, change);
        changed += change > 0.0;
    }
    EXPECT_EQ(changed, changes.size());
    EXPECT_NEAR(report.at("largest_change_mm").get<double>(), largest, 1e-18);
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const json& c = changes[i];
        const std::size_t k = c.at("segment");
        EXPECT_EQ(
            lines[i].rfind("camwright-cli: " + kTyped + ": contour[" + std::to_string(k) + "]", 0),
            0u)
            << lines[i];
        EXPECT_NE(lines[i].find("typing tolerance of 1e-05 mm"), std::string::npos) << lines[i];
        EXPECT_EQ(c.at("center").at("from"), before[k].at("center")) << k;
        EXPECT_EQ(c.at("center").at("to"), after[k].at("center")) << k;
        EXPECT_EQ(c.at("radius").at("from"), before[k].at("radius")) << k;
        EXPECT_EQ(c.at("radius").at("to"), after[k].at("radius")) << k;
        EXPECT_NEAR(c.at("distance_mm").get<double>(),
                    hypot(before[k].at("center"), after[k].at("center")) +
                        std::abs(before[k].at("radius").get<double>() -
                                 after[k].at("radius").get<double>()),
                    1e-18)
            << k;
    }
    // The windows: tangent at 30° ± 20.30859° + k·60° (math.md §3), to the rounding.
    for (std::size_t k = 0; k + 1 < after.size(); ++k) {
        const double mid = 30.0 + 60.0 * static_cast<double>(k / 2);
        EXPECT_NEAR(after[k].at("phi_end").get<double>(), mid + (k % 2 == 0 ? -20.30859 : 20.30859),
                    1e-3)
            << k;
        EXPECT_EQ(report.at("joints")[k].at("angle_deg"), after[k].at("phi_end"));
    }
    // A second run has nothing left to change.
    const std::string again = dir.file("again.cam.json");
    const auto second = test::runCli({"fit-windows", out, "--out", again});
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(second.err, "");
    EXPECT_TRUE(json::parse(second.out).at("changes").empty());
}

TEST(CliFitWindows, TheSeedTableAsPrintedIsRefusedNamingEachJointWithItsGap) {
    const test::TempDir dir;
    const std::string out = dir.file("never.cam.json");
    const auto r = test::runCli({"fit-windows", kPrinted, "--out", out});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(out));
    // The first notch at 25.74 misses lobe 1; lobe 3 at (−18.1, −18.1) misses both its notches.
    const json c = json::parse(test::readFile(kPrinted)).at("contour");
    const auto gap = [&](std::size_t a, std::size_t b) {
        return hypot(c[a].at("center"), c[b].at("center")) -
               (c[a].at("radius").get<double>() + c[b].at("radius").get<double>());
    };
    const std::regex line(
        R"(camwright-cli: .*: contour\[(\d+)\]/contour\[(\d+)\]: the neighbouring segments miss )"
        R"(each other by ([0-9.e+-]+) mm, more than the typing tolerance of 1e-05 mm, so there )"
        R"(is no boundary to fit)");
    std::vector<std::size_t> named;
    for (const std::string& l : linesOf(r.err)) {
        std::smatch m;
        ASSERT_TRUE(std::regex_match(l, m, line)) << l;
        const std::size_t a = std::stoul(m[1]);
        named.push_back(a);
        EXPECT_NEAR(std::stod(m[3]), gap(a, std::stoul(m[2])), 1e-9 * gap(a, std::stoul(m[2])))
            << l;
    }
    EXPECT_EQ(named, (std::vector<std::size_t>{0, 4, 5}));
}

TEST(CliFitWindows, RefusesWhatItCannotDoAndWritesNothing) {
    const test::TempDir dir;
    const std::string out = dir.file("never.cam.json");
    EXPECT_EQ(test::runCli({"fit-windows", kTyped}).exitCode, 1);  // no --out
    EXPECT_EQ(test::runCli({"fit-windows", dir.file("none.cam.json"), "--out", out}).exitCode, 2);
    // A project with another problem: fitting its windows cannot make it valid.
    json p = json::parse(test::readFile(kTyped));
    p["contour"][3]["radius"] = -1.0;
    const std::string broken = dir.file("broken.cam.json");
    test::writeFileWithMode(broken, p.dump(), 0644);
    const auto r = test::runCli({"fit-windows", broken, "--out", out});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("contour[3]"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace cam
