#pragma once
/// @file
/// @brief A key typed into a table cell that cannot be edited is answered, not swallowed.

class QTableView;

namespace cam {

/// @brief When a printable key is pressed on a current cell of `table` that is not editable,
/// the status bar and a tooltip say which cell and why it is not typed in: the cell's own
/// tooltip, which for a computed cell says what it follows from (issue 31: typing into a
/// read-only cell was lost without a word).
void sayWhyCellsAreReadOnly(QTableView* table);

}  // namespace cam
