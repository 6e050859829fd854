#pragma once
/// @file
/// @brief Reading and writing `.cam.json` project files, format version 1 (project-format.md).

#include <string>
#include <string_view>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

inline constexpr int kProjectFormatVersion = 1;

/// @brief Parses and validates a project. Every problem comes back located: a JSON path such
/// as `contour[3].radius`, a joint `contour[4]/contour[5]`, or `line L, column C` for syntax.
[[nodiscard]] Result<Project> parseProject(std::string_view text);

/// @brief Reads a file and parses it; an unreadable file is reported at its path.
[[nodiscard]] Result<Project> loadProjectFile(const std::string& path);

/// @brief The project as format-v1 JSON (mm, degrees), fields in the documented order,
/// unknown top-level keys last. Requires every number to be finite (validate first).
[[nodiscard]] std::string serializeProject(const Project& project);

/// @brief Reads a whole file; errors are located at the path.
[[nodiscard]] Result<std::string> readTextFile(const std::string& path);

}  // namespace cam
