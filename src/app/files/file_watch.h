#pragma once
/// @file
/// @brief The open project's file on disk. The document keeps the digest of the content this
/// window last read or wrote (ProjectDocument::fileDigest); FileWatch watches the file and its
/// folder (an atomic replace is a new file in the folder) and says when what is on disk is no
/// longer that content, once per new content. It also marks the file "open in a Camwright
/// window" with a shared advisory lock (flock) held while it is the document's file, which any
/// window of any process can test, and the kernel drops when the process ends.

#include <sys/types.h>
#include <QByteArray>
#include <QFileSystemWatcher>
#include <QObject>
#include <QString>
#include <QTimer>

namespace cam {

class ProjectDocument;

/// @brief What is on disk at the document's file, compared with what the window knows.
enum class DiskState {
    Same,     ///< the content this window last read or wrote (or no file and none known)
    Changed,  ///< other content
    Removed,  ///< no file there (deleted, or moved away)
};

class FileWatch : public QObject {
    Q_OBJECT
public:
    explicit FileWatch(ProjectDocument* document, QObject* parent = nullptr);
    ~FileWatch() override;

    /// @brief Reads the file now (the whole of it) and compares it with what the window knows.
    [[nodiscard]] DiskState check() const;
    /// @brief SHA-256 of content, as the document keeps it.
    [[nodiscard]] static QByteArray digest(const QByteArray& content);
    /// @brief SHA-256 of the file's content now; empty when it cannot be read.
    [[nodiscard]] static QByteArray digestOfFile(const QString& path);
    /// @brief Whether a Camwright window other than this one has `path` open (its shared
    /// lock is held), in this process or another.
    [[nodiscard]] bool isOpenElsewhere(const QString& path) const;

signals:
    /// The file on disk no longer holds what the window knows: emitted once for each new
    /// content (or removal), after the file system has been quiet for a moment.
    void changedOnDisk(DiskState state);

private:
    void follow();  ///< the document's file changed: watch the new one
    void settle();  ///< something happened in the file or its folder: look once it is quiet
    void look();
    void mark();  ///< the shared lock on the file's current inode
    void unmark();

    ProjectDocument* m_document;
    QFileSystemWatcher m_watcher;
    QTimer m_quiet;
    QString m_path;
    /// What the last look found, to skip reading a file nobody touched: size, time, inode.
    struct Stat {
        bool exists = false;
        qint64 size = -1;
        qint64 mtimeNs = -1;
        quint64 inode = 0;
        bool operator==(const Stat&) const = default;
    };
    [[nodiscard]] Stat statOf() const;
    Stat m_seen;
    QByteArray m_reported;  ///< digest of the disk content last reported ("-" for removal)
    int m_markFd = -1;
    quint64 m_markInode = 0;
};

}  // namespace cam
