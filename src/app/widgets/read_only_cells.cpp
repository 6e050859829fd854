#include "widgets/read_only_cells.h"

#include <QCoreApplication>
#include <QKeyEvent>
#include <QStatusTipEvent>
#include <QTableView>
#include <QToolTip>

namespace cam {
namespace {

class ReadOnlyCellKeys : public QObject {
public:
    explicit ReadOnlyCellKeys(QTableView* table) : QObject(table), m_table(table) {}

    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched != m_table || event->type() != QEvent::KeyPress) return false;
        const auto* key = static_cast<QKeyEvent*>(event);
        const QString typed = key->text();
        if (typed.isEmpty() || !typed.at(0).isPrint() || typed.at(0).isSpace() ||
            (key->modifiers() & (Qt::ControlModifier | Qt::AltModifier))) {
            return false;
        }
        const QModelIndex current = m_table->currentIndex();
        // (While a cell is edited, its editor has the keys, not the table.)
        if (!current.isValid() || (current.flags() & Qt::ItemIsEditable)) return false;
        const QAbstractItemModel* model = m_table->model();
        const QString cell =
            QCoreApplication::translate("cam::ReadOnlyCells", "%1, row %2")
                .arg(model->headerData(current.column(), Qt::Horizontal).toString(),
                     model->headerData(current.row(), Qt::Vertical).toString());
        const QString why = current.data(Qt::ToolTipRole).toString();
        const QString message =
            why.isEmpty()
                ? QCoreApplication::translate("cam::ReadOnlyCells", "%1 is not typed in.").arg(cell)
                : QCoreApplication::translate("cam::ReadOnlyCells", "%1 is not typed in: %2")
                      .arg(cell, why);
        QStatusTipEvent tip(message);
        QCoreApplication::sendEvent(m_table, &tip);
        const QRect rect = m_table->visualRect(current);
        QToolTip::showText(m_table->viewport()->mapToGlobal(rect.bottomLeft()), message,
                           m_table->viewport(), {}, 8000);
        return true;  // the key is answered
    }

private:
    QTableView* m_table;
};

}  // namespace

void sayWhyCellsAreReadOnly(QTableView* table) {
    table->installEventFilter(new ReadOnlyCellKeys(table));
}

}  // namespace cam
