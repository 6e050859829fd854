// camwright-cli on a grooved cam (issue 32, cli.md): `state` gives the roller's contact with
// both flanks and `analyze` the outer flank's checks and the lands, checked on an eccentric
// disc against closed forms: its flanks are circles about the disc's centre c, of radius R and
// R + 2ρ + c_l, and a roller on a line through the rotation centre sits where that line
// crosses the circle R + ρ (pressed on the inner flank) or R + ρ + c_l (on the outer one).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "test_support.h"

namespace cam {
namespace {

using Json = nlohmann::json;

constexpr double kE = 5.0, kR = 30.0, kRho = 4.0, kClearance = 0.25;

/// The disc: a circle of radius kR about (kE, 0), run by a radial roller in a groove.
std::string grooveDisc(const test::TempDir& dir, const std::string& lands = "",
                       const std::string& more = "") {
    const std::string path = dir.file("disc.cam.json");
    std::ofstream(path) << R"({"format": "camwright", "version": 1, "name": "Grooved disc",
      "motion": {"period_s": 2},
      "contour": [{"type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                   "phi_start": 0, "phi_end": 360}],
      "follower": {"type": "roller", "radius": 4, "closure": "groove",
                   "groove_clearance_mm": 0.25)"
                        << lands << "}" << more << "}";
    return path;
}

Eigen::Vector2d vec(const Json& j) { return {j.at(0).get<double>(), j.at(1).get<double>()}; }

TEST(CliGroove, StatePlacesTheRollerOnBothFlanksWhereTheClosedFormPutsIt) {
    const test::TempDir dir;
    const std::string project = grooveDisc(dir);
    const Eigen::Vector2d c(kE, 0.0);
    for (const double t : {0.0, 0.13, 0.5, 0.77, 1.31, 1.9}) {
        SCOPED_TRACE("t=" + std::to_string(t));
        const auto run = test::runCli({"state", project, "--t", std::to_string(t)});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const Json f = Json::parse(run.out).at("follower");
        ASSERT_TRUE(f.contains("outer_flank")) << f.dump();
        const Json& o = f.at("outer_flank");
        // The line of motion through the rotation centre, as the follower's centre shows it.
        const Eigen::Vector2d centre = vec(f.at("center")), u = centre.normalized();
        const Eigen::Vector2d n(-u.y(), u.x());
        const double side = n.dot(c);
        const auto sOn = [&](double radius) {
            return u.dot(c) + std::sqrt(radius * radius - side * side);
        };
        EXPECT_NEAR(f.at("s").get<double>(), sOn(kR + kRho), 1e-9);
        EXPECT_NEAR(o.at("s").get<double>(), sOn(kR + kRho + kClearance), 1e-9);
        EXPECT_NEAR(vec(o.at("center")).dot(n), 0.0, 1e-9);  // on the same line
        // Contacts: the inner on the disc, the outer on the outer flank ρ across the roller.
        EXPECT_NEAR((vec(f.at("contact")) - c).norm(), kR, 1e-9);
        EXPECT_NEAR((vec(o.at("contact")) - c).norm(), kR + 2 * kRho + kClearance, 1e-9);
        EXPECT_NEAR((vec(o.at("contact")) - vec(o.at("center"))).norm(), kRho, 1e-9);
        // The outer flank's radius of curvature and both pressure angles: the line of force
        // runs through c, at sin α = side / (radius of the roller centre's circle).
        EXPECT_NEAR(o.at("rho_profile").get<double>(), kR + 2 * kRho + kClearance, 1e-9);
        EXPECT_NEAR(
            std::abs(std::sin(o.at("pressure_angle_deg").get<double>() * std::numbers::pi / 180)),
            std::abs(side) / (kR + kRho + kClearance), 1e-9);
        EXPECT_NEAR(
            std::abs(std::sin(f.at("pressure_angle_deg").get<double>() * std::numbers::pi / 180)),
            std::abs(side) / (kR + kRho), 1e-9);
        // Pressed outwards the follower stands c_l/cos-ish further out: its lift is measured
        // from the same zero as the inner flank's.
        EXPECT_NEAR(o.at("lift").get<double>() - f.at("lift").get<double>(),
                    o.at("s").get<double>() - f.at("s").get<double>(), 1e-12);
    }
}

TEST(CliGroove, AnalyzeGivesTheOuterFlankAndTheLandsInClosedForm) {
    const test::TempDir dir;
    const double width = 2 * kRho + kClearance;
    // The inner flank comes to R − E = 25 mm from the centre (at 180°), the outer flank
    // reaches R + w + E = 43.25 mm (at 0°).
    const auto analyze = [&](const std::string& lands) {
        const auto run = test::runCli({"analyze", grooveDisc(dir, lands)});
        EXPECT_EQ(run.exitCode, 0) << run.err;
        return Json::parse(run.out).at("follower").at("groove");
    };
    const Json g = analyze(R"(, "inner_land_radius_mm": 24, "outer_land_radius_mm": 43)");
    EXPECT_EQ(g.at("width_mm").get<double>(), width);
    EXPECT_EQ(g.at("clearance_mm").get<double>(), kClearance);
    const Json& inner = g.at("lands").at("inner");
    const Json& outer = g.at("lands").at("outer");
    EXPECT_NEAR(inner.at("radius").get<double>(), kR - kE, 1e-12);
    EXPECT_NEAR(inner.at("phi_deg").get<double>(), 180.0, 1e-9);
    EXPECT_TRUE(inner.at("kept").get<bool>());
    EXPECT_NEAR(outer.at("radius").get<double>(), kR + width + kE, 1e-12);
    EXPECT_NEAR(std::remainder(outer.at("phi_deg").get<double>(), 360.0), 0.0, 1e-9);
    EXPECT_FALSE(outer.at("kept").get<bool>());  // 43.25 > 43
    EXPECT_EQ(outer.at("land_radius").get<double>(), 43.0);
    // The outer flank is the circle R + w everywhere; a disc has no hollow.
    const Json& curvature = g.at("outer_flank").at("curvature");
    EXPECT_NEAR(curvature.at("min_convex").at("value").get<double>(), kR + width, 1e-9);
    EXPECT_TRUE(curvature.at("min_concave").is_null());
    // Without land radii nothing is checked against them.
    const Json free = analyze("");
    EXPECT_TRUE(free.at("lands").at("inner").at("land_radius").is_null());
    EXPECT_TRUE(free.at("lands").at("outer").at("kept").get<bool>());
}

TEST(CliGroove, ASpringClosedCamHasNoOuterFlank) {
    const auto run =
        test::runCli({"state", test::examplePath("six-lobe-arc-cam.cam.json"), "--t", "0.1"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(Json::parse(run.out).at("follower").contains("outer_flank"));
}

TEST(CliGroove, AnalyzeNamesTheCrossoversWhereTheLoadTurnsNegative) {
    // Inertia alone: the load m·s''·ω² is negative where s'' is, s(φ) = E·cos φ +
    // √((R + ρ)² − E²·sin² φ) on the radial line at φ. Its zeros, by bisection here, are the
    // crossovers; a groove has no jump speed and needs no preload.
    const test::TempDir dir;
    const auto run =
        test::runCli({"analyze", grooveDisc(dir, "", R"(, "dynamics": {"mass_kg": 0.5})")});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json f = Json::parse(run.out).at("forces");
    EXPECT_TRUE(f.at("jump_speed_rpm").is_null());
    EXPECT_TRUE(f.at("min_preload_N").is_null());
    EXPECT_FALSE(f.contains("lift_off_deg"));
    const auto s = [](double phi) {
        const double k = kR + kRho;
        return kE * std::cos(phi) + std::sqrt(k * k - kE * kE * std::sin(phi) * std::sin(phi));
    };
    const auto s2 = [&](double phi) {
        const double h = 1e-3;
        return (-s(phi - 2 * h) + 16 * s(phi - h) - 30 * s(phi) + 16 * s(phi + h) -
                s(phi + 2 * h)) /
               (12 * h * h);
    };
    const auto root = [&](double a, double b) {
        const bool negativeAtA = s2(a) < 0;
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + b);
            ((s2(m) < 0) == negativeAtA ? a : b) = m;
        }
        return 0.5 * (a + b) * 180 / std::numbers::pi;
    };
    // s'' < 0 round φ = 0 (the disc's far side under the roller), > 0 round 180°.
    ASSERT_LT(s2(0.0), 0.0);
    ASSERT_GT(s2(std::numbers::pi), 0.0);
    const double back = root(0.0, std::numbers::pi);                   // turns positive
    const double into = root(std::numbers::pi, 2 * std::numbers::pi);  // turns negative
    const Json& crossovers = f.at("crossovers");
    ASSERT_EQ(crossovers.size(), 1u) << f.dump();
    const auto sameAngle = [](double a, double b) {
        return std::abs(std::remainder(a - b, 360.0)) < 1e-6;
    };
    // The turn's direction decides which end comes first: both are the closed form's zeros.
    const double to = crossovers[0].at("to_outer_deg"), from = crossovers[0].at("to_inner_deg");
    EXPECT_TRUE(sameAngle(to, into) || sameAngle(to, back)) << to;
    EXPECT_TRUE(sameAngle(from, into) || sameAngle(from, back)) << from;
    EXPECT_FALSE(sameAngle(to, from));
    EXPECT_TRUE(f.at("outer_flank").at("max_normal_N").get<double>() > 0.0);
}

TEST(CliGroove, SynthesizeBuildsAGroovedCamFromADesign) {
    // The bundled cycloidal design (base radius 40 mm, lift 10 mm) with its roller (8 mm) in a
    // groove: synthesize fits the inner flank; the groove follows. At the top dwell the inner
    // flank is the circle 40 + 10 and the outer flank reaches 2ρ + c beyond it.
    const test::TempDir dir;
    Json project =
        Json::parse(test::readFile(test::examplePath("synthesised-cycloidal-roller.cam.json")));
    project["contour"] = Json::array();
    project["follower"]["closure"] = "groove";
    project["follower"]["groove_clearance_mm"] = 0.1;
    const std::string in = dir.file("design.cam.json"), out = dir.file("grooved.cam.json");
    std::ofstream(in) << project.dump(1);
    const auto made = test::runCli({"synthesize", in, "--out", out});
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const Json written = Json::parse(test::readFile(out));
    EXPECT_EQ(written.at("follower").at("closure"), "groove");
    EXPECT_EQ(written.at("follower").at("groove_clearance_mm"), 0.1);
    EXPECT_GT(written.at("contour").size(), 10u);
    const auto analyzed = test::runCli({"analyze", out});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json lands = Json::parse(analyzed.out).at("follower").at("groove").at("lands");
    const double tolerance = project.at("design").at("tolerance");
    EXPECT_NEAR(lands.at("outer").at("radius").get<double>(), 40.0 + 10.0 + 2 * 8.0 + 0.1,
                tolerance);
    EXPECT_NEAR(lands.at("inner").at("radius").get<double>(), 40.0, tolerance);
    // And its groove is milled.
    const std::string ngc = dir.file("grooved.ngc");
    ASSERT_EQ(test::runCli({"export", out, "--format", "gcode", "--out", ngc}).exitCode, 0);
    EXPECT_NE(test::readFile(ngc).find("one slot pass on the groove's centre line"),
              std::string::npos);
}

// A conjugate yoke on the same disc, its line offset by e = 3 mm: the second roller (5 mm) 80
// mm behind the first, at (s − D)·u + e·n with s = u·c + √((R + ρ)² − (e − n·c)²).
std::string conjugateDisc(const test::TempDir& dir) {
    const std::string path = dir.file("conjugate.cam.json");
    std::ofstream(path) << R"({"format": "camwright", "version": 1, "name": "Conjugate disc",
      "motion": {"period_s": 2},
      "contour": [{"type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                   "phi_start": 0, "phi_end": 360}],
      "follower": {"type": "roller", "radius": 4, "offset": 3, "closure": "conjugate",
                   "conjugate_distance_mm": 80, "conjugate_radius_mm": 5}})";
    return path;
}

Eigen::Vector2d secondCentre(const Eigen::Vector2d& u) {
    const Eigen::Vector2d n(-u.y(), u.x()), c(kE, 0.0);
    const double e = 3.0, side = e - n.dot(c);
    const double s = u.dot(c) + std::sqrt((kR + kRho) * (kR + kRho) - side * side);
    return (s - 80.0) * u + e * n;
}

TEST(CliConjugate, StateAnalyzeAndTheDxfHoldTheSecondRollerWhereTheClosedFormPutsIt) {
    const test::TempDir dir;
    const std::string project = conjugateDisc(dir);
    // state: the second roller's centre, ρ₂ from its contact.
    for (const double t : {0.0, 0.37, 1.21}) {
        const auto run = test::runCli({"state", project, "--t", std::to_string(t)});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const Json f = Json::parse(run.out).at("follower");
        const Eigen::Vector2d first = vec(f.at("center"));
        // The cam angle is found from the first roller's centre by brute force over the closed
        // form (every 1e-3°: the second centre, 80 mm on, is then known to 1e-3 mm).
        double best = 1e300;
        Eigen::Vector2d expected = Eigen::Vector2d::Zero();
        for (int k = 0; k < 360000; ++k) {
            const double phi = 2 * std::numbers::pi * k / 360000;
            const Eigen::Vector2d u(std::cos(phi), std::sin(phi));
            const Eigen::Vector2d candidate = secondCentre(u) + 80.0 * u;  // the first's
            if ((candidate - first).norm() < best) {
                best = (candidate - first).norm();
                expected = secondCentre(u);
            }
        }
        EXPECT_LT(best, 1e-3);
        const Json& second = f.at("second_roller");
        EXPECT_NEAR((vec(second.at("center")) - expected).norm(), 0.0, 1e-3);
        EXPECT_NEAR((vec(second.at("center")) - vec(second.at("contact"))).norm(), 5.0, 1e-9);
    }
    // analyze: the play the fitted plate leaves, within the 0.001 mm it was fitted to.
    const auto analyzed = test::runCli({"analyze", project});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json c = Json::parse(analyzed.out).at("follower").at("conjugate");
    EXPECT_EQ(c.at("tolerance_mm").get<double>(), 1e-3);
    EXPECT_LE(c.at("max_play_mm").get<double>(), 1e-3);
    EXPECT_GE(c.at("min_play_mm").get<double>(), -1e-3);
    // The second plate's largest pressure angle, from the closed-form centre path's tangent
    // (central differences): the contact normal is that tangent turned clockwise, from −u.
    double largest = 0.0;
    for (int k = 0; k < 36000; ++k) {
        const double phi = 2 * std::numbers::pi * k / 36000, h = 1e-5;
        const Eigen::Vector2d u(std::cos(phi), std::sin(phi));
        const Eigen::Vector2d t = (secondCentre({std::cos(phi + h), std::sin(phi + h)}) -
                                   secondCentre({std::cos(phi - h), std::sin(phi - h)}))
                                      .normalized();
        const Eigen::Vector2d normal(t.y(), -t.x()), towards = -u;
        const double a =
            std::atan2(towards.x() * normal.y() - towards.y() * normal.x(), towards.dot(normal));
        if (std::abs(a) > std::abs(largest)) largest = a;
    }
    EXPECT_NEAR(c.at("pressure_angle").at("max").at("value_deg").get<double>(),
                largest * 180 / std::numbers::pi, 1e-4);
    // A disc's second plate is convex all round.
    EXPECT_TRUE(c.at("curvature").at("min_concave").is_null());
    EXPECT_GT(c.at("curvature").at("min_convex").at("value").get<double>(), 0.0);
    // The DXF: the first plate on PLATE_1, the second's arcs on PLATE_2, read by ezdxf; every
    // closed-form centre of the second roller lies 5 mm from them to the tolerance.
    const std::string dxf = dir.file("pair.dxf");
    ASSERT_EQ(test::runCli({"export", project, "--format", "dxf", "--out", dxf}).exitCode, 0);
    const auto read = test::run(
        "/usr/bin/python3",
        {"-c",
         "import ezdxf, json, sys\n"
         "doc = ezdxf.readfile(sys.argv[1])\n"
         "assert not doc.audit().errors\n"
         "print(json.dumps({'plate1': len([e for e in doc.modelspace() if e.dxf.layer == "
         "'PLATE_1']), 'arcs': [[e.dxf.center.x, e.dxf.center.y, e.dxf.radius, "
         "e.dxf.start_angle, e.dxf.end_angle] for e in doc.modelspace() if e.dxf.layer == "
         "'PLATE_2' and e.dxftype() == 'ARC']}))\n",
         dxf},
        120);
    ASSERT_EQ(read.exitCode, 0) << read.err;
    const Json layers = Json::parse(read.out);
    EXPECT_EQ(layers.at("plate1").get<int>(), 1);
    const Json& arcs = layers.at("arcs");
    ASSERT_GT(arcs.size(), 4u);
    double worst = 0.0;
    for (int k = 0; k < 7200; ++k) {
        const double phi = 2 * std::numbers::pi * k / 7200;
        const Eigen::Vector2d q = secondCentre({std::cos(phi), std::sin(phi)});
        double d = 1e300;
        for (const Json& a : arcs) {
            const Eigen::Vector2d centre(a[0].get<double>(), a[1].get<double>());
            const double radius = a[2], from = a[3].get<double>() * std::numbers::pi / 180,
                         to = a[4].get<double>() * std::numbers::pi / 180;
            const Eigen::Vector2d w = q - centre;
            const double along =
                std::remainder(std::atan2(w.y(), w.x()) - from, 2 * std::numbers::pi);
            const double span = std::remainder(to - from - 1e-12, 2 * std::numbers::pi);
            const double a0 = along < 0 ? along + 2 * std::numbers::pi : along;
            const double s0 = span <= 0 ? span + 2 * std::numbers::pi : span;
            if (a0 <= s0) d = std::min(d, std::abs(w.norm() - radius));
        }
        worst = std::max(worst, std::abs(d - 5.0));
    }
    EXPECT_LE(worst, 1e-3 + 1e-9);
    // The SVG draws the second plate as its own path: read by svgelements (y up drawn up, so
    // negated), its points lie 5 mm from the closed-form path of the second roller's centre.
    const std::string svg = dir.file("pair.svg");
    ASSERT_EQ(test::runCli({"export", project, "--format", "svg", "--out", svg}).exitCode, 0);
    const auto points = test::run(
        "/usr/bin/python3",
        {"-c",
         "import json, sys, svgelements\n"
         "doc = svgelements.SVG.parse(sys.argv[1], reify=False)\n"
         "plate = [e for e in doc.elements() if e.values.get('id') == 'second-plate']\n"
         "assert len(plate) == 1\n"
         "path = plate[0]\n"
         "print(json.dumps([[p.x, -p.y] for p in (path.point(i / 3000) for i in range(3000))]))\n",
         svg},
        120);
    ASSERT_EQ(points.exitCode, 0) << points.err;
    std::vector<Eigen::Vector2d> path;
    for (int k = 0; k < 36000; ++k) {
        const double phi = 2 * std::numbers::pi * k / 36000;
        path.push_back(secondCentre({std::cos(phi), std::sin(phi)}));
    }
    double svgWorst = 0.0;
    for (const Json& p : Json::parse(points.out)) {
        const Eigen::Vector2d q(p[0].get<double>(), p[1].get<double>());
        double d = 1e300;
        for (const Eigen::Vector2d& c : path) d = std::min(d, (q - c).squaredNorm());
        svgWorst = std::max(svgWorst, std::abs(std::sqrt(d) - 5.0));
    }
    // The fit's 0.001 mm and the closed form's samples, 0.01° apart at 55 mm (≤ 1e-5 mm).
    EXPECT_LE(svgWorst, 1e-3 + 1e-5);
}

TEST(CliConjugate, WithDynamicsTheSecondRollerTakesTheLoadOverWhereItTurnsNegative) {
    // The same yoke driven by inertia alone: the load m·s''·ω² is negative where s'' is, and
    // no spring is needed — no lift-off, jump speed or preload, but the second roller's share.
    const test::TempDir dir;
    std::string text = test::readFile(conjugateDisc(dir));
    text.replace(text.rfind('}'), 1,
                 R"(, "dynamics": {"mass_kg": 0.5, "contact_width_mm": 10,
                    "cam_material": {"E_MPa": 210000, "poisson": 0.3},
                    "follower_material": {"E_MPa": 210000, "poisson": 0.3}}})");
    const std::string path = dir.file("conjugate-dynamics.cam.json");
    std::ofstream(path) << text;
    const auto run = test::runCli({"analyze", path});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Json f = Json::parse(run.out).at("forces");
    EXPECT_TRUE(f.at("jump_speed_rpm").is_null());
    EXPECT_TRUE(f.at("min_preload_N").is_null());
    EXPECT_FALSE(f.contains("lift_off_deg"));
    ASSERT_EQ(f.at("crossovers").size(), 1u);
    const Json& crossing = f.at("crossovers")[0];
    // Where s'' of the closed form changes sign (central differences, bisected).
    const auto s = [](double phi) {
        const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x()), c(kE, 0.0);
        const double side = 3.0 - n.dot(c);
        return u.dot(c) + std::sqrt((kR + kRho) * (kR + kRho) - side * side);
    };
    const auto s2 = [&](double phi) {
        const double h = 1e-3;
        return (-s(phi - 2 * h) + 16 * s(phi - h) - 30 * s(phi) + 16 * s(phi + h) -
                s(phi + 2 * h)) /
               (12 * h * h);
    };
    for (const char* key : {"to_second_deg", "to_first_deg"}) {
        double phi = crossing.at(key).get<double>() * std::numbers::pi / 180;
        // Refined on the closed form from the reported angle: within 1e-6° of it.
        double a = phi - 1e-3, b = phi + 1e-3;
        ASSERT_NE(s2(a) < 0, s2(b) < 0) << key;
        const bool negativeAtA = s2(a) < 0;
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + b);
            ((s2(m) < 0) == negativeAtA ? a : b) = m;
        }
        EXPECT_NEAR(phi, 0.5 * (a + b), 1e-6 * std::numbers::pi / 180) << key;
        // Into the second roller the load turns negative; back, positive.
        EXPECT_EQ(negativeAtA, std::string(key) == "to_first_deg") << key;
    }
    EXPECT_EQ(f.at("second_roller_carries_deg").size(), 1u);
    EXPECT_GT(f.at("second_roller").at("max_normal_N").get<double>(), 0.0);
    EXPECT_GT(f.at("second_roller").at("max_contact_stress_MPa").get<double>(), 0.0);
}

TEST(CliConjugate, SynthesizeReportsTheSecondPlateOfTheNewFirstOne) {
    // The bundled cycloidal design (base radius 40 mm, lift 10 mm, an 8 mm roller) as a
    // conjugate pair: synthesize fits the first plate and reports the second's play, within
    // the design's tolerance; too short a yoke is a note, and the project is written anyway.
    const test::TempDir dir;
    Json project =
        Json::parse(test::readFile(test::examplePath("synthesised-cycloidal-roller.cam.json")));
    project["contour"] = Json::array();
    project["follower"]["closure"] = "conjugate";
    project["follower"]["conjugate_distance_mm"] = 150;
    project["follower"]["conjugate_radius_mm"] = 8;
    const std::string in = dir.file("design.cam.json"), out = dir.file("pair.cam.json");
    std::ofstream(in) << project.dump(1);
    const auto made = test::runCli({"synthesize", in, "--out", out});
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const Json report = Json::parse(made.out);
    const double tolerance = project.at("design").at("tolerance");
    const Json& second = report.at("second_plate");
    EXPECT_GT(second.at("plate_arcs").get<int>(), 4);
    EXPECT_LE(second.at("max_play_mm").get<double>(), tolerance);
    EXPECT_GE(second.at("min_play_mm").get<double>(), -tolerance);
    // The same figures as analyze gives the written project.
    const auto analyzed = test::runCli({"analyze", out});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json c = Json::parse(analyzed.out).at("follower").at("conjugate");
    EXPECT_EQ(c.at("max_play_mm"), second.at("max_play_mm"));

    project["follower"]["conjugate_distance_mm"] = 40;  // the roller reaches 58 mm
    std::ofstream(in) << project.dump(1);
    const auto short_ = test::runCli({"synthesize", in, "--out", out});
    ASSERT_EQ(short_.exitCode, 0) << short_.err;
    const Json shortReport = Json::parse(short_.out);
    EXPECT_TRUE(shortReport.at("second_plate").is_null());
    bool noted = false;
    for (const Json& note : shortReport.at("notes")) {
        noted |= note.get<std::string>().find("no second plate: follower.conjugate_distance_mm") !=
                 std::string::npos;
    }
    EXPECT_TRUE(noted) << shortReport.dump(1);
}

TEST(CliConjugate, ABellCrankCarriesItsSecondRollerRigidlyOnThePivot) {
    // A swinging roller (pivot (70, 0), arm 60 mm) with a second arm of 60 mm at −48°: at every
    // instant the second roller's centre is 60 mm from the pivot (turned with the cam to
    // R(φ)·(70, 0)) and 2·60·sin 24° from the first roller's — the crank is rigid; the fitted
    // plate holds it within the tolerance; the second plate is milled, and rs274 accepts it.
    const test::TempDir dir;
    const std::string path = dir.file("crank.cam.json");
    std::ofstream(path) << R"({"format": "camwright", "version": 1, "name": "Bell crank",
      "motion": {"period_s": 2},
      "contour": [{"type": "arc", "center": [6, -2], "radius": 25, "branch": "outer",
                   "phi_start": 0, "phi_end": 360}],
      "follower": {"type": "roller", "radius": 4, "motion": "oscillating", "pivot": [70, 0],
                   "arm_length": 60, "closure": "conjugate", "conjugate_angle_deg": -48,
                   "conjugate_arm_length_mm": 60, "conjugate_radius_mm": 5}})";
    for (const double t : {0.0, 0.3, 1.45}) {
        const auto run = test::runCli({"state", path, "--t", std::to_string(t)});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const Json state = Json::parse(run.out);
        const double phi = state.at("phi_deg").get<double>() * std::numbers::pi / 180;
        const Eigen::Vector2d pivot = 70.0 * Eigen::Vector2d(std::cos(phi), std::sin(phi));
        const Json& f = state.at("follower");
        const Eigen::Vector2d first = vec(f.at("center"));
        const Eigen::Vector2d second = vec(f.at("second_roller").at("center"));
        EXPECT_NEAR((first - pivot).norm(), 60.0, 1e-9) << t;
        EXPECT_NEAR((second - pivot).norm(), 60.0, 1e-9) << t;
        EXPECT_NEAR((second - first).norm(), 2 * 60.0 * std::sin(24.0 * std::numbers::pi / 180),
                    1e-9)
            << t;
        // Turned clockwise (−48°) from the first arm about the pivot.
        const Eigen::Vector2d a = first - pivot, b = second - pivot;
        EXPECT_NEAR(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)),
                    -48.0 * std::numbers::pi / 180, 1e-9);
    }
    const auto analyzed = test::runCli({"analyze", path});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
    const Json c = Json::parse(analyzed.out).at("follower").at("conjugate");
    EXPECT_EQ(c.at("angle_deg").get<double>(), -48.0);
    EXPECT_EQ(c.at("arm_length_mm").get<double>(), 60.0);
    EXPECT_FALSE(c.contains("distance_mm"));
    EXPECT_LE(c.at("max_play_mm").get<double>(), 1e-3);
    EXPECT_GE(c.at("min_play_mm").get<double>(), -1e-3);
    const std::string ngc = dir.file("crank-2.ngc");
    ASSERT_EQ(test::runCli({"export", path, "--format", "gcode", "--plate", "2", "--tool-radius",
                            "3", "--out", ngc})
                  .exitCode,
              0);
    const auto accepted = test::run(test::kRs274, {ngc, dir.file("canon.txt")}, 120);
    EXPECT_EQ(accepted.exitCode, 0) << accepted.err;
}

}  // namespace
}  // namespace cam
