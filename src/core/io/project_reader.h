#pragma once
/// @file
/// @brief A parsed `.cam.json` document → the Project it describes (format version 1).

#include "common/diagnostic.h"
#include "io/json_syntax.h"
#include "project/project.h"

namespace cam {

inline constexpr int kProjectFormatVersion = 1;

/// @brief The project a parsed file describes, converted to mm and degrees, its units kept in
/// Project::units. Checks structure only: format and version, every field present where
/// required and of the right type, no unknown key inside a known object (a typo must not
/// vanish). Every problem is located by its JSON path. The geometric rules (windows, joints,
/// ranges) are validateProject's: a structurally sound file with geometric problems reads.
[[nodiscard]] Result<Project> readProject(const Json& root);

}  // namespace cam
