// Big and non-file inputs to the core's loading (issue 9, #7): a million segments load in
// seconds, and readTextFile refuses what is too large or not a file before reading it, saying
// its size or what it is. Big inputs are generated here; tests/bench/load_bench.cpp measures.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "big_projects.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

TEST(BigProjects, AMillionSegmentsAreReadAndValidatedInSeconds) {
    // 612d090 took 2 min 53 s for a million segments (160,000: 10 s): quadratic. About 5 s now
    // for the parse, the reading and every check; the bound only tells seconds from minutes.
    const std::size_t n = test::kSanitized ? 50'000 : 1'000'000;
    const std::string text = test::projectOfLines(n);
    const auto start = std::chrono::steady_clock::now();
    const auto project = parseProject(text);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    ASSERT_TRUE(project.ok()) << project.errors().front().location << ": "
                              << project.errors().front().message;
    ASSERT_EQ(project.value().contour.size(), n);
    // The last side ends where the first begins, one turn later.
    EXPECT_NEAR(project.value().contour.front().phiStartDeg, 0.0, 1e-9);
    EXPECT_NEAR(project.value().contour.back().phiEndDeg, 360.0, 1e-9);
    EXPECT_LT(took.count(), test::kSanitized ? 90.0 : 60.0);
}

TEST(BigProjects, EveryEmptySegmentIsOneProblemInOrder) {
    const std::size_t n = 400'000;
    const auto project = parseProject(test::projectOfEmptySegments(n));
    ASSERT_FALSE(project.ok());
    ASSERT_EQ(project.errors().size(), n);
    EXPECT_EQ(project.errors().front().location, "contour[0].type");
    EXPECT_EQ(project.errors().back().location, "contour[399999].type");
    EXPECT_EQ(project.errors().back().message, "missing");
}

// --- readTextFile: size and kind are checked before a byte is read --------------------------

TEST(ReadTextFile, TheLimitIs64MiBAndAFileOfExactlyThatSizeIsRead) {
    EXPECT_EQ(kMaxProjectFileBytes, 64u * 1024 * 1024);
    const TempDir dir;
    const std::string file = dir.file("limit.json");
    std::ofstream(file) << "";
    ASSERT_EQ(::truncate(file.c_str(), static_cast<off_t>(kMaxProjectFileBytes)), 0);  // sparse
    const auto text = readTextFile(file);
    ASSERT_TRUE(text.ok()) << text.errors().front().message;
    EXPECT_EQ(text.value().size(), kMaxProjectFileBytes);
}

TEST(ReadTextFile, ALargerFileIsRefusedWithItsSize) {
    const TempDir dir;
    const std::string file = dir.file("big.json");
    std::ofstream(file) << "";
    const off_t size = static_cast<off_t>(kMaxProjectFileBytes) + 1;
    ASSERT_EQ(::truncate(file.c_str(), size), 0);
    const auto text = readTextFile(file);
    ASSERT_FALSE(text.ok());
    ASSERT_EQ(text.errors().size(), 1u);
    EXPECT_EQ(text.errors().front().location, file);
    EXPECT_EQ(text.errors().front().message,
              "is 64.0 MiB (67108865 bytes): files larger than 64 MiB are not read");
}

TEST(ReadTextFile, WhatIsNotARegularFileIsRefusedSayingWhatItIs) {
    const TempDir dir;
    const std::string fifo = dir.file("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fs::create_symlink("/dev/zero", dir.path() / "zeros");
    struct Case {
        std::string path;
        const char* kind;
    };
    // /dev/zero never ends (612d090: "internal error: std::bad_alloc") and a FIFO without a
    // writer would block forever: neither is read, nor waited for.
    for (const Case& c :
         {Case{"/dev/zero", "a character device"}, Case{dir.file("zeros"), "a character device"},
          Case{fifo, "a FIFO"}, Case{dir.path().string(), "a folder"}}) {
        SCOPED_TRACE(c.path);
        const auto text = readTextFile(c.path);
        ASSERT_FALSE(text.ok());
        EXPECT_EQ(text.errors().front().location, c.path);
        EXPECT_EQ(text.errors().front().message,
                  std::string("is ") + c.kind + ", not a regular file: not read");
    }
}

TEST(ReadTextFile, AMissingFileGivesTheSystemsReason) {
    const TempDir dir;
    const auto text = readTextFile(dir.file("missing.json"));
    ASSERT_FALSE(text.ok());
    EXPECT_EQ(text.errors().front().message, "cannot open: No such file or directory");
}

}  // namespace
}  // namespace cam
