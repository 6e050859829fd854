#pragma once
/// @file
/// @brief Point lists for tool paths: one `x,y,z[,bulge]` point per line, in mm (cli.md).

#include <string_view>
#include <vector>

#include "common/diagnostic.h"
#include "toolpath/tool_path.h"

namespace cam {

/// @brief Parses a point list (parseNumberRows: a header line is one without any number, blank
/// lines are skipped, a byte-order mark is skipped). Problems are located as `line N`.
[[nodiscard]] Result<std::vector<PathPoint>> parsePathCsv(std::string_view text);

}  // namespace cam
