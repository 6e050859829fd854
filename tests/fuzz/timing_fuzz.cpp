// libFuzzer entry point of the timing harness (tests/fuzz/harnesses.h says what it checks).
// Build: cmake --preset fuzz && cmake --build --preset fuzz; run: see tests/fuzz/README.md.

#include <cstddef>
#include <cstdint>

#include "harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    cam::fuzz::fuzzTiming(data, size);
    return 0;
}
