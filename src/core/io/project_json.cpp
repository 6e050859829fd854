#include "io/project_json.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/json_syntax.h"
#include "project/validate.h"

namespace cam {
namespace {

/// Closes a file descriptor at the end of a scope.
struct FileDescriptor {
    int fd;
    ~FileDescriptor() { ::close(fd); }
};

std::string notARegularFile(mode_t mode) {
    const char* kind = S_ISDIR(mode)    ? "a folder"
                       : S_ISFIFO(mode) ? "a FIFO"
                       : S_ISCHR(mode)  ? "a character device"
                       : S_ISBLK(mode)  ? "a block device"
                       : S_ISSOCK(mode) ? "a socket"
                                        : "a special file";
    return std::string("is ") + kind + ", not a regular file: not read";
}

std::string tooLarge(off_t bytes) {
    char mib[32];
    std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(bytes) / (1 << 20));
    return "is " + std::string(mib) + " MiB (" + std::to_string(bytes) +
           " bytes): files larger than " + std::to_string(kMaxProjectFileBytes >> 20) +
           " MiB are not read";
}

}  // namespace

Result<Project> parseProjectStructure(std::string_view text) {
    Json root;
    Diagnostics syntax = parseJson(text, root);
    if (!syntax.empty()) return syntax;
    return readProject(root);
}

Result<Project> parseProject(std::string_view text) {
    auto project = parseProjectStructure(text);
    if (!project.ok()) return project;
    Diagnostics problems = validateProject(project.value());
    if (hasErrors(problems)) return problems;
    return project;
}

Result<std::string> readTextFile(const std::string& path) {
    auto refuse = [&](std::string message) { return Diagnostics{{path, std::move(message)}}; };
    auto failed = [&](const char* what) {
        return refuse(what + std::string(std::strerror(errno)));
    };
    // Look before opening: opening a device can have effects of its own, and reading /dev/zero
    // or a FIFO never ends.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return failed("cannot open: ");
    if (!S_ISREG(st.st_mode)) return refuse(notARegularFile(st.st_mode));
    if (static_cast<std::uint64_t>(st.st_size) > kMaxProjectFileBytes)
        return refuse(tooLarge(st.st_size));
    // O_NONBLOCK: if a FIFO took the file's place since stat(), open must not wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return failed("cannot open: ");
    const FileDescriptor file{fd};
    if (::fstat(fd, &st) != 0) return failed("cannot examine: ");
    if (!S_ISREG(st.st_mode)) return refuse(notARegularFile(st.st_mode));
    if (static_cast<std::uint64_t>(st.st_size) > kMaxProjectFileBytes)
        return refuse(tooLarge(st.st_size));

    // One byte more than the size: the read that finds the end needs no second buffer. A file
    // that grows while it is read is read up to one byte past the limit, no further.
    std::string text(static_cast<std::size_t>(st.st_size) + 1, '\0');
    std::size_t size = 0;
    for (;;) {
        if (size == text.size()) {
            if (size > kMaxProjectFileBytes) {
                return refuse("grew past " + std::to_string(kMaxProjectFileBytes >> 20) +
                              " MiB while it was read: larger files are not read");
            }
            text.resize(std::min<std::size_t>(2 * size, kMaxProjectFileBytes + 1));
        }
        const ssize_t n = ::read(fd, text.data() + size, text.size() - size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return failed("cannot read: ");
        if (n == 0) break;
        size += static_cast<std::size_t>(n);
    }
    text.resize(size);
    return text;
}

Result<Project> loadProjectStructure(const std::string& path) {
    auto text = readTextFile(path);
    if (!text.ok()) return text.errors();
    return parseProjectStructure(text.value());
}

Result<Project> loadProjectFile(const std::string& path) {
    auto text = readTextFile(path);
    if (!text.ok()) return text.errors();
    return parseProject(text.value());
}

}  // namespace cam
