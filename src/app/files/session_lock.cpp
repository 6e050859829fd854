#include "files/session_lock.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace cam {
namespace {

/// flock with the interruptions retried; true when the lock is ours.
bool tryExclusiveLock(int fd) {
    int rc = 0;
    do {
        rc = ::flock(fd, LOCK_EX | LOCK_NB);
    } while (rc != 0 && errno == EINTR);
    return rc == 0;
}

QString systemError() { return QString::fromLocal8Bit(std::strerror(errno)); }

}  // namespace

std::unique_ptr<SessionLock> SessionLock::create(const QString& path, QString* problem) {
    const QFileInfo target(path);
    const QString hidden =
        target.absolutePath() + QStringLiteral("/.") + target.fileName() + QStringLiteral(".new");
    const QByteArray hiddenName = QFile::encodeName(hidden);
    const int fd = ::open(hiddenName.constData(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    const auto fail = [&](const QString& what) {
        if (problem) *problem = what;
        if (fd >= 0) {
            ::unlink(hiddenName.constData());
            ::close(fd);
        }
        return std::unique_ptr<SessionLock>();
    };
    if (fd < 0) return fail(QStringLiteral("%1: %2").arg(hidden, systemError()));
    if (!tryExclusiveLock(fd)) return fail(QStringLiteral("%1: %2").arg(hidden, systemError()));
    // What QLockFile writes, for a person (or an older Camwright) reading the file: the
    // process id, the program and the host. Only the lock itself is ever trusted.
    const QByteArray info = QByteArray::number(QCoreApplication::applicationPid()) + '\n' +
                            QCoreApplication::applicationName().toUtf8() + '\n' +
                            QSysInfo::machineHostName().toUtf8() + '\n';
    if (::write(fd, info.constData(), static_cast<size_t>(info.size())) != info.size())
        return fail(QStringLiteral("%1: %2").arg(hidden, systemError()));
    if (::rename(hiddenName.constData(), QFile::encodeName(path).constData()) != 0)
        return fail(QStringLiteral("%1: %2").arg(path, systemError()));
    return std::unique_ptr<SessionLock>(new SessionLock(path, fd));
}

std::unique_ptr<SessionLock> SessionLock::claim(const QString& path) {
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return {};
    if (!tryExclusiveLock(fd)) {
        ::close(fd);
        return {};
    }
    return std::unique_ptr<SessionLock>(new SessionLock(path, fd));
}

SessionLock::~SessionLock() {
    if (m_fd >= 0) ::close(m_fd);  // closing the last descriptor drops the lock
}

void SessionLock::removeFile() { QFile::remove(m_path); }

}  // namespace cam
