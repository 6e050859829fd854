#include "cli/plot_pictures.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "cli/arguments.h"
#include "export/free_text.h"
#include "io/atomic_file.h"

extern char** environ;

namespace cam::cli {

std::string plotNameList() {
    std::string list;
    for (const char* name : kPlotNames) {
        if (!list.empty()) list += ", ";
        list += name;
    }
    return list;
}

std::string pictureApp() {
    if (const char* app = std::getenv("CAMWRIGHT_APP"); app && *app) {
        if (::access(app, X_OK) != 0) {
            throw CliError{kNotComputable, app,
                           "(CAMWRIGHT_APP) is not an executable: the plots are drawn by the "
                           "desktop app camwright"};
        }
        return app;
    }
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path app = self.parent_path() / "camwright";
    if (ec || ::access(app.c_str(), X_OK) != 0) {
        throw CliError{kNotComputable, app.string(),
                       "not found: pictures of the plots are drawn by the desktop app camwright, "
                       "installed beside camwright-cli (or named by CAMWRIGHT_APP)"};
    }
    return app.string();
}

namespace {

/// A folder of our own under the system's temporary folder, removed with what is in it.
class PrivateFolder {
public:
    PrivateFolder() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "camwright-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) {
            throw CliError{kNotComputable, pattern,
                           std::string("cannot be made: ") + std::strerror(errno)};
        }
        m_path = pattern;
    }
    ~PrivateFolder() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    PrivateFolder(const PrivateFolder&) = delete;
    PrivateFolder& operator=(const PrivateFolder&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

}  // namespace

int drawPlotWithApp(const std::string& project, const std::string& plot, const std::string& format,
                    const std::optional<std::string>& size, const std::string& out) {
    const std::string app = pictureApp();
    // The app reads its arguments as UTF-8 (Qt): a path that is not valid UTF-8 would name
    // another file. Such a path goes through a folder of our own: the project as a link with a
    // name the app can read (the name a picture's title may take), the picture written there
    // and then put in its place by the core's writer.
    std::optional<PrivateFolder> folder;
    std::string appProject = project, appOut = out;
    if (!isValidUtf8(project) || !isValidUtf8(out)) {
        folder.emplace();
        if (!isValidUtf8(project)) {
            std::string stem = std::filesystem::path(project).filename().string();
            for (const char* suffix : {".cam.json", ".json"}) {
                const std::string s = suffix;
                if (stem.size() > s.size() && stem.ends_with(s)) {
                    stem.resize(stem.size() - s.size());
                    break;
                }
            }
            std::string readable = oneLine(stem);
            std::replace(readable.begin(), readable.end(), '/', '_');
            if (readable.empty()) readable = "project";
            appProject = (folder->path() / (readable + ".cam.json")).string();
            std::error_code ec;
            std::filesystem::create_symlink(std::filesystem::absolute(project, ec), appProject, ec);
            if (ec) throw CliError{kNotComputable, project, "cannot be linked: " + ec.message()};
        }
        if (!isValidUtf8(out)) appOut = (folder->path() / ("picture." + format)).string();
    }
    std::vector<std::string> args{app, "--export-plot", plot, "--format", format, "--out", appOut};
    if (size) {
        args.push_back("--size");
        args.push_back(*size);
    }
    args.push_back(appProject);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    // The app draws without a display; its own platform choice would follow a DISPLAY.
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "QT_QPA_PLATFORM=", 16) != 0) env.emplace_back(*e);
    }
    env.emplace_back("QT_QPA_PLATFORM=offscreen");
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);

    pid_t pid = 0;
    const int spawned =
        ::posix_spawn(&pid, app.c_str(), nullptr, nullptr, argv.data(), envp.data());
    if (spawned != 0) {
        throw CliError{kNotComputable, app,
                       std::string("cannot be started: ") + std::strerror(spawned)};
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw CliError{kNotComputable, app, std::strerror(errno)};
    }
    if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        if (code == kOk && appOut != out) {
            std::ifstream in(appOut, std::ios::binary);
            const std::string picture{std::istreambuf_iterator<char>(in),
                                      std::istreambuf_iterator<char>()};
            if (!in) throw CliError{kNotComputable, out, "the picture drawn cannot be read back"};
            const Diagnostics written = writeFileAtomically(out, picture);
            if (!written.empty()) throw CliError{kInvalidInput, out, written.front().message};
        }
        return code;
    }
    throw CliError{
        kNotComputable, app,
        "stopped by signal " + std::to_string(WTERMSIG(status)) + " while drawing " + plot};
}

}  // namespace cam::cli
