#include "cli/output.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cam::cli {

void occupyClosedStandardStreams() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        // Read-only even for stdout and stderr: writing to it then fails instead of
        // pretending to succeed. open() returns the lowest free number, which is `fd`.
        const int opened = ::open("/dev/null", O_RDONLY);
        if (opened >= 0 && opened != fd) {
            ::dup2(opened, fd);
            ::close(opened);
        }
    }
}

bool CheckedOutput::writeAll(const char* data, std::size_t n) {
    while (m_error == 0 && n > 0) {
        const ssize_t written = ::write(m_fd, data, n);
        if (written < 0) {
            if (errno == EINTR) continue;
            m_error = errno;
        } else if (written == 0) {
            m_error = EIO;  // write(2) never returns 0 for n > 0; do not loop forever if it does
        } else {
            data += written;
            n -= static_cast<std::size_t>(written);
        }
    }
    return m_error == 0;
}

int CheckedOutput::sync() {
    const bool ok = writeAll(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return ok ? 0 : -1;
}

CheckedOutput::int_type CheckedOutput::overflow(int_type c) {
    if (sync() != 0) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
}

std::streamsize CheckedOutput::xsputn(const char* data, std::streamsize n) {
    if (n <= epptr() - pptr()) {
        std::memcpy(pptr(), data, static_cast<std::size_t>(n));
        pbump(static_cast<int>(n));
        return n;
    }
    // Larger than what is left of the buffer: write what is buffered, then the block itself.
    if (sync() != 0 || !writeAll(data, static_cast<std::size_t>(n))) return 0;
    return n;
}

bool CheckedOutput::finish() {
    if (m_finished) return m_error == 0;
    m_finished = true;
    sync();
    // EBADF: there was nothing to close (occupyClosedStandardStreams could not open /dev/null);
    // a write to it would have failed already.
    if (::close(m_fd) != 0 && m_error == 0 && errno != EINTR && errno != EBADF) m_error = errno;
    return m_error == 0;
}

std::string CheckedOutput::failureText() const {
    if (m_error == EBADF) return "is closed or not open for writing: the results are lost";
    return std::string("cannot write the results: ") + std::strerror(m_error);
}

}  // namespace cam::cli
