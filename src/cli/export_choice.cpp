#include "cli/export_choice.h"

#include <algorithm>

namespace cam::cli {

std::vector<std::string_view> exportFormatNames() {
    std::vector<std::string_view> names;
    for (const ExportFormatKind& format : exportFormats()) {
        if (!format.name.empty()) names.push_back(format.name);
    }
    const ExportFormatKind& picture = exportFormat(ExportFormatId::Picture);
    for (const ExportDialectKind& dialect : picture.dialects) {
        if (std::find(names.begin(), names.end(), dialect.name) == names.end()) {
            names.push_back(dialect.name);
        }
    }
    return names;
}

std::optional<ExportChoice> chooseExportFormat(std::string_view name, bool plot) {
    const ExportFormatKind& picture = exportFormat(ExportFormatId::Picture);
    if (const ExportDialectKind* dialect = findDialect(picture, name)) {
        // "svg" alone is the drawing; with --plot, a picture.
        bool drawing = false;
        for (const ExportFormatKind& format : exportFormats()) drawing |= format.name == name;
        if (plot || !drawing) return ExportChoice{&picture, dialect};
    }
    for (const ExportFormatKind& format : exportFormats()) {
        if (format.name.empty() || format.name != name) continue;
        return ExportChoice{&format, format.dialects.empty() ? nullptr : &format.dialects[0]};
    }
    return std::nullopt;
}

std::vector<std::string_view> dialectNames(ExportFormatId id) {
    std::vector<std::string_view> names;
    for (const ExportDialectKind& dialect : exportFormat(id).dialects)
        names.push_back(dialect.name);
    return names;
}

std::string joinNames(const std::vector<std::string_view>& names, std::string_view separator,
                      std::string_view last) {
    std::string out;
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (k > 0) out += k + 1 == names.size() && !last.empty() ? last : separator;
        out += names[k];
    }
    return out;
}

}  // namespace cam::cli
