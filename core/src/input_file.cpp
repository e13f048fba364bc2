#include "fv/input_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fv {
namespace {

std::string with_errno(const char* what) {
    return std::string(what) + ": " + std::strerror(errno);
}

// Reads fd to its end or to `limit` bytes. Streams (FIFO, pipe, device) are read without blocking, waiting
// at most timeout_ms each time no data is ready.
std::string read_all(int fd, bool stream, std::size_t limit, int timeout_ms, std::string& text) {
    text.clear();
    char buf[65536];
    while (text.size() < limit) {
        if (stream) {
            pollfd p{fd, POLLIN, 0};
            const int r = ::poll(&p, 1, timeout_ms);
            if (r < 0 && errno == EINTR) continue;
            if (r < 0) return with_errno("cannot wait for data");
            if (r == 0)
                return "no data within " + std::to_string(timeout_ms / 1000) +
                       " s (a FIFO or pipe with no writer?)";
        }
        const ssize_t n = ::read(fd, buf, std::min(sizeof buf, limit - text.size()));
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            if (errno == EISDIR) return "is a directory, not a file";
            return with_errno("cannot read");
        }
        if (n == 0) break;
        text.append(buf, static_cast<std::size_t>(n));
    }
    return {};
}

} // namespace

std::string read_input_file(const std::string& path, std::string& text, const InputLimits& limits) {
    if (path.empty()) return "empty path; give a file name";
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return errno == ENOENT ? "does not exist" : with_errno("cannot open");
    if (S_ISDIR(st.st_mode)) return "is a directory, not a file";
    if (S_ISSOCK(st.st_mode)) return "is a socket, not a file";
    if (S_ISBLK(st.st_mode)) return "is a block device, not a file";
    const bool stream = !S_ISREG(st.st_mode);
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, without end.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | (stream ? O_NONBLOCK : 0));
    if (fd < 0) return with_errno("cannot open");
    std::string error;
    if (::isatty(fd))
        error = "is a terminal; give a file, or pipe the data in and name /dev/stdin";
    else
        error = read_all(fd, stream, limits.max_bytes + 1, limits.timeout_ms, text);
    ::close(fd);
    return error;
}

} // namespace fv
