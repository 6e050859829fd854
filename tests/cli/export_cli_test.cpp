// camwright-cli export (issue 10): every file is read back by the program that will use it —
// ezdxf (with its audit) for DXF, svgelements for SVG, Python's csv for the cam table — and
// compared with an independent profile (tests/reference/polar_reference.py, mpmath): see
// tests/reference/check_export.py. The cams are the bundled example and the reference cams
// (arcs of both branches, lines, Béziers, Hermite segments, windows across 0°), plus cams made
// here that no other test uses.

#include <gtest/gtest.h>

#include <sstream>

#include <algorithm>
#include <cctype>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const char* const kPython = "/usr/bin/python3";

std::string checker() {
    return std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_export.py";
}

/// The checker's verdict on `file`: its JSON summary; a failed check fails the test with the
/// reasons it printed.
Json check(const std::string& kind, const std::string& project, const std::string& file,
           std::vector<std::string> extra = {}) {
    std::vector<std::string> args{checker(), kind, project, file};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::run(kPython, args, 600);
    EXPECT_EQ(r.exitCode, 0) << kind << " check of " << file << ":\n" << r.err;
    if (r.out.empty()) return Json::object();
    return Json::parse(r.out);
}

/// Every cam the exports are checked on: the example and tests/data/reference.
std::vector<std::string> cams() {
    std::vector<std::string> paths{test::examplePath("six-lobe-arc-cam.cam.json")};
    for (const auto& e : fs::directory_iterator(test::dataPath("reference"))) {
        const std::string p = e.path().string();
        if (p.ends_with(".cam.json")) paths.push_back(p);
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::size_t segmentCount(const std::string& project) {
    return Json::parse(test::readFile(project)).at("contour").size();
}

bool hasSplines(const std::string& project) {
    const Json doc = Json::parse(test::readFile(project));
    for (const auto& s : doc.at("contour")) {
        if (s.at("type") == "bezier" || s.at("type") == "hermite") return true;
    }
    return false;
}

class ExportEveryCam : public ::testing::TestWithParam<std::string> {
protected:
    test::TempDir dir;
};

std::string camName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = fs::path(info.param).filename().string();
    name = name.substr(0, name.find('.'));
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

// Fact: ezdxf reads the DXF with a clean audit (R2000, mm); an arc or line segment is exactly
// one ARC or LINE within 1e-9 mm of the exact profile (centre, radius, both ends, the right
// part of the circle); a spline's arcs stay within the tolerance; the chain closes within
// 1e-6 mm; the CENTRES are the arcs' centres.
TEST_P(ExportEveryCam, DxfIsTheExactProfileInLinesAndArcs) {
    const std::string out = dir.file("cam.dxf");
    const auto r =
        test::runCli({"export", GetParam(), "--format", "dxf", "--out", out, "--centres"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "");
    const Json s = check("dxf", GetParam(), out, {"--tolerance", "0.001"});
    EXPECT_EQ(s.value("audit_errors", -1), 0);
    EXPECT_EQ(s.value("audit_fixes", -1), 0);
    EXPECT_LE(s.value("worst_exact_mm", 1.0), 1e-9);
    EXPECT_LE(s.value("worst_gap_mm", 1.0), 1e-6);
    if (!hasSplines(GetParam())) {
        // Never a chain of short lines: one entity per segment.
        EXPECT_EQ(s.value("contour_entities", 0), segmentCount(GetParam()));
    } else {
        EXPECT_GT(s.value("contour_entities", 0), segmentCount(GetParam()));
        EXPECT_LE(s.value("worst_spline_mm", 1.0), 0.001);
    }
}

// Fact: the SVG is 1:1 in mm (viewBox = width × height in mm), the profile one closed path of
// M, L, A and Z within 1e-6 mm of the exact profile, splines included (their default
// tolerance in SVG is 1e-6 mm).
TEST_P(ExportEveryCam, SvgPathIsTheProfileToAMillionthOfAMillimetre) {
    const std::string out = dir.file("cam.svg");
    const auto r = test::runCli({"export", GetParam(), "--format", "svg", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("svg", GetParam(), out, {"--tolerance", "1e-6"});
    EXPECT_LE(s.value("worst_mm", 1.0), 1e-6);
    EXPECT_EQ(s.value("title", std::string()),
              Json::parse(test::readFile(GetParam())).value("name", std::string()));
}

// Fact: the cam table's positions are the knife-edge lift r(φ) − min r at 360·i/N degrees to
// 1e-9 of the stroke (min r found independently), its velocities r'(φ)·π/180.
TEST_P(ExportEveryCam, CamTablePositionsAreTheLiftToABillionthOfTheStroke) {
    const std::string out = dir.file("cam.csv");
    const auto r = test::runCli(
        {"export", GetParam(), "--format", "camtable", "--out", out, "--points", "360"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("camtable", GetParam(), out);
    EXPECT_EQ(s.value("rows", 0), 360);
    EXPECT_LE(s.value("worst_position_rel", 1.0), 1e-9);
}

// Fact: the CODESYS table is Structured Text with ARRAY[0..N] OF SMC_CAMXYVA (the knot at 360°
// repeating the first) and an MC_CAM_REF with byType 3 (XYVA), byVarType 6 (LREAL) and
// nElements N + 1; its knots are the lift to 1e-9 of the stroke, and the fifth-order
// polynomials a drive puts through them follow the profile between the knots (away from
// joints) to 1e-4 of the stroke — which they do only with slopes per master degree.
TEST_P(ExportEveryCam, CodesysCamIsTheLiftInXyvaKnots) {
    const std::string out = dir.file("cam.st");
    const auto r = test::runCli(
        {"export", GetParam(), "--format", "camtable", "--dialect", "codesys", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("codesys", GetParam(), out);
    EXPECT_EQ(s.value("knots", 0), 361);
    EXPECT_LE(s.value("worst_knot_rel", 1.0), 1e-9);
    EXPECT_LE(s.value("worst_smooth_midpoint_rel", 1.0), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Cams, ExportEveryCam, ::testing::ValuesIn(cams()), camName);

/// A project file of the given contour, written into `dir`.
std::string writeProject(const test::TempDir& dir, const std::string& name, const Json& contour) {
    const Json project{{"format", "camwright"},
                       {"version", 1},
                       {"name", name},
                       {"units", {{"length", "mm"}, {"angle", "deg"}}},
                       {"motion", {{"rpm", 60}}},
                       {"contour", contour}};
    const std::string path = dir.file(name + ".cam.json");
    std::ofstream(path) << project.dump(2);
    return path;
}

// Fact: a cam of one arc (a circle) is one CIRCLE; an eccentric circle is an exact cam.
TEST(ExportDxf, ACircleCamIsOneCircle) {
    test::TempDir dir;
    const std::string cam = writeProject(dir, "eccentric",
                                         Json::array({{{"type", "arc"},
                                                       {"center", {3.5, -1.25}},
                                                       {"radius", 17.0},
                                                       {"branch", "outer"},
                                                       {"phi_start", 0.0},
                                                       {"phi_end", 360.0}}}));
    const std::string out = dir.file("c.dxf");
    const auto r = test::runCli({"export", cam, "--format", "dxf", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("dxf", cam, out);
    EXPECT_EQ(s.value("types", Json::array()), Json::array({"CIRCLE"}));
    const std::string svg = dir.file("c.svg");
    ASSERT_EQ(test::runCli({"export", cam, "--format", "svg", "--out", svg}).exitCode, 0);
    EXPECT_LE(check("svg", cam, svg).value("worst_mm", 1.0), 1e-6);
}

// Fact: the polyline option writes one closed LWPOLYLINE whose bulge arcs are the profile.
TEST(ExportDxf, PolylineOptionIsOneClosedBulgedPolyline) {
    test::TempDir dir;
    const std::vector<std::string> cams{test::dataPath("reference/d-flat.cam.json"),
                                        test::dataPath("reference/spline-mix.cam.json")};
    for (const std::string& cam : cams) {
        SCOPED_TRACE(cam);
        const std::string out = dir.file("p.dxf");
        const auto r = test::runCli({"export", cam, "--format", "dxf", "--out", out, "--polyline"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const Json s = check("dxf", cam, out);
        EXPECT_EQ(s.value("polyline", false), true);
        EXPECT_LE(s.value("worst_exact_mm", 1.0), 1e-9);
    }
}

// Fact: with --spline-entities a Bézier or Hermite segment is one degree-3 SPLINE with exactly
// its control points (a Hermite's P1 = p0 + t0/3, P2 = p3 − t1/3).
TEST(ExportDxf, SplineEntitiesCarryTheExactControlPoints) {
    test::TempDir dir;
    const std::string cam = test::dataPath("reference/spline-mix.cam.json");
    const std::string out = dir.file("s.dxf");
    const auto r =
        test::runCli({"export", cam, "--format", "dxf", "--out", out, "--spline-entities"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("dxf", cam, out);
    EXPECT_EQ(s.value("contour_entities", 0), 4);
    EXPECT_EQ(s.value("types", Json::array()), Json::array({"ARC", "LINE", "SPLINE"}));
    EXPECT_LE(s.value("worst_exact_mm", 1.0), 1e-9);
}

// Fact: the TOOLPATH layer keeps the tool radius from the profile everywhere.
TEST(ExportDxf, ToolPathLayerKeepsTheToolRadius) {
    test::TempDir dir;
    const std::string cam = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::string out = dir.file("t.dxf");
    const auto r =
        test::runCli({"export", cam, "--format", "dxf", "--out", out, "--tool-radius", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json s = check("dxf", cam, out, {"--tool-radius", "2"});
    EXPECT_GE(s.value("toolpath_entities", 0), 13);
    EXPECT_LE(s.value("toolpath_worst_mm", 1.0), 1e-3);
}

// Fact: a grooved cam's DXF has its inner flank (the contour, exact as on CONTOUR), its outer
// flank and the roller's pitch curve on layers FLANK_INNER, FLANK_OUTER and PITCH, as true arcs
// about the profile's own centres, every point of the outer flank 2ρ + c from the profile along
// its normals to 1e-9 mm; the SVG draws both flanks and the pitch curve, each within 1e-6 mm of
// that offset measured against the profile's arcs (tests/reference/check_export.py).
TEST(ExportGroove, DxfAndSvgCarryBothFlanksAsTrueArcs) {
    test::TempDir dir;
    Json project = Json::parse(test::readFile(test::examplePath("six-lobe-arc-cam.cam.json")));
    project["follower"] = {
        {"type", "roller"}, {"radius", 1.5}, {"closure", "groove"}, {"groove_clearance_mm", 0.4}};
    const std::string cam = dir.file("grooved.cam.json");
    std::ofstream(cam) << project.dump(1);
    const std::string dxf = dir.file("g.dxf"), svg = dir.file("g.svg");
    ASSERT_EQ(test::runCli({"export", cam, "--format", "dxf", "--out", dxf}).exitCode, 0);
    const Json d = check("dxf", cam, dxf, {"--groove", "1.5", "0.4"});
    EXPECT_EQ(d.value("contour_entities", 0), 13);  // FLANK_INNER
    EXPECT_EQ(d.value("flank_outer_entities", 0), 13);
    EXPECT_EQ(d.value("pitch_entities", 0), 13);
    EXPECT_LE(d.value("worst_exact_mm", 1.0), 1e-9);
    EXPECT_LE(d.value("worst_flank_outer_exact_mm", 1.0), 1e-9);
    EXPECT_LE(d.value("worst_pitch_exact_mm", 1.0), 1e-9);
    EXPECT_LE(d.value("worst_flank_outer_dense_mm", 1.0), 1e-2);
    // No CONTOUR layer: the contour is the inner flank.
    EXPECT_EQ(test::readFile(dxf).find("\nCONTOUR\n"), std::string::npos);
    ASSERT_EQ(test::runCli({"export", cam, "--format", "svg", "--out", svg}).exitCode, 0);
    const Json v = check("svg", cam, svg, {"--groove", "1.5", "0.4", "--tolerance", "1e-6"});
    EXPECT_LE(v.value("worst_outer_flank_mm", 1.0), 1e-6);
    EXPECT_LE(v.value("worst_pitch_mm", 1.0), 1e-6);
    // A groove that cannot be milled (the notches, radius 4.84 mm, are tighter than 2ρ + c)
    // exports nothing and says where.
    project["follower"]["groove_clearance_mm"] = 2.0;
    std::ofstream(cam) << project.dump(1);
    fs::remove(dxf);
    const auto refused = test::runCli({"export", cam, "--format", "dxf", "--out", dxf});
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("undercuts the groove's outer flank"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(fs::exists(dxf));
}

// Fact: export csv is the sampled turn, byte for byte what `sample` writes (whose numbers the
// reference tests check).
TEST(ExportCsv, IsTheSampledTurnWithTheFollowersColumns) {
    test::TempDir dir;
    const std::string cam = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::string out = dir.file("turn.csv");
    ASSERT_EQ(
        test::runCli({"export", cam, "--format", "csv", "--out", out, "--points", "720"}).exitCode,
        0);
    const auto sample = test::runCli({"sample", cam, "--samples", "720"});
    ASSERT_EQ(sample.exitCode, 0);
    // Every line is the `sample` line and eight follower columns after it.
    std::istringstream exported(test::readFile(out)), sampled(sample.out);
    std::string a, b;
    int lines = 0;
    while (std::getline(sampled, b)) {
        ASSERT_TRUE(std::getline(exported, a));
        std::size_t cut = a.size();
        for (int c = 0; c < 8; ++c) cut = a.rfind(',', cut - 1);
        EXPECT_EQ(a.substr(0, cut), b);
        if (lines == 0) {
            EXPECT_EQ(a.substr(cut + 1),
                      "s,lift,follower_v,follower_a,follower_j,pressure_angle_deg,rho_profile,"
                      "rho_pitch");
        }
        ++lines;
    }
    EXPECT_EQ(lines, 721);
    EXPECT_FALSE(std::getline(exported, a));
}

// Fact: every bad argument is refused with a message naming it, the right exit code, and no
// file; an existing file at --out is left as it was.
TEST(ExportArguments, BadArgumentsAreLocatedAndLeaveNoFile) {
    test::TempDir dir;
    const std::string cam = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::string out = dir.file("x.dxf");
    struct Case {
        std::vector<std::string> args;
        int exitCode;
        std::string message;
    };
    const std::vector<Case> cases{
        {{"--format", "step", "--out", out}, 1, "--format: unknown format 'step'"},
        {{"--out", out}, 1, "--format is required"},
        {{"--format", "dxf"}, 1, "--out FILE is required"},
        {{"--format", "dxf", "--out", out, "--tolerance", "0"}, 2, "--tolerance: the tolerance"},
        {{"--format", "dxf", "--out", out, "--tolerance", "-1"}, 2, "--tolerance"},
        {{"--format", "dxf", "--out", out, "--tolerance", "nan"}, 2, "--tolerance"},
        {{"--format", "camtable", "--out", out, "--points", "0"}, 2, "--points"},
        {{"--format", "camtable", "--out", out, "--points", "-5"}, 2, "--points"},
        {{"--format", "camtable", "--out", out, "--dialect", "punched-tape"},
         2,
         "--dialect: unknown cam table dialect 'punched-tape' (csv, codesys, beckhoff, rockwell, "
         "kollmorgen)"},
        {{"--format", "svg", "--out", out, "--points", "10"},
         1,
         "--points: is not an option of --format svg"},
        {{"--format", "csv", "--out", out, "--polyline"}, 1, "--polyline"},
        {{"--format", "dxf", "--out", out, "--tool-radius", "0"}, 2, "--tool-radius"},
        {{"--format", "dxf", "--out", out, "--tool-radius", "5"}, 3, "contour["},
        {{"--format", "dxf", "--out", dir.file("no/such/folder/x.dxf")}, 2, "no/such/folder"},
        {{"--format", "dxf", "--out", cam}, 2, "is the project being exported"},
    };
    const std::string before = test::readFile(cam);
    for (const Case& c : cases) {
        std::vector<std::string> args{"export", cam};
        args.insert(args.end(), c.args.begin(), c.args.end());
        SCOPED_TRACE(Json(args).dump());
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, c.exitCode) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_FALSE(fs::exists(out));
    }
    EXPECT_EQ(test::readFile(cam), before);
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{});

    // An export that fails leaves the file that was there as it was.
    std::ofstream(out) << "old drawing";
    const auto r =
        test::runCli({"export", cam, "--format", "dxf", "--out", out, "--tool-radius", "5"});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(test::readFile(out), "old drawing");
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"x.dxf"});
}

// Fact: a tool wider than a concave arc is refused for the TOOLPATH layer, naming the arc
// (the example's concave arcs have radius 4.84 mm).
TEST(ExportArguments, AToolTooWideForAConcaveArcNamesIt) {
    test::TempDir dir;
    const auto r =
        test::runCli({"export", test::examplePath("six-lobe-arc-cam.cam.json"), "--format", "dxf",
                      "--out", dir.file("t.dxf"), "--tool-radius", "5"});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("six-lobe-arc-cam.cam.json: contour[0]: the tool radius 5 mm is not "
                         "smaller than the radius"),
              std::string::npos)
        << r.err;
}

TEST(ExportNames, OneRuleNamesTheGcodeTheCamTableAndTheSvg) {
    // Issue 31: the G-code was headed "x.cam.json" and the cam table "x" for the same project.
    // One rule now: the project's name, else its file's name without ".cam.json".
    test::TempDir dir;
    Json project = Json::parse(test::readFile(test::kExample));
    project.erase("name");
    project["machining"] = {
        {"axis_accel", {500.0, 500.0, 200.0}}, {"feed_max", 50.0}, {"tool_radius", 2.0}};
    const std::string path = dir.file("Pump cam 7.cam.json");
    test::writeText(path, project.dump(2));
    const auto exportTo = [&](const std::string& format, const std::string& out) {
        const auto r = test::runCli({"export", path, "--format", format, "--out", dir.file(out)});
        EXPECT_EQ(r.exitCode, 0) << format << ": " << r.err;
        return test::readFile(dir.file(out));
    };
    const std::string gcode = exportTo("gcode", "p.ngc");
    EXPECT_NE(gcode.find("(Camwright G-code: Pump cam 7)"), std::string::npos)
        << gcode.substr(0, 200);
    const std::string table = exportTo("camtable", "p.csv");
    EXPECT_NE(table.find(" of Pump cam 7"), std::string::npos) << table.substr(0, 200);
    const std::string svg = exportTo("svg", "p.svg");
    EXPECT_NE(svg.find("<title>Pump cam 7</title>"), std::string::npos) << svg.substr(0, 400);
    // With a name, the name.
    project["name"] = "Intake";
    test::writeText(path, project.dump(2));
    EXPECT_NE(exportTo("gcode", "n.ngc").find("(Camwright G-code: Intake)"), std::string::npos);
    EXPECT_NE(exportTo("camtable", "n.csv").find(" of Intake"), std::string::npos);
}

}  // namespace
}  // namespace cam
