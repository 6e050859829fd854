// One verdict: camwright-cli validate, the window's compute engine and its document judge every
// project of a corpus (the examples, every structurally sound file of tests/data/invalid, and
// followers that cannot ride their cam) alike: the same verdict and the same problems.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "app_test_support.h"
#include "document/project_document.h"
#include "engine/compute_result.h"
#include "io/project_json.h"

namespace cam {
namespace {

struct VerdictCase {
    std::string name;
    std::string path;
};

/// A copy of the swinging-arm example with its follower's fields replaced, as a temporary file.
std::string swingingArmWith(const std::string& name, const nlohmann::json& follower) {
    auto json =
        nlohmann::json::parse(test::readFile(test::examplePath("swinging-arm-cam.cam.json")));
    json["follower"].update(follower);
    return test::writeTempFile(name, json.dump(2));
}

std::vector<VerdictCase> verdictCorpus() {
    std::vector<VerdictCase> cases;
    for (const auto& entry : std::filesystem::directory_iterator(CAMWRIGHT_EXAMPLES)) {
        cases.push_back({entry.path().filename().string(), entry.path().string()});
    }
    for (const auto& entry : std::filesystem::directory_iterator(test::dataPath("invalid"))) {
        if (entry.path().string().ends_with(".cam.json")) {
            cases.push_back({entry.path().filename().string(), entry.path().string()});
        }
    }
    // The case the two used to disagree on: the CLI refused these, the window drew and
    // exported them. A follower that cannot ride its cam makes the project invalid.
    cases.push_back({"pivot inside the cam",
                     swingingArmWith("verdict-pivot-inside.cam.json", {{"pivot", {10.0, 0.0}}})});
    cases.push_back({"arm that cannot reach the cam",
                     swingingArmWith("verdict-arm-short.cam.json", {{"pivot", {300.0, 0.0}}})});
    auto design = nlohmann::json::parse(
        test::readFile(test::examplePath("synthesised-cycloidal-roller.cam.json")));
    design["contour"] = nlohmann::json::array();
    cases.push_back({"a design awaiting its contour",
                     test::writeTempFile("verdict-awaits.cam.json", design.dump(2))});
    design["design"]["base_radius"] = -1.0;
    cases.push_back({"a design with a problem and no contour",
                     test::writeTempFile("verdict-design-problem.cam.json", design.dump(2))});
    std::sort(cases.begin(), cases.end(),
              [](const VerdictCase& a, const VerdictCase& b) { return a.name < b.name; });
    return cases;
}

/// The CLI's verdict, as `validate` prints it: "computed", "awaits contour" or "invalid".
std::string cliVerdict(const test::RunResult& run) {
    if (run.exitCode == 2) return "invalid";
    if (run.exitCode == 0 && run.out.starts_with("valid: a design, no contour yet")) {
        return "awaits contour";
    }
    if (run.exitCode == 0 && run.out.starts_with("valid: ")) return "computed";
    return "exit " + std::to_string(run.exitCode) + ": " + run.out + run.err;
}

/// The lines `validate` prints for these problems (errors only: notes are not problems).
std::string cliLines(const std::string& path, const Diagnostics& problems) {
    std::string lines;
    for (const Diagnostic& d : problems) {
        if (d.severity != Severity::Error) continue;
        lines += "camwright-cli: " + path + ": " + d.location + ": " + d.message + '\n';
    }
    return lines;
}

TEST(OneVerdict, TheCliTheEngineAndTheDocumentAgreeOnEveryProject) {
    std::map<std::string, int> verdicts;
    // Counted so that agreement is not agreement on nothing.
    int followerCannotRide = 0;
    for (const VerdictCase& c : verdictCorpus()) {
        SCOPED_TRACE(c.name);
        const test::RunResult cli = test::runCli({"validate", c.path});
        auto loaded = loadProjectStructure(c.path);
        if (!loaded.ok()) {
            // A file the window cannot open either: no engine or document ever sees it.
            EXPECT_EQ(cli.exitCode, 2);
            ++verdicts["unreadable"];
            continue;
        }
        ComputeRequest request;
        request.project = std::make_shared<const Project>(loaded.value());
        std::atomic<bool> cancel{false};
        const ComputeResultPtr result = computeProject(request, cancel);
        ASSERT_TRUE(result);
        const std::string engine = evaluationStatusName(result->status);
        EXPECT_EQ(cliVerdict(cli), engine) << cli.err;
        EXPECT_EQ(cli.err, cliLines(c.path, result->problems));
        ++verdicts[engine];
        // The document lists the same problems and so refuses the same exports.
        ProjectDocument document;
        document.reset(loaded.value(), {});
        ASSERT_EQ(document.diagnostics().size(), result->problems.size());
        for (std::size_t k = 0; k < result->problems.size(); ++k) {
            EXPECT_EQ(document.diagnostics()[k].location, result->problems[k].location);
            EXPECT_EQ(document.diagnostics()[k].message, result->problems[k].message);
        }
        EXPECT_EQ(document.isValid(), result->status != EvaluationStatus::Invalid);
        if (result->status == EvaluationStatus::Invalid && result->contour) {
            ++followerCannotRide;  // or an open joint: drawn, but invalid
        }
    }
    for (const auto& [verdict, count] : verdicts) std::cout << verdict << ": " << count << '\n';
    EXPECT_GE(verdicts["computed"], 5);
    EXPECT_GE(verdicts["awaits contour"], 1);
    EXPECT_GE(verdicts["invalid"], 35);
    EXPECT_GE(verdicts["unreadable"], 5);
    EXPECT_GE(followerCannotRide, 4);
}

TEST(OneVerdict, AFollowerThatCannotRideTheCamIsAProblemEverywhere) {
    const std::string path =
        swingingArmWith("verdict-pivot-inside-2.cam.json", {{"pivot", {10.0, 0.0}}});
    Project project = loadProjectStructure(path).value();
    ComputeRequest request;
    request.project = std::make_shared<const Project>(project);
    std::atomic<bool> cancel{false};
    const ComputeResultPtr result = computeProject(request, cancel);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->status, EvaluationStatus::Invalid);
    ASSERT_FALSE(result->problems.empty());
    EXPECT_EQ(result->problems.front().location, "follower.pivot");
    // Still drawn while the designer edits: the contour is computed, the follower is not.
    EXPECT_TRUE(result->ok());
    EXPECT_FALSE(result->follower);
    EXPECT_FALSE(result->followerErrors.empty());
    ProjectDocument document;
    document.reset(project, {});
    EXPECT_FALSE(document.isValid());
    const std::string out =
        (std::filesystem::temp_directory_path() / "verdict-refused.dxf").string();
    std::filesystem::remove(out);
    const test::RunResult cli = test::runCli({"export", path, "--format", "dxf", "--out", out});
    EXPECT_EQ(cli.exitCode, 2) << cli.err;
    EXPECT_NE(cli.err.find("follower.pivot"), std::string::npos) << cli.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace cam
