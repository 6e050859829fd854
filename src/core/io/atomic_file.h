#pragma once
/// @file
/// @brief The one way Camwright writes a file (the app's Save, every CLI `--out`): all of the
/// new content or none of it, with the target's mode, owner and symlinks kept. POSIX.

#include <sys/types.h>
#include <string>
#include <string_view>

#include "common/diagnostic.h"

namespace cam {

/// @brief "a folder", "a FIFO", …: what a file of this mode is that is not a regular file, as a
/// term of the diagnostic catalogue.
[[nodiscard]] const char* fileKindName(mode_t mode);

/// @brief Streams a file into a temporary sibling and renames it over the target on commit().
///
/// - **Where**: the target is the path with every symlink followed (chains and relative links
///   too); the temporary file `.<name>.camwright-XXXXXX.tmp` (six random letters or digits) is
///   created next to that resolved file, so the rename stays inside one folder and the symlinks
///   stay symlinks. A dangling symlink is followed too: its target is created, as `echo > link`
///   would.
/// - **What is refused**: a target that exists and is not a regular file (a folder, a FIFO, a
///   device, a socket) — left untouched, nothing is opened; a link to an open file descriptor
///   (`/dev/stdout`, `/proc/self/fd/N`: what it names is a pipe or a terminal as often as a
///   file, and renaming over that file would cut it off from whoever has it open); a symlink
///   loop; a file this process may not write (as `>` in a shell would refuse it; root may write
///   any).
/// - **Order**: write the temporary file, fsync it, rename it over the target, fsync the
///   folder. Until the rename the target is untouched; any failure before it removes the
///   temporary file. A failure of the folder's fsync (after the rename) is reported too: the
///   new content is in place but may not survive a power loss.
/// - **Metadata**: an existing target keeps its permission bits (also set-id and sticky) and,
///   where permitted, its owner and group (an EPERM from fchown is ignored); a new file gets
///   0666 & ~umask (and the folder's default ACL), like any created file. Other hard links to
///   the old file keep the old content.
/// - **Errors**: Diagnostics located at the path as given, saying what failed and why (the
///   errno text), e.g. {"out.csv", "cannot write /data/out.csv: File too large"}. The first
///   failure is kept; later writes do nothing.
/// - **Leftovers**: the writer holds an exclusive flock(2) on its temporary file from creation
///   to the rename. A temporary file of the same target that nobody holds locked belongs to a
///   writer that died (SIGKILL, a power loss): each new writer removes those before it creates
///   its own, so a crash costs disk space only until the next write of that file. Files of that
///   name pattern that someone holds locked (a live writer, in this or another process) and
///   files that cannot be opened to test the lock (another user's) are left alone.
/// - **Signals**: with installTemporaryFileCleanup(), SIGINT, SIGTERM and SIGHUP remove every
///   temporary file in progress before the program ends by the signal as it would have.
///
/// Destroyed without commit() (or after a failure), it removes the temporary file and leaves
/// the target as it was.
class AtomicFileWriter {
public:
    /// @brief Resolves the target and creates the temporary file; check ok().
    explicit AtomicFileWriter(std::string path);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    /// @brief False (with errors()) once anything has failed.
    [[nodiscard]] bool ok() const { return m_errors.empty(); }
    /// @brief Appends a chunk to the temporary file (nothing once something has failed).
    void write(std::string_view chunk);
    /// @brief fsync, rename over the target, fsync of the folder; returns the problems, empty
    /// on success. Only the first call does anything.
    [[nodiscard]] Diagnostics commit();
    [[nodiscard]] const Diagnostics& errors() const { return m_errors; }

private:
    void resolveTarget();
    void createTemporary();
    /// Records the failure `code` (the first failure only), whose arguments are `args` and then
    /// the OS's text for `error`.
    void fail(DiagnosticCode code, int error, std::vector<DiagnosticArg> args);
    void discardTemporary();
    void removeStaleTemporaries(const std::string& folder, const std::string& name) const;

    std::string m_path;
    std::string m_resolvedPath;
    std::string m_tempPath;
    int m_fd = -1;
    int m_signalSlot = -1;  ///< where the temporary file is known to the signal handler, or -1
    bool m_targetExists = false;
    mode_t m_mode = 0;
    uid_t m_uid = 0;
    gid_t m_gid = 0;
    bool m_committed = false;
    Diagnostics m_errors;
};

/// @brief Makes SIGINT, SIGTERM and SIGHUP remove the temporary files of every AtomicFileWriter
/// in progress, then end the program by that signal as before (exit status 128 + signal).
/// Signals that are ignored (nohup) or already handled are left as they are. For programs, not
/// libraries: call it once at start (the CLI does). Async-signal-safe: the handler only calls
/// unlink(2) on paths prepared before, for up to 16 writers at a time.
void installTemporaryFileCleanup();

/// @brief Writes a whole file through AtomicFileWriter: all of `content` or, on failure, the
/// target untouched and the problem returned.
[[nodiscard]] Diagnostics writeFileAtomically(const std::string& path, std::string_view content);

}  // namespace cam
