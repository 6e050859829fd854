#include "io/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <random>
#include <utility>

#include "common/translate_marker.h"

namespace cam {
namespace {

// Linux's own limit for one path lookup (MAXSYMLINKS).
constexpr int kMaxSymlinkHops = 40;

// The temporary file of target "name" is ".name" + kTempInfix + six letters or digits +
// kTempSuffix; nothing else in the folder is ever removed.
constexpr std::string_view kTempInfix = ".camwright-";
constexpr std::string_view kTempSuffix = ".tmp";
constexpr std::size_t kRandomChars = 6;

// procfs: its fd links name open files, pipes and terminals, not paths to replace.
constexpr long kProcSuperMagic = 0x9fa0;

bool isTemporaryOf(std::string_view entry, const std::string& name) {
    const std::size_t prefix = 1 + name.size() + kTempInfix.size();
    if (entry.size() != prefix + kRandomChars + kTempSuffix.size()) return false;
    if (entry[0] != '.' || entry.substr(1, name.size()) != name ||
        entry.substr(1 + name.size(), kTempInfix.size()) != kTempInfix ||
        entry.substr(prefix + kRandomChars) != kTempSuffix) {
        return false;
    }
    for (const char c : entry.substr(prefix, kRandomChars)) {
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))) {
            return false;
        }
    }
    return true;
}

bool sameFile(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The temporary files in progress, for the signal handler: fixed storage (a handler may not
// allocate, and must never read memory being freed), claimed and released with atomics.
// state: 0 free, 1 being filled, 2 armed (path complete, removed on a signal).
struct SignalSlot {
    std::atomic<int> state{0};
    char path[PATH_MAX];
};
constexpr int kSignalSlots = 16;
SignalSlot g_signalSlots[kSignalSlots];
constexpr int kCleanedSignals[] = {SIGINT, SIGTERM, SIGHUP};

int armSignalSlot(const std::string& path) {
    if (path.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSignalSlots; ++i) {
        int expected = 0;
        if (g_signalSlots[i].state.compare_exchange_strong(expected, 1)) {
            std::memcpy(g_signalSlots[i].path, path.c_str(), path.size() + 1);
            g_signalSlots[i].state.store(2);
            return i;
        }
    }
    return -1;  // more writers at once than slots: a signal leaves this one to the next writer
}

void releaseSignalSlot(int& slot) {
    if (slot >= 0) g_signalSlots[slot].state.store(0);
    slot = -1;
}

/// Holds back SIGINT, SIGTERM and SIGHUP in this thread for the scope; a signal that arrives
/// meanwhile is delivered when the scope ends.
class BlockedCleanedSignals {
public:
    BlockedCleanedSignals() {
        sigset_t set;
        sigemptyset(&set);
        for (const int signal : kCleanedSignals) sigaddset(&set, signal);
        ::pthread_sigmask(SIG_BLOCK, &set, &m_previous);
    }
    ~BlockedCleanedSignals() { ::pthread_sigmask(SIG_SETMASK, &m_previous, nullptr); }
    BlockedCleanedSignals(const BlockedCleanedSignals&) = delete;
    BlockedCleanedSignals& operator=(const BlockedCleanedSignals&) = delete;

private:
    sigset_t m_previous{};
};

extern "C" void removeTemporariesAndDie(int signal) {
    const int savedErrno = errno;
    for (SignalSlot& slot : g_signalSlots) {
        if (slot.state.load() == 2) ::unlink(slot.path);
    }
    errno = savedErrno;
    // SA_RESETHAND has restored the default action; the signal is blocked until this handler
    // returns, and then ends the program as it would have without the handler.
    ::raise(signal);
}

std::string folderOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string randomSuffix() {
    static constexpr char kChars[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::random_device device;
    std::uniform_int_distribution<std::size_t> pick(0, sizeof(kChars) - 2);
    std::string out(6, 'X');
    for (char& c : out) c = kChars[pick(device)];
    return out;
}

}  // namespace

const char* fileKindName(mode_t mode) {
    if (S_ISDIR(mode)) return CAM_TRANSLATE_NOOP("Diagnostic", "a folder");
    if (S_ISFIFO(mode)) return CAM_TRANSLATE_NOOP("Diagnostic", "a FIFO");
    if (S_ISCHR(mode)) return CAM_TRANSLATE_NOOP("Diagnostic", "a character device");
    if (S_ISBLK(mode)) return CAM_TRANSLATE_NOOP("Diagnostic", "a block device");
    if (S_ISSOCK(mode)) return CAM_TRANSLATE_NOOP("Diagnostic", "a socket");
    return CAM_TRANSLATE_NOOP("Diagnostic", "a special file");
}

AtomicFileWriter::AtomicFileWriter(std::string path) : m_path(std::move(path)) {
    resolveTarget();
    if (ok()) createTemporary();
}

AtomicFileWriter::~AtomicFileWriter() { discardTemporary(); }

void AtomicFileWriter::fail(DiagnosticCode code, int error, std::vector<DiagnosticArg> args) {
    if (m_errors.empty()) {
        args.emplace_back(std::strerror(error));  // the OS's own words
        m_errors.push_back(Diagnostic::make(FilePlace{m_path}, code, std::move(args)));
    }
    discardTemporary();
}

void AtomicFileWriter::discardTemporary() {
    // Removed while still locked: no other writer can take it for a leftover meanwhile.
    if (!m_tempPath.empty()) ::unlink(m_tempPath.c_str());
    m_tempPath.clear();
    releaseSignalSlot(m_signalSlot);
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
}

void AtomicFileWriter::removeStaleTemporaries(const std::string& folder,
                                              const std::string& name) const {
    DIR* dir = ::opendir(folder.c_str());
    if (dir == nullptr) return;  // creating the temporary file will say what is wrong
    const std::string prefix = folder == "/" ? "/" : folder + "/";
    while (const dirent* entry = ::readdir(dir)) {
        if (!isTemporaryOf(entry->d_name, name)) continue;
        const std::string path = prefix + entry->d_name;
        const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) continue;  // not ours to judge (another user's), or already gone
        struct stat opened {
        }, named{};
        // Unlocked means its writer is gone: a live writer holds the lock until its rename. The
        // name must still be the file we locked (another writer may have removed it and a new
        // one taken the name) when it is removed.
        if (::fstat(fd, &opened) == 0 && S_ISREG(opened.st_mode) &&
            ::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::lstat(path.c_str(), &named) == 0 &&
            sameFile(opened, named)) {
            ::unlink(path.c_str());
        }
        ::close(fd);
    }
    ::closedir(dir);
}

void AtomicFileWriter::resolveTarget() {
    if (m_path.empty()) {
        m_errors.push_back(Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileNoName));
        return;
    }
    std::string current = m_path;
    for (int hops = 0;; ++hops) {
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0) {
            if (errno != ENOENT) {
                fail(DiagnosticCode::FileCannotExamine, errno, {current});
                return;
            }
            // Nothing there (also the end of a dangling symlink): a new file is created.
            m_resolvedPath = current;
            return;
        }
        if (S_ISLNK(st.st_mode)) {
            struct statfs fs {};
            if (::statfs(folderOf(current).c_str(), &fs) == 0 &&
                static_cast<long>(fs.f_type) == kProcSuperMagic) {
                m_errors.push_back(
                    current == m_path
                        ? Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileIsDescriptorLink)
                        : Diagnostic::make(FilePlace{m_path},
                                           DiagnosticCode::FileLinkTargetIsDescriptorLink,
                                           {current}));
                return;
            }
            if (hops == kMaxSymlinkHops) {
                fail(DiagnosticCode::FileLinkLoop, ELOOP, {});
                return;
            }
            std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
            const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
            if (n < 0) {
                fail(DiagnosticCode::FileCannotReadLink, errno, {current});
                return;
            }
            if (n == 0 || static_cast<std::size_t>(n) >= link.size()) {
                fail(DiagnosticCode::FileCannotReadLink, ENAMETOOLONG, {current});
                return;
            }
            link.resize(static_cast<std::size_t>(n));
            // A relative link is relative to the folder that holds the link.
            current = link.front() == '/' ? link : folderOf(current) + "/" + link;
            continue;
        }
        if (!S_ISREG(st.st_mode)) {
            const std::string kind = fileKindName(st.st_mode);
            m_errors.push_back(
                current == m_path
                    ? Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileNotRegular, {kind})
                    : Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileLinkTargetNotRegular,
                                       {current, kind}));
            return;
        }
        // A read-only file says "do not change me"; the folder's permissions alone would allow
        // the rename.
        if (::faccessat(AT_FDCWD, current.c_str(), W_OK, AT_EACCESS) != 0) {
            fail(DiagnosticCode::FileCannotWrite, errno, {current});
            return;
        }
        m_resolvedPath = current;
        m_targetExists = true;
        m_mode = st.st_mode & 07777;
        m_uid = st.st_uid;
        m_gid = st.st_gid;
        return;
    }
}

void AtomicFileWriter::createTemporary() {
    const std::string folder = folderOf(m_resolvedPath);
    const std::string name = nameOf(m_resolvedPath);
    if (name.empty() || name == "." || name == "..") {
        m_errors.push_back(Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileNamesFolder));
        return;
    }
    removeStaleTemporaries(folder, name);
    // An existing target's owner is copied here, its mode in commit(); until then the temporary
    // file is private. A new file gets 0666 & ~umask (and any default ACL) from the kernel.
    const mode_t createMode = m_targetExists ? 0600 : 0666;
    const std::string prefix =
        (folder == "/" ? "/" : folder + "/") + "." + name + std::string(kTempInfix);
    for (int attempt = 0; attempt < 100 && m_fd < 0; ++attempt) {
        std::string temp = prefix + randomSuffix() + std::string(kTempSuffix);
        // Created and made known to the signal handler with the cleaned signals blocked: a
        // Ctrl+C in between would otherwise leave a file the handler does not know about.
        int fd = -1;
        int openError = 0;
        {
            const BlockedCleanedSignals blocked;
            fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, createMode);
            openError = errno;
            if (fd >= 0) m_signalSlot = armSignalSlot(temp);
        }
        if (fd < 0) {
            if (openError == EEXIST) continue;
            fail(DiagnosticCode::FileCannotCreateTemporary, openError, {folder});
            return;
        }
        // Locked for as long as it is written. Another writer's cleanup may have locked and
        // removed it between open and flock (it looked like a leftover): then take a new name.
        // Where there are no locks (an NFS mount without lockd) it is written unlocked, and
        // nobody's cleanup can judge it either.
        while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
        }
        struct stat opened {
        }, named{};
        if (::fstat(fd, &opened) != 0 || ::lstat(temp.c_str(), &named) != 0 ||
            !sameFile(opened, named)) {
            releaseSignalSlot(m_signalSlot);
            ::close(fd);
            continue;
        }
        m_fd = fd;
        m_tempPath = std::move(temp);
    }
    if (m_fd < 0) {
        fail(DiagnosticCode::FileCannotCreateTemporary, EEXIST, {folder});
        return;
    }
    if (!m_targetExists) return;
    if (::fchown(m_fd, m_uid, m_gid) != 0) {
        // Not permitted to give the file away: keep at least the group if we may.
        if (errno != EPERM ||
            (::fchown(m_fd, static_cast<uid_t>(-1), m_gid) != 0 && errno != EPERM)) {
            fail(DiagnosticCode::FileCannotCopyOwner, errno, {m_resolvedPath});
            return;
        }
    }
}

void AtomicFileWriter::write(std::string_view chunk) {
    if (m_committed) return;
    while (ok() && !chunk.empty()) {
        const ssize_t n = ::write(m_fd, chunk.data(), chunk.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(DiagnosticCode::FileCannotWrite, errno, {m_resolvedPath});
            return;
        }
        chunk.remove_prefix(static_cast<std::size_t>(n));
    }
}

Diagnostics AtomicFileWriter::commit() {
    if (m_committed) return m_errors;
    m_committed = true;
    if (!ok()) return m_errors;
    // The mode is set last: a write by an unprivileged process clears set-id bits.
    if (m_targetExists && ::fchmod(m_fd, m_mode) != 0) {
        fail(DiagnosticCode::FileCannotCopyPermissions, errno, {m_resolvedPath});
        return m_errors;
    }
    if (::fsync(m_fd) != 0) {
        fail(DiagnosticCode::FileCannotFlush, errno, {m_resolvedPath});
        return m_errors;
    }
    // Something may have appeared in its place while we wrote; replace only a regular file.
    struct stat st {};
    if (::lstat(m_resolvedPath.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        m_errors.push_back(Diagnostic::make(FilePlace{m_path}, DiagnosticCode::FileBecameOther,
                                            {m_resolvedPath, fileKindName(st.st_mode)}));
        discardTemporary();
        return m_errors;
    }
    // Renamed while still open and locked: until then it must not look like a leftover.
    if (::rename(m_tempPath.c_str(), m_resolvedPath.c_str()) != 0) {
        fail(DiagnosticCode::FileCannotReplace, errno, {m_resolvedPath});
        return m_errors;
    }
    m_tempPath.clear();  // it is the target now
    releaseSignalSlot(m_signalSlot);
    // fsync succeeded, so the content is on disk; a failing close would still be news.
    if (::close(std::exchange(m_fd, -1)) != 0 && errno != EINTR) {
        fail(DiagnosticCode::FileReplacedCannotClose, errno, {m_resolvedPath});
        return m_errors;
    }
    // Make the rename itself durable. Some file systems cannot fsync a folder (EINVAL): there is
    // nothing more to do on those.
    const std::string folder = folderOf(m_resolvedPath);
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0 || (::fsync(dir) != 0 && errno != EINVAL)) {
        fail(DiagnosticCode::FileReplacedCannotFlushFolder, errno, {folder});
    }
    if (dir >= 0) ::close(dir);
    return m_errors;
}

void installTemporaryFileCleanup() {
    for (const int signal : kCleanedSignals) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL ||
            (current.sa_flags & SA_SIGINFO) != 0) {
            continue;  // ignored or handled by someone else: not ours to change
        }
        struct sigaction action {};
        action.sa_handler = removeTemporariesAndDie;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESETHAND;
        ::sigaction(signal, &action, nullptr);
    }
}

Diagnostics writeFileAtomically(const std::string& path, std::string_view content) {
    AtomicFileWriter writer(path);
    writer.write(content);
    return writer.commit();
}

}  // namespace cam
