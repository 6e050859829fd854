// camwright-cli state's `follower` object (cli.md, math.md §7): against the 50-digit contact
// reference (tests/reference/follower_reference.py: followers placed by their contact condition,
// derivatives by mpmath.diff) on cams with rollers, offsets, knives and flat faces; the knife on
// the radial line against the polar state of the same command; refusals.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.h"

namespace cam {
namespace {

using test::relClose;
using Json = nlohmann::json;

Json followerAt(const std::string& project, double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", t);
    const auto run = test::runCli({"state", project, "--t", text});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return Json::parse(run.out);
}

/// The rows of a cam table in the CSV dialect: master_deg, position, velocity, acceleration.
std::vector<std::array<double, 4>> camTableRows(const std::string& text) {
    std::vector<std::array<double, 4>> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == 'm') continue;
        std::array<double, 4> row{};
        EXPECT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &row[0], &row[1], &row[2], &row[3]),
                  4)
            << line;
        rows.push_back(row);
    }
    return rows;
}

TEST(CliFollowerReference, StateAgreesWithTheContactReferenceToOneBillionth) {
    namespace fs = std::filesystem;
    int cams = 0, states = 0;
    for (const auto& entry : fs::directory_iterator(test::dataPath("reference/followers"))) {
        const std::string path = entry.path().string();
        if (!path.ends_with(".expected.json")) continue;
        const std::string project = path.substr(0, path.size() - 14) + ".cam.json";
        const Json expected = Json::parse(test::readFile(path));
        ++cams;
        for (const Json& e : expected) {
            const double t = e.at("t");
            SCOPED_TRACE(entry.path().filename().string() + " t=" + std::to_string(t));
            const Json state = followerAt(project, t);
            const Json& f = state.at("follower");
            // Positions to 1e-9 of the cam's size; derivatives to 1e-9 of their own size, with a
            // floor of 1e-9 of s·ω^k for values that are zero.
            const bool arm = e.contains("psi_deg");
            EXPECT_EQ(f.at("motion"), arm ? "oscillating" : "translating");
            const double size =
                std::hypot(e.at("center_x").get<double>(), e.at("center_y").get<double>());
            EXPECT_TRUE(relClose(f.at("center")[0], e.at("center_x"), 1e-9, size)) << "center x";
            EXPECT_TRUE(relClose(f.at("center")[1], e.at("center_y"), 1e-9, size)) << "center y";
            EXPECT_TRUE(relClose(f.at("contact")[0], e.at("contact_x"), 1e-9, size)) << "contact x";
            EXPECT_TRUE(relClose(f.at("contact")[1], e.at("contact_y"), 1e-9, size)) << "contact y";
            // ψ to 1e-9 rad (a 1e-9 mm move of a tip 1 mm out); its rates like s's.
            const std::array<const char*, 4> names =
                arm ? std::array{"psi_deg", "omega_arm", "alpha_arm", "jerk_arm"}
                    : std::array{"s", "v", "a", "j"};
            if (arm) {
                EXPECT_NEAR(f.at("psi_deg"), e.at("psi_deg"), 1e-9 * 180.0 / M_PI) << "psi";
            } else {
                EXPECT_TRUE(relClose(f.at("s"), e.at("s"), 1e-9)) << "s";
            }
            // Zeros of the rates get an absolute floor of 1e-12 of their size plus 1e-9.
            for (std::size_t k = 1; k < 4; ++k) {
                const double want = e.at(names[k]);
                EXPECT_TRUE(relClose(f.at(names[k]), want, 1e-9, 1e-3 * std::abs(want) + 1.0))
                    << names[k];
            }
            EXPECT_NEAR(f.at("pressure_angle_deg"), e.at("pressure_angle_deg"), 1e-9)
                << "pressure angle";
            ++states;
        }
    }
    EXPECT_GE(cams, 8);
    EXPECT_GE(states, 68);
}

TEST(CliFollowerCamTable, PositionsAreTheFollowersLiftAtTheMasterAngles) {
    // The roller with offset on the six-lobe cam: every reference instant falls on a knot of a
    // 3600-point table (0.1° steps). Positions differ by what s differs by in the reference; the
    // velocity per degree is v/ω·π/180.
    const std::string base = test::dataPath("reference/followers/six-lobe-roller-offset");
    const Json expected = Json::parse(test::readFile(base + ".expected.json"));
    test::TempDir dir;
    const std::string out = dir.file("table.csv");
    const auto run = test::runCli(
        {"export", base + ".cam.json", "--format", "camtable", "--points", "3600", "--out", out});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::array<double, 4>> rows = camTableRows(test::readFile(out));
    ASSERT_EQ(rows.size(), 3600u);
    double stroke = 0.0;
    for (const auto& r : rows) stroke = std::max(stroke, r[1]);
    const double omega = 2.0 * M_PI / 0.4, perDeg = M_PI / 180.0;
    const auto knot = [&](const Json& e) {
        const double tenth = e.at("phi_deg").get<double>() * 10.0;
        EXPECT_NEAR(tenth, std::round(tenth), 1e-6);
        return static_cast<std::size_t>(std::lround(tenth)) % 3600;
    };
    const Json& first = expected.front();
    for (const Json& e : expected) {
        SCOPED_TRACE("phi " + std::to_string(e.at("phi_deg").get<double>()));
        const auto& row = rows[knot(e)];
        EXPECT_NEAR(row[1] - rows[knot(first)][1],
                    e.at("s").get<double>() - first.at("s").get<double>(), 1e-9 * stroke);
        EXPECT_TRUE(relClose(row[2], e.at("v").get<double>() / omega * perDeg, 1e-9, 1e-3));
        EXPECT_GE(row[1], -1e-12);
    }
}

TEST(CliFollowerCsv, TheFollowersColumnsAreTheReferenceAtTheirInstants) {
    // Every reference instant of the six-lobe roller is a row of a 3600-row turn (T = 0.4 s).
    const std::string base = test::dataPath("reference/followers/six-lobe-roller-offset");
    const Json expected = Json::parse(test::readFile(base + ".expected.json"));
    test::TempDir dir;
    const std::string out = dir.file("turn.csv");
    const auto run = test::runCli(
        {"export", base + ".cam.json", "--format", "csv", "--points", "3600", "--out", out});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::vector<std::vector<double>> rows;
    std::istringstream in(test::readFile(out));
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        ASSERT_EQ(row.size(), 23u) << line;
        rows.push_back(row);
    }
    ASSERT_EQ(rows.size(), 3600u);
    for (const Json& e : expected) {
        const double t = e.at("t");
        const auto k = static_cast<std::size_t>(std::lround(t / 0.4 * 3600));
        ASSERT_NEAR(rows[k][0], t, 1e-15);
        const double s = e.at("s");
        EXPECT_TRUE(relClose(rows[k][15], s, 1e-9)) << t;
        EXPECT_TRUE(relClose(rows[k][17], e.at("v"), 1e-9, 1.0)) << t;
        EXPECT_NEAR(rows[k][20], e.at("pressure_angle_deg").get<double>(), 1e-8) << t;
        EXPECT_GE(rows[k][16], -1e-12);  // the lift
    }
}

TEST(CliFollowerArm, TheCamTableAndTheCsvHoldTheArmsAngleInDegrees) {
    // The swinging roller on the pear cam (T = 0.25 s, arm "ccw": the lift grows with ψ). A
    // 3600-point table has a knot every 0.1°; reference instants that fall on one are checked.
    const std::string base = test::dataPath("reference/followers/pear-tangent-arm-roller");
    const Json expected = Json::parse(test::readFile(base + ".expected.json"));
    test::TempDir dir;
    const std::string table = dir.file("table.csv"), turn = dir.file("turn.csv");
    auto run = test::runCli(
        {"export", base + ".cam.json", "--format", "camtable", "--points", "3600", "--out", table});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string text = test::readFile(table);
    EXPECT_NE(text.find("# slave=lift_deg\n"), std::string::npos);
    const std::vector<std::array<double, 4>> rows = camTableRows(text);
    ASSERT_EQ(rows.size(), 3600u);
    const double omega = 2.0 * M_PI / 0.25;
    int checked = 0;
    const Json* first = nullptr;
    std::size_t firstKnot = 0;
    for (const Json& e : expected) {
        const double tenth = e.at("phi_deg").get<double>() * 10.0;
        if (std::abs(tenth - std::round(tenth)) > 1e-6) continue;
        const auto knot = static_cast<std::size_t>(std::lround(tenth)) % 3600;
        if (!first) {
            first = &e;
            firstKnot = knot;
        }
        SCOPED_TRACE("phi " + std::to_string(e.at("phi_deg").get<double>()));
        // Positions differ by what ψ differs by; the rate per master degree is ψ' (deg/deg).
        EXPECT_NEAR(rows[knot][1] - rows[firstKnot][1],
                    e.at("psi_deg").get<double>() - first->at("psi_deg").get<double>(), 1e-9);
        EXPECT_TRUE(relClose(rows[knot][2], e.at("omega_arm").get<double>() / omega, 1e-9, 1e-3));
        EXPECT_GE(rows[knot][1], -1e-12);
        ++checked;
    }
    EXPECT_GE(checked, 5);
    // The CSV: ψ in degrees and the arm's rates under their own names.
    run = test::runCli(
        {"export", base + ".cam.json", "--format", "csv", "--points", "1000", "--out", turn});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string csv = test::readFile(turn);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "t,phi_deg,segment,r,x,y,v_r,v_phi,v,a_r,a_phi,a,j_r,j_phi,j,psi_deg,lift_deg,"
              "omega_arm,alpha_arm,jerk_arm,pressure_angle_deg,rho_profile,rho_pitch");
    // t = 0.04 s is row 160 of 1000 (T = 0.25 s).
    std::istringstream lines(csv);
    std::string line;
    for (int k = 0; k <= 160 + 1; ++k) std::getline(lines, line);
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');)
        row.push_back(cell.empty() ? NAN : std::stod(cell));
    if (line.back() == ',') row.push_back(NAN);  // the contact is on a line: both radii empty
    ASSERT_EQ(row.size(), 23u);
    EXPECT_TRUE(std::isnan(row[21]) && std::isnan(row[22]));
    const Json& at004 = expected.at(1);
    ASSERT_NEAR(row[0], at004.at("t").get<double>(), 1e-15);
    EXPECT_NEAR(row[15], at004.at("psi_deg").get<double>(), 1e-9);
    EXPECT_TRUE(relClose(row[17], at004.at("omega_arm"), 1e-9, 1e-3));
    EXPECT_NEAR(row[20], at004.at("pressure_angle_deg").get<double>(), 1e-8);
}

TEST(CliFollower, AKnifeOnTheRadialLineIsThePolarState) {
    const std::string example = test::examplePath("six-lobe-arc-cam.cam.json");
    // The lowest r of the six-lobe cam, from `analyze`, is where the lift is zero.
    const auto analyze = test::runCli({"analyze", example});
    ASSERT_EQ(analyze.exitCode, 0) << analyze.err;
    const double minR = Json::parse(analyze.out).at("extremes").at("r").at("min").at("value");
    for (double t : {0.0, 0.013, 0.1, 0.2345, 0.39}) {
        const Json s = followerAt(example, t);
        const Json& f = s.at("follower");
        EXPECT_EQ(f.at("type"), "knife");
        EXPECT_EQ(f.at("motion"), "translating");
        EXPECT_TRUE(relClose(f.at("s"), s.at("r"), 1e-14));
        EXPECT_TRUE(relClose(f.at("v"), s.at("v_r"), 1e-12, 1.0));
        EXPECT_TRUE(relClose(f.at("lift"), s.at("r").get<double>() - minR, 1e-9, 1.0));
        EXPECT_GE(f.at("lift").get<double>(), -1e-12);
    }
}

TEST(CliFollower, WhatCannotBeComputedIsRefusedWithItsPlace) {
    test::TempDir dir;
    auto project = Json::parse(test::readFile(test::examplePath("six-lobe-arc-cam.cam.json")));
    // A roller wider than the cam's concave arcs (radius 4.84 mm): an invalid project.
    project["follower"] = {{"type", "roller"}, {"radius", 5.0}};
    std::string path = test::writeTempFile(dir.file("wide.cam.json"), project.dump());
    auto run = test::runCli({"state", path, "--t", "0.1"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("follower.radius"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("contour[0]"), std::string::npos) << run.err;
    // Swinging arms that cannot ride the cam (its profile reaches 29 mm from the centre): a
    // pivot inside it, an arm too short to reach it, one so long it passes beyond it. Every
    // command and `validate` name the field and the angle.
    const auto refused = [&](const Json& follower, const std::string& field,
                             const std::string& words) {
        project["follower"] = follower;
        const std::string file = test::writeTempFile(dir.file("arm.cam.json"), project.dump());
        for (const auto& args : {std::vector<std::string>{"state", file, "--t", "0.1"},
                                 std::vector<std::string>{"analyze", file},
                                 std::vector<std::string>{"validate", file}}) {
            const auto result = test::runCli(args);
            EXPECT_EQ(result.exitCode, 2) << args[0] << ": " << result.err;
            EXPECT_NE(result.err.find(file + ": " + field), std::string::npos) << result.err;
            EXPECT_NE(result.err.find(words), std::string::npos) << result.err;
        }
    };
    const Json arm{{"type", "roller"}, {"radius", 2.0}, {"motion", "oscillating"}};
    Json inside = arm;
    inside["pivot"] = {20.0, 15.0};  // 25 mm from the centre
    inside["arm_length"] = 10.0;
    refused(inside, "follower.pivot", "inside the cam");
    Json shortArm = arm;
    shortArm["pivot"] = {60.0, 0.0};
    shortArm["arm_length"] = 20.0;  // the roller's centre reaches 20 mm, the cam is 31 mm away
    refused(shortArm, "follower.arm_length", "too short");
    Json longArm = shortArm;
    longArm["arm_length"] = 95.0;
    refused(longArm, "follower.arm_length", "too long");
    // Nothing is refused that can ride: the same arm at 45 mm.
    Json fits = shortArm;
    fits["arm_length"] = 45.0;
    project["follower"] = fits;
    path = test::writeTempFile(dir.file("fits.cam.json"), project.dump());
    EXPECT_EQ(test::runCli({"validate", path}).exitCode, 0);
}

// analyze's curvature tells convex from concave (each a magnitude, with its angle) and checks
// them against the roller and the cutter; its pressure angle is a magnitude per phase. The
// seed's six-lobe cam has two radii (math.md §3): convex arcs of 8.10318055 mm and hollows of
// 4.84070597 mm; a 2 mm roller's pitch curve adds 2 mm to the first and takes it from the
// second.
TEST(CliAnalyze, CurvatureIsToldApartAndPressureAnglesArePerPhase) {
    const std::string path = test::dataPath("reference/followers/six-lobe-roller-offset.cam.json");
    const auto run = test::runCli({"analyze", path});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json f = Json::parse(run.out)["follower"];
    EXPECT_FALSE(f.contains("rho_profile_min"));
    EXPECT_FALSE(f.contains("rho_pitch_min"));
    const Json& c = f["curvature"];
    EXPECT_NEAR(c["profile"]["min_convex"]["value"].get<double>(), 8.10318055, 1e-7);
    EXPECT_NEAR(c["profile"]["min_concave"]["value"].get<double>(), 4.84070597, 1e-7);
    EXPECT_NEAR(c["pitch"]["min_convex"]["value"].get<double>(), 8.10318055 + 2.0, 1e-7);
    EXPECT_NEAR(c["pitch"]["min_concave"]["value"].get<double>(), 4.84070597 - 2.0, 1e-7);
    EXPECT_TRUE(c["profile"]["min_concave"].contains("phi_deg"));
    EXPECT_EQ(c["roller_radius"], 2.0);
    EXPECT_EQ(c["roller_fits"], true);
    EXPECT_FALSE(c.contains("tool_fits"));  // the project names no cutter

    const Json& p = f["pressure_angle"];
    EXPECT_TRUE(p["dwell"].is_null());  // no arc is centred on the axis: no dwell
    const double rise = p["rise"]["value_deg"], fall = p["return"]["value_deg"];
    EXPECT_GT(rise, 0.0);
    EXPECT_GT(fall, 0.0);  // a magnitude, not the most negative angle
    EXPECT_EQ(p["max"]["value_deg"].get<double>(), std::max(rise, fall));
    const double limit = p["limit_deg"];
    EXPECT_EQ(limit, 30.0);  // the translating default as written, not 29.999999999999996
    ASSERT_FALSE(p["exceeded"].empty());
    for (const Json& r : p["exceeded"]) {
        EXPECT_GT(r["peak_deg"].get<double>(), limit);
        EXPECT_NEAR(r["excess_deg"].get<double>(), r["peak_deg"].get<double>() - limit, 1e-12);
        EXPECT_GE(r["peak_phi_deg"].get<double>(), r["from_deg"].get<double>() - 1e-9);
        EXPECT_LE(r["peak_phi_deg"].get<double>(), r["to_deg"].get<double>() + 1e-9);
        EXPECT_LE(r["peak_deg"].get<double>(), p["max"]["value_deg"].get<double>() + 1e-12);
    }

    // A 5 mm cutter does not enter a 4.84 mm hollow; a 4.8 mm one does.
    Json project = Json::parse(test::readFile(path));
    for (const double tool : {5.0, 4.8}) {
        project["machining"] = {
            {"axis_accel", {500, 500, 200}}, {"feed_max", 100}, {"tool_radius", tool}};
        const std::string with =
            test::writeTestTempFile("analyze", "tool.cam.json", project.dump());
        const auto again = test::runCli({"analyze", with});
        ASSERT_EQ(again.exitCode, 0) << again.err;
        const Json cc = Json::parse(again.out)["follower"]["curvature"];
        EXPECT_EQ(cc["tool_radius"], tool);
        EXPECT_EQ(cc["tool_fits"], tool < 4.84070597) << tool;
    }
}

// Every bundled example is a cam a designer may build on: it validates, and its follower
// rides it within the project's pressure-angle limit, with no undercut and no stretch it
// cannot reach.
TEST(BundledExamples, ValidateAndPassTheirFollowerChecks) {
    int count = 0, withFollower = 0;
    for (const auto& entry : std::filesystem::directory_iterator(CAMWRIGHT_EXAMPLES)) {
        const std::string path = entry.path().string();
        if (!path.ends_with(".cam.json")) continue;
        ++count;
        const auto validate = test::runCli({"validate", path});
        EXPECT_EQ(validate.exitCode, 0) << path << "\n" << validate.out << validate.err;
        const auto analyze = test::runCli({"analyze", path});
        ASSERT_EQ(analyze.exitCode, 0) << path << "\n" << analyze.err;
        const Json report = Json::parse(analyze.out);
        // The seed's six-lobe cam names no follower: a knife by default, with the seed's steep
        // flanks (63°); the examples that name a follower are made for it.
        if (!Json::parse(test::readFile(path)).contains("follower")) continue;
        ++withFollower;
        const Json& f = report["follower"];
        EXPECT_TRUE(f["pressure_angle"]["exceeded"].empty()) << path << ": " << f["pressure_angle"];
        EXPECT_TRUE(f["undercut"].empty()) << path << ": " << f["undercut"];
    }
    EXPECT_GE(count, 5);  // the six-lobe cam, a roller, a swinging arm, a design, a spline cam
    EXPECT_GE(withFollower, 4);
}

}  // namespace
}  // namespace cam
