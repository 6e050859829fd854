#include "io/project_json.h"

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

}  // namespace cam
