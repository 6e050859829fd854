#pragma once
/// @file
/// @brief Text with a few comma-separated numbers per line: point lists for tool paths and
/// teach-in points. One reader, so both accept and refuse the same things.

#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostic.h"

namespace cam {

/// @brief What one row holds: its values are named (e.g. {"x", "y", "z", "bulge"}); the first
/// `required` of them must be present, the others may be.
struct RowShape {
    std::vector<std::string> names;
    std::size_t required = 0;
};

/// @brief The numbers of every non-blank line, `shape.required` to `shape.names.size()` per
/// line, separated by commas. A UTF-8 byte-order mark is skipped; a first line with no number
/// in any cell is a header (so "x,y" is one, "O,0" — a letter O — is a mistake and reported).
/// Numbers must be finite, in C notation. Problems are located as `line N` (1-based, as an
/// editor shows them); at most 20 are listed.
[[nodiscard]] Result<std::vector<std::vector<double>>> parseNumberRows(std::string_view text,
                                                                       const RowShape& shape);

}  // namespace cam
