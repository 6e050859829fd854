#pragma once
/// @file
/// @brief A user's motion from a table of points (law `table`): normalised points through a
/// C2 quintic spline, and the two-column text (x, y from 0 to 1) that Inventor's cam design
/// reads for a user-defined motion.

#include <string_view>
#include <vector>

#include "common/diagnostic.h"
#include "design/motion_law.h"
#include "project/project.h"

namespace cam {

/// @brief The most points a motion table may have.
inline constexpr std::size_t kMaxMotionTablePoints = 10000;

/// @brief Every problem of a table's points, each at `place` (the segment's `points`): fewer
/// than two, a number not finite, x not strictly increasing, not from (0, 0) to (1, 1).
[[nodiscard]] Diagnostics motionTableProblems(const std::vector<MotionTablePoint>& points,
                                              const Place& place);

/// @brief The spline through a table's points: a quintic on each interval with y, y', y''
/// shared at the knots (C2 everywhere). At a point that gives its velocity the spline takes
/// it and its jerk is continuous (C3); at one that does not, the velocity is found too, with
/// jerk and snap continuous (C4, the quintic spline). At both ends v is the point's (0 where
/// not given) and a = 0.
class MotionTableSpline {
public:
    /// @brief Errors: motionTableProblems' (located at `place`), or a system that cannot be
    /// solved.
    [[nodiscard]] static Result<MotionTableSpline> build(
        const std::vector<MotionTablePoint>& points, const Place& place);
    /// @brief y and its derivatives at x in [0, 1] (clamped).
    [[nodiscard]] LawPoint at(double x) const;
    /// @brief The knots' x, and y, y', y'' at each.
    [[nodiscard]] const std::vector<double>& knots() const { return m_x; }

private:
    std::vector<double> m_x, m_y, m_v, m_a;
};

/// @brief A table as text: one point per line, "x y" or "x y dy/dx", separated by blanks, tabs,
/// commas or semicolons; empty lines and lines starting with '#', ';' or "//" are skipped.
/// Errors name the line ("line 3": not a number, not two or three columns).
[[nodiscard]] Result<std::vector<MotionTablePoint>> parseMotionTable(std::string_view text);

}  // namespace cam
