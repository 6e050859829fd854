#pragma once
/// @file
/// @brief Whether the session that wrote a recovery copy still runs, told by the kernel: an
/// exclusive advisory lock (flock) on a file, held for as long as the session lives and dropped
/// by the kernel however the process ends (exit, crash, SIGKILL). Nothing depends on process
/// ids, which the next session may be given again (containers, systemd) or which a thread of a
/// live process may carry. Qt's QLockFile holds the same flock on its file while it lives, so a
/// copy of an older Camwright (session-PID-N.lock) is told alive or dead the same way.

#include <QString>
#include <memory>

namespace cam {

class SessionLock {
public:
    /// @brief Creates `path` and holds its lock. The file is made and locked under a hidden
    /// name, then renamed into place: no other session ever finds it unlocked (and removes it
    /// as stale). Null, with `problem` set, when it cannot be made.
    static std::unique_ptr<SessionLock> create(const QString& path, QString* problem = nullptr);
    /// @brief Takes the lock of an existing file whose owner has ended: null when another
    /// process (or another holder in this one) holds it, or when there is no such file.
    static std::unique_ptr<SessionLock> claim(const QString& path);

    SessionLock(const SessionLock&) = delete;
    SessionLock& operator=(const SessionLock&) = delete;
    /// Releases the lock (the file stays).
    ~SessionLock();

    [[nodiscard]] const QString& path() const { return m_path; }
    /// @brief Deletes the file while still holding its lock, so nobody can take it in between.
    void removeFile();

private:
    SessionLock(QString path, int fd) : m_path(std::move(path)), m_fd(fd) {}

    QString m_path;
    int m_fd = -1;
};

}  // namespace cam
