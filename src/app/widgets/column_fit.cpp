#include "widgets/column_fit.h"

#include <QHeaderView>
#include <QTableView>
#include <algorithm>

namespace cam {
namespace {

/// Edits of at most this many rows widen columns by those rows alone; a refresh of more (the
/// whole table's problem colours) changes no text and measures nothing.
constexpr int kRowsMeasuredPerEdit = 8;

void widenFor(QTableView* table, int first, int last) {
    if (last - first + 1 > kRowsMeasuredPerEdit) return;
    QAbstractItemModel* model = table->model();
    QHeaderView* header = table->horizontalHeader();
    for (int column = 0; column < model->columnCount(); ++column) {
        if (table->isColumnHidden(column)) continue;
        int needed = header->sectionSize(column);
        for (int row = first; row <= last; ++row) {
            needed = std::max(needed, table->sizeHintForIndex(model->index(row, column)).width());
        }
        if (needed > header->sectionSize(column)) header->resizeSection(column, needed);
    }
}

}  // namespace

void keepColumnsFitting(QTableView* table) {
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    QAbstractItemModel* model = table->model();
    QObject::connect(model, &QAbstractItemModel::modelReset, table,
                     &QTableView::resizeColumnsToContents);
    QObject::connect(
        model, &QAbstractItemModel::rowsInserted, table,
        [table](const QModelIndex&, int first, int last) { widenFor(table, first, last); });
    QObject::connect(model, &QAbstractItemModel::dataChanged, table,
                     [table](const QModelIndex& topLeft, const QModelIndex& bottomRight) {
                         widenFor(table, topLeft.row(), bottomRight.row());
                     });
    table->resizeColumnsToContents();
}

}  // namespace cam
