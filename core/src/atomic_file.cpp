#include "fv/atomic_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fv {
namespace {

std::string directory_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string errno_text() {
    return std::strerror(errno);
}

} // namespace

std::string check_writable(const std::string& path) {
    if (path.empty()) return "empty path";
    if (path.back() == '/') return "'" + path + "' names a directory, not a file";
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return "'" + path + "' is a directory, not a file";
        // Renaming over a device or a pipe (say /dev/null as root) would replace it: refuse.
        if (!S_ISREG(st.st_mode)) return "'" + path + "' exists and is not a regular file";
    }
    const std::string dir = directory_of(path);
    if (::stat(dir.c_str(), &st) != 0) return "directory '" + dir + "' does not exist";
    if (!S_ISDIR(st.st_mode)) return "'" + dir + "' is not a directory";
    if (::access(dir.c_str(), W_OK | X_OK) != 0) return "directory '" + dir + "' is not writable";
    // access() says yes to root everywhere; only creating a file there tells for sure (e.g. /proc, read-only
    // mounts).
    std::string probe = dir + "/.fv-probe-XXXXXX";
    const int fd = ::mkstemp(probe.data());
    if (fd < 0) return "cannot create files in directory '" + dir + "': " + errno_text();
    ::close(fd);
    ::unlink(probe.c_str());
    return {};
}

std::string write_file_atomic(const std::string& path, std::string_view data) {
    if (auto why = check_writable(path); !why.empty()) return why;
    const std::string dir = directory_of(path);
    // The temporary file lives in the target's directory so that rename() stays on one file system.
    std::string tmpl = dir + "/.fv-tmp-XXXXXX";
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) return "cannot create a temporary file in '" + dir + "': " + errno_text();
    const char* p = data.data();
    std::size_t left = data.size();
    std::string error;
    while (left > 0 && error.empty()) {
        const ssize_t w = ::write(fd, p, left);
        if (w < 0) {
            if (errno == EINTR) continue;
            error = "cannot write '" + path + "': " + errno_text();
        } else {
            p += w;
            left -= static_cast<std::size_t>(w);
        }
    }
    if (error.empty() && ::fsync(fd) != 0) error = "cannot flush '" + path + "': " + errno_text();
    // mkstemp creates 0600; results are ordinary user files.
    if (error.empty()) ::fchmod(fd, 0644);
    if (::close(fd) != 0 && error.empty()) error = "cannot close '" + path + "': " + errno_text();
    if (error.empty() && ::rename(tmpl.c_str(), path.c_str()) != 0)
        error = "cannot replace '" + path + "': " + errno_text();
    if (!error.empty()) ::unlink(tmpl.c_str());
    return error;
}

} // namespace fv
