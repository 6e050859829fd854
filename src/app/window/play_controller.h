#pragma once
/// @file
/// @brief Play (F5): turns the cam at a fraction of its real speed, the cursor (and the
/// follower on the contour) moving with it; only markers move, nothing is computed.

#include <QElapsedTimer>
#include <QObject>

class QAction;
class QComboBox;
class QTimer;
class QWidget;

namespace cam {

class CursorModel;

class PlayController : public QObject {
    Q_OBJECT
public:
    /// @brief The action and the speed box are children of `window`, for its tool bar and menu.
    PlayController(CursorModel* cursor, QWidget* window);

    [[nodiscard]] QAction* action() const { return m_action; }
    [[nodiscard]] QComboBox* speedBox() const { return m_speed; }
    /// @brief The fraction of the real speed Play turns the cam at.
    [[nodiscard]] double speedFactor() const;

private:
    CursorModel* m_cursor;
    QAction* m_action;
    QComboBox* m_speed;
    QTimer* m_timer;
    QElapsedTimer m_clock;
};

}  // namespace cam
