#pragma once
/// @file
/// @brief The path study of a spline (math.md §4): x(t), y(t) and their first and second
/// derivatives over the segment parameter taken as time, analytic and by difference quotient.

#include <array>
#include <vector>

#include "geometry/bezier.h"

namespace cam {

struct PathStudy {
    enum Series { X, Y, DX, DY, DDX, DDY, Count };
    std::vector<double> t;  ///< piece index + s, s in [0, 1]
    std::array<std::vector<double>, Count> analytic;
    /// Central difference quotients of the sampled positions with the constant step h: first
    /// derivative (x(t+h) − x(t−h))/2h, second (x(t+h) − 2x(t) + x(t−h))/h². Positions equal
    /// the analytic ones.
    std::array<std::vector<double>, Count> quotient;
    double step = 0.0;  ///< h
};

/// @brief Samples every piece at `samplesPerPiece` + 1 parameters (ends included).
[[nodiscard]] PathStudy studyPath(const std::vector<CubicBezier>& pieces, int samplesPerPiece);

}  // namespace cam
