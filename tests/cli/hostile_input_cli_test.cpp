// camwright-cli against hostile input and faults (issue 9): no input crashes or hangs it, no
// failed write is reported as success, every failure names its place, and an interrupted --out
// leaves nothing behind. Big inputs are generated here, not kept in the repository.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "big_projects.h"
#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using test::emptyObjects;
using test::projectOfArcs;
using test::projectOfEmptySegments;
using test::readFile;
using test::RunResult;
using test::TempDir;

using test::kExample;

using test::contains;

std::size_t lineCount(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

using test::writeText;

/// A square of four lines: fillet needs a real corner.
std::string writeSquare(const TempDir& dir) {
    const std::string path = dir.file("square.cam.json");
    writeText(path, R"({"format": "camwright", "version": 1, "motion": {"period_s": 1},
      "contour": [{"type": "line", "from": [10, -10], "to": [10, 10]},
                  {"type": "line", "from": [10, 10], "to": [-10, 10]},
                  {"type": "line", "from": [-10, 10], "to": [-10, -10]},
                  {"type": "line", "from": [-10, -10], "to": [10, -10]}]})");
    return path;
}

/// The hidden siblings `.<name>.…` of a file: where --out streams to.
std::vector<std::string> temporariesOf(const fs::path& folder, const std::string& name) {
    std::vector<std::string> out;
    for (const std::string& e : test::folderEntries(folder)) {
        if (e.rfind("." + name + ".", 0) == 0) out.push_back(e);
    }
    return out;
}

// --- running the CLI with a broken stdout, or in the background --------------------------------

enum class Stdout { DevFull, Closed, AtTheSizeLimit };

/// Runs camwright-cli with stdout on /dev/full, closed, or appending to a file that has reached
/// the process's file size limit (RLIMIT_FSIZE: a full disk for this process; SIGXFSZ left at
/// its default, which kills). stderr goes to a new file, below the limit, and is captured.
RunResult runWithBrokenStdout(const std::vector<std::string>& args, Stdout mode,
                              const std::string& scratch) {
    constexpr rlim_t kLimit = 64 * 1024;
    const std::string errPath = scratch + ".err";
    if (mode == Stdout::AtTheSizeLimit) writeText(scratch, std::string(kLimit, '#'));
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int e = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(e, 2);
        if (mode == Stdout::Closed) {
            ::close(1);
        } else {
            const int o = mode == Stdout::DevFull ? ::open("/dev/full", O_WRONLY)
                                                  : ::open(scratch.c_str(), O_WRONLY | O_APPEND);
            ::dup2(o, 1);
            if (mode == Stdout::AtTheSizeLimit) {
                const rlimit limit{kLimit, kLimit};
                ::setrlimit(RLIMIT_FSIZE, &limit);
            }
        }
        ::alarm(60);
        std::vector<char*> argv{const_cast<char*>(CAMWRIGHT_CLI)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(CAMWRIGHT_CLI, argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    RunResult r;
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.err = readFile(errPath);
    fs::remove(errPath);
    return r;
}

/// camwright-cli running in the background (stdout and stderr to /dev/null), with SIGINT and
/// SIGTERM at their defaults as for a command run in the foreground (a test run in the
/// background of a script inherits SIGINT ignored). A test that stops early (a failed ASSERT)
/// does not leave it behind: it is killed and reaped.
class BackgroundCli {
public:
    explicit BackgroundCli(const std::vector<std::string>& args) : m_pid(::fork()) {
        if (m_pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1);
            ::dup2(null, 2);
            ::signal(SIGINT, SIG_DFL);
            ::signal(SIGTERM, SIG_DFL);
            ::alarm(120);
            std::vector<char*> argv{const_cast<char*>(CAMWRIGHT_CLI)};
            for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            ::execv(CAMWRIGHT_CLI, argv.data());
            ::_exit(127);
        }
    }
    ~BackgroundCli() {
        if (m_pid <= 0) return;
        ::kill(m_pid, SIGKILL);
        wait();
    }
    BackgroundCli(const BackgroundCli&) = delete;
    BackgroundCli& operator=(const BackgroundCli&) = delete;

    void signal(int signal) const { ::kill(m_pid, signal); }
    /// Waits for it to end; its wait status.
    int wait() {
        int status = 0;
        ::waitpid(m_pid, &status, 0);
        m_pid = -1;
        return status;
    }

private:
    pid_t m_pid;
};

/// Whether someone holds an exclusive flock(2) on the file, as a writer does on its temporary.
bool isLocked(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool free = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
    ::close(fd);  // releases the lock if we took it
    return !free;
}

/// Waits until a temporary file of `name` appears in `folder` (the writer has started).
bool waitForTemporary(const fs::path& folder, const std::string& name) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline) {
        if (!temporariesOf(folder, name).empty()) return true;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return false;
}

// --- 1. small files that once overflowed the stack ---------------------------------------------

TEST(CliHostileInput, SmallFilesThatOverflowedTheStackAreRefusedWithTheirPlace) {
    // At 612d090 each of these ended in a segmentation fault (exit 139): std::regex recursed
    // over nlohmann's message, which quotes the whole last token.
    // A token is quoted to its first 40 characters and "…" (io/json_syntax.h), not echoed whole.
    struct Case {
        const char* name;
        std::string text;
        std::string says;  // location and the start of the message
        std::string ends;  // the capped quote that ends it
    };
    const std::vector<Case> cases{
        {"tabs", R"({"format": "camwright",)" + std::string(3500, '\t') + "#",
         "line 1, column 3524: syntax error",  // the '#'
         "…'"},
        {"unterminated-string", R"({"format": ")" + std::string(30000, 'a'),
         "line 1, column 30013: syntax error while parsing value - invalid string: missing "
         "closing quote",  // the end of the file
         "; last read: '\"" + std::string(39, 'a') + "…'"},
        {"huge-number", R"({"format": )" + std::string(40000, '1'),
         "line 1, column 12: number '",  // the first digit
         std::string(40, '1') + "…' is too large for a double"},
    };
    const TempDir dir;
    for (const Case& c : cases) {
        const std::string file = dir.file(std::string(c.name) + ".cam.json");
        writeText(file, c.text);
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"validate", file},
              std::vector<std::string>{"state", file, "--t", "0"}}) {
            SCOPED_TRACE(args[0] + " " + c.name);
            const RunResult r = test::runCli(args);
            EXPECT_EQ(r.signal, 0);
            EXPECT_EQ(r.exitCode, 2);
            EXPECT_EQ(r.out, "");
            EXPECT_EQ(r.err.rfind("camwright-cli: " + file + ": " + c.says, 0), 0u) << r.err;
            EXPECT_TRUE(r.err.ends_with(c.ends + "\n")) << r.err.substr(0, 400);
            EXPECT_EQ(lineCount(r.err), 1u);
            EXPECT_LT(r.err.size(), 250 + file.size()) << r.err.substr(0, 400);
        }
    }
}

// --- 4. results that cannot be written are a failure -------------------------------------------

/// Every command that prints results, with arguments that succeed quickly even with sanitizers
/// (timing a point list, not the six lobes). sample writes 2.7 MB: many blocks, not one.
std::vector<std::vector<std::string>> everyPrintingCommand(const TempDir& dir) {
    const std::string square = writeSquare(dir);
    const std::string points = dir.file("points.csv");
    writeText(points, "0,0,0\n100,0,0\n100,100,0\n");
    return {{"validate", kExample},
            {"state", kExample, "--t", "0.05"},
            {"sample", kExample, "--samples", "10000"},
            {"analyze", kExample},
            {"timing", "--path", points, "--method", "exact-stop", "--accel", "500,500,200"},
            {"fillet", square, "--joint", "1", "--radius", "3", "--out", dir.file("f.cam.json")},
            {"--help"},
            {"--version"}};
}

TEST(CliOutputFailures, AFullStdoutIsExitTwoWithAMessageForEveryCommand) {
    const TempDir dir;
    for (const auto& args : everyPrintingCommand(dir)) {
        SCOPED_TRACE(args[0]);
        ASSERT_EQ(test::runCli(args).exitCode, 0);  // the same command succeeds normally
        const RunResult r = runWithBrokenStdout(args, Stdout::DevFull, dir.file("scratch"));
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_EQ(r.err,
                  "camwright-cli: stdout: cannot write the results: No space left on device\n");
    }
}

TEST(CliOutputFailures, AClosedStdoutIsExitTwoWithAMessageForEveryCommand) {
    const TempDir dir;
    for (const auto& args : everyPrintingCommand(dir)) {
        SCOPED_TRACE(args[0]);
        const RunResult r = runWithBrokenStdout(args, Stdout::Closed, dir.file("scratch"));
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_EQ(r.err,
                  "camwright-cli: stdout: is closed or not open for writing: the results are "
                  "lost\n");
    }
    // A closed stdout must not be taken over by a file opened later: sample --out writes
    // nothing to stdout and succeeds, and the file holds only the CSV.
    const std::string out = dir.file("turn.csv");
    const RunResult r = runWithBrokenStdout({"sample", kExample, "--samples", "8", "--out", out},
                                            Stdout::Closed, dir.file("scratch"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lineCount(readFile(out)), 9u);
}

TEST(CliOutputFailures, AStdoutFileAtTheSizeLimitIsExitTwoWithAMessageForEveryCommand) {
    // The full disk of the issue: `sample > out.csv` under `ulimit -f` wrote part of the CSV and
    // was killed by SIGXFSZ (at 612d090), or on a full disk wrote 3,930 of 100,001 lines and
    // exited 0.
    const TempDir dir;
    for (const auto& args : everyPrintingCommand(dir)) {
        SCOPED_TRACE(args[0]);
        const std::string scratch = dir.file("out.txt");
        const RunResult r = runWithBrokenStdout(args, Stdout::AtTheSizeLimit, scratch);
        EXPECT_EQ(r.signal, 0);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_EQ(r.err, "camwright-cli: stdout: cannot write the results: File too large\n");
        EXPECT_EQ(readFile(scratch), std::string(64 * 1024, '#'));  // not a byte more
    }
}

// In a forked child: `sample --out` under a 64 KiB file size limit, SIGXFSZ ignored or not.
[[noreturn]] void execSampleUnderASizeLimit(const std::string& out, const std::string& errPath,
                                            bool ignoreSigxfsz) {
    const int e = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(e, 2);
    if (ignoreSigxfsz) ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    ::execl(CAMWRIGHT_CLI, CAMWRIGHT_CLI, "sample", kExample.c_str(), "--samples", "100000",
            "--out", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
}

TEST(CliOutputFailures, AnOutFileOverTheSizeLimitIsExitTwoTheOldFileWholeAndNoTemporary) {
    for (const bool ignored : {true, false}) {
        SCOPED_TRACE(ignored ? "SIGXFSZ ignored" : "SIGXFSZ at its default");
        const TempDir dir;
        const std::string out = dir.file("turn.csv");
        const std::string old(100 * 1024, 'o');  // above the limit: only new bytes count
        writeText(out, old);
        const pid_t pid = ::fork();
        if (pid == 0) execSampleUnderASizeLimit(out, dir.file("err"), ignored);
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
        EXPECT_EQ(WEXITSTATUS(status), 2);
        EXPECT_EQ(readFile(dir.file("err")),
                  "camwright-cli: " + out + ": cannot write " + out + ": File too large\n");
        EXPECT_EQ(readFile(out), old);
        EXPECT_TRUE(temporariesOf(dir.path(), "turn.csv").empty());
    }
}

// --- 5. --out never destroys what it should not; an interrupted --out leaves nothing ----------

TEST(CliOut, AnythingButARegularFileOrANewPathIsRefusedAndLeftAlone) {
    const TempDir dir;
    // /dev/full and /dev/stdout are reached through links of our own: a writer that got this
    // wrong (612d090 did, as root) renames over the link, not over the machine's /dev entries.
    std::error_code ec;
    const fs::path devStdout = fs::read_symlink("/dev/stdout", ec);
    ASSERT_FALSE(ec) << "/dev/stdout is not a symbolic link here: " << ec.message();
    fs::create_symlink(devStdout, dir.path() / "stdout");
    fs::create_symlink("/dev/full", dir.path() / "full");
    fs::create_directory(dir.path() / "folder");
    ASSERT_EQ(::mkfifo(dir.file("pipe").c_str(), 0600), 0);
    const std::string square = writeSquare(dir);
    const auto before = test::folderEntries(dir.path());
    struct Case {
        std::string out;
        std::string says;
    };
    const std::vector<Case> cases{
        // The test runner gives the CLI a regular file as stdout: following /dev/stdout to it and
        // renaming over it would replace the file under the shell's redirection.
        {dir.file("stdout"),
         "/proc/self/fd/1 is a link to an open file descriptor, not a file: not replaced"},
        {"/dev/fd/1", "is a link to an open file descriptor, not a file: not replaced"},
        {dir.file("full"), "/dev/full is a character device, not a regular file: not replaced"},
        {dir.file("folder"), "is a folder, not a regular file: not replaced"},
        {dir.file("pipe"), "is a FIFO, not a regular file: not replaced"},
    };
    for (const Case& c : cases) {
        for (const auto& args :
             {std::vector<std::string>{"sample", kExample, "--samples", "8", "--out", c.out},
              std::vector<std::string>{"fillet", square, "--joint", "1", "--radius", "3", "--out",
                                       c.out}}) {
            SCOPED_TRACE(args[0] + " --out " + c.out);
            const RunResult r = test::runCli(args);
            EXPECT_EQ(r.signal, 0);
            EXPECT_EQ(r.exitCode, 2);
            EXPECT_EQ(r.out, "");
            EXPECT_EQ(r.err, "camwright-cli: " + c.out + ": " + c.says + "\n");
        }
    }
    EXPECT_EQ(test::folderEntries(dir.path()), before);  // no temporary file either
    EXPECT_EQ(fs::read_symlink(dir.path() / "stdout"), devStdout);
    EXPECT_EQ(fs::read_symlink(dir.path() / "full"), "/dev/full");
    EXPECT_TRUE(fs::is_empty(dir.path() / "folder"));
    EXPECT_TRUE(fs::is_fifo(dir.path() / "pipe"));
}

TEST(CliOut, ThroughASymlinkTheTargetKeepsItsModeAndOwner) {
    if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file to another owner";
    const TempDir dir;
    fs::create_directory(dir.path() / "data");
    const std::string target = dir.file("data/turn.csv");
    test::writeFileWithMode(target, "old", 0640);
    constexpr uid_t kOwner = 4242;  // someone else's file, which root updates for them
    constexpr gid_t kGroup = 4343;
    ASSERT_EQ(::chown(target.c_str(), kOwner, kGroup), 0);
    fs::create_symlink("data/turn.csv", dir.path() / "latest.csv");
    for (const auto& args :
         {std::vector<std::string>{"sample", kExample, "--samples", "8", "--out",
                                   dir.file("latest.csv")},
          std::vector<std::string>{"fillet", writeSquare(dir), "--joint", "1", "--radius", "3",
                                   "--out", dir.file("latest.csv")}}) {
        SCOPED_TRACE(args[0]);
        const RunResult r = test::runCli(args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::is_symlink(dir.path() / "latest.csv"));
        EXPECT_NE(readFile(target), "old");
        struct stat st {};
        ASSERT_EQ(::stat(target.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 07777, 0640u);
        EXPECT_EQ(st.st_uid, kOwner);
        EXPECT_EQ(st.st_gid, kGroup);
    }
    EXPECT_EQ(test::folderEntries(dir.path() / "data"), std::vector<std::string>{"turn.csv"});
}

TEST(CliOut, SigtermAndSigintDuringALongSampleLeaveNoTemporaryFile) {
    for (const int signal : {SIGTERM, SIGINT}) {
        SCOPED_TRACE(strsignal(signal));
        const TempDir dir;
        const std::string out = dir.file("turn.csv");
        writeText(out, "old");
        BackgroundCli cli({"sample", kExample, "--samples", "1000000", "--out", out});
        ASSERT_TRUE(waitForTemporary(dir.path(), "turn.csv"));
        cli.signal(signal);
        const int status = cli.wait();
        ASSERT_TRUE(WIFSIGNALED(status)) << "exit code " << WEXITSTATUS(status);
        EXPECT_EQ(WTERMSIG(status), signal);  // still ends by the signal, as a shell expects
        EXPECT_EQ(readFile(out), "old");
        EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"turn.csv"});
    }
}

TEST(CliOut, TheLeftoverOfAKilledRunIsRemovedByTheNextRunToTheSameFile) {
    const TempDir dir;
    const std::string out = dir.file("turn.csv");
    writeText(out, "old");
    writeText(dir.file("other.csv"), "other");
    // SIGKILL: nothing can run, the temporary file stays...
    BackgroundCli cli({"sample", kExample, "--samples", "1000000", "--out", out});
    ASSERT_TRUE(waitForTemporary(dir.path(), "turn.csv"));
    cli.signal(SIGKILL);
    ASSERT_TRUE(WIFSIGNALED(cli.wait()));
    ASSERT_EQ(temporariesOf(dir.path(), "turn.csv").size(), 1u);
    EXPECT_EQ(readFile(out), "old");
    // ... until the next run that writes the same file.
    const RunResult r = test::runCli({"sample", kExample, "--samples", "8", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineCount(readFile(out)), 9u);
    EXPECT_EQ(test::folderEntries(dir.path()), (std::vector<std::string>{"other.csv", "turn.csv"}));
}

TEST(CliOut, TheTemporaryFileOfARunningWriterIsNotTouched) {
    const TempDir dir;
    const std::string out = dir.file("turn.csv");
    BackgroundCli slow({"sample", kExample, "--samples", "500000", "--out", out});
    ASSERT_TRUE(waitForTemporary(dir.path(), "turn.csv"));
    // Stopped (alive, but not getting anywhere) while it holds its temporary file locked: caught
    // between creating and locking it, the file would look like a leftover, and the writer would
    // take a new one when it went on.
    std::vector<std::string> slowTemp;
    for (int attempt = 0; attempt < 1000; ++attempt) {
        slow.signal(SIGSTOP);
        slowTemp = temporariesOf(dir.path(), "turn.csv");
        if (slowTemp.size() == 1 && isLocked(dir.file(slowTemp.front()))) break;
        slow.signal(SIGCONT);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(slowTemp.size(), 1u);
    ASSERT_TRUE(isLocked(dir.file(slowTemp.front())));
    const RunResult quick = test::runCli({"sample", kExample, "--samples", "8", "--out", out});
    EXPECT_EQ(quick.exitCode, 0) << quick.err;
    EXPECT_EQ(temporariesOf(dir.path(), "turn.csv"), slowTemp);
    slow.signal(SIGCONT);
    const int status = slow.wait();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(lineCount(readFile(out)), 500001u);  // the slow writer finished last
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"turn.csv"});
}

// --- 7. big inputs: linear; size and kind checked before reading ------------------------------

/// Runs `validate file` and says how long it took, in seconds.
double secondsToValidate(const std::string& file, RunResult& result) {
    const auto start = std::chrono::steady_clock::now();
    result = test::run(CAMWRIGHT_CLI, {"validate", file}, 100);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The bounds below are generous on purpose (a shared machine, two jobs at once): they only
// separate seconds from the minutes the quadratic steps of 612d090 took. tests/bench/
// load_bench.cpp measures the time per segment from 10,000 to 1,000,000.

TEST(CliBigInputs, ValidatingTwoHundredThousandSegmentsTakesSecondsNotMinutes) {
    // 160,000 segments took 10 s at 612d090, 200,000 arcs 18.7 s (a million: 2 min 53 s);
    // about 1.5 s now. With sanitizers (some 25 times slower) a quarter of them.
    const TempDir dir;
    const std::size_t n = test::kSanitized ? 50000 : 200000;
    const std::string file = dir.file("arcs.cam.json");
    writeText(file, projectOfArcs(n));
    RunResult r;
    const double took = secondsToValidate(file, r);
    EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 300);
    EXPECT_EQ(r.out, "valid: " + std::to_string(n) + " segments\n");
    EXPECT_LT(took, test::kSanitized ? 60.0 : 10.0);
}

TEST(CliBigInputs, FourHundredThousandEmptyObjectsAreRefusedInSecondsNotMinutes) {
    // 1.2 MB: 24 s to refuse at 612d090 (68 s on a busy machine), as the parser rescanned the
    // array after every object. About 0.2 s now.
    const TempDir dir;
    const std::size_t n = 400000;
    const std::string top = dir.file("top.json");
    writeText(top, emptyObjects(n));
    RunResult r;
    double took = secondsToValidate(top, r);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "camwright-cli: " + top + ": (top level): must be an object (got an array)\n");
    EXPECT_LT(took, test::kSanitized ? 60.0 : 10.0);

    // As the contour each object is a segment without a type: one line for each, in order.
    const std::string contour = dir.file("contour.cam.json");
    writeText(contour, projectOfEmptySegments(n));
    took = secondsToValidate(contour, r);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), n);
    const std::string prefix = "camwright-cli: " + contour + ": contour[";
    EXPECT_EQ(r.err.substr(0, r.err.find('\n') + 1), prefix + "0].type: missing\n");
    EXPECT_TRUE(r.err.ends_with(prefix + std::to_string(n - 1) + "].type: missing\n"));
    EXPECT_LT(took, test::kSanitized ? 60.0 : 10.0);
}

TEST(CliBigInputs, AFileOver64MiBIsRefusedWithItsSizeBeforeItIsRead) {
    const TempDir dir;
    // Sparse files: no disk space, and reading 8 GiB would take far longer than the bound.
    struct Case {
        const char* name;
        off_t size;
        const char* says;
    };
    for (const Case c :
         {Case{"just-over.cam.json", (off_t{64} << 20) + 1,
               "is 64.0 MiB (67108865 bytes): files larger than 64 MiB are not read"},
          Case{"huge.cam.json", off_t{8} << 30,
               "is 8192.0 MiB (8589934592 bytes): files larger than 64 MiB are not "
               "read"}}) {
        SCOPED_TRACE(c.name);
        const std::string file = dir.file(c.name);
        writeText(file, "");
        ASSERT_EQ(::truncate(file.c_str(), c.size), 0);
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"validate", file},
              std::vector<std::string>{"timing", "--path", file, "--method", "seed", "--accel",
                                       "1,1"}}) {
            // Reading 8 GiB would take a while and the memory would run out: a hang is killed.
            const auto start = std::chrono::steady_clock::now();
            const RunResult r = test::run(CAMWRIGHT_CLI, args, 30);
            const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
            EXPECT_EQ(r.signal, 0);
            EXPECT_EQ(r.exitCode, 2);
            EXPECT_EQ(r.err, "camwright-cli: " + file + ": " + c.says + "\n");
            EXPECT_LT(took.count(), 10.0);
        }
    }
}

TEST(CliBigInputs, DevicesFifosAndFoldersAreRefusedSayingWhatTheyAre) {
    const TempDir dir;
    const std::string fifo = dir.file("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    struct Case {
        std::string path;
        const char* kind;
    };
    for (const Case& c : {Case{"/dev/zero", "a character device"}, Case{fifo, "a FIFO"},
                          Case{dir.path().string(), "a folder"}}) {
        SCOPED_TRACE(c.path);
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"validate", c.path},
              std::vector<std::string>{"state", c.path, "--t", "0"},
              std::vector<std::string>{"timing", "--path", c.path, "--method", "seed", "--accel",
                                       "1,1"}}) {
            // /dev/zero never ends and a FIFO waits for a writer: a hang is killed after 10 s.
            const RunResult r = test::run(CAMWRIGHT_CLI, args, 10);
            EXPECT_EQ(r.signal, 0);
            EXPECT_EQ(r.exitCode, 2);
            EXPECT_EQ(r.err, "camwright-cli: " + c.path + ": is " + c.kind +
                                 ", not a regular file: not read\n");
        }
    }
}

// --- 11. the point list's and the project's own traps -----------------------------------------

TEST(CliInputKinds, APointListWithAByteOrderMarkKeepsItsFirstPoint) {
    const TempDir dir;
    const std::string csv = dir.file("bom.csv");
    writeText(csv,
              "\xEF\xBB\xBF"
              "0,0,0\n100,0,0\n200,0,0\n");
    const RunResult r =
        test::runCli({"timing", "--path", csv, "--method", "exact-stop", "--accel", "500,500,200"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto json = nlohmann::json::parse(r.out);
    EXPECT_EQ(json.at("length_mm").get<double>(), 200.0);
    EXPECT_EQ(json.at("segments").get<int>(), 2);
}

TEST(CliInputKinds, AFirstLineWithALetterOForZeroIsAnErrorOnLineOne) {
    const TempDir dir;
    const std::string csv = dir.file("typo.csv");
    writeText(csv, "O,0,0\n10,0,0\n20,0,0\n");
    const RunResult r =
        test::runCli({"timing", "--path", csv, "--method", "exact-stop", "--accel", "500,500,200"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "camwright-cli: " + csv + ": line 1: x must be a finite number (got \"O\")\n");
}

TEST(CliInputKinds, ANulByteInAProjectIsAnErrorAtItsOffset) {
    // Everything after a NUL used to be ignored: a whole project, a NUL and garbage was valid.
    const TempDir dir;
    const std::string text = readFile(kExample);
    const std::size_t inside = text.find("\"contour\"");
    ASSERT_NE(inside, std::string::npos);
    struct Case {
        const char* name;
        std::string bytes;
        std::size_t nul;
    };
    // Built by appending: GCC 12 warns falsely on std::string::insert here (-Wrestrict).
    std::string trailing = text;
    trailing.push_back('\0');
    trailing += "garbage \x01\x02 {not json";
    std::string within = text.substr(0, inside);
    within.push_back('\0');
    within.append(text, inside);
    for (const Case& c :
         {Case{"trailing", trailing, text.size()}, Case{"within", within, inside}}) {
        SCOPED_TRACE(c.name);
        const std::string file = dir.file(std::string(c.name) + ".cam.json");
        writeText(file, c.bytes);
        for (const char* command : {"validate", "analyze"}) {
            const RunResult r = test::runCli({command, file});
            EXPECT_EQ(r.exitCode, 2);
            EXPECT_EQ(r.out, "");
            EXPECT_TRUE(contains(r.err, "a NUL byte (at byte offset " + std::to_string(c.nul) +
                                            "): a project file is text"))
                << r.err;
            EXPECT_EQ(r.err.rfind("camwright-cli: " + file + ": line ", 0), 0u) << r.err;
            EXPECT_EQ(lineCount(r.err), 1u);
        }
    }
}

}  // namespace
}  // namespace cam
