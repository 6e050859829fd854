#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <utility>

namespace cam {
namespace {

// Linux's own limit for one path lookup (MAXSYMLINKS).
constexpr int kMaxSymlinkHops = 40;

// procfs: its fd links name open files, pipes and terminals, not paths to replace.
constexpr long kProcSuperMagic = 0x9fa0;

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

const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
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

AtomicFileWriter::AtomicFileWriter(std::string path) : m_path(std::move(path)) {
    resolveTarget();
    if (ok()) createTemporary();
}

AtomicFileWriter::~AtomicFileWriter() { discardTemporary(); }

void AtomicFileWriter::fail(const std::string& what, int error) {
    if (m_errors.empty()) m_errors.push_back({m_path, what + ": " + std::strerror(error)});
    discardTemporary();
}

void AtomicFileWriter::discardTemporary() {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
    if (!m_tempPath.empty()) ::unlink(m_tempPath.c_str());
    m_tempPath.clear();
}

void AtomicFileWriter::resolveTarget() {
    if (m_path.empty()) {
        m_errors.push_back({m_path, "no file name given"});
        return;
    }
    std::string current = m_path;
    for (int hops = 0;; ++hops) {
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0) {
            if (errno != ENOENT) {
                fail("cannot examine " + current, errno);
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
                    {m_path, (current == m_path ? "" : current + " ") +
                                 "is a link to an open file descriptor, not a file: not replaced"});
                return;
            }
            if (hops == kMaxSymlinkHops) {
                fail("cannot follow its symbolic links", ELOOP);
                return;
            }
            std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
            const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
            if (n < 0) {
                fail("cannot read the symbolic link " + current, errno);
                return;
            }
            if (n == 0 || static_cast<std::size_t>(n) >= link.size()) {
                fail("cannot read the symbolic link " + current, ENAMETOOLONG);
                return;
            }
            link.resize(static_cast<std::size_t>(n));
            // A relative link is relative to the folder that holds the link.
            current = link.front() == '/' ? link : folderOf(current) + "/" + link;
            continue;
        }
        if (!S_ISREG(st.st_mode)) {
            m_errors.push_back({m_path, (current == m_path ? "" : current + " ") + "is " +
                                            kindOf(st.st_mode) +
                                            ", not a regular file: not replaced"});
            return;
        }
        // A read-only file says "do not change me"; the folder's permissions alone would allow
        // the rename.
        if (::faccessat(AT_FDCWD, current.c_str(), W_OK, AT_EACCESS) != 0) {
            fail("cannot write " + current, errno);
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
        m_errors.push_back({m_path, "names a folder, not a file"});
        return;
    }
    // An existing target's owner is copied here, its mode in commit(); until then the temporary
    // file is private. A new file gets 0666 & ~umask (and any default ACL) from the kernel.
    const mode_t createMode = m_targetExists ? 0600 : 0666;
    const std::string prefix = (folder == "/" ? "/" : folder + "/") + "." + name + ".camwright-";
    for (int attempt = 0; attempt < 100 && m_fd < 0; ++attempt) {
        std::string temp = prefix + randomSuffix();
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, createMode);
        if (fd >= 0) {
            m_fd = fd;
            m_tempPath = std::move(temp);
        } else if (errno != EEXIST) {
            fail("cannot create a temporary file in " + folder, errno);
            return;
        }
    }
    if (m_fd < 0) {
        fail("cannot create a temporary file in " + folder, EEXIST);
        return;
    }
    if (!m_targetExists) return;
    if (::fchown(m_fd, m_uid, m_gid) != 0) {
        // Not permitted to give the file away: keep at least the group if we may.
        if (errno != EPERM ||
            (::fchown(m_fd, static_cast<uid_t>(-1), m_gid) != 0 && errno != EPERM)) {
            fail("cannot give the new file the owner of " + m_resolvedPath, errno);
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
            fail("cannot write " + m_resolvedPath, errno);
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
        fail("cannot give the new file the permissions of " + m_resolvedPath, errno);
        return m_errors;
    }
    if (::fsync(m_fd) != 0) {
        fail("cannot flush " + m_resolvedPath + " to disk", errno);
        return m_errors;
    }
    const int fd = std::exchange(m_fd, -1);
    if (::close(fd) != 0) {
        fail("cannot write " + m_resolvedPath, errno);
        return m_errors;
    }
    // Something may have appeared in its place while we wrote; replace only a regular file.
    struct stat st {};
    if (::lstat(m_resolvedPath.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        m_errors.push_back({m_path, m_resolvedPath + " became " + kindOf(st.st_mode) +
                                        " while it was written: not replaced"});
        discardTemporary();
        return m_errors;
    }
    if (::rename(m_tempPath.c_str(), m_resolvedPath.c_str()) != 0) {
        fail("cannot replace " + m_resolvedPath, errno);
        return m_errors;
    }
    m_tempPath.clear();  // it is the target now
    // Make the rename itself durable. Some file systems cannot fsync a folder (EINVAL): there is
    // nothing more to do on those.
    const std::string folder = folderOf(m_resolvedPath);
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0 || (::fsync(dir) != 0 && errno != EINVAL)) {
        fail("replaced, but cannot flush the folder " + folder + " to disk", errno);
    }
    if (dir >= 0) ::close(dir);
    return m_errors;
}

Diagnostics writeFileAtomically(const std::string& path, std::string_view content) {
    AtomicFileWriter writer(path);
    writer.write(content);
    return writer.commit();
}

}  // namespace cam
