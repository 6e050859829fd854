// The one file writer (io/atomic_file.h), guarantee by guarantee: a temporary sibling renamed
// over the target; symlinks followed and kept; mode and owner kept; non-files refused; never a
// partial file, even when a write fails midway; links to open descriptors refused; no temporary
// file left by a signal, nor for long by a crash.

#include "io/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using test::fileMode;
using test::folderEntries;
using test::readFile;
using test::TempDir;
using test::writeFileWithMode;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The hidden siblings `.<name>.…` of a file: where the writer streams to.
std::vector<std::string> temporariesOf(const fs::path& folder, const std::string& name) {
    std::vector<std::string> out;
    for (const std::string& e : folderEntries(folder)) {
        if (e.rfind("." + name + ".", 0) == 0) out.push_back(e);
    }
    return out;
}

/// Sets the umask for one scope.
class ScopedUmask {
public:
    explicit ScopedUmask(mode_t mask) : m_old(::umask(mask)) {}
    ~ScopedUmask() { ::umask(m_old); }

private:
    mode_t m_old;
};

// --- 1. temporary sibling, rename, failures leave the target and no temporary ---------------

TEST(AtomicFile, StreamsIntoATemporarySiblingAndRenamesItOnCommit) {
    TempDir dir;
    const std::string target = dir.file("p.cam.json");
    writeFileWithMode(target, "old", 0644);
    {
        AtomicFileWriter writer(target);
        ASSERT_TRUE(writer.ok()) << writer.errors().front().text();
        writer.write("new ");
        writer.write("content");
        // Mid-way: the target is untouched, the new content sits in one hidden sibling.
        EXPECT_EQ(readFile(target), "old");
        const auto temps = temporariesOf(dir.path(), "p.cam.json");
        ASSERT_EQ(temps.size(), 1u);
        // A known pattern, so leftovers of a crash can be found: .<name>.camwright-XXXXXX.tmp
        EXPECT_EQ(temps.front().rfind(".p.cam.json.camwright-", 0), 0u) << temps.front();
        EXPECT_EQ(temps.front().size(), std::string(".p.cam.json.camwright-XXXXXX.tmp").size());
        EXPECT_TRUE(temps.front().ends_with(".tmp")) << temps.front();
        EXPECT_EQ(readFile(dir.file(temps.front())), "new content");
        EXPECT_TRUE(writer.commit().empty());
    }
    EXPECT_EQ(readFile(target), "new content");
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.cam.json"});
    ASSERT_TRUE(writeFileAtomically(target, "second").empty());
    EXPECT_EQ(readFile(target), "second");
}

TEST(AtomicFile, DestroyedWithoutCommitLeavesTheTargetAndNoTemporary) {
    TempDir dir;
    const std::string target = dir.file("p.cam.json");
    ASSERT_TRUE(writeFileAtomically(target, "second").empty());
    {
        AtomicFileWriter writer(target);
        writer.write("half a fi");
        // destroyed without commit: as if the program gave up mid-way
    }
    EXPECT_EQ(readFile(target), "second");
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.cam.json"});
}

TEST(AtomicFile, AnUncreatableTemporaryIsReportedWithThePathAndTheReason) {
    TempDir dir;
    const std::string target = dir.file("missing/x.json");
    const Diagnostics failed = writeFileAtomically(target, "x");
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_EQ(failed.front().location, target);
    EXPECT_TRUE(contains(failed.front().message,
                         "cannot create a temporary file in " + dir.file("missing")))
        << failed.front().message;
    EXPECT_TRUE(contains(failed.front().message, "No such file or directory"))
        << failed.front().message;
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(AtomicFile, AFailedRenameLeavesTheTargetAndReportsIt) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    writeFileWithMode(target, "old", 0644);
    AtomicFileWriter writer(target);
    writer.write("new");
    // Take the temporary file away behind the writer's back: the rename itself fails.
    const auto temps = temporariesOf(dir.path(), "p.csv");
    ASSERT_EQ(temps.size(), 1u);
    fs::remove(dir.path() / temps.front());
    const Diagnostics failed = writer.commit();
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_EQ(failed.front().location, target);
    EXPECT_TRUE(contains(failed.front().message, "cannot replace " + target + ": No such file"))
        << failed.front().message;
    EXPECT_EQ(readFile(target), "old");
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
}

TEST(AtomicFile, ATargetThatBecomesAFolderWhileWrittenIsNotReplaced) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    AtomicFileWriter writer(target);
    writer.write("new");
    fs::create_directory(target);
    std::ofstream(dir.file("p.csv/inside")) << "keep";
    const Diagnostics failed = writer.commit();
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_TRUE(contains(failed.front().message, "folder")) << failed.front().message;
    EXPECT_EQ(readFile(dir.file("p.csv/inside")), "keep");
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
}

TEST(AtomicFile, CommitIsFinalAndAFailureStopsFurtherWrites) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    AtomicFileWriter writer(target);
    writer.write("one");
    ASSERT_TRUE(writer.commit().empty());
    writer.write("two");  // after commit: ignored, the file is complete
    EXPECT_TRUE(writer.commit().empty());
    EXPECT_EQ(readFile(target), "one");
}

// --- 2. symlinks: the file they point to is replaced, the links stay links ------------------

TEST(AtomicFile, WritesThroughSymlinkChainsAndRelativeLinksAndKeepsThem) {
    TempDir dir;
    fs::create_directories(dir.path() / "real");
    fs::create_directories(dir.path() / "links");
    const std::string real = dir.file("real/data.csv");
    writeFileWithMode(real, "old", 0640);
    // links/out.csv -> ../real/data.csv (relative to the link's own folder)
    fs::create_symlink("../real/data.csv", dir.path() / "links/out.csv");
    // chain.csv -> links/out.csv -> ../real/data.csv
    fs::create_symlink("links/out.csv", dir.path() / "chain.csv");
    // absolute.csv -> /…/chain.csv
    fs::create_symlink(dir.path() / "chain.csv", dir.path() / "absolute.csv");

    for (const char* name : {"links/out.csv", "chain.csv", "absolute.csv"}) {
        SCOPED_TRACE(name);
        const std::string via = dir.file(name);
        AtomicFileWriter writer(via);
        ASSERT_TRUE(writer.ok()) << writer.errors().front().text();
        writer.write(std::string("through ") + name);
        // The temporary file sits next to the real file, so the rename stays in one folder.
        EXPECT_EQ(temporariesOf(dir.path() / "real", "data.csv").size(), 1u);
        EXPECT_TRUE(temporariesOf(dir.path() / "links", "out.csv").empty());
        ASSERT_TRUE(writer.commit().empty());
        EXPECT_EQ(readFile(real), std::string("through ") + name);
        EXPECT_EQ(fileMode(real), 0640);
        for (const char* link : {"links/out.csv", "chain.csv", "absolute.csv"}) {
            EXPECT_TRUE(fs::is_symlink(dir.path() / link)) << link;
        }
        EXPECT_EQ(folderEntries(dir.path() / "real"), std::vector<std::string>{"data.csv"});
    }
}

TEST(AtomicFile, ADanglingSymlinkGetsItsTargetCreated) {
    TempDir dir;
    fs::create_directories(dir.path() / "real");
    fs::create_symlink("real/new.csv", dir.path() / "out.csv");
    ASSERT_TRUE(writeFileAtomically(dir.file("out.csv"), "created").empty());
    EXPECT_TRUE(fs::is_symlink(dir.path() / "out.csv"));
    EXPECT_EQ(readFile(dir.file("real/new.csv")), "created");
}

TEST(AtomicFile, ASymlinkLoopIsRefused) {
    TempDir dir;
    fs::create_symlink("b.csv", dir.path() / "a.csv");
    fs::create_symlink("a.csv", dir.path() / "b.csv");
    const Diagnostics failed = writeFileAtomically(dir.file("a.csv"), "x");
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_EQ(failed.front().location, dir.file("a.csv"));
    EXPECT_TRUE(contains(failed.front().message, "Too many levels of symbolic links"))
        << failed.front().message;
    EXPECT_TRUE(fs::is_symlink(dir.path() / "a.csv"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "b.csv"));
    EXPECT_EQ(folderEntries(dir.path()), (std::vector<std::string>{"a.csv", "b.csv"}));
}

// --- 3. permission bits and owner of an existing file; the umask for a new one --------------

TEST(AtomicFile, AnExistingFileKeepsItsPermissionBits) {
    TempDir dir;
    for (const int mode : {0600, 0640, 0604, 0755, 0660, 02750}) {
        SCOPED_TRACE(mode);
        const std::string target = dir.file("p.csv");
        writeFileWithMode(target, "old", mode);
        ASSERT_EQ(fileMode(target), mode);
        ASSERT_TRUE(writeFileAtomically(target, "new").empty());
        EXPECT_EQ(readFile(target), "new");
        EXPECT_EQ(fileMode(target), mode);
    }
}

TEST(AtomicFile, ANewFileGetsTheDefaultModeLessTheUmask) {
    TempDir dir;
    for (const mode_t mask : {022, 027, 077, 002}) {
        SCOPED_TRACE(mask);
        const ScopedUmask scoped(mask);
        const std::string target = dir.file("new" + std::to_string(mask) + ".csv");
        ASSERT_TRUE(writeFileAtomically(target, "x").empty());
        EXPECT_EQ(fileMode(target), static_cast<int>(0666 & ~mask));
    }
}

TEST(AtomicFile, AnExistingFileKeepsItsOwnerAndGroup) {
    if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file to another owner";
    TempDir dir;
    const std::string target = dir.file("p.csv");
    writeFileWithMode(target, "old", 0640);
    ASSERT_EQ(::chown(target.c_str(), 1234, 5678), 0);
    ASSERT_TRUE(writeFileAtomically(target, "new").empty());
    struct stat st {};
    ASSERT_EQ(::stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 1234u);
    EXPECT_EQ(st.st_gid, 5678u);
    EXPECT_EQ(st.st_mode & 07777, 0640u);  // fchown did not clear what fchmod set
}

TEST(AtomicFile, AFileWeMayNotWriteIsNotReplaced) {
    if (::geteuid() == 0) GTEST_SKIP() << "root may write any file";
    TempDir dir;
    const std::string target = dir.file("read-only.csv");
    writeFileWithMode(target, "old", 0444);
    const Diagnostics failed = writeFileAtomically(target, "new");
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_TRUE(contains(failed.front().message, "Permission denied")) << failed.front().message;
    EXPECT_EQ(readFile(target), "old");
}

// --- 4. anything that is not a regular file is refused and left alone -----------------------

TEST(AtomicFile, AFolderAFifoAndALinkToAFifoAreRefusedAndLeftAlone) {
    TempDir dir;
    fs::create_directory(dir.path() / "folder");
    std::ofstream(dir.file("folder/inside")) << "keep";
    ASSERT_EQ(::mkfifo(dir.file("pipe").c_str(), 0600), 0);
    fs::create_symlink("pipe", dir.path() / "to-pipe");
    const auto before = folderEntries(dir.path());

    struct Case {
        const char* name;
        const char* says;
    };
    for (const Case c : {Case{"folder", "is a folder, not a regular file"},
                         Case{"pipe", "is a FIFO, not a regular file"},
                         Case{"to-pipe", "pipe is a FIFO, not a regular file"}}) {
        SCOPED_TRACE(c.name);
        AtomicFileWriter writer(dir.file(c.name));
        EXPECT_FALSE(writer.ok());
        writer.write("never");
        const Diagnostics failed = writer.commit();
        ASSERT_EQ(failed.size(), 1u);
        EXPECT_EQ(failed.front().location, dir.file(c.name));
        EXPECT_TRUE(contains(failed.front().message, c.says)) << failed.front().message;
    }
    EXPECT_EQ(folderEntries(dir.path()), before);  // no temporary file either
    EXPECT_TRUE(fs::is_directory(dir.path() / "folder"));
    EXPECT_EQ(readFile(dir.file("folder/inside")), "keep");
    EXPECT_TRUE(fs::is_fifo(dir.path() / "pipe"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "to-pipe"));
}

// --- 5. never a partial file: a write that fails midway --------------------------------------

// In a forked child (the limit must not touch the test process): a file size limit far below
// what is written makes write() fail with EFBIG part-way. Exit codes say what went wrong.
int childWritingPastTheSizeLimit(const std::string& target, bool streaming) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) return 10;
    const std::string big(1 << 20, 'n');
    Diagnostics failed;
    if (streaming) {
        AtomicFileWriter writer(target);
        for (int i = 0; i < 64; ++i) writer.write(std::string_view(big).substr(0, 16 * 1024));
        if (writer.ok()) return 11;
        // The temporary file is gone as soon as the write failed, not only at destruction.
        if (!temporariesOf(fs::path(target).parent_path(), "p.csv").empty()) return 12;
        failed = writer.commit();
    } else {
        failed = writeFileAtomically(target, big);
    }
    if (failed.size() != 1) return 13;
    if (!contains(failed.front().message, "File too large")) return 14;
    if (failed.front().location != target) return 15;
    return 0;
}

TEST(AtomicFile, AWriteThatFailsMidwayLeavesTheOldFileWholeAndNoTemporary) {
    for (const bool streaming : {false, true}) {
        SCOPED_TRACE(streaming ? "streaming" : "one call");
        TempDir dir;
        const std::string target = dir.file("p.csv");
        const std::string old(100 * 1024, 'o');  // larger than the limit: only new bytes count
        writeFileWithMode(target, old, 0600);
        const pid_t pid = ::fork();
        if (pid == 0) ::_exit(childWritingPastTheSizeLimit(target, streaming));
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFEXITED(status)) << "child killed by signal " << WTERMSIG(status);
        EXPECT_EQ(WEXITSTATUS(status), 0);
        EXPECT_EQ(readFile(target), old);
        EXPECT_EQ(fileMode(target), 0600);
        EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
    }
}

// --- 6. a link to an open file descriptor is not a file to replace -------------------------

TEST(AtomicFile, DevStdoutAndProcFdLinksAreRefused) {
    TempDir dir;
    // Our own stdout pointing at a regular file is the dangerous case: following the link would
    // rename over that file behind the back of whoever has it open.
    const std::string captured = dir.file("captured.txt");
    std::ofstream(captured) << "old";
    const int fd = ::open(captured.c_str(), O_WRONLY);
    ASSERT_GE(fd, 0);
    // /dev/stdout itself is used through a copy of its link: a writer that got this wrong
    // (612d090 did, as root) would rename over the machine's /dev/stdout, not a test file.
    std::error_code ec;
    const fs::path devStdout = fs::read_symlink("/dev/stdout", ec);
    ASSERT_FALSE(ec) << "/dev/stdout is not a symbolic link here: " << ec.message();
    ASSERT_EQ(devStdout, "/proc/self/fd/1");
    const std::string stdoutLink = dir.file("stdout");
    fs::create_symlink(devStdout, stdoutLink);
    struct Case {
        std::string path;
        std::string says;
    };
    const std::string fdText = std::to_string(fd);
    for (const Case& c :
         {Case{stdoutLink, "/proc/self/fd/1 is a link"},
          Case{"/proc/self/fd/" + fdText, "is a link"}, Case{"/dev/fd/" + fdText, "is a link"}}) {
        SCOPED_TRACE(c.path);
        const Diagnostics failed = writeFileAtomically(c.path, "new");
        ASSERT_EQ(failed.size(), 1u);
        EXPECT_EQ(failed.front().location, c.path);
        EXPECT_TRUE(contains(failed.front().message,
                             c.says + " to an open file descriptor, not a file: not replaced"))
            << failed.front().message;
    }
    ::close(fd);
    EXPECT_EQ(readFile(captured), "old");
    EXPECT_TRUE(fs::is_symlink(stdoutLink));
    EXPECT_EQ(folderEntries(dir.path()), (std::vector<std::string>{"captured.txt", "stdout"}));
}

// --- 7. leftovers: a dead writer's temporary file goes with the next write, a live one stays --

TEST(AtomicFile, ALeftoverOfADeadWriterIsRemovedByTheNextWriteOfThatFile) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    writeFileWithMode(target, "old", 0644);
    // What a SIGKILLed writer leaves: a temporary file nobody holds locked. Next to it, files
    // that only look alike and must stay: another target's, other suffixes, a folder.
    std::ofstream(dir.file(".p.csv.camwright-Ab3dE9.tmp")) << "half a fi";
    const std::vector<std::string> unrelated{
        ".other.csv.camwright-Ab3dE9.tmp", ".p.csv.camwright-Ab3dE9.tmp.bak",
        ".p.csv.camwright-Ab3dE.tmp",      ".p.csv.camwright-Ab3dE9",
        ".p.csv.camwright-Ab_dE9.tmp",     "p.csv.camwright-Ab3dE9.tmp"};
    for (const std::string& name : unrelated) std::ofstream(dir.file(name)) << "keep";
    fs::create_directory(dir.path() / ".p.csv.camwright-Folder.tmp");

    ASSERT_TRUE(writeFileAtomically(target, "new").empty());
    EXPECT_EQ(readFile(target), "new");
    EXPECT_FALSE(fs::exists(dir.path() / ".p.csv.camwright-Ab3dE9.tmp"));
    for (const std::string& name : unrelated) EXPECT_EQ(readFile(dir.file(name)), "keep") << name;
    EXPECT_TRUE(fs::is_directory(dir.path() / ".p.csv.camwright-Folder.tmp"));
}

TEST(AtomicFile, ATemporaryFileOfALiveWriterIsLeftAlone) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    AtomicFileWriter slow(target);
    ASSERT_TRUE(slow.ok());
    slow.write("the slow writer's content");
    const auto slowTemp = temporariesOf(dir.path(), "p.csv");
    ASSERT_EQ(slowTemp.size(), 1u);
    // A second writer of the same file (flock locks are per open file, so this holds within one
    // process as between two) finds it locked and leaves it.
    ASSERT_TRUE(writeFileAtomically(target, "quick").empty());
    EXPECT_EQ(readFile(target), "quick");
    EXPECT_EQ(temporariesOf(dir.path(), "p.csv"), slowTemp);
    EXPECT_EQ(readFile(dir.file(slowTemp.front())), "the slow writer's content");
    ASSERT_TRUE(slow.commit().empty());
    EXPECT_EQ(readFile(target), "the slow writer's content");
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
}

TEST(AtomicFile, ALeftoverHeldLockedByAnotherProcessIsLeftAlone) {
    TempDir dir;
    const std::string target = dir.file("p.csv");
    const std::string held = dir.file(".p.csv.camwright-Held00.tmp");
    std::ofstream(held) << "in progress";
    int ready[2];
    int release[2];
    ASSERT_EQ(::pipe(ready), 0);
    ASSERT_EQ(::pipe(release), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int fd = ::open(held.c_str(), O_RDONLY);
        if (fd < 0 || ::flock(fd, LOCK_EX) != 0) ::_exit(1);
        char c = 'r';
        if (::write(ready[1], &c, 1) != 1) ::_exit(2);
        if (::read(release[0], &c, 1) != 1) ::_exit(3);  // hold the lock until told
        ::_exit(0);
    }
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    const bool written = writeFileAtomically(target, "new").empty();
    const bool heldSurvived = fs::exists(held);
    ASSERT_EQ(::write(release[1], &c, 1), 1);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_TRUE(written);
    EXPECT_TRUE(heldSurvived);
    // Once its holder is gone it is a leftover like any other.
    ASSERT_TRUE(writeFileAtomically(target, "newer").empty());
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
    for (int fd : {ready[0], ready[1], release[0], release[1]}) ::close(fd);
}

// In a forked child: a writer in progress, then the signal. Exit codes say what went wrong.
[[noreturn]] void childKilledWhileWriting(const std::string& target, int signal) {
    // As in a foreground program: a test run in the background of a script inherits SIGINT
    // ignored, and the cleanup leaves ignored signals alone (nohup).
    ::signal(signal, SIG_DFL);
    installTemporaryFileCleanup();
    AtomicFileWriter writer(target);
    writer.write("half a fi");
    if (!writer.ok() || temporariesOf(fs::path(target).parent_path(), "p.csv").size() != 1) {
        ::_exit(10);
    }
    ::raise(signal);
    ::_exit(11);  // not reached: the signal ends the process
}

TEST(AtomicFile, SigintSigtermAndSighupRemoveTheTemporaryFileAndStillEndTheProgram) {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        SCOPED_TRACE(strsignal(signal));
        TempDir dir;
        const std::string target = dir.file("p.csv");
        writeFileWithMode(target, "old", 0644);
        const pid_t pid = ::fork();
        if (pid == 0) childKilledWhileWriting(target, signal);
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFSIGNALED(status)) << "exit code " << WEXITSTATUS(status);
        EXPECT_EQ(WTERMSIG(status), signal);
        EXPECT_EQ(readFile(target), "old");
        EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"p.csv"});
    }
}

}  // namespace
}  // namespace cam
