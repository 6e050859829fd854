#pragma once
/// @file
/// @brief After a crash: the question that offers a dead session's recovery copy (Restore,
/// Discard, or keep it for later) and the restore itself.

#include <QObject>

#include "files/autosave.h"

class QWidget;

namespace cam {

class RecoveryPrompt : public QObject {
    Q_OBJECT
public:
    RecoveryPrompt(Autosave* autosave, QWidget* window);

    /// @brief Offers to restore the newest recovery copy a dead session left. True when a
    /// project was restored.
    bool offer();
    /// @brief Opens a recovery copy as the project it was (its file, unsaved); the copy goes
    /// once this session's own holds it. Problems are shown; true when restored.
    bool restore(const Autosave::Orphan& orphan);

signals:
    /// What the status bar says of it.
    void message(const QString& text, int timeoutMs);

private:
    Autosave* m_autosave;
    QWidget* m_window;
};

}  // namespace cam
