// The memory of one computation serves the next: an edit's result touches few new pages.

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>

#include "app_test_support.h"
#include "engine/compute_result.h"
#include "engine/memory_reuse.h"
#include "views/plot_data.h"

// GCC names an address-sanitized build by __SANITIZE_ADDRESS__, clang by __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define CAMWRIGHT_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAMWRIGHT_ADDRESS_SANITIZER 1
#endif
#endif

// The policy is glibc's; the address sanitizer brings its own allocator.
#if defined(__GLIBC__) && !defined(CAMWRIGHT_ADDRESS_SANITIZER)
#define CAMWRIGHT_GLIBC_ALLOCATOR 1
#else
#define CAMWRIGHT_GLIBC_ALLOCATOR 0
#endif

namespace cam {
namespace {

constexpr bool kGlibcAllocator = CAMWRIGHT_GLIBC_ALLOCATOR;
constexpr const char* kNotGlibcAllocator = "tunes glibc's allocator only (not the sanitizer's)";

long minorFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// The policy itself, independent of any computation: once set, a 1 MB block comes from the
// heap (below its break) instead of a mapping of its own. It once compiled to nothing in a
// build whose unity batch put no C library header before its glibc test.
TEST(MemoryReuse, BigBlocksComeFromTheHeapOnceTheProcessKeepsFreedMemory) {
    if (!kGlibcAllocator) GTEST_SKIP() << kNotGlibcAllocator;
#if CAMWRIGHT_GLIBC_ALLOCATOR
    keepFreedMemoryForReuse();
    void* block = std::malloc(1 << 20);
    ASSERT_NE(block, nullptr);
    const bool fromHeap = static_cast<char*>(block) < static_cast<char*>(sbrk(0));
    std::free(block);
    EXPECT_TRUE(fromHeap) << "a 1 MB block was mapped on its own";
#endif
}

TEST(MemoryReuse, AnEditsComputationTouchesFewNewPages) {
    if (!kGlibcAllocator) GTEST_SKIP() << kNotGlibcAllocator;
#if CAMWRIGHT_GLIBC_ALLOCATOR
    keepFreedMemoryForReuse();
    Project p = test::loadExample();
    p.samplesPerTurn = 100'000;
    const ComputeRequest request{1, std::make_shared<const Project>(p), PlotAxis::Angle};
    const QcpPlotDataPreparer preparer;
    const std::atomic<bool> cancel{false};
    // An edit: its result is made, shown, and freed when the next one replaces it.
    const auto edit = [&] {
        ComputeResultPtr result = computeProject(request, cancel, &preparer);
        ASSERT_TRUE(result && result->ok());
    };
    edit();
    edit();
    const long before = minorFaults();
    edit();
    const long faults = minorFaults() - before;
    // Measured: about 5,300 without keepFreedMemoryForReuse() (every block above 128 kB
    // mapped afresh and unmapped when freed), 0 to 30 with it.
    EXPECT_LT(faults, 800) << faults << " page faults";
#endif
}

}  // namespace
}  // namespace cam
