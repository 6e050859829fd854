#pragma once
/// @file
/// @brief Autosave and crash recovery. While the document has unsaved changes, a recovery copy
/// is written every 30 s (settings key `autosave/intervalS`; the command line's
/// `--autosave-interval`) to the application's data folder through QSaveFile. Each running
/// window owns one copy, named by its process id and guarded by a QLockFile held while it runs;
/// saving, a new or opened project and a clean exit remove it. A copy whose lock nobody holds
/// was left by a session that crashed or was killed: the next start offers to restore it.

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

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
    [[nodiscard]] QString folder() const { return m_folder; }

    /// @brief What a crashed session left behind.
    struct Orphan {
        QString project;   ///< the recovery copy (.cam.json)
        QString meta;      ///< its companion: the original file and the time
        QString lock;      ///< its lock file
        QString original;  ///< the file the project was saved as (empty: untitled)
        QDateTime saved;   ///< when the copy was written
    };
    /// @brief Copies whose session is gone (their lock is free), newest first.
    [[nodiscard]] std::vector<Orphan> orphans() const;
    /// @brief Removes an orphan's files.
    static void discard(const Orphan& orphan);

signals:
    /// A copy was written (or failed: `problem` is not empty).
    void written(const QString& path, const QString& problem);

private:
    void removeOwnCopy();

    ProjectDocument* m_document;
    QString m_folder;
    QString m_projectPath, m_metaPath;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    quint64 m_changes = 0;    ///< edits seen
    quint64 m_writtenAt = 0;  ///< m_changes when the copy was last written
    bool m_hasCopy = false;
};

}  // namespace cam
