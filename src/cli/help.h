#pragma once
/// @file
/// @brief What camwright-cli accepts and how it explains itself: one table of commands, from
/// which the parser takes each command's options and `--help` its text, so the two cannot
/// disagree.

#include <iosfwd>
#include <string>
#include <vector>

#include "cli/arguments.h"

namespace cam::cli {

/// @brief One option of a command: `--name VALUE` (a flag when `value` is empty) and what it
/// does, its default included.
struct OptionHelp {
    std::string name;
    std::string value;
    std::string text;
};

/// @brief A command: how it is called, what it does, its options, examples.
struct CommandHelp {
    std::string name;
    std::string synopsis;  ///< after "camwright-cli ": "state PROJECT --t SECONDS"; "\n" breaks it
    std::string summary;   ///< one line for the overview
    std::string description;
    std::vector<OptionHelp> options;
    std::vector<std::string> examples;  ///< after "camwright-cli "
    std::size_t positionals = 1;        ///< at most this many positional arguments
    std::size_t minPositionals = 1;     ///< at least this many
    /// Runs the command (cli/commands.h): results to `out`, problems to `err` or thrown as
    /// CliError; returns the exit code.
    int (*run)(const Arguments& args, std::ostream& out, std::ostream& err) = nullptr;

    /// @brief What the parser accepts: the options with a value and the flags above.
    [[nodiscard]] CommandSyntax syntax() const;
};

/// @brief Every command, in the order the overview lists them.
[[nodiscard]] const std::vector<CommandHelp>& commandTable();

/// @brief The command called `name`, or null.
[[nodiscard]] const CommandHelp* findCommand(const std::string& name);

/// @brief `camwright-cli --help`: every command in a line or two, units, exit codes.
[[nodiscard]] std::string overviewHelp();

/// @brief `camwright-cli COMMAND --help`, laid out like a man page: synopsis, description,
/// options with their defaults, exit codes, examples. Lines of at most 80 columns.
[[nodiscard]] std::string commandHelp(const CommandHelp& command);

}  // namespace cam::cli
