#pragma once
/// @file
/// @brief View ▸ Cursor: the keys that move the cursor from the contour view and the plots —
/// Left/Right one sample of the turn, Shift+Left/Right the previous or next joint, Home and
/// End the turn's first and last sample. They act where the mouse would: with the focus in
/// the contour view or the plots (a table or a number box keeps its own arrow keys).

#include <QObject>

class QMenu;
class QWidget;

namespace cam {

class CursorModel;

class CursorActions : public QObject {
    Q_OBJECT
public:
    /// @param where the widget whose children's focus the keys act in (the window's centre)
    CursorActions(CursorModel* cursor, QWidget* where, QMenu* menu);
};

}  // namespace cam
