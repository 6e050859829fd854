#pragma once
/// @file
/// @brief Table columns that fit their contents without measuring the whole table on every
/// edit.

class QTableView;

namespace cam {

/// @brief The columns of `table` fit their contents when its model is reset (a project loaded)
/// and when rows are inserted; an edit of a few rows only widens a column whose new text needs
/// more room. QHeaderView::ResizeToContents measured every cell of the table on every edit
/// (0.8 ms for 13 rows, linear in the rows), and the columns jumped while the user typed. The
/// user may still drag a column's width.
void keepColumnsFitting(QTableView* table);

}  // namespace cam
