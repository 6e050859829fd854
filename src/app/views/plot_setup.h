#pragma once
/// @file
/// @brief How the window's plots over a turn (or along the tool's path) are made: panned and
/// zoomed along x only, so that their y range stays the one the view chose, with the tick
/// format of axis_format.h.

class QCPGraph;
class QCustomPlot;
class QString;
class QWidget;

namespace cam {

/// @brief A plot that pans and zooms along x only, named `objectName` (nullptr: unnamed), with
/// `yLabel` on its y axis and every axis in the window's tick format. Its curves, items and
/// x label are the caller's.
[[nodiscard]] QCustomPlot* newAlongXPlot(QWidget* parent, const char* objectName,
                                         const QString& yLabel);

/// @brief Empties `graph` by giving it a container of its own: the one it draws may be a
/// result's prepared data, shared with other graphs and drawn again later (clearing it would
/// empty them all).
void clearGraph(QCPGraph* graph);

}  // namespace cam
