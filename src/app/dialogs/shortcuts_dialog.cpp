#include "dialogs/shortcuts_dialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

namespace cam {

ShortcutsDialog::ShortcutsDialog(QWidget* window) : QDialog(window) {
    setObjectName("shortcutsDialog");
    setWindowTitle(tr("Keyboard Shortcuts"));
    std::vector<std::pair<QString, QString>> rows;
    for (const QAction* action : window->findChildren<QAction*>()) {
        if (action->shortcut().isEmpty() || action->text().isEmpty()) continue;
        const QVariant title = action->property(kShortcutTitle);
        QString text = title.isValid() ? title.toString() : action->text();
        text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
        text.remove(QChar(0x2026));  // "Export…" → "Export"
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        if (std::find(rows.begin(), rows.end(), std::pair{text, keys}) == rows.end()) {
            rows.emplace_back(text, keys);
        }
    }
    std::sort(rows.begin(), rows.end());
    // Keys that belong to widgets rather than to actions.
    rows.emplace_back(tr("Edit a cell: type, Enter or Tab to take it"),
                      QKeySequence(Qt::Key_Return).toString(QKeySequence::NativeText));
    rows.emplace_back(tr("Cancel a cell's edit"),
                      QKeySequence(Qt::Key_Escape).toString(QKeySequence::NativeText));
    rows.emplace_back(tr("Step a value live"), tr("Up, Down, Page Up, Page Down, wheel"));
    rows.emplace_back(tr("Zoom a plot or the contour"), tr("Mouse wheel"));
    m_table = new QTableWidget(static_cast<int>(rows.size()), 2, this);
    m_table->setObjectName("shortcutsTable");
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Keys")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        m_table->setItem(r, 0, new QTableWidgetItem(rows[static_cast<std::size_t>(r)].first));
        m_table->setItem(r, 1, new QTableWidgetItem(rows[static_cast<std::size_t>(r)].second));
    }
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(520, 560);
}

}  // namespace cam
