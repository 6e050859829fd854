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

/// @brief Streams a file into a temporary sibling and renames it over the target on commit().
/// Destroyed without commit(), it removes the temporary file and leaves the target untouched.
class AtomicFileWriter {
public:
    explicit AtomicFileWriter(std::string path);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    /// @brief False (with errors()) if the temporary file could not be created or written.
    [[nodiscard]] bool ok() const { return m_errors.empty(); }
    void write(std::string_view chunk);
    /// @brief Flushes to disk and renames; returns the problems, empty on success.
    [[nodiscard]] Diagnostics commit();
    [[nodiscard]] const Diagnostics& errors() const { return m_errors; }

private:
    void fail(const char* what);
    std::string m_path;
    std::string m_tempPath;
    int m_fd = -1;
    Diagnostics m_errors;
};

/// @brief Writes a file atomically: a temporary file in the same folder, flushed to disk, then
/// renamed over the target. On failure the target is untouched and the error is returned.
[[nodiscard]] Diagnostics writeFileAtomically(const std::string& path, std::string_view content);

}  // namespace cam
