#pragma once
/// @file
/// @brief Command-line parsing for camwright-cli: commands, options and their typed values.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cam::cli {

enum ExitCode { kOk = 0, kUsage = 1, kInvalidInput = 2, kNotComputable = 3 };

/// @brief A located failure: `camwright-cli: <location>: <message>`, exit `code`.
struct CliError {
    int code;
    std::string location;
    std::string message;
};

/// @brief The parsed command line: one command, positional arguments and `--name value` options.
struct Arguments {
    std::string command;
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;
    std::vector<std::string> flags;
    /// `COMMAND --help` (or -h): nothing else is checked, the command's help is wanted.
    bool help = false;

    [[nodiscard]] bool hasFlag(const std::string& name) const;
    [[nodiscard]] std::optional<std::string> option(const std::string& name) const;
};

/// @brief What a command accepts; anything else is a usage error.
struct CommandSyntax {
    std::string name;
    std::size_t positionals;           ///< at most this many positional arguments
    std::vector<std::string> options;  ///< names that take a value, e.g. "--t"
    std::vector<std::string> flags;    ///< names without a value
    std::size_t minPositionals = 1;    ///< at least this many
};

/// @brief Splits argv by the syntax of its command. Throws CliError (exit 1) on bad usage; an
/// unknown command or option names the nearest known one when a typo is plausible.
Arguments parseArguments(const std::vector<std::string>& args,
                         const std::vector<CommandSyntax>& commands);

/// @brief The one candidate a typo most plausibly meant: within an edit distance (insertions,
/// deletions, substitutions and swaps of neighbours) of a third of its length, at least 1 and
/// at most 2, or the only candidate `given` begins; none when two are equally near.
[[nodiscard]] std::optional<std::string> nearestName(const std::string& given,
                                                     const std::vector<std::string>& candidates);

/// @brief A finite double, the whole text. Throws CliError (exit 2) naming `option`.
double parseFiniteNumber(const std::string& option, const std::string& text, const char* what);

/// @brief A finite number > 0. Throws CliError (exit 2) naming `option`.
double parsePositive(const std::string& option, const std::string& text, const char* unit);

/// @brief A whole number in [lo, hi]. Throws CliError (exit 2) naming `option`.
long long parseCount(const std::string& option, const std::string& text, long long lo,
                     long long hi);

}  // namespace cam::cli
