#include "io/path_csv.h"

#include "io/number_rows.h"

namespace cam {

Result<std::vector<PathPoint>> parsePathCsv(std::string_view text) {
    const auto rows = parseNumberRows(text, {{"x", "y", "z", "bulge"}, 3});
    if (!rows.ok()) return rows.errors();
    std::vector<PathPoint> points;
    for (const std::vector<double>& row : rows.value()) {
        PathPoint p;
        p.position = {row[0], row[1], row[2]};
        if (row.size() == 4) p.bulge = row[3];
        points.push_back(p);
    }
    if (points.size() < 2) {
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::Points}, DiagnosticCode::PathTooFewPoints)};
    }
    return points;
}

}  // namespace cam
