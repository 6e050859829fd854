#pragma once
/// @file
/// @brief Help → Keyboard Shortcuts: every action of the window that has a shortcut, with it,
/// and the keys of the tables and plots that belong to no action.

#include <QDialog>

class QTableWidget;

namespace cam {

/// @brief The name of an action's property that titles it in the list when its text changes
/// as the window is used (Undo's names the next step, Play's turns into Pause).
inline constexpr char kShortcutTitle[] = "shortcutTitle";

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    /// @brief Lists the shortcuts of `window`'s actions as they are now.
    explicit ShortcutsDialog(QWidget* window);
    [[nodiscard]] QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table;
};

}  // namespace cam
