#pragma once
/// @file
/// @brief Reading and writing `.cam.json` project files, format version 1 (project-format.md).

#include <string>
#include <string_view>

#include "common/diagnostic.h"
#include "io/project_reader.h"
#include "io/project_writer.h"
#include "project/project.h"

namespace cam {

/// @brief A project file's text → the project, checked for syntax and structure only (see
/// readProject): an unfinished design with geometric problems reads, and validateProject then
/// lists its problems. Syntax errors are located `line L, column C`, the rest by JSON path.
[[nodiscard]] Result<Project> parseProjectStructure(std::string_view text);

/// @brief parseProjectStructure, then validateProject: only a project the engine can compute
/// comes back; otherwise every problem, located (`contour[3].radius`, `contour[4]/contour[5]`).
[[nodiscard]] Result<Project> parseProject(std::string_view text);

/// @brief Reads a file and parses its structure; an unreadable file is reported at its path.
[[nodiscard]] Result<Project> loadProjectStructure(const std::string& path);

/// @brief Reads a file and parses and validates it (parseProject).
[[nodiscard]] Result<Project> loadProjectFile(const std::string& path);

/// @brief Reads a whole file; errors are located at the path.
[[nodiscard]] Result<std::string> readTextFile(const std::string& path);

}  // namespace cam
