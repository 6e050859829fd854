// Replays every input a fuzzer has failed on (tests/fuzz/regressions/<target>/) and the seed
// corpora (tests/fuzz/corpus/<target>/) through the harness functions the fuzzers run. A broken
// invariant aborts, and so fails this test binary: no death test is needed, and no input can
// be quietly skipped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "harnesses.h"
#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;

/// The files of tests/fuzz/<kind>/<target>/, sorted (none if the folder does not exist).
std::vector<fs::path> inputs(const std::string& kind, const std::string& target) {
    const fs::path folder = fs::path(CAMWRIGHT_SOURCE_DIR) / "tests" / "fuzz" / kind / target;
    std::vector<fs::path> files;
    if (!fs::is_directory(folder)) return files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::size_t replay(const std::string& kind, const fuzz::Harness& harness) {
    const std::vector<fs::path> files = inputs(kind, harness.name);
    for (const fs::path& file : files) {
        // Named before it runs: an abort leaves this as the last line of the log.
        std::fprintf(stderr, "replaying %s\n", file.string().c_str());
        std::fflush(stderr);
        const std::string bytes = test::readFile(file.string());
        harness.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    return files.size();
}

class FuzzReplay : public ::testing::TestWithParam<fuzz::Harness> {};

TEST_P(FuzzReplay, Regressions) {
    const std::size_t count = replay("regressions", GetParam());
    RecordProperty("inputs", static_cast<int>(count));
}

TEST_P(FuzzReplay, SeedCorpus) {
    const std::size_t count = replay("corpus", GetParam());
    RecordProperty("inputs", static_cast<int>(count));
    EXPECT_GT(count, 0u) << "every target keeps a seed corpus in tests/fuzz/corpus/"
                         << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, ::testing::ValuesIn(fuzz::kHarnesses),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cam
