#pragma once
/// @file
/// @brief Reading and writing `.cam.json` project files, format version 1 (project-format.md).

#include <cstdint>
#include <string>
#include <string_view>

#include "common/diagnostic.h"
#include "io/project_reader.h"
#include "io/project_writer.h"
#include "project/project.h"

namespace cam {

/// @brief A project file's text → the project, checked for syntax and structure only (see
/// readProject): an unfinished design with geometric problems reads, and evaluateProject then
/// lists its problems. Syntax errors are located `line L, column C`, the rest by JSON path.
[[nodiscard]] Result<Project> parseProjectStructure(std::string_view text);

/// @brief parseProjectStructure, then documentProblems: only a project the engine can compute
/// comes back; otherwise every problem, located (`contour[3].radius`, `contour[4]/contour[5]`).
[[nodiscard]] Result<Project> parseProject(std::string_view text);

/// @brief Reads a file and parses its structure; an unreadable file is reported at its path.
[[nodiscard]] Result<Project> loadProjectStructure(const std::string& path);

/// @brief Reads a file and parses and validates it (parseProject).
[[nodiscard]] Result<Project> loadProjectFile(const std::string& path);

/// @brief The largest project file (or point list) readTextFile reads: 64 MiB, checked before
/// reading. A real project is a few kilobytes; 64 MiB of JSON hold some 600,000 line segments,
/// which take about 0.5 GB of memory while they are parsed. The app refuses larger files too.
inline constexpr std::uint64_t kMaxProjectFileBytes = 64ull << 20;

/// @brief Reads a whole file; errors are located at the path:
/// - anything that is not a regular file (a folder, a FIFO, a device, a socket) is refused,
///   saying what it is, without reading from it or waiting for a writer (`/dev/zero` and a FIFO
///   never end);
/// - a file larger than kMaxProjectFileBytes is refused with its size, before it is read;
/// - otherwise the reason from the system (`cannot open: Permission denied`).
[[nodiscard]] Result<std::string> readTextFile(const std::string& path);

/// @brief The JSON library's version ("3.11.2"), for Help → About.
[[nodiscard]] std::string jsonLibraryVersion();

}  // namespace cam
