#include "io/number_rows.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace cam {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
        s.remove_suffix(1);
    }
    return s;
}

std::optional<double> number(std::string_view cell) {
    cell = trim(cell);
    if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (cell.empty() || ec != std::errc{} || ptr != cell.data() + cell.size()) return std::nullopt;
    return v;
}

std::vector<std::string_view> cellsOf(std::string_view line) {
    std::vector<std::string_view> cells;
    for (std::string_view rest = line;;) {
        const std::size_t comma = rest.find(',');
        cells.push_back(rest.substr(0, comma));
        if (comma == std::string_view::npos) return cells;
        rest = rest.substr(comma + 1);
    }
}

/// The first `count` names, "x,y,z".
std::string namesList(const RowShape& shape, std::size_t count) {
    std::string out;
    for (std::size_t i = 0; i < count; ++i) out += (i ? "," : "") + shape.names[i];
    return out;
}

/// A row of the wrong length: the lengths it may have, "x,y,z or x,y,z,bulge".
Diagnostic wrongLength(const RowShape& shape, std::size_t line, std::size_t cells) {
    const std::string longest = namesList(shape, shape.names.size());
    const FilePositionPlace at{line};
    if (shape.required == 0 || shape.required >= shape.names.size()) {
        return Diagnostic::make(at, DiagnosticCode::RowValueCountExact,
                                {longest, static_cast<double>(cells)});
    }
    return Diagnostic::make(
        at, DiagnosticCode::RowValueCount,
        {namesList(shape, shape.required), longest, static_cast<double>(cells)});
}

}  // namespace

Result<std::vector<std::vector<double>>> parseNumberRows(std::string_view text,
                                                         const RowShape& shape) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte-order mark
    std::vector<std::vector<double>> rows;
    Diagnostics errors;
    std::size_t lineNumber = 0;
    bool first = true;
    while (!text.empty() && errors.size() < 20) {
        const std::size_t eol = text.find('\n');
        const std::string_view line = trim(text.substr(0, eol));
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++lineNumber;
        if (line.empty()) continue;
        const std::vector<std::string_view> cells = cellsOf(line);
        if (first) {
            first = false;
            bool anyNumber = false;
            for (std::string_view c : cells) anyNumber = anyNumber || number(c).has_value();
            if (!anyNumber) continue;  // a header line
        }
        if (cells.size() < shape.required || cells.size() > shape.names.size()) {
            errors.push_back(wrongLength(shape, lineNumber, cells.size()));
            continue;
        }
        std::vector<double> row;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto v = number(cells[c]);
            if (!v || !std::isfinite(*v)) {
                errors.push_back(Diagnostic::make(FilePositionPlace{lineNumber},
                                                  DiagnosticCode::RowValueNotFinite,
                                                  {shape.names[c], std::string(trim(cells[c]))}));
                break;
            }
            row.push_back(*v);
        }
        if (row.size() == cells.size()) rows.push_back(std::move(row));
    }
    if (!errors.empty()) return errors;
    return rows;
}

}  // namespace cam
