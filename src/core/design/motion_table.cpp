#include "design/motion_table.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace cam {
namespace {

/// The rows that give a quintic's jerk and snap at its ends from (y0, v0, a0, y1, v1, a1) over
/// an interval of width h: the quintic of Poly5Law with x scaled by h, differentiated.
struct EndRows {
    std::array<double, 6> jerkLeft, jerkRight, snapLeft, snapRight;
};

EndRows endRows(double h) {
    const double h2 = h * h, h3 = h2 * h, h4 = h3 * h;
    const auto scaled = [](std::array<double, 6> r, double by) {
        for (double& v : r) v /= by;
        return r;
    };
    return {scaled({-60.0, -36.0 * h, -9.0 * h2, 60.0, -24.0 * h, 3.0 * h2}, h3),
            scaled({-60.0, -24.0 * h, -3.0 * h2, 60.0, -36.0 * h, 9.0 * h2}, h3),
            scaled({360.0, 192.0 * h, 36.0 * h2, -360.0, 168.0 * h, -24.0 * h2}, h4),
            scaled({-360.0, -168.0 * h, -24.0 * h2, 360.0, -192.0 * h, 36.0 * h2}, h4)};
}

}  // namespace

Diagnostics motionTableProblems(const std::vector<MotionTablePoint>& points, const Place& place) {
    Diagnostics out;
    const auto error = [&](DiagnosticCode code, std::vector<DiagnosticArg> args) {
        out.push_back(Diagnostic::make(place, code, std::move(args)));
    };
    if (points.size() < 2) {
        error(DiagnosticCode::MotionTableTooFew, {static_cast<double>(points.size())});
        return out;
    }
    if (points.size() > kMaxMotionTablePoints) {
        error(DiagnosticCode::MotionTableTooMany,
              {static_cast<double>(kMaxMotionTablePoints), static_cast<double>(points.size())});
        return out;
    }
    for (const MotionTablePoint& p : points) {
        for (double v : {p.x, p.y, p.v.value_or(0.0)}) {
            if (!std::isfinite(v)) {
                error(DiagnosticCode::NotFinite, {v});
                return out;
            }
        }
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (!(points[i].x > points[i - 1].x)) {
            error(DiagnosticCode::MotionTableNotIncreasing,
                  {static_cast<double>(i), points[i - 1].x, points[i].x});
            return out;
        }
    }
    const MotionTablePoint &first = points.front(), &last = points.back();
    if (first.x != 0.0 || first.y != 0.0 || last.x != 1.0 || last.y != 1.0) {
        error(DiagnosticCode::MotionTableEnds, {first.x, first.y, last.x, last.y});
    }
    return out;
}

Result<MotionTableSpline> MotionTableSpline::build(const std::vector<MotionTablePoint>& points,
                                                   const Place& place) {
    if (Diagnostics problems = motionTableProblems(points, place); !problems.empty()) {
        return problems;
    }
    const std::size_t n = points.size();
    MotionTableSpline s;
    s.m_x.resize(n);
    s.m_y.resize(n);
    s.m_v.assign(n, 0.0);
    s.m_a.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        s.m_x[i] = points[i].x;
        s.m_y[i] = points[i].y;
        if (points[i].v) s.m_v[i] = *points[i].v;
    }
    // Unknowns: a at every inner knot, v at an inner knot that gives none. Equations: the jerk
    // continuous at every inner knot, the snap too where v is unknown.
    std::vector<std::optional<Eigen::Index>> vIndex(n), aIndex(n);
    Eigen::Index unknowns = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        aIndex[i] = unknowns++;
        if (!points[i].v) vIndex[i] = unknowns++;
    }
    if (unknowns > 0) {
        std::vector<Eigen::Triplet<double>> entries;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
        Eigen::Index row = 0;
        // Adds coefficient c of value `which` (0 y, 1 v, 2 a) at knot k to equation `row`.
        const auto add = [&](Eigen::Index eq, std::size_t k, int which, double c) {
            const std::optional<Eigen::Index>& index = which == 1   ? vIndex[k]
                                                       : which == 2 ? aIndex[k]
                                                                    : std::nullopt;
            if (index) {
                entries.emplace_back(eq, *index, c);
            } else {
                const double known = which == 0 ? s.m_y[k] : which == 1 ? s.m_v[k] : s.m_a[k];
                rhs[eq] -= c * known;
            }
        };
        // right end of interval i−1 minus left end of interval i, at knot i.
        const auto equate = [&](std::size_t i, bool snap) {
            const EndRows before = endRows(s.m_x[i] - s.m_x[i - 1]);
            const EndRows after = endRows(s.m_x[i + 1] - s.m_x[i]);
            const std::array<double, 6>& l = snap ? before.snapRight : before.jerkRight;
            const std::array<double, 6>& r = snap ? after.snapLeft : after.jerkLeft;
            for (int w = 0; w < 3; ++w) {
                add(row, i - 1, w, l[static_cast<std::size_t>(w)]);
                add(row, i, w, l[static_cast<std::size_t>(w + 3)] - r[static_cast<std::size_t>(w)]);
                add(row, i + 1, w, -r[static_cast<std::size_t>(w + 3)]);
            }
            ++row;
        };
        for (std::size_t i = 1; i + 1 < n; ++i) {
            equate(i, false);
            if (!points[i].v) equate(i, true);
        }
        Eigen::SparseMatrix<double> m(unknowns, unknowns);
        m.setFromTriplets(entries.begin(), entries.end());
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
        lu.compute(m);
        if (lu.info() != Eigen::Success) {
            return Diagnostics{Diagnostic::make(place, DiagnosticCode::MotionTableSingular)};
        }
        const Eigen::VectorXd solution = lu.solve(rhs);
        if (lu.info() != Eigen::Success || !solution.allFinite()) {
            return Diagnostics{Diagnostic::make(place, DiagnosticCode::MotionTableSingular)};
        }
        for (std::size_t i = 1; i + 1 < n; ++i) {
            s.m_a[i] = solution[*aIndex[i]];
            if (vIndex[i]) s.m_v[i] = solution[*vIndex[i]];
        }
    }
    return s;
}

LawPoint MotionTableSpline::at(double x) const {
    x = std::clamp(x, 0.0, 1.0);
    const auto it = std::upper_bound(m_x.begin(), m_x.end(), x);
    const std::size_t i = std::min<std::size_t>(
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - m_x.begin(), 1)) - 1,
        m_x.size() - 2);
    const double h = m_x[i + 1] - m_x[i];
    const Poly5Law piece(h, m_y[i], m_y[i + 1], m_v[i], m_a[i], m_v[i + 1], m_a[i + 1]);
    return piece.at((x - m_x[i]) / h);
}

Result<std::vector<MotionTablePoint>> parseMotionTable(std::string_view text) {
    std::vector<MotionTablePoint> points;
    std::size_t lineNo = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string_view::npos) continue;
        line = line.substr(first);
        if (line[0] == '#' || line[0] == ';' || line.substr(0, 2) == "//") continue;
        std::vector<double> values;
        std::size_t pos = 0;
        while (pos < line.size()) {
            const std::size_t start = line.find_first_not_of(" \t,;", pos);
            if (start == std::string_view::npos) break;
            const std::size_t stop = std::min(line.find_first_of(" \t,;", start), line.size());
            const std::string_view word = line.substr(start, stop - start);
            double v = 0.0;
            const char* begin = word.data() + (word[0] == '+' ? 1 : 0);
            const auto [ptr, ec] = std::from_chars(begin, word.data() + word.size(), v);
            if (ec != std::errc{} || ptr != word.data() + word.size() || !std::isfinite(v)) {
                return Diagnostics{Diagnostic::make(FilePositionPlace{lineNo, first + start + 1},
                                                    DiagnosticCode::MotionTableNotANumber,
                                                    {std::string(word.substr(0, 40))})};
            }
            values.push_back(v);
            pos = stop;
        }
        if (values.size() != 2 && values.size() != 3) {
            return Diagnostics{Diagnostic::make(FilePositionPlace{lineNo, 0},
                                                DiagnosticCode::MotionTableColumns,
                                                {static_cast<double>(values.size())})};
        }
        MotionTablePoint p{values[0], values[1], std::nullopt};
        if (values.size() == 3) p.v = values[2];
        points.push_back(p);
        if (points.size() > kMaxMotionTablePoints) {
            return Diagnostics{Diagnostic::make(
                FilePositionPlace{lineNo, 0}, DiagnosticCode::MotionTableTooMany,
                {static_cast<double>(kMaxMotionTablePoints), static_cast<double>(points.size())})};
        }
    }
    return points;
}

}  // namespace cam
