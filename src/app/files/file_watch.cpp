#include "files/file_watch.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <cerrno>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "document/project_document.h"

namespace cam {
namespace {

/// Quiet time before a change is looked at: a writer's temporary file, rename and folder
/// sync come as a burst.
constexpr int kQuietMs = 150;
/// Stands for "no file" among the digests already reported.
const QByteArray kRemoved = QByteArrayLiteral("-");

}  // namespace

FileWatch::FileWatch(ProjectDocument* document, QObject* parent)
    : QObject(parent), m_document(document) {
    m_quiet.setSingleShot(true);
    m_quiet.setInterval(kQuietMs);
    connect(&m_quiet, &QTimer::timeout, this, &FileWatch::look);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &FileWatch::settle);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, this, &FileWatch::settle);
    connect(document, &ProjectDocument::filePathChanged, this, &FileWatch::follow);
    follow();
}

FileWatch::~FileWatch() { unmark(); }

QByteArray FileWatch::digest(const QByteArray& content) {
    return QCryptographicHash::hash(content, QCryptographicHash::Sha256);
}

QByteArray FileWatch::digestOfFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&file)) return {};
    return hash.result();
}

FileWatch::Stat FileWatch::statOf() const {
    struct stat s {};
    if (m_path.isEmpty() || ::stat(QFile::encodeName(m_path).constData(), &s) != 0) return {};
    return {true, static_cast<qint64>(s.st_size),
            static_cast<qint64>(s.st_mtim.tv_sec) * 1000000000 + s.st_mtim.tv_nsec,
            static_cast<quint64>(s.st_ino)};
}

DiskState FileWatch::check() const {
    if (m_path.isEmpty()) return DiskState::Same;
    if (!QFileInfo::exists(m_path)) return DiskState::Removed;
    const QByteArray known = m_document->fileDigest();
    // Nothing known of it (a project restored without its file's digest): nothing to lose.
    if (known.isEmpty()) return DiskState::Same;
    return digestOfFile(m_path) == known ? DiskState::Same : DiskState::Changed;
}

bool FileWatch::isOpenElsewhere(const QString& path) const {
    const QByteArray name = QFile::encodeName(path);
    const int fd = ::open(name.constData(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return false;
    bool elsewhere = false;
    int rc = 0;
    do {
        rc = ::flock(fd, LOCK_EX | LOCK_NB);
    } while (rc != 0 && errno == EINTR);
    if (rc == 0) {
        ::flock(fd, LOCK_UN);
    } else {
        // Held: by another window, unless it is only this window's own mark.
        struct stat s {};
        const bool ours =
            m_markFd >= 0 && ::fstat(fd, &s) == 0 && static_cast<quint64>(s.st_ino) == m_markInode;
        if (ours) {
            // Drop ours for a moment: whether anybody else still holds it.
            ::flock(m_markFd, LOCK_UN);
            do {
                rc = ::flock(fd, LOCK_EX | LOCK_NB);
            } while (rc != 0 && errno == EINTR);
            elsewhere = rc != 0;
            if (rc == 0) ::flock(fd, LOCK_UN);
            ::flock(m_markFd, LOCK_SH | LOCK_NB);
        } else {
            elsewhere = true;
        }
    }
    ::close(fd);
    return elsewhere;
}

void FileWatch::follow() {
    const QString path = m_document->filePath();
    if (path == m_path) return;
    if (!m_watcher.files().isEmpty()) m_watcher.removePaths(m_watcher.files());
    if (!m_watcher.directories().isEmpty()) m_watcher.removePaths(m_watcher.directories());
    unmark();
    m_path = path;
    m_reported.clear();
    m_seen = statOf();
    if (m_path.isEmpty()) return;
    m_watcher.addPath(QFileInfo(m_path).absolutePath());
    if (m_seen.exists) m_watcher.addPath(m_path);
    mark();
}

void FileWatch::settle() { m_quiet.start(); }

void FileWatch::look() {
    if (m_path.isEmpty()) return;
    // A replaced file is a new inode: watch and mark the one now there.
    if (QFileInfo::exists(m_path) && !m_watcher.files().contains(m_path)) m_watcher.addPath(m_path);
    const Stat now = statOf();
    if (now == m_seen) return;
    m_seen = now;
    if (now.inode != m_markInode) mark();
    const QByteArray onDisk = now.exists ? digestOfFile(m_path) : kRemoved;
    if (onDisk.isEmpty()) return;  // unreadable for now: look again at its next change
    if (onDisk == m_document->fileDigest() || m_document->fileDigest().isEmpty()) {
        m_reported.clear();  // back to what the window knows
        return;
    }
    if (onDisk == m_reported) return;
    m_reported = onDisk;
    emit changedOnDisk(now.exists ? DiskState::Changed : DiskState::Removed);
}

void FileWatch::mark() {
    unmark();
    if (m_path.isEmpty()) return;
    const int fd = ::open(QFile::encodeName(m_path).constData(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return;
    struct stat s {};
    if (::fstat(fd, &s) != 0 || !S_ISREG(s.st_mode) || ::flock(fd, LOCK_SH | LOCK_NB) != 0) {
        ::close(fd);
        return;
    }
    m_markFd = fd;
    m_markInode = static_cast<quint64>(s.st_ino);
}

void FileWatch::unmark() {
    if (m_markFd >= 0) ::close(m_markFd);
    m_markFd = -1;
    m_markInode = 0;
}

}  // namespace cam
