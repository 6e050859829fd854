#pragma once
/// @file
/// @brief Every export format and dialect described once: its name on the command line, its
/// title in the Export dialog, its file suffix and the CLI options it takes. camwright-cli's
/// `export` (its parsing and its help) and the window's Export dialog read this table; adding a
/// format or a dialect is docs/architecture.md's recipe.

#include <span>
#include <string>
#include <string_view>

namespace cam {

enum class ExportFormatId {
    Csv,       ///< the sampled turn (exports.md `csv`)
    Dxf,       ///< the DXF drawing
    Svg,       ///< the 1:1 SVG drawing
    Gcode,     ///< the milling program
    CamTable,  ///< the servo cam table, in one of its dialects
    Picture,   ///< a picture of one of the app's plots, in one of its dialects
};

/// @brief One dialect of a format: a cam table's CSV or CODESYS text, a picture's PNG or PDF.
struct ExportDialectKind {
    std::string_view name;  ///< `--dialect NAME` (cam table) or `--format NAME` (picture)
    /// English, for the Export dialog; the app translates it in context "ExportFormat".
    const char* title;
    std::string_view suffix;  ///< the file suffix it gets by default
};

struct ExportFormatKind {
    ExportFormatId id;
    /// `--format NAME`; empty when the format is chosen by its dialects' names instead (a
    /// picture: `--format png`).
    std::string_view name;
    /// English, for the Export dialog; the app translates it in context "ExportFormat".
    const char* title;
    std::string_view suffix;  ///< the file suffix it gets by default (a dialect's wins)
    std::span<const std::string_view> options;  ///< the CLI options with a value it takes
    std::span<const std::string_view> flags;    ///< the CLI flags it takes
    std::span<const ExportDialectKind> dialects;
};

/// @brief Every format, in ExportFormatId order (the order the Export dialog lists them).
[[nodiscard]] std::span<const ExportFormatKind> exportFormats();
/// @brief The row of a format.
[[nodiscard]] const ExportFormatKind& exportFormat(ExportFormatId id);

/// @brief The dialect called `name` of a format, or null.
[[nodiscard]] const ExportDialectKind* findDialect(const ExportFormatKind& format,
                                                   std::string_view name);

/// @brief The name every export of a project carries (the G-code header, the cam table's name,
/// the SVG's and a picture's title): the project's name, else its file's name without the
/// folder and ".cam.json" (or ".json"), else "untitled" (a project never saved).
[[nodiscard]] std::string exportName(const std::string& projectName, const std::string& filePath);

}  // namespace cam
