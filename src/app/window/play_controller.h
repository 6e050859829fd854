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
    /// @brief Whether Play turns the cam under a follower that stands still (remembered; on
    /// at first) or, off, moves the follower round the cam that stands still.
    [[nodiscard]] QAction* turnCamAction() const { return m_turnCam; }
    /// @brief Play runs and turns the cam.
    [[nodiscard]] bool turning() const;
    [[nodiscard]] QComboBox* speedBox() const { return m_speed; }
    /// @brief The fraction of the real speed Play turns the cam at.
    [[nodiscard]] double speedFactor() const;

signals:
    /// @brief The contour view turns the cam (Play runs with Play Turns the Cam) or not.
    void turningChanged(bool on);

private:
    CursorModel* m_cursor;
    QAction* m_action;
    QAction* m_turnCam;
    QComboBox* m_speed;
    QTimer* m_timer;
    QElapsedTimer m_clock;
};

}  // namespace cam
