#pragma once
/// @file
/// @brief Autosave and crash recovery. While the document has unsaved changes, a recovery copy
/// is written every 30 s (settings key `autosave/intervalS`; the command line's
/// `--autosave-interval`) to the application's data folder through QSaveFile. Each window owns
/// one copy, named by a random session id (`session-<id>.cam.json`, its note `session-<id>.json`)
/// and guarded by a lock file (`session-<id>.lock`, files/session_lock.h) taken with the first
/// copy and held while the session runs;
/// saving, a new or opened project and a clean exit remove it. A copy whose lock nobody holds
/// was left by a session that crashed or was killed: the next start offers to restore it,
/// whatever process id it is given. A session only ever deletes the files it wrote itself, or
/// those of an ended session whose lock it holds; it removes the lock files ended sessions
/// left without a copy.

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

#include "files/session_lock.h"

namespace cam {

class ProjectDocument;

class Autosave : public QObject {
    Q_OBJECT
public:
    /// @brief Watches `document` and writes its recovery copy into `folder` (default: the
    /// application's data folder + "/recovery").
    explicit Autosave(ProjectDocument* document, QString folder = {}, QObject* parent = nullptr);
    /// Removes this session's copy: the program ends cleanly.
    ~Autosave() override;

    /// @brief Time between recovery copies (at least 10 ms).
    void setIntervalMs(int ms);
    [[nodiscard]] int intervalMs() const { return m_timer.interval(); }
    /// @brief Writes the copy now when there are unsaved changes not yet in it; returns the
    /// problem, or empty.
    QString writeNow();
    [[nodiscard]] QString recoveryPath() const { return m_projectPath; }
    /// @brief Where the note beside the copy names the original file and the time it was saved.
    [[nodiscard]] QString notePath() const { return m_metaPath; }
    [[nodiscard]] QString lockPath() const { return m_lockPath; }
    [[nodiscard]] QString folder() const { return m_folder; }

    /// @brief What a crashed session left behind. While this object lives, its session's lock
    /// is held here: no other starting session offers the same copy.
    struct Orphan {
        QString project;            ///< the recovery copy (.cam.json)
        QString meta;               ///< its companion: the original file and the time
        QString lock;               ///< its lock file (may be missing)
        QString original;           ///< the file the project was saved as (empty: untitled)
        QByteArray originalDigest;  ///< what the session knew that file held (empty: unknown)
        QDateTime saved;            ///< when the copy was written
        std::shared_ptr<SessionLock> claim;  ///< the ended session's lock, held (null: none)
    };
    /// @brief Copies whose session is gone (their lock is free), newest first, each claimed.
    /// Files of ended sessions without a copy (a lock, a note, a half-written temporary) are
    /// removed on the way.
    [[nodiscard]] std::vector<Orphan> orphans() const;
    /// @brief Removes an orphan's files.
    static void discard(const Orphan& orphan);
    /// @brief Restore: the orphan's project becomes the document (unsaved, with its original
    /// file), this session's own copy is written at once, and only then is the orphan removed.
    /// True when the document now holds the copy. `problem` says what went wrong: the copy
    /// could not be read (the document is untouched), or it was restored but this session's
    /// copy could not be written. On any problem the orphan stays where it is.
    bool adopt(const Orphan& orphan, QString* problem);

signals:
    /// A copy was written (or failed: `problem` is not empty).
    void written(const QString& path, const QString& problem);

private:
    void removeOwnCopy();

    ProjectDocument* m_document;
    QString m_folder;
    QString m_projectPath, m_metaPath, m_lockPath;
    std::unique_ptr<SessionLock> m_lock;
    QTimer m_timer;
    quint64 m_changes = 0;    ///< edits seen
    quint64 m_writtenAt = 0;  ///< m_changes when the copy was last written
    bool m_hasCopy = false;   ///< this session wrote the copy at m_projectPath
};

}  // namespace cam
