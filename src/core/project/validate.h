#pragma once
/// @file
/// @brief Every rule of project-format.md, checked on the document, each problem located.

#include <cstddef>
#include <optional>
#include <string>

#include "common/diagnostic.h"
#include "common/tolerances.h"
#include "project/project.h"

namespace cam {

struct ValidationOptions {
    /// Check that neighbouring segments meet (C0). The editor's engine turns this off so that a
    /// contour with an opened joint is still drawn (its r jumps there) while it is being edited.
    bool checkJoints = true;
};

/// @brief All problems of the document but its motion design's (design/motion_design.h:
/// designProblems; evaluation/evaluation.h asks both); empty when it is valid.
[[nodiscard]] Diagnostics validateProject(const Project& project, ValidationOptions options = {});

/// @brief Why a length (mm) cannot be in a project: not finite, or beyond 1e6 mm.
[[nodiscard]] std::optional<Diagnostic> lengthProblem(const Place& place, double value);

/// @brief Polar window of a line from its end points, in degrees; the start is unwrapped to lie
/// within 180° of `nearDeg` (the previous segment's end, or 0).
[[nodiscard]] std::pair<double, double> lineWindowDeg(const SegmentSpec& line, double nearDeg);

/// @brief Why joint K cannot be operated on by `operation`, a term of the diagnostic catalogue
/// ("a fillet"): the contour has fewer than two segments, or K is not one of its joints
/// 0 .. n−1; none when it is one.
[[nodiscard]] std::optional<Diagnostic> jointIndexProblem(std::size_t segmentCount,
                                                          std::size_t joint, const char* operation);

}  // namespace cam
