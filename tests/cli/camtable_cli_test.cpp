// camwright-cli export --format camtable (issue 33, points 3 and 4): the table's source (the
// design's law or the contour), the controllers' dialects and the report of their
// interpolation error. Every file is read back by tests/reference/check_camtable.py, a reader
// written from the vendors' documentation that rebuilds each controller's interpolation and
// compares it with the closed form of the design (cycloidal rise 0–120° by 10 mm, dwell,
// cycloidal return 180–300°, dwell): y = h(x − sin(2πx)/2π).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

// Its own namespace: the unity build puts it beside export_cli_test.cpp.
namespace cam::camtable_cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const char* const kPython = "/usr/bin/python3";
const char* const kDialects[] = {"csv", "codesys", "beckhoff", "rockwell", "kollmorgen"};

/// A design never synthesised: "a plain electronic cam, master → slave directly".
const char* const kDesignOnly = R"({"format": "camwright", "version": 1,
  "name": "Cycloidal servo cam", "units": {"length": "mm", "angle": "deg"},
  "motion": {"rpm": 60.0}, "contour": [],
  "follower": {"type": "roller", "offset": 0.0, "radius": 8.0},
  "design": {"base_radius": 40.0, "tolerance": 0.001, "segments": [
    {"law": "cycloidal", "to_deg": 120.0, "lift": 10.0},
    {"law": "dwell", "to_deg": 180.0, "lift": 10.0},
    {"law": "cycloidal", "to_deg": 300.0, "lift": 0.0},
    {"law": "dwell", "to_deg": 360.0, "lift": 0.0}]}})";

std::string checker() {
    return std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_camtable.py";
}

struct Exported {
    Json report;  ///< the CLI's JSON on stdout
    Json check;   ///< the reader's re-evaluation
};

/// Exports `project` as a cam table with `options` and has the reader re-evaluate the file (and
/// compare it with the CLI's report).
Exported exportAndCheck(const test::TempDir& dir, const std::string& project,
                        const std::string& dialect, std::vector<std::string> options) {
    const std::string out = dir.file("table." + dialect);
    std::vector<std::string> args{"export",    project, "--format", "camtable",
                                  "--dialect", dialect, "--out",    out};
    args.insert(args.end(), options.begin(), options.end());
    const auto r = test::runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    if (r.exitCode != 0) return {};
    const std::string reportPath = dir.file("report.json");
    test::writeText(reportPath, r.out);
    const auto c = test::run(kPython, {checker(), dialect, project, out, "--report", reportPath});
    EXPECT_EQ(c.exitCode, 0) << dialect << ":\n" << c.err;
    return {Json::parse(r.out), c.out.empty() ? Json::object() : Json::parse(c.out)};
}

std::string designOnly(const test::TempDir& dir) {
    const std::string path = dir.file("design-only.cam.json");
    test::writeText(path, kDesignOnly);
    return path;
}

// Fact: for every dialect, the report's largest position, velocity and acceleration errors are
// what the reader gets by rebuilding the controller's interpolation from the file and comparing
// it with the closed form at the same angles (to 1e-6 of the error, plus rounding); the points
// themselves are the law (to 1e-12 mm, or a REAL's rounding for Rockwell); the characteristics
// are the cycloid's extremes (checked by the reader against 2h/β, 2πh/β², 4π²h/β³). With 36
// points the quintic dialects are within 1e-6 mm, the cubic splines are not (their error is h⁴:
// the quintic's h⁶ is far smaller).
TEST(CamTableDialects, TheReportedErrorIsTheControllersInterpolationReEvaluated) {
    const test::TempDir dir;
    const std::string project = designOnly(dir);
    for (const char* dialect : kDialects) {
        for (const char* points : {"36", "360"}) {
            SCOPED_TRACE(std::string(dialect) + " " + points);
            const Exported e = exportAndCheck(dir, project, dialect, {"--points", points});
            ASSERT_TRUE(e.check.contains("max_error")) << e.check.dump();
            EXPECT_EQ(e.report.at("points"), std::stoi(points));
            EXPECT_EQ(e.report.at("source"), "law");
            EXPECT_EQ(e.report.at("slave_unit"), "mm");
            EXPECT_TRUE(e.check.value("report_agrees", false));
            const bool real = std::string(dialect) == "rockwell";
            // A REAL holds 24 bits: 10 mm to 1e-6 mm at worst.
            EXPECT_LE(e.check.at("knot_error").get<double>(), real ? 1e-6 : 1e-12);
            const bool quintic = e.report.at("interpolation") == "quintic";
            if (std::string(points) == "36") {
                if (quintic) {
                    EXPECT_LT(e.report.at("max_error").at("position").get<double>(), 1e-6);
                } else {
                    EXPECT_GT(e.report.at("max_error").at("position").get<double>(), 1e-4);
                }
            }
        }
    }
}

// Fact: --tolerance T writes the fewest points whose interpolation the reader finds within T:
// the table it writes re-evaluates to ≤ T, and the table of one point fewer (written with
// --points) to > T. The report carries T.
TEST(CamTableTolerance, TheFewestPointsThatMeetItAreWritten) {
    const test::TempDir dir;
    const std::string project = designOnly(dir);
    for (const char* dialect : {"csv", "beckhoff", "rockwell", "kollmorgen"}) {
        for (const double tolerance : {1e-3, 1e-5}) {
            SCOPED_TRACE(std::string(dialect) + " " + std::to_string(tolerance));
            std::ostringstream text;
            text << tolerance;
            const Exported met = exportAndCheck(dir, project, dialect, {"--tolerance", text.str()});
            ASSERT_TRUE(met.check.contains("max_error"));
            EXPECT_EQ(met.report.at("tolerance").get<double>(), tolerance);
            const int n = met.report.at("points");
            EXPECT_LE(met.check.at("max_error").at("position").get<double>(), tolerance);
            ASSERT_GT(n, 4);
            const Exported fewer =
                exportAndCheck(dir, project, dialect, {"--points", std::to_string(n - 1)});
            ASSERT_TRUE(fewer.check.contains("max_error"));
            EXPECT_GT(fewer.check.at("max_error").at("position").get<double>(), tolerance)
                << n - 1 << " points";
        }
    }
}

/// The CSV's rows: master_deg, position, velocity, acceleration.
std::vector<std::vector<double>> csvRows(const std::string& text) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == 'm') continue;
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    return rows;
}

// Fact: a project with a design and its synthesised contour exports its law by default: in the
// dwells (120–180° at 10 mm, 300–360° at 0) its rows are exactly the design's lift with zero
// velocity and acceleration. The contour's table (--source contour), made of tangent arcs, is
// not exact there, though within 0.01 mm; its report says so by a larger error of its own kind.
TEST(CamTableSource, TheLawIsExactInTheDwellsTheArcFittedContourIsNot) {
    const test::TempDir dir;
    const std::string project = test::examplePath("synthesised-cycloidal-roller.cam.json");
    const auto run = [&](const std::vector<std::string>& extra, const std::string& file) {
        std::vector<std::string> args{"export",   project, "--format",
                                      "camtable", "--out", dir.file(file)};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return Json::parse(r.out.empty() ? "{}" : r.out);
    };
    EXPECT_EQ(run({}, "default.csv").value("source", ""), "law");
    EXPECT_EQ(run({"--source", "law"}, "law.csv").value("source", ""), "law");
    EXPECT_EQ(run({"--source", "contour"}, "contour.csv").value("source", ""), "contour");
    EXPECT_EQ(test::readFile(dir.file("default.csv")), test::readFile(dir.file("law.csv")));
    EXPECT_NE(test::readFile(dir.file("law.csv")).find("# source=law\n"), std::string::npos);
    const auto law = csvRows(test::readFile(dir.file("law.csv")));
    const auto contour = csvRows(test::readFile(dir.file("contour.csv")));
    ASSERT_EQ(law.size(), 360u);
    ASSERT_EQ(contour.size(), 360u);
    int inexact = 0;
    for (std::size_t deg : {121u, 130u, 150u, 170u, 179u, 301u, 320u, 340u, 359u}) {
        SCOPED_TRACE(deg);
        const double lift = deg < 180 ? 10.0 : 0.0;
        EXPECT_EQ(law[deg][1], lift);
        EXPECT_EQ(law[deg][2], 0.0);
        EXPECT_EQ(law[deg][3], 0.0);
        EXPECT_NEAR(contour[deg][1], lift, 0.01);
        if (contour[deg][1] != lift || contour[deg][2] != 0.0 || contour[deg][3] != 0.0) ++inexact;
    }
    EXPECT_GT(inexact, 0);
}

// Fact: on a swinging arm the law's table is in degrees of swing like the contour's (both say
// slave=lift_deg and slave_unit "deg"), and the two agree to what the arcs cost (within 0.005°
// and 0.005°/° at every point, the design's tolerance being 0.001 mm): the law's derivatives
// per radian were made per master degree, not left per radian (180/π apart).
TEST(CamTableSource, ASwingingArmsLawIsInDegreesLikeItsContour) {
    const test::TempDir dir;
    const std::string project = test::examplePath("swinging-arm-cam.cam.json");
    std::vector<std::vector<std::vector<double>>> tables;
    for (const char* source : {"law", "contour"}) {
        const std::string out = dir.file(std::string(source) + ".csv");
        const auto r = test::runCli(
            {"export", project, "--format", "camtable", "--source", source, "--out", out});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(Json::parse(r.out).value("slave_unit", ""), "deg");
        EXPECT_NE(test::readFile(out).find("# slave=lift_deg\n"), std::string::npos);
        tables.push_back(csvRows(test::readFile(out)));
    }
    ASSERT_EQ(tables[0].size(), 360u);
    ASSERT_EQ(tables[1].size(), 360u);
    double stroke = 0.0;
    for (std::size_t i = 0; i < 360; ++i) {
        stroke = std::max(stroke, tables[0][i][1]);
        EXPECT_NEAR(tables[0][i][1], tables[1][i][1], 0.005) << i;
        EXPECT_NEAR(tables[0][i][2], tables[1][i][2], 0.005) << i;
    }
    EXPECT_GT(stroke, 1.0);
}

// Fact: a design never synthesised (no contour) exports its law as a cam table, by default and
// with --source law, the same file both ways; the reader finds it the closed form. Every other
// format still refuses it, saying its contour was never synthesised; --source contour refuses
// it located at --source. Neither refusal writes a file.
TEST(CamTableSource, ADesignNeverSynthesisedIsAPlainElectronicCam) {
    const test::TempDir dir;
    const std::string project = designOnly(dir);
    const Exported e = exportAndCheck(dir, project, "csv", {});
    EXPECT_EQ(e.report.value("source", ""), "law");
    EXPECT_EQ(e.report.value("points", 0), 360);
    EXPECT_LE(e.check.value("knot_error", 1.0), 1e-12);
    const auto explicitLaw = test::runCli({"export", project, "--format", "camtable", "--source",
                                           "law", "--out", dir.file("law.csv")});
    EXPECT_EQ(explicitLaw.exitCode, 0) << explicitLaw.err;
    EXPECT_EQ(test::readFile(dir.file("law.csv")), test::readFile(dir.file("table.csv")));

    const std::string out = dir.file("refused.out");
    auto r = test::runCli({"export", project, "--format", "dxf", "--out", out});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("never synthesised"), std::string::npos) << r.err;
    r = test::runCli(
        {"export", project, "--format", "camtable", "--source", "contour", "--out", out});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--source: contour: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("never synthesised"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(out));
}

// Fact: every bad --source or --tolerance is refused with a message naming it, the CLI's exit
// code (1 usage, 2 invalid input, 3 not computable) and no file.
TEST(CamTableArguments, BadSourcesAndTolerancesAreLocatedAndLeaveNoFile) {
    const test::TempDir dir;
    const std::string designed = designOnly(dir);
    const std::string noDesign = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::string out = dir.file("x.csv");
    struct Case {
        std::string project;
        std::vector<std::string> args;
        int exitCode;
        std::string message;
    };
    const std::vector<Case> cases{
        {designed, {"--source", "cam"}, 2, "--source: unknown source 'cam' (law, contour)"},
        {noDesign, {"--source", "law"}, 2, "--source: law: "},
        {designed, {"--tolerance", "0"}, 2, "--tolerance: must be > 0"},
        {designed, {"--tolerance", "-0.001"}, 2, "--tolerance: must be > 0"},
        {designed, {"--tolerance", "nan"}, 2, "--tolerance"},
        {designed, {"--tolerance", "1e-3", "--points", "100"}, 1, "--tolerance: cannot be given"},
        {designed, {"--tolerance", "1e-30"}, 3, "--tolerance: 1e-30 cannot be met with 1000000"},
        {noDesign, {"--source", "contour", "--dialect", "siemens"}, 2, "--dialect: unknown"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"export", c.project, "--format", "camtable", "--out", out};
        args.insert(args.end(), c.args.begin(), c.args.end());
        SCOPED_TRACE(Json(args).dump());
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, c.exitCode) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace cam::camtable_cli
