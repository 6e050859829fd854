#include "window/play_controller.h"

#include <QAction>
#include <QComboBox>
#include <QSettings>
#include <QTimer>

#include "dialogs/shortcuts_dialog.h"
#include "widgets/icons.h"
#include "widgets/quantity_format.h"
#include "window/cursor_model.h"

namespace cam {

PlayController::PlayController(CursorModel* cursor, QWidget* window)
    : QObject(window), m_cursor(cursor) {
    m_action = new QAction(tr("Play"), window);
    m_action->setObjectName("actionPlay");
    m_action->setCheckable(true);
    m_action->setShortcut(QKeySequence(Qt::Key_F5));
    m_action->setToolTip(tr("Turn the cam with the follower riding it (F5)"));
    m_speed = new QComboBox(window);
    m_speed->setObjectName("playSpeedComboBox");
    m_speed->setToolTip(tr("Play at this fraction of the cam's real speed"));
    for (double factor : {0.01, 0.05, 0.1, 0.25, 0.5, 1.0}) {
        m_speed->addItem(formatQuantity(DisplayQuantity::Ratio, factor) + QStringLiteral("×"),
                         factor);
    }
    const int index = m_speed->findData(QSettings().value("view/playSpeed", 0.05).toDouble());
    m_speed->setCurrentIndex(index >= 0 ? index : 1);
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this] { QSettings().setValue("view/playSpeed", speedFactor()); });
    m_timer = new QTimer(this);
    m_timer->setInterval(16);  // about 60 frames a second
    connect(m_timer, &QTimer::timeout, this, [this] {
        const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) / 1e9;
        m_clock.restart();
        // The cursor's time runs at the chosen fraction of real time; a frame only moves the
        // markers (one state and one follower position at the cursor).
        m_cursor->setTime(m_cursor->time() + elapsed * speedFactor());
    });
    m_action->setProperty(kShortcutTitle, tr("Play / Pause"));
    m_turnCam = new QAction(tr("Play Turns the Cam"), window);
    m_turnCam->setObjectName("actionPlayTurnsCam");
    m_turnCam->setCheckable(true);
    m_turnCam->setIcon(actionIcon("camwright-turning-cam"));
    m_turnCam->setChecked(QSettings().value("view/playTurnsCam", true).toBool());
    m_turnCam->setToolTip(
        tr("Play turns the cam under a follower that stands still, as on the machine; off, "
           "the cam stands still and the follower goes round it"));
    connect(m_turnCam, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/playTurnsCam", on);
        emit turningChanged(turning());
    });
    connect(m_action, &QAction::toggled, this, [this](bool on) {
        emit turningChanged(turning());
        m_action->setText(on ? tr("Pause") : tr("Play"));
        m_action->setIcon(actionIcon(on ? "media-playback-pause" : "media-playback-start"));
        if (on) {
            m_clock.start();
            m_timer->start();
        } else {
            m_timer->stop();
        }
    });
}

bool PlayController::turning() const { return m_action->isChecked() && m_turnCam->isChecked(); }

double PlayController::speedFactor() const { return m_speed->currentData().toDouble(); }

}  // namespace cam
