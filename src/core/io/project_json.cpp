#include "io/project_json.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "evaluation/evaluation.h"
#include "io/atomic_file.h"
#include "io/json_syntax.h"

namespace cam {
namespace {

/// Closes a file descriptor at the end of a scope.
struct FileDescriptor {
    int fd;
    ~FileDescriptor() { ::close(fd); }
};

Diagnostic notARegularFile(const std::string& path, mode_t mode) {
    return Diagnostic::make(FilePlace{path}, DiagnosticCode::FileNotRegularToRead,
                            {fileKindName(mode)});
}

Diagnostic tooLarge(const std::string& path, off_t bytes) {
    return Diagnostic::make(FilePlace{path}, DiagnosticCode::FileTooLargeToRead,
                            {static_cast<double>(bytes) / (1 << 20), static_cast<double>(bytes),
                             static_cast<double>(kMaxProjectFileBytes >> 20)});
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
    Diagnostics problems = documentProblems(project.value());
    if (hasErrors(problems)) return problems;
    return project;
}

Result<std::string> readTextFile(const std::string& path) {
    auto refuse = [&](Diagnostic problem) { return Diagnostics{std::move(problem)}; };
    // The OS's own words stay an argument as they are.
    auto failed = [&](DiagnosticCode code) {
        return refuse(Diagnostic::make(FilePlace{path}, code, {std::strerror(errno)}));
    };
    // Look before opening: opening a device can have effects of its own, and reading /dev/zero
    // or a FIFO never ends.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return failed(DiagnosticCode::FileCannotOpen);
    if (!S_ISREG(st.st_mode)) return refuse(notARegularFile(path, st.st_mode));
    if (static_cast<std::uint64_t>(st.st_size) > kMaxProjectFileBytes)
        return refuse(tooLarge(path, st.st_size));
    // O_NONBLOCK: if a FIFO took the file's place since stat(), open must not wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return failed(DiagnosticCode::FileCannotOpen);
    const FileDescriptor file{fd};
    if (::fstat(fd, &st) != 0) return failed(DiagnosticCode::FileCannotExamineOpen);
    if (!S_ISREG(st.st_mode)) return refuse(notARegularFile(path, st.st_mode));
    if (static_cast<std::uint64_t>(st.st_size) > kMaxProjectFileBytes)
        return refuse(tooLarge(path, st.st_size));

    // One byte more than the size: the read that finds the end needs no second buffer. A file
    // that grows while it is read is read up to one byte past the limit, no further.
    std::string text(static_cast<std::size_t>(st.st_size) + 1, '\0');
    std::size_t size = 0;
    for (;;) {
        if (size == text.size()) {
            if (size > kMaxProjectFileBytes) {
                return refuse(Diagnostic::make(FilePlace{path}, DiagnosticCode::FileGrewTooLarge,
                                               {static_cast<double>(kMaxProjectFileBytes >> 20)}));
            }
            text.resize(std::min<std::size_t>(2 * size, kMaxProjectFileBytes + 1));
        }
        const ssize_t n = ::read(fd, text.data() + size, text.size() - size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return failed(DiagnosticCode::FileCannotRead);
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
