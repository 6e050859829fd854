#pragma once
/// @file
/// @brief The ranges of the export options every format shares, and their messages.

#include "common/diagnostic.h"

namespace cam {

/// @brief Splines become arcs within a tolerance from this to kMaxExportToleranceMm, mm.
inline constexpr double kMinExportToleranceMm = 1e-6;
inline constexpr double kMaxExportToleranceMm = 1.0;

/// @brief A tolerance outside [1e-6, 1] mm (or not a number), located `--tolerance`.
void checkTolerance(double toleranceMm, Diagnostics& errors);
/// @brief A tool radius that is not in (0, 1e6] mm, located `--tool-radius`.
void checkToolRadius(double radiusMm, Diagnostics& errors);

}  // namespace cam
