// camwright-cli: everything the desktop application computes, without a display (cli.md).

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/help.h"
#include "cli/output.h"
#include "io/atomic_file.h"

namespace {

int run(const std::vector<std::string>& args, std::ostream& out) {
    using namespace cam::cli;
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
        out << overviewHelp();
        return kOk;
    }
    if (!args.empty() && args[0] == "--version") {
        out << "camwright-cli " << CAMWRIGHT_VERSION << "\n";
        return kOk;
    }
    std::vector<CommandSyntax> commands;
    for (const CommandHelp& c : commandTable()) commands.push_back(c.syntax());
    try {
        // `help` alone is the overview, `help COMMAND` that command's page.
        if (!args.empty() && args[0] == "help") {
            if (args.size() == 1) {
                out << overviewHelp();
                return kOk;
            }
            const Arguments asked = parseArguments({args[1], "--help"}, commands);
            if (args.size() > 2) throw CliError{kUsage, "help", "takes one command"};
            out << commandHelp(*findCommand(asked.command));
            return kOk;
        }
        const Arguments parsed = parseArguments(args, commands);
        if (parsed.help) {
            out << commandHelp(*findCommand(parsed.command));
            return kOk;
        }
        const CommandHelp* command = findCommand(parsed.command);
        return command && command->run ? command->run(parsed, out, std::cerr) : kUsage;
    } catch (const CliError& e) {
        out.flush();
        std::cerr << "camwright-cli: " << e.location << ": " << e.message << "\n";
        if (e.code == kUsage) {
            const bool known = !args.empty() && findCommand(args[0]) != nullptr;
            std::cerr << "(run 'camwright-cli " << (known ? args[0] + " " : std::string())
                      << "--help' for usage)\n";
        }
        return e.code;
    } catch (const std::exception& e) {
        out.flush();
        std::cerr << "camwright-cli: internal error: " << e.what() << "\n";
        return kNotComputable;
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace cam::cli;
    occupyClosedStandardStreams();
    // Over a file size limit (ulimit -f) write() then fails with EFBIG and is reported with the
    // file's name, instead of the signal killing the program with a temporary file left behind.
    std::signal(SIGXFSZ, SIG_IGN);
    // Ctrl+C or a kill during `--out` leaves no temporary file behind (io/atomic_file.h).
    cam::installTemporaryFileCleanup();
    std::ios::sync_with_stdio(false);
    CheckedOutput results(STDOUT_FILENO);
    std::ostream out(&results);
    const int code = run(std::vector<std::string>(argv + 1, argv + argc), out);
    // Results that did not reach stdout are a failure, whatever the command said.
    if (!results.finish()) {
        std::cerr << "camwright-cli: stdout: " << results.failureText() << "\n";
        return code == kOk ? kInvalidInput : code;
    }
    return code;
}
