#include "cli/plot_pictures.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "cli/arguments.h"

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

int drawPlotWithApp(const std::string& project, const std::string& plot, const std::string& format,
                    const std::optional<std::string>& size, const std::string& out) {
    const std::string app = pictureApp();
    std::vector<std::string> args{app, "--export-plot", plot, "--format", format, "--out", out};
    if (size) {
        args.push_back("--size");
        args.push_back(*size);
    }
    args.push_back(project);
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
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    throw CliError{
        kNotComputable, app,
        "stopped by signal " + std::to_string(WTERMSIG(status)) + " while drawing " + plot};
}

}  // namespace cam::cli
