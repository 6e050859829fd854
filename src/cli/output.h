#pragma once
/// @file
/// @brief camwright-cli's standard streams: results written to stdout are checked to the last
/// byte, so a full disk, /dev/full or a closed stdout is an error (exit 2), never a success.

#include <array>
#include <streambuf>
#include <string>

namespace cam::cli {

/// @brief Makes sure file descriptors 0, 1 and 2 are open before anything else is: a file the
/// program opens later would otherwise take the number of a closed stdout, and the results
/// would be written into it. A closed stdout is replaced by /dev/null opened read-only, so every
/// write to it fails (EBADF) and is reported instead of vanishing.
void occupyClosedStandardStreams();

/// @brief A stream buffer on a file descriptor that remembers the first failed write.
///
/// Writes go straight to write(2) in blocks (interrupted and partial writes are continued);
/// after the first failure nothing more is written and the buffer reports failure, so the
/// ostream on it turns bad. finish() flushes and closes the descriptor: close(2) can report
/// what write(2) did not (a network file system, a quota).
class CheckedOutput : public std::streambuf {
public:
    explicit CheckedOutput(int fd) : m_fd(fd) {
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    }
    ~CheckedOutput() override { sync(); }
    CheckedOutput(const CheckedOutput&) = delete;
    CheckedOutput& operator=(const CheckedOutput&) = delete;

    /// @brief Writes what is buffered and closes the descriptor; false when anything failed.
    bool finish();
    /// @brief The errno of the first failure, 0 if none.
    [[nodiscard]] int error() const { return m_error; }
    /// @brief Why the output failed, for a message: "cannot write the results: No space left on
    /// device"; a closed stdout says so.
    [[nodiscard]] std::string failureText() const;

protected:
    int_type overflow(int_type c) override;
    int sync() override;
    std::streamsize xsputn(const char* data, std::streamsize n) override;

private:
    bool writeAll(const char* data, std::size_t n);

    int m_fd;
    int m_error = 0;
    bool m_finished = false;
    std::array<char, 1 << 16> m_buffer{};
};

}  // namespace cam::cli
