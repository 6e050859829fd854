// camwright-cli explains itself: a page per command (COMMAND --help, help COMMAND) that names
// every option the command accepts, the nearest name for a typo, the man page in step.

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "export/export_formats.h"
#include "test_support.h"

namespace cam {
namespace {

/// The commands of cli.md with the options it gives each (the contract: help may say more).
const std::vector<std::pair<std::string, std::vector<std::string>>> kSpecCommands{
    {"validate", {}},
    {"state", {"--t"}},
    {"sample", {"--samples", "--out"}},
    {"analyze", {}},
    {"timing", {"--path", "--method", "--accel", "--vmax", "--feed", "--step", "--detail"}},
    {"export",
     {"--format", "--out", "--plot", "--tolerance", "--points", "--dialect", "--tool-radius",
      "--depth"}},
    {"synthesize", {"--out", "--tolerance", "--output"}},
    {"fillet", {"--joint", "--radius", "--speed", "--accel", "--vae", "--out"}},
    {"size", {"--min-radius", "--out"}},
    {"fit-windows", {"--out"}},
};

/// The options a help page lists: the lines "  --name ..." of its options section.
std::set<std::string> listedOptions(const std::string& page) {
    std::set<std::string> out;
    const auto at = page.find("\noptions:\n");
    if (at == std::string::npos) return out;
    std::istringstream in(page.substr(at + 10));
    const std::regex option(R"(^  (--[a-z-]+)( |$).*)");
    for (std::string line; std::getline(in, line) && !line.empty();) {
        std::smatch m;
        if (std::regex_match(line, m, option)) out.insert(m[1]);
    }
    return out;
}

std::size_t columns(const std::string& line) {
    std::size_t n = 0;
    for (const char c : line) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

TEST(CliHelp, EveryCommandHasAPageNamingEveryOptionItAccepts) {
    for (const auto& [command, specOptions] : kSpecCommands) {
        SCOPED_TRACE(command);
        const auto r = test::runCli({command, "--help"});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err, "");
        EXPECT_EQ(r.out.rfind("camwright-cli " + command + " — ", 0), 0u) << r.out;
        EXPECT_NE(r.out.find("\nusage: camwright-cli " + command + " "), std::string::npos);
        EXPECT_NE(r.out.find("exit codes: 0 ok, 1 usage error"), std::string::npos);
        EXPECT_NE(r.out.find("  camwright-cli " + command + " "), std::string::npos)
            << "no example";
        // Every option cli.md gives the command is explained on its page …
        const std::set<std::string> listed = listedOptions(r.out);
        for (const std::string& o : specOptions) EXPECT_TRUE(listed.contains(o)) << o;
        // … and every option the page lists is one the command takes: given alone it may
        // lack its value or PROJECT, but it is never an unknown option.
        for (const std::string& o : listed) {
            const auto tried = test::runCli({command, o});
            EXPECT_EQ(tried.err.find("unknown option"), std::string::npos)
                << o << ": " << tried.err;
        }
        // A page for a terminal: no line over 80 columns.
        std::istringstream in(r.out);
        for (std::string line; std::getline(in, line);) EXPECT_LE(columns(line), 80u) << line;
        // The same page by `help COMMAND`, with -h, and after other arguments (even wrong ones).
        EXPECT_EQ(test::runCli({"help", command}).out, r.out);
        EXPECT_EQ(test::runCli({command, "-h"}).out, r.out);
        EXPECT_EQ(test::runCli({command, "no-such.cam.json", "--bogus", "--help"}).out, r.out);
    }
    // An option the parser does not know is no option a page lists (the check above can fail).
    EXPECT_NE(test::runCli({"state", "--bogus"}).err.find("unknown option"), std::string::npos);
}

TEST(CliHelp, TheOverviewListsEveryCommandAndHowToGetItsPage) {
    const auto r = test::runCli({"--help"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(test::runCli({"help"}).out, r.out);
    EXPECT_NE(r.out.find("camwright-cli COMMAND --help"), std::string::npos);
    for (const auto& [command, options] : kSpecCommands) {
        EXPECT_NE(r.out.find("\n  " + command + " "), std::string::npos) << command;
    }
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) EXPECT_LE(columns(line), 80u) << line;
    // What --out does to a file is said where every command's --out is (issue 27: Save and
    // --out replace a hard-linked file by a new one).
    EXPECT_NE(r.out.find("a hard link to the old FILE keeps the old content"), std::string::npos)
        << r.out;
    const auto unknown = test::runCli({"help", "frobnicate"});
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_NE(unknown.err.find("frobnicate: unknown command"), std::string::npos) << unknown.err;
}

TEST(CliHelp, ATypoIsAnsweredWithTheNearestName) {
    const std::string example = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"analyse", example}, "analyse: unknown command; did you mean 'analyze'?"},
        {{"valdiate", example}, "valdiate: unknown command; did you mean 'validate'?"},
        {{"exprot", example}, "exprot: unknown command; did you mean 'export'?"},
        {{"synth", example}, "synth: unknown command; did you mean 'synthesize'?"},
        {{"Timing", example}, "Timing: unknown command; did you mean 'timing'?"},
        {{"export", example, "--tolerence", "0.1"},
         "--tolerence: unknown option for 'export'; did you mean --tolerance?"},
        {{"sample", example, "--sample", "10"},
         "--sample: unknown option for 'sample'; did you mean --samples?"},
        {{"timing", example, "--metod", "seed"},
         "--metod: unknown option for 'timing'; did you mean --method?"},
    };
    for (const auto& [args, expected] : cases) {
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, 1) << args[0];
        EXPECT_NE(r.err.find("camwright-cli: " + expected + "\n"), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
    }
    // Nothing near: no guess.
    for (const std::vector<std::string>& args : {std::vector<std::string>{"frobnicate", example},
                                                 {"x", example},
                                                 {"state", example, "--time", "1"},
                                                 {"export", example, "--p", "1"}}) {
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
    }
    // The hint after a usage error points to the command's own page.
    EXPECT_NE(
        test::runCli({"export", example}).err.find("(run 'camwright-cli export --help' for usage)"),
        std::string::npos);
}

TEST(CliHelp, TheManPageNamesEveryCommandAndOption) {
    std::string man = test::readFile(CAMWRIGHT_SOURCE_DIR "/packaging/man/camwright-cli.1");
    // roff's escaped hyphens and font changes, as the page reads.
    man = std::regex_replace(man, std::regex(R"(\\-)"), "-");
    man = std::regex_replace(man, std::regex(R"(\\f[BIRP])"), "");
    for (const auto& [command, unused] : kSpecCommands) {
        SCOPED_TRACE(command);
        EXPECT_NE(man.find(".BI " + command + " "), std::string::npos);
        for (const std::string& o : listedOptions(test::runCli({command, "--help"}).out)) {
            EXPECT_NE(man.find(o), std::string::npos) << o;
        }
    }
    EXPECT_NE(man.find("camwright-cli COMMAND --help"), std::string::npos);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

// Every export format and dialect is one row of the core's table (export/export_formats.h):
// the command accepts, refuses and documents exactly what the table says.
TEST(CliHelp, ExportTakesAndDocumentsEveryFormatAndDialectOfTheTable) {
    const test::RunResult help = test::runCli({"export", "--help"});
    ASSERT_EQ(help.exitCode, 0) << help.err;
    const test::RunResult unknown = test::runCli(
        {"export", test::kExample, "--format", "no-such-format", "--out", "/nonexistent/x"});
    EXPECT_EQ(unknown.exitCode, 1);
    std::vector<std::string> names;
    for (const ExportFormatKind& format : exportFormats()) {
        if (!format.name.empty()) names.emplace_back(format.name);
        for (const ExportDialectKind& dialect : format.dialects) {
            if (format.id == ExportFormatId::Picture) names.emplace_back(dialect.name);
            // Every dialect is named on the help page.
            EXPECT_TRUE(test::contains(help.out, std::string(dialect.name))) << dialect.name;
        }
        // Every option a format takes is explained on the help page.
        for (std::string_view option : format.options) {
            EXPECT_TRUE(test::contains(help.out, std::string(option))) << option;
        }
        for (std::string_view flag : format.flags) {
            EXPECT_TRUE(test::contains(help.out, std::string(flag))) << flag;
        }
    }
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        EXPECT_TRUE(test::contains(help.out, name));
        // The refusal of an unknown format lists it as a choice.
        EXPECT_TRUE(test::contains(unknown.err, name)) << unknown.err;
    }
    // An option of one format is refused for another: each row's list is what the command
    // checks.
    const test::RunResult wrong = test::runCli({"export", test::kExample, "--format", "svg",
                                                "--dialect", "csv", "--out", "/nonexistent/x"});
    EXPECT_EQ(wrong.exitCode, 1);
    EXPECT_TRUE(test::contains(wrong.err, "--dialect: is not an option of --format svg"))
        << wrong.err;
}

}  // namespace
}  // namespace cam
