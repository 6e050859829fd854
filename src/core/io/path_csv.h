#pragma once
/// @file
/// @brief Point lists for tool paths: one `x,y,z[,bulge]` point per line, in mm (cli.md).

#include <string_view>
#include <vector>

#include "common/diagnostic.h"
#include "timing/tool_path.h"

namespace cam {

/// @brief Parses a point list. A first line that is not numeric is a header; blank lines are
/// skipped. Problems are located as `line N` (1-based, as an editor shows them).
[[nodiscard]] Result<std::vector<PathPoint>> parsePathCsv(std::string_view text);

}  // namespace cam
