#pragma once
/// @file
/// @brief Numbers as export files write them: C locale, whatever the process's locale is.

#include <charconv>
#include <string>

namespace cam {

/// @brief Appends the shortest text that reads back to exactly `value` (0.1, not
/// 0.10000000000000001; 1e-05 where that is shorter than 0.00001), and 0 for -0: a sign on a
/// zero only says from which side round-off came.
inline void appendExact(std::string& out, double value) {
    if (value == 0.0) value = 0.0;  // -0 → 0
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

/// @brief Appends `value` with `decimals` digits after the point (%.Nf), never "-0.000".
inline void appendFixed(std::string& out, double value, int decimals) {
    char buffer[64];
    auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string_view::npos) {
        text.remove_prefix(1);
    }
    out.append(text);
}

}  // namespace cam
