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
        std::vector<std::string> names;
        for (const CommandSyntax& c : commands) names.push_back(c.name);
        const auto meant = nearestName(out.command, names);
        throw CliError{kUsage, out.command,
                       meant ? "unknown command; did you mean '" + *meant + "'?"
                             : "unknown command (try --help)"};
    }
    auto contains = [](const std::vector<std::string>& v, const std::string& s) {
        return std::find(v.begin(), v.end(), s) != v.end();
    };
    // Help wins over everything else on the line (a missing PROJECT, an unknown option).
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--help" || args[i] == "-h") {
            out.help = true;
            return out;
        }
    }
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
                std::vector<std::string> names = syntax->options;
                names.insert(names.end(), syntax->flags.begin(), syntax->flags.end());
                const auto meant = nearestName(name, names);
                throw CliError{kUsage, name,
                               "unknown option for '" + out.command + "'" +
                                   (meant ? "; did you mean " + *meant + "?" : std::string())};
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

namespace {

/// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
/// neighbouring characters each cost 1 (analyse → analyze 1, valdiate → validate 1).
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}

}  // namespace

std::optional<std::string> nearestName(const std::string& given,
                                       const std::vector<std::string>& candidates) {
    // A long argument is no typo of a name (and would cost a table of its length squared).
    if (given.empty() || given.size() > 64) return std::nullopt;
    const std::size_t allowed = std::clamp<std::size_t>(given.size() / 3, 1, 2);
    std::optional<std::string> best;
    std::size_t bestDistance = allowed + 1;
    bool tie = false;
    for (const std::string& c : candidates) {
        const std::size_t d = editDistance(given, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
            tie = false;
        } else if (d == bestDistance) {
            tie = true;
        }
    }
    if (best && !tie) return best;
    // An abbreviation: the only name it begins ("synth" → synthesize), at least three letters
    // (or "--" and two) so that "e" or "--t" is no guess.
    const std::size_t letters = given.rfind("--", 0) == 0 ? given.size() - 2 : given.size();
    if (letters < 2 || given.size() < 3) return std::nullopt;
    std::optional<std::string> prefixOf;
    for (const std::string& c : candidates) {
        if (c.size() > given.size() && c.rfind(given, 0) == 0) {
            if (prefixOf) return std::nullopt;
            prefixOf = c;
        }
    }
    return prefixOf;
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

double parsePositive(const std::string& option, const std::string& text, const char* unit) {
    const double v = parseFiniteNumber(option, text, unit);
    if (!(v > 0)) throw CliError{kInvalidInput, option, "must be > 0 (got \"" + text + "\")"};
    return v;
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
