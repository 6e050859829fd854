#pragma once
/// @file
/// @brief The fuzz harnesses as plain functions: the libFuzzer entry points call them, and the
/// regression test replays every saved input through the same code in the normal build.
///
/// Each takes any byte string. It returns normally when the code under test behaved; on a
/// broken invariant (a refusal without a message, a non-finite result reported as success, a
/// result that does not validate) it prints what broke to stderr and aborts, so libFuzzer
/// records the input and the test binary fails.

#include <cstddef>
#include <cstdint>

namespace cam::fuzz {

/// @brief A project file's text through parse, validate, compile, state, sampling, analysis,
/// save and reload (save → load → save must be byte-stable).
void fuzzProject(const std::uint8_t* data, std::size_t size);

/// @brief The point-list reader (parseNumberRows, parsePathCsv) as the CLI's `--path` and the
/// app's teach-in import use it; what it accepts is written back with 17 digits and must read
/// back the same; accepted points go on into a tool path or a teach-in contour.
void fuzzPointList(const std::uint8_t* data, std::size_t size);

/// @brief filletJoint and filletRange on a contour built from the bytes (a polygon of lines and
/// arcs around the rotation centre, or a project file's text) at a joint and radius from the
/// bytes: the result validates, loads back from its saved text and has the asked radius, or the
/// refusal says why.
void fuzzFillet(const std::uint8_t* data, std::size_t size);

/// @brief A tool path from fuzzed points and bulges, machine limits and seed step from the bytes,
/// then the seed, exact-stop and optimal methods and one profile (timePath, as the CLI runs
/// them): results finite, optimal no slower than exact stop, or the refusal says why.
void fuzzTiming(const std::uint8_t* data, std::size_t size);

/// @brief A harness by the name of its target (its folder under tests/fuzz/regressions/).
struct Harness {
    const char* name;
    void (*run)(const std::uint8_t* data, std::size_t size);
};
inline constexpr Harness kHarnesses[] = {
    {"project", fuzzProject},
    {"point_list", fuzzPointList},
    {"fillet", fuzzFillet},
    {"timing", fuzzTiming},
};

}  // namespace cam::fuzz
