#pragma once
/// @file
/// @brief Every tolerance that decides what counts as "the same", in one place.

namespace cam {

/// @brief Largest disagreement of two window boundaries that still counts as "the same angle".
inline constexpr double kWindowToleranceDeg = 1e-9;
/// @brief Largest positional gap at a joint (C0) that is not an error.
inline constexpr double kJointToleranceMm = 1e-6;
/// @brief How far two neighbouring segments may miss each other and still be made to meet by
/// Fit Windows (contour/fit_windows.h), which then moves the later one by the smallest change:
/// the rounding of typed numbers. Eight-digit centres, as the seed's Table 1 prints them, miss
/// by up to 2e-6 mm; a real gap in a design is far wider. Also the most any segment is moved.
inline constexpr double kTypingToleranceMm = 1e-5;
/// @brief How far a line's given window may differ from the polar angles of its end points.
inline constexpr double kLineWindowToleranceDeg = 1e-6;
/// @brief A joint is tangent (no corner: C1 in φ) when the contour's tangent turns by at most
/// this much there. Used by the analysis, the fillets, the tool-path offset and the planner, so
/// that they agree on which joints are corners. Files carry about ten significant digits (the
/// six-lobe example breaks by 8e-7°).
inline constexpr double kTangentToleranceDeg = 1e-5;
/// @brief A G1 joint is C1 (C1 is C2) when the first (second) derivative of P(φ) jumps by at
/// most this fraction of its local size: "nearly continuous" in the sense of math.md §4.
inline constexpr double kCurvatureToleranceRel = 1e-6;

}  // namespace cam
