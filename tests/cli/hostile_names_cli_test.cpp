// Issue 27: a project's name is free text, and every export that carries it must stay valid in
// the program that reads it, whatever the name holds. Each name of the hostile-name corpus
// (tests/hostile_names.h) goes into the six-lobe example; camwright-cli writes the cam table
// (CSV and CODESYS), the SVG drawing and the G-code program; tests/reference/check_free_text.py
// reads them with expat and rsvg-convert, Python's csv, the IEC 61131-3 identifier rule and
// keyword list, and LinuxCNC's rs274 where it is at hand.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "hostile_names.h"
#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;

/// The six-lobe example named `name`, written to `path`.
void writeNamed(const std::string& path, const std::string& name) {
    nlohmann::json project = nlohmann::json::parse(test::readFile(test::kExample));
    project["name"] = name;
    // The name holds anything but invalid UTF-8, which JSON cannot carry.
    test::writeText(path, project.dump(2));
}

/// "07": file names in the corpus's order.
/// (Appended: GCC 12 warns falsely on "literal" + string, PR105651.)
std::string twoDigits(std::size_t i) {
    std::string digits = i < 10 ? "0" : "";
    return digits.append(std::to_string(i));
}

TEST(HostileNames, EveryExportCarryingTheNameStaysValidForItsReader) {
    const test::TempDir dir;
    const fs::path out = dir.path() / "out";
    fs::create_directory(out);
    const auto names = test::hostileNames();
    ASSERT_EQ(names.size(), 29u);
    for (std::size_t i = 0; i < names.size(); ++i) {
        SCOPED_TRACE(names[i].kind);
        const std::string project = dir.file(twoDigits(i) + ".cam.json");
        writeNamed(project, names[i].text);
        const std::string stem = (out / twoDigits(i)).string();
        const std::vector<std::vector<std::string>> exports{
            {"--format", "camtable", "--dialect", "csv", "--out", stem + ".camtable.csv"},
            {"--format", "camtable", "--dialect", "codesys", "--out", stem + ".codesys.st"},
            {"--format", "camtable", "--dialect", "beckhoff", "--out", stem + ".beckhoff.st"},
            {"--format", "camtable", "--dialect", "rockwell", "--out", stem + ".rockwell.st"},
            {"--format", "camtable", "--dialect", "kollmorgen", "--out", stem + ".kollmorgen.csv"},
            {"--format", "svg", "--out", stem + ".drawing.svg"},
            {"--format", "gcode", "--tool-radius", "3", "--out", stem + ".program.ngc"},
        };
        for (const auto& options : exports) {
            std::vector<std::string> args{"export", project};
            args.insert(args.end(), options.begin(), options.end());
            const auto r = test::runCli(args);
            EXPECT_EQ(r.exitCode, 0) << options[1] << ": " << r.err;
        }
    }
    EXPECT_TRUE(test::exportsAreValid(out.string(), 7 * names.size()));
}

TEST(HostileNames, TheCheckerRefusesWhatTheProbeFound) {
    // The checker itself must be able to fail: the files the probe's names produced before
    // issue 27 (written by hand here), each refused for its reason.
    const test::TempDir dir;
    const std::string table =
        "# camwright cam table of cam\n=1+1,x: master angle -> follower lift s(phi) - min s\n"
        "# master_start_deg=0\n# master_step_deg=1\n# points=1\n# periodic=true\n"
        "# slave=lift_mm\nmaster_deg,position,velocity_per_deg,acceleration_per_deg2\n0,1,0,0\n";
    test::writeText(dir.file("injected.csv"), table);
    test::writeText(dir.file("title.svg"),
                    "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\">"
                    "<title>Cams & Co</title></svg>\n");
    test::writeText(dir.file("keyword.st"),
                    "(* Camwright electronic cam: END_VAR *)\nVAR_GLOBAL\n"
                    "    END_VAR_knots : ARRAY[0..1] OF SMC_CAMXYVA := [\n"
                    "        (dX := 0.0, dY := 1.0, dV := 0.0, dA := 0.0)\n    ];\n"
                    "    END_VAR : MC_CAM_REF := (xStart := 0.0, xEnd := 360.0, byType := 3, "
                    "byVarType := 6,\n        nElements := 2, nTappets := 0, "
                    "pce := ADR(END_VAR_knots));\nEND_VAR\n");
    test::writeText(dir.file("comment.ngc"), "%\n(Camwright G-code: a (b) c)\nG21\nM30\n%\n");
    const auto r = test::run("/usr/bin/python3",
                             {test::freeTextChecker(), dir.path().string(), "--points", "1"});
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_TRUE(test::contains(r.out, "injected.csv: the first 6 lines are not all comments"))
        << r.out;
    EXPECT_TRUE(test::contains(r.out, "title.svg: expat refuses it")) << r.out;
    EXPECT_TRUE(test::contains(r.out, "keyword.st: 'END_VAR' is a reserved word")) << r.out;
    EXPECT_TRUE(test::contains(r.out, "comment.ngc: line 2: '(' inside a comment")) << r.out;
}

}  // namespace
}  // namespace cam
