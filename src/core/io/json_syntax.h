#pragma once
/// @file
/// @brief JSON text → an ordered DOM, with every syntax problem located in the text.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

#include "common/diagnostic.h"

namespace cam {

using Json = nlohmann::ordered_json;

/// @brief Deepest nesting of arrays and objects a project file may have.
inline constexpr int kMaxJsonDepth = 64;

/// @brief Parses `text` into `out`. Returns the problem, empty on success:
/// - a syntax error or a number too large for a double at `line L, column C` (1-based, found
///   from the parser's byte position, never by reading its message);
/// - a NUL byte at its byte offset (the parser would take it for the end of the text);
/// - a duplicated key or nesting deeper than kMaxJsonDepth at its JSON path (`contour[0].radius`).
/// Linear in the size of the text. At most the first 40 characters of a token are quoted.
[[nodiscard]] Diagnostics parseJson(std::string_view text, Json& out);

/// @brief The line and column (both from 1) of byte `offset` (0-based) into `text`: "line 3,
/// column 14".
[[nodiscard]] FilePositionPlace filePosition(std::string_view text, std::size_t offset);

}  // namespace cam
