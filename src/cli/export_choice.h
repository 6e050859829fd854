#pragma once
/// @file
/// @brief What `export --format NAME` names, read from the core's table of export formats
/// (export/export_formats.h), for the command and its help alike.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "export/export_formats.h"

namespace cam::cli {

/// @brief The names `--format` takes, in the table's order: each format's own, then a
/// picture's dialects that no format already has ("png", "pdf").
[[nodiscard]] std::vector<std::string_view> exportFormatNames();

/// @brief A format and, for one that has them, its dialect.
struct ExportChoice {
    const ExportFormatKind* format = nullptr;
    const ExportDialectKind* dialect = nullptr;
};

/// @brief What `--format name` chooses; `plot`: `--plot` was given too (an SVG picture rather
/// than the SVG drawing). None for an unknown name.
[[nodiscard]] std::optional<ExportChoice> chooseExportFormat(std::string_view name, bool plot);

/// @brief The names of a format's dialects ("csv", "codesys").
[[nodiscard]] std::vector<std::string_view> dialectNames(ExportFormatId id);

/// @brief "a, b, c" or, with `last`, "a, b or c".
[[nodiscard]] std::string joinNames(const std::vector<std::string_view>& names,
                                    std::string_view separator, std::string_view last = {});

}  // namespace cam::cli
