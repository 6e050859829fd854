#pragma once
/// @file
/// @brief A Project → `.cam.json` text (format version 1), in the units the file had.

#include <string>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief The project as format-v1 JSON, fields in the documented order, unknown top-level keys
/// last, lengths and window angles in Project::units. A value read from a file in metres or
/// radians is written back as the shortest decimal that reads as the same millimetres/degrees,
/// so save → load → save is byte-stable in every unit. Requires every number to be finite
/// (check with nonFiniteValues first).
[[nodiscard]] std::string serializeProject(const Project& project);

/// @brief The fields of the project that hold NaN or an infinity, located; a file cannot hold
/// them (JSON has no such numbers), so such a project must not be saved.
[[nodiscard]] Diagnostics nonFiniteValues(const Project& project);

/// @brief The value to write in a file whose unit is `factor` times the internal unit: the
/// double with the fewest significant digits whose product with `factor` is exactly
/// `internal` (what reading it back computes); x/factor if there is none.
[[nodiscard]] double fileValue(double internal, double factor);

}  // namespace cam
