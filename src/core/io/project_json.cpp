#include "io/project_json.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/json_syntax.h"
#include "project/validate.h"

namespace cam {

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
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return Diagnostics{{path, "is a folder, not a file"}};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Diagnostics{{path, std::string("cannot open: ") + std::strerror(errno)}};
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return Diagnostics{{path, "read error"}};
    return buffer.str();
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

AtomicFileWriter::AtomicFileWriter(std::string path) : m_path(std::move(path)) {
    namespace fs = std::filesystem;
    const fs::path target(m_path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string name = ".";  // built by appends: GCC 12 warns falsely on "." + string (PR105651)
    name += target.filename().string();
    name += ".XXXXXX";
    m_tempPath = (dir / name).string();
    m_fd = ::mkstemp(m_tempPath.data());
    if (m_fd < 0) {
        m_errors.push_back({m_path, std::string("cannot write: ") + std::strerror(errno)});
        m_tempPath.clear();
    }
}

AtomicFileWriter::~AtomicFileWriter() {
    if (m_fd >= 0) ::close(m_fd);
    if (!m_tempPath.empty()) ::unlink(m_tempPath.c_str());
}

void AtomicFileWriter::fail(const char* what) {
    if (m_errors.empty())
        m_errors.push_back({m_path, std::string(what) + ": " + std::strerror(errno)});
}

void AtomicFileWriter::write(std::string_view chunk) {
    while (ok() && !chunk.empty()) {
        const ssize_t n = ::write(m_fd, chunk.data(), chunk.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write");
            return;
        }
        chunk.remove_prefix(static_cast<std::size_t>(n));
    }
}

Diagnostics AtomicFileWriter::commit() {
    if (ok()) {
        ::fchmod(m_fd, 0644);
        if (::fsync(m_fd) != 0) fail("cannot flush to disk");
    }
    if (m_fd >= 0 && ::close(m_fd) != 0) fail("cannot write");
    m_fd = -1;
    if (ok() && ::rename(m_tempPath.c_str(), m_path.c_str()) != 0) fail("cannot replace");
    if (ok()) m_tempPath.clear();  // renamed: nothing left to remove
    return m_errors;
}

Diagnostics writeFileAtomically(const std::string& path, std::string_view content) {
    AtomicFileWriter writer(path);
    writer.write(content);
    return writer.commit();
}

}  // namespace cam
