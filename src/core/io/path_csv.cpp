#include "io/path_csv.h"

#include <charconv>
#include <cmath>

namespace cam {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
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

}  // namespace

Result<std::vector<PathPoint>> parsePathCsv(std::string_view text) {
    std::vector<PathPoint> points;
    Diagnostics errors;
    std::size_t lineNumber = 0;
    bool first = true;
    while (!text.empty()) {
        const std::size_t eol = text.find('\n');
        const std::string_view line = trim(text.substr(0, eol));
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++lineNumber;
        if (line.empty()) continue;
        std::vector<std::string_view> cells;
        for (std::string_view rest = line;;) {
            const std::size_t comma = rest.find(',');
            cells.push_back(rest.substr(0, comma));
            if (comma == std::string_view::npos) break;
            rest = rest.substr(comma + 1);
        }
        const bool numeric = number(cells.front()).has_value();
        if (first && !numeric) {  // a header line
            first = false;
            continue;
        }
        first = false;
        const std::string at = "line " + std::to_string(lineNumber);
        if (cells.size() < 3 || cells.size() > 4) {
            errors.push_back({at, "expected x,y,z or x,y,z,bulge (got " +
                                      std::to_string(cells.size()) + " values)"});
            continue;
        }
        PathPoint p;
        bool ok = true;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto v = number(cells[c]);
            if (!v || !std::isfinite(*v)) {
                static const char* names[] = {"x", "y", "z", "bulge"};
                errors.push_back({at, std::string(names[c]) + " must be a finite number (got \"" +
                                          std::string(trim(cells[c])) + "\")"});
                ok = false;
                continue;
            }
            if (c < 3) {
                p.position[static_cast<Eigen::Index>(c)] = *v;
            } else {
                p.bulge = *v;
            }
        }
        if (ok) points.push_back(p);
        if (errors.size() >= 20) break;  // enough to see what is wrong
    }
    if (!errors.empty()) return errors;
    if (points.size() < 2) return Diagnostics{{"points", "a path needs at least two points"}};
    return points;
}

}  // namespace cam
