#include "cli/arguments.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace cam::cli {

bool Arguments::hasFlag(const std::string& name) const {
    return std::find(flags.begin(), flags.end(), name) != flags.end();
}

std::optional<std::string> Arguments::option(const std::string& name) const {
    const auto it = options.find(name);
    return it == options.end() ? std::nullopt : std::optional(it->second);
}

Arguments parseArguments(const std::vector<std::string>& args,
                         const std::vector<CommandSyntax>& commands) {
    if (args.empty()) throw CliError{kUsage, "usage", "no command given (try --help)"};
    Arguments out;
    out.command = args.front();
    const auto syntax = std::find_if(commands.begin(), commands.end(),
                                     [&](const CommandSyntax& c) { return c.name == out.command; });
    if (syntax == commands.end()) {
        throw CliError{kUsage, out.command, "unknown command (try --help)"};
    }
    auto contains = [](const std::vector<std::string>& v, const std::string& s) {
        return std::find(v.begin(), v.end(), s) != v.end();
    };
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() > 2 && a.rfind("--", 0) == 0) {
            std::string name = a, value;
            bool inlineValue = false;
            if (const auto eq = a.find('='); eq != std::string::npos) {
                name = a.substr(0, eq);
                value = a.substr(eq + 1);
                inlineValue = true;
            }
            if (contains(syntax->flags, name) && !inlineValue) {
                out.flags.push_back(name);
            } else if (contains(syntax->options, name)) {
                if (!inlineValue) {
                    if (i + 1 >= args.size()) throw CliError{kUsage, name, "needs a value"};
                    value = args[++i];
                }
                if (out.options.contains(name)) throw CliError{kUsage, name, "given twice"};
                out.options[name] = value;
            } else {
                throw CliError{kUsage, name, "unknown option for '" + out.command + "'"};
            }
        } else {
            out.positional.push_back(a);
        }
    }
    if (out.positional.size() < syntax->minPositionals) {
        throw CliError{kUsage, out.command, "missing PROJECT argument"};
    }
    if (out.positional.size() > syntax->positionals) {
        throw CliError{kUsage, out.command, "unexpected argument '" + out.positional.back() + "'"};
    }
    return out;
}

double parseFiniteNumber(const std::string& option, const std::string& text, const char* what) {
    double value = 0.0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (!text.empty() && *first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (text.empty() || ec != std::errc{} || ptr != last || !std::isfinite(value)) {
        throw CliError{
            kInvalidInput, option,
            std::string("must be a finite number of ") + what + " (got \"" + text + "\")"};
    }
    return value;
}

long long parseCount(const std::string& option, const std::string& text, long long lo,
                     long long hi) {
    long long value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc{} || ptr != text.data() + text.size() || value < lo ||
        value > hi) {
        throw CliError{kInvalidInput, option,
                       "must be a whole number from " + std::to_string(lo) + " to " +
                           std::to_string(hi) + " (got \"" + text + "\")"};
    }
    return value;
}

}  // namespace cam::cli
