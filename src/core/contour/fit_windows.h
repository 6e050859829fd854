#pragma once
/// @file
/// @brief "Fit windows": move every window boundary to where the neighbouring segments meet.

#include <vector>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief The contour with each boundary set to the intersection (or, for circles that touch,
/// the tangent point) of its two neighbours nearest to the current boundary angle. Lines get
/// their end points there too. A joint whose neighbours do not meet is an error naming it.
[[nodiscard]] Result<std::vector<SegmentSpec>> fitWindows(const std::vector<SegmentSpec>& contour);

}  // namespace cam
