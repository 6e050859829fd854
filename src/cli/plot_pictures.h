#pragma once
/// @file
/// @brief `export --format png|pdf|svg --plot NAME`: pictures of the app's plots. They are drawn
/// by the desktop app itself (`camwright --export-plot`, installed beside camwright-cli), so a
/// picture is exactly what the app shows, and camwright-cli links no Qt.

#include <optional>
#include <string>

namespace cam::cli {

/// @brief The plots `--plot` names, as the app knows them.
inline constexpr const char* kPlotNames[] = {"contour",        "velocity", "acceleration",
                                             "jerk",           "feed",     "axis-acceleration",
                                             "pressure-angle", "lift",     "motion"};
/// @brief "contour, velocity, …".
[[nodiscard]] std::string plotNameList();

/// @brief The app to draw with: $CAMWRIGHT_APP if set, else `camwright` in the folder of this
/// executable. None (nothing executable there) gives exit 3 naming where it looked.
[[nodiscard]] std::string pictureApp();

/// @brief Runs `APP --export-plot PLOT --format FORMAT --out OUT [--size SIZE] PROJECT` on the
/// offscreen platform, with stdout and stderr passed through; returns its exit code (the same
/// codes as ours). A crash of the app throws CliError (exit 3).
int drawPlotWithApp(const std::string& project, const std::string& plot, const std::string& format,
                    const std::optional<std::string>& size, const std::string& out);

}  // namespace cam::cli
