// camwright-cli as a user runs it: commands, output formats, exit codes, located messages.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.h"

namespace cam {
namespace {

using test::kExample;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<double> csvRow(const std::string& line) {
    std::vector<double> out;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::stod(cell));
    return out;
}

TEST(CliValidate, AcceptsTheExample) {
    const auto r = test::runCli({"validate", kExample});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "valid: 13 segments\n");
    EXPECT_EQ(r.err, "");
}

TEST(CliValidate, ListsEveryProblemOnItsOwnLine) {
    const std::string bad = test::dataPath("invalid/window-gap.cam.json");
    const auto r = test::runCli({"validate", bad});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    const auto errLines = lines(r.err);
    ASSERT_FALSE(errLines.empty());
    for (const auto& l : errLines) EXPECT_EQ(l.rfind("camwright-cli: " + bad + ": ", 0), 0u) << l;
    EXPECT_NE(r.err.find("contour[0]/contour[1]: gap of 1°"), std::string::npos) << r.err;
}

TEST(CliState, PrintsOneJsonObjectWithEveryField) {
    const auto r = test::runCli({"state", kExample, "--t", "0.05"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto s = nlohmann::json::parse(r.out);
    std::vector<std::string> keys;
    for (const auto& [k, v] : s.items()) keys.push_back(k);
    std::sort(keys.begin(), keys.end());
    std::vector<std::string> expected{"t",     "phi_deg", "segment", "r",       "v_r",
                                      "v_phi", "v",       "a_r",     "a_phi",   "a",
                                      "j_r",   "j_phi",   "j",       "follower"};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(keys, expected);
    EXPECT_DOUBLE_EQ(s.at("phi_deg").get<double>(), 45.0);
    // Every number reads back as the double the engine computed: shortest round-trip form.
    const std::string text = r.out;
    EXPECT_NE(text.find("\"t\": 0.05"), std::string::npos) << text;
}

TEST(CliSample, WritesTheDocumentedHeaderAndNRowsOverOneTurn) {
    const auto r = test::runCli({"sample", kExample, "--samples", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto l = lines(r.out);
    ASSERT_EQ(l.size(), 9u);
    EXPECT_EQ(l[0], "t,phi_deg,segment,r,x,y,v_r,v_phi,v,a_r,a_phi,a,j_r,j_phi,j");
    for (std::size_t k = 1; k < l.size(); ++k) {
        const auto row = csvRow(l[k]);
        ASSERT_EQ(row.size(), 15u);
        EXPECT_DOUBLE_EQ(row[0], 0.4 * (k - 1) / 8.0);  // t = k·T/N
        EXPECT_NEAR(row[1], 45.0 * (k - 1), 1e-12);
        EXPECT_NEAR(std::hypot(row[4], row[5]), row[3], 1e-12 * row[3]);  // x, y on the ray
    }
    // Row for t = 0.05 s equals `state --t 0.05` to the last digit (17 significant digits).
    const auto st = nlohmann::json::parse(test::runCli({"state", kExample, "--t", "0.05"}).out);
    const auto row = csvRow(l[2]);
    EXPECT_NEAR(row[3], st.at("r").get<double>(), 1e-13 * row[3]);
    EXPECT_NEAR(row[9], st.at("a_r").get<double>(), 1e-11 * std::abs(row[9]));
}

/// Significant digits of a number's text: those of its mantissa without leading and trailing
/// zeros ("0.5" 1, "10" 1, "120.25" 5).
int significantDigits(const std::string& cell) {
    std::string digits;
    for (const char c : cell.substr(0, cell.find_first_of("eE"))) {
        if (c >= '0' && c <= '9' && !(digits.empty() && c == '0')) digits += c;
    }
    while (!digits.empty() && digits.back() == '0') digits.pop_back();
    return static_cast<int>(digits.size());
}

TEST(CliSample, EveryNumberIsExactShortestAndNeverMinusZero) {
    const auto r = test::runCli({"sample", kExample, "--samples", "720"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = lines(r.out);
    ASSERT_EQ(rows.size(), 721u);
    int shortCells = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::istringstream in(rows[i]);
        for (std::string cell; std::getline(in, cell, ',');) {
            ASSERT_FALSE(cell.empty()) << rows[i];
            char* end = nullptr;
            const double v = std::strtod(cell.c_str(), &end);
            ASSERT_EQ(*end, '\0') << cell;
            EXPECT_FALSE(cell.front() == '-' && v == 0.0) << "row " << i << ": " << cell;
            // Shortest: one significant digit fewer no longer reads back to the same double.
            const int n = significantDigits(cell);
            if (n > 1) {
                char fewer[400];  // %g of a double: at most ~330 characters
                std::snprintf(fewer, sizeof fewer, "%.*g", n - 1, v);
                EXPECT_NE(std::strtod(fewer, nullptr), v) << "row " << i << ": " << cell;
            }
            shortCells += n <= 6;
        }
    }
    // t = k/720 of the turn and φ = k/2 degrees: the angles are short (0.5, 1, 1.5, …).
    EXPECT_EQ(rows[1].substr(0, 4), "0,0,");
    EXPECT_EQ(csvRow(rows[2])[1], 0.5);
    EXPECT_NE(rows[2].find(",0.5,"), std::string::npos) << rows[2];
    EXPECT_GE(shortCells, 720);
}

TEST(CliSample, DefaultsToTheProjectSamplingAndWritesFilesAtomically) {
    namespace fs = std::filesystem;
    const fs::path out = fs::temp_directory_path() / "camwright_cli_sample.csv";
    fs::remove(out);
    const auto r = test::runCli({"sample", kExample, "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "");                                          // results went to the file
    EXPECT_EQ(lines(test::readFile(out.string())).size(), 3601u);  // default 3600 per turn
    fs::remove(out);
}

// --out goes through the core's one writer (io/atomic_file.h): what a user's file was, it stays.
TEST(CliSample, OutOverAPrivateFileKeepsItPrivate) {
    const test::TempDir dir;
    const std::string out = dir.file("turn.csv");
    test::writeFileWithMode(out, "old", 0600);
    const auto r = test::runCli({"sample", kExample, "--samples", "100000", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::fileMode(out), 0600);
    EXPECT_EQ(lines(test::readFile(out)).size(), 100001u);  // written in several chunks
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"turn.csv"});
}

TEST(CliSample, OutThroughASymlinkWritesItsTargetAndKeepsTheLink) {
    namespace fs = std::filesystem;
    const test::TempDir dir;
    fs::create_directory(dir.path() / "data");
    test::writeFileWithMode(dir.file("data/turn.csv"), "old", 0640);
    fs::create_symlink("data/turn.csv", dir.path() / "latest.csv");
    const auto r =
        test::runCli({"sample", kExample, "--samples", "8", "--out", dir.file("latest.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir.path() / "latest.csv"));
    EXPECT_EQ(lines(test::readFile(dir.file("data/turn.csv"))).size(), 9u);
    EXPECT_EQ(test::fileMode(dir.file("data/turn.csv")), 0640);
}

TEST(CliSample, OutToAFifoIsRefusedWithExitTwoAndLeftAlone) {
    namespace fs = std::filesystem;
    const test::TempDir dir;
    const std::string out = dir.file("pipe");
    ASSERT_EQ(::mkfifo(out.c_str(), 0600), 0);
    const auto r = test::runCli({"sample", kExample, "--samples", "8", "--out", out});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "camwright-cli: " + out + ": is a FIFO, not a regular file: not replaced\n");
    EXPECT_TRUE(fs::is_fifo(out));
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"pipe"});
}

TEST(CliAnalyze, ReportsJointsAndExtremes) {
    const auto r = test::runCli({"analyze", kExample});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto a = nlohmann::json::parse(r.out);
    ASSERT_EQ(a.at("joints").size(), 13u);
    const auto& j = a.at("joints").at(0);
    EXPECT_EQ(j.at("left"), 0);
    EXPECT_EQ(j.at("right"), 1);
    EXPECT_EQ(j.at("continuity"), "C1");
    EXPECT_NEAR(j.at("phi_deg").get<double>(), 9.691410798731425, 1e-9);
    EXPECT_LT(j.at("c0_gap_mm").get<double>(), 1e-6);
    EXPECT_LT(std::abs(j.at("tangent_break_deg").get<double>()), 1e-5);
    for (const char* key : {"jump_dr", "jump_d2r", "jump_a_r"}) EXPECT_TRUE(j.contains(key));
    const auto& rMax = a.at("extremes").at("r").at("max");
    EXPECT_NEAR(rMax.at("value").get<double>(), 29.0, 1e-9);
    for (const char* q : {"r", "v_r", "v", "a_r", "a", "j_r", "j"}) {
        EXPECT_TRUE(a.at("extremes").contains(q)) << q;
    }
}

TEST(CliErrors, EveryBadFileGivesExitTwoAndItsLocation) {
    const auto manifest =
        nlohmann::json::parse(test::readFile(test::dataPath("invalid/cases.json")));
    for (const auto& c : manifest) {
        const std::string file = test::dataPath("invalid/" + c.at("file").get<std::string>());
        for (const char* command : {"validate", "analyze"}) {
            const auto r = test::runCli({command, file});
            SCOPED_TRACE(std::string(command) + " " + file);
            EXPECT_EQ(r.signal, 0);
            EXPECT_EQ(r.exitCode, 2) << r.err;
            EXPECT_EQ(r.out, "");
            EXPECT_NE(r.err.find(c.at("location").get<std::string>()), std::string::npos) << r.err;
            EXPECT_EQ(r.err.rfind("camwright-cli: ", 0), 0u) << r.err;
        }
    }
}

TEST(CliErrors, BadArgumentsGiveTheDocumentedExitCode) {
    const auto manifest =
        nlohmann::json::parse(test::readFile(test::dataPath("invalid/cli_cases.json")));
    ASSERT_GE(manifest.size(), 20u);
    const std::string data = test::dataPath("invalid");
    for (const auto& c : manifest) {
        std::vector<std::string> args;
        for (std::string a : c.at("args")) {
            for (const auto& [from, to] :
                 {std::pair<std::string, std::string>{"@VALID@", kExample}, {"@DATA@", data}}) {
                if (const auto at = a.find(from); at != std::string::npos)
                    a.replace(at, from.size(), to);
            }
            args.push_back(a);
        }
        const auto r = test::runCli(args);
        SCOPED_TRACE(c.at("args").dump());
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, c.at("exit").get<int>()) << r.err;
        EXPECT_NE(r.err.find(c.at("stderr_contains").get<std::string>()), std::string::npos)
            << r.err;
        EXPECT_EQ(r.out, "");
    }
    EXPECT_FALSE(std::filesystem::exists(data + "/no-such-dir"));
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// The point of an arc (centre c, radius R, the outer or inner crossing) on the ray at φ.
std::array<double, 2> arcPoint(double cx, double cy, double R, bool outer, double phi) {
    const double ux = std::cos(phi), uy = std::sin(phi);
    const double along = ux * cx + uy * cy, across = ux * cy - uy * cx;
    const double rho = along + (outer ? 1.0 : -1.0) * std::sqrt(R * R - across * across);
    return {rho * ux, rho * uy};
}

TEST(CliAnalyze, AnArcTablesJerkIsUnboundedAtEveryJointWhereTheAccelerationJumps) {
    // The seed's six-lobe cam: tangent arcs of two radii, so the acceleration jumps at each of
    // its 12 joints. The jump at joint 1 (arc 0, inner, about (25.73752542, 0), R 4.84070597;
    // arc 1, outer, about (18.0971765, 10.44840972), R 8.10318055; math.md §3), from each arc's
    // own P(φ) by central differences: ω²·|P₀''(φ) − P₁''(φ)|.
    const auto run = test::runCli({"analyze", kExample});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json r = nlohmann::json::parse(run.out);
    const auto& unbounded = r["jerk_unbounded_at"];
    ASSERT_EQ(unbounded.size(), 12u);
    EXPECT_EQ(r["extremes"]["j"]["between_joints_only"], true);
    EXPECT_EQ(r["extremes"]["j_r"]["between_joints_only"], true);
    EXPECT_EQ(r["follower"]["j"]["between_joints_only"], true);
    const auto& first = unbounded[0];
    EXPECT_EQ(first["left"], 0);
    EXPECT_EQ(first["right"], 1);
    const double phi = first["phi_deg"].get<double>() * 3.14159265358979323846 / 180.0;
    const double omega = r["omega_rad_s"];
    constexpr double h = 1e-4;
    const auto second = [&](double cx, double cy, double R, bool outer) {
        const auto a = arcPoint(cx, cy, R, outer, phi - h), b = arcPoint(cx, cy, R, outer, phi),
                   c = arcPoint(cx, cy, R, outer, phi + h);
        return std::array<double, 2>{(a[0] - 2 * b[0] + c[0]) / (h * h),
                                     (a[1] - 2 * b[1] + c[1]) / (h * h)};
    };
    const auto p0 = second(25.73752542, 0.0, 4.84070597, false);
    const auto p1 = second(18.0971765, 10.44840972, 8.10318055, true);
    const double jump = omega * omega * std::hypot(p0[0] - p1[0], p0[1] - p1[1]);
    EXPECT_NEAR(first["acceleration_jump"].get<double>(), jump, 1e-5 * jump);
    // A circle about the axis has no joint whose acceleration jumps: none listed.
    const std::string disc = test::writeTestTempFile("analyze", "disc.cam.json", R"({
      "format": "camwright", "version": 1, "motion": {"period_s": 1},
      "contour": [{"type": "arc", "center": [0, 0], "radius": 20, "branch": "outer",
                   "phi_start": 0, "phi_end": 180},
                  {"type": "arc", "center": [0, 0], "radius": 20, "branch": "outer",
                   "phi_start": 180, "phi_end": 360}]})");
    const auto plain = test::runCli({"analyze", disc});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const nlohmann::json d = nlohmann::json::parse(plain.out);
    EXPECT_TRUE(d["jerk_unbounded_at"].empty());
    EXPECT_EQ(d["extremes"]["j"]["between_joints_only"], false);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(CliAnalyze, ItsTextIsExactlyTheJsonLibrarysOwnLayout) {
    // analyze writes its joints one by one rather than as one tree (a hundred thousand took
    // 400 MB): the text must still be what nlohmann-json writes for the whole document, which
    // its own parse and dump(2) give back. With joints, and with none (a single segment).
    const std::string single = test::writeTestTempFile("analyze", "single.cam.json", R"({
      "format": "camwright", "version": 1, "motion": {"period_s": 1},
      "contour": [{"type": "arc", "center": [0, 0], "radius": 20, "branch": "outer",
                   "phi_start": 0, "phi_end": 360}]})");
    for (const std::string& path : {std::string(kExample), single}) {
        const auto run = test::runCli({"analyze", path});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const nlohmann::ordered_json parsed = nlohmann::ordered_json::parse(run.out);
        EXPECT_EQ(parsed.dump(2) + "\n", run.out) << path;
        EXPECT_EQ(parsed["joints"].size(), path == single ? 0U : 13U) << path;
    }
}

}  // namespace
}  // namespace cam
