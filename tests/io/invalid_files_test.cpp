// Every malformed file in tests/data/invalid/cases.json is refused with a message that names
// where the problem is, on loading or by the one evaluation; none crashes. Every valid
// reference cam is accepted.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "evaluation/evaluation.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

TEST(InvalidFiles, EachIsRefusedWithItsLocation) {
    const auto manifest =
        nlohmann::json::parse(test::readFile(test::dataPath("invalid/cases.json")));
    ASSERT_GE(manifest.size(), 40u);
    for (const auto& c : manifest) {
        const std::string file = c.at("file");
        const std::string location = c.at("location");
        SCOPED_TRACE(file + " (" + c.at("rule").get<std::string>() + ")");
        // Refused on loading, or — what needs the compiled contour and the follower on it (a
        // conjugate yoke too short) — by the one evaluation.
        const auto p = loadProjectFile(test::dataPath("invalid/" + file));
        const Diagnostics problems = p.ok() ? evaluateProject(p.value()).problems : p.errors();
        ASSERT_TRUE(hasErrors(problems));
        bool found = false;
        std::string all;
        for (const Diagnostic& d : problems) {
            found = found || d.text().find(location) != std::string::npos;
            all += "\n  " + d.text();
        }
        EXPECT_TRUE(found) << "expected a message at '" << location << "', got:" << all;
    }
}

TEST(ValidFiles, ReferenceCamsAndExamplesLoad) {
    namespace fs = std::filesystem;
    int count = 0;
    for (const auto& dir : {test::dataPath("reference"), std::string(CAMWRIGHT_EXAMPLES)}) {
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string path = entry.path().string();
            if (!path.ends_with(".cam.json")) continue;
            const auto p = loadProjectFile(path);
            EXPECT_TRUE(p.ok()) << path << ": " << (p.ok() ? "" : p.errors().front().text());
            ++count;
        }
    }
    EXPECT_GE(count, 7);
}

TEST(ValidFiles, TheCorpusControlsLoad) {
    for (const char* name : {"valid-base.cam.json", "valid-bom.cam.json", "valid-design.cam.json",
                             "valid-dynamics.cam.json"}) {
        const auto p = loadProjectFile(test::dataPath(std::string("invalid/") + name));
        EXPECT_TRUE(p.ok()) << name << ": " << (p.ok() ? "" : p.errors().front().text());
    }
    const auto design = loadProjectFile(test::dataPath("invalid/valid-design.cam.json"));
    ASSERT_TRUE(design.ok());
    ASSERT_TRUE(design.value().design);
    EXPECT_EQ(design.value().design->segments[2].law, MotionLawType::Poly5);
    const auto dynamics = loadProjectFile(test::dataPath("invalid/valid-dynamics.cam.json"));
    ASSERT_TRUE(dynamics.ok());
    ASSERT_TRUE(dynamics.value().dynamics);
}

}  // namespace
}  // namespace cam
