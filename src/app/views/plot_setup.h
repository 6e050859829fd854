#pragma once
/// @file
/// @brief How the window's plots over a turn (or along the tool's path) are made: panned and
/// zoomed along x only, so that their y range stays the one the view chose, with the tick
/// format of axis_format.h.

class QCustomPlot;
class QString;
class QWidget;

namespace cam {

/// @brief A plot that pans and zooms along x only, named `objectName` (nullptr: unnamed), with
/// `yLabel` on its y axis and every axis in the window's tick format. Its curves, items and
/// x label are the caller's.
[[nodiscard]] QCustomPlot* newAlongXPlot(QWidget* parent, const char* objectName,
                                         const QString& yLabel);

}  // namespace cam
