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
