#include "fv/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fv {
namespace {

// Linux's own limit on symbolic links followed while resolving one path.
constexpr int kMaxLinks = 40;

std::string directory_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string errno_text() {
    return std::strerror(errno);
}

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

// The descriptor a path names when it is one of the process's own open files, else -1. These are "magic"
// links: renaming over /proc/self/fd/1 is impossible and replacing the file behind it would bypass the
// shell's redirect (say `>>`), so the descriptor itself is written.
int own_descriptor(const std::string& path) {
    if (path == "/dev/stdout") return 1;
    if (path == "/dev/stderr") return 2;
    if (path == "/dev/stdin") return 0;
    const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/";
    for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                      std::string("/proc/thread-self/fd/"), own}) {
        if (path.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string n = path.substr(prefix.size());
        if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::atoi(n.c_str());
    }
    return -1;
}

// Whether files can be created in `dir`. access() says yes to root everywhere; only creating a file there
// tells for sure (read-only mounts, /proc, /sys).
std::string check_creatable_in(const std::string& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) != 0) {
        if (errno == ENOENT) return "directory " + quoted(dir) + " does not exist";
        return "directory " + quoted(dir) + ": " + errno_text();
    }
    if (!S_ISDIR(st.st_mode)) return quoted(dir) + " is not a directory";
    if (::access(dir.c_str(), W_OK | X_OK) != 0) return "directory " + quoted(dir) + " is not writable";
    std::string probe = dir + "/.fv-probe-XXXXXX";
    const int fd = ::mkstemp(probe.data());
    if (fd < 0) return "cannot create files in directory " + quoted(dir) + ": " + errno_text();
    ::close(fd);
    ::unlink(probe.c_str());
    return {};
}

// The permission bits a newly created file gets from open(..., 0666): the process's umask applied. Read
// once (umask() can only be read by setting it, which would race between threads writing files).
mode_t new_file_mode() {
    static const mode_t mode = [] {
        const mode_t mask = ::umask(022);
        ::umask(mask);
        return static_cast<mode_t>(0666 & ~mask);
    }();
    return mode;
}

std::string write_all(int fd, std::string_view data, const std::string& what) {
    const char* p = data.data();
    std::size_t left = data.size();
    while (left > 0) {
        const ssize_t w = ::write(fd, p, left);
        if (w < 0) {
            if (errno == EINTR) continue;
            return "cannot write " + what + ": " + errno_text();
        }
        p += w;
        left -= static_cast<std::size_t>(w);
    }
    return {};
}

std::string write_descriptor(int fd, std::string_view data, const std::string& path) {
    // Whatever the program already printed to stdio goes first, as it would with `> file`.
    std::fflush(nullptr);
    return write_all(fd, data, quoted(path));
}

std::string write_special(const std::string& path, std::string_view data) {
    // O_NONBLOCK: opening a FIFO for writing blocks until a reader opens it; non-blocking it fails with ENXIO
    // instead, which is reported rather than waited for. No O_CREAT, no O_TRUNC: the file exists and is not
    // a regular file.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENXIO) return "FIFO " + quoted(path) + " has no reader";
        return "cannot open " + quoted(path) + ": " + errno_text();
    }
    // Once open, write with ordinary blocking semantics (a full pipe waits for its reader).
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::string error = write_all(fd, data, quoted(path));
    if (::close(fd) != 0 && error.empty()) error = "cannot close " + quoted(path) + ": " + errno_text();
    return error;
}

std::string write_regular(const std::string& path, std::string_view data) {
    const std::string dir = directory_of(path);
    struct stat old {};
    const bool exists = ::stat(path.c_str(), &old) == 0;
    // The temporary file lives in the target's directory so that rename() stays on one file system.
    std::string tmpl = dir + "/.fv-tmp-XXXXXX";
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) return "cannot create a temporary file in " + quoted(dir) + ": " + errno_text();
    std::string error = write_all(fd, data, quoted(path));
    if (error.empty() && ::fsync(fd) != 0) error = "cannot flush " + quoted(path) + ": " + errno_text();
    // mkstemp creates 0600. A replaced file keeps its mode and, where allowed (root), its owner; a new one
    // gets what open() would have given it.
    if (error.empty()) {
        ::fchmod(fd, exists ? (old.st_mode & 07777) : new_file_mode());
        // Only root may give a file away; anyone else keeps the new file as their own, which is no damage.
        if (exists && (old.st_uid != ::geteuid() || old.st_gid != ::getegid()) &&
            ::fchown(fd, old.st_uid, old.st_gid) != 0)
            errno = 0;
    }
    if (::close(fd) != 0 && error.empty()) error = "cannot close " + quoted(path) + ": " + errno_text();
    if (error.empty() && ::rename(tmpl.c_str(), path.c_str()) != 0)
        error = "cannot replace " + quoted(path) + ": " + errno_text();
    if (!error.empty()) ::unlink(tmpl.c_str());
    return error;
}

} // namespace

std::string resolve_output(const std::string& path, OutputTarget& target) {
    if (path.empty()) return "empty path";
    std::string cur = path;
    for (int links = 0; links <= kMaxLinks; ++links) {
        if (const int fd = own_descriptor(cur); fd >= 0) {
            const int flags = ::fcntl(fd, F_GETFL);
            if (flags < 0)
                return quoted(path) + " names descriptor " + std::to_string(fd) + ", which is not open";
            if ((flags & O_ACCMODE) == O_RDONLY)
                return quoted(path) + " names descriptor " + std::to_string(fd) + ", which is open read-only";
            target = {OutputTarget::Kind::descriptor, cur, fd};
            return {};
        }
        if (cur.back() == '/') return quoted(cur) + " names a directory, not a file";
        struct stat st {};
        if (::lstat(cur.c_str(), &st) != 0) {
            if (errno != ENOENT) return quoted(cur) + ": " + errno_text();
            // A new file (or a dangling link's target): its directory must take it.
            if (auto why = check_creatable_in(directory_of(cur)); !why.empty()) return why;
            target = {OutputTarget::Kind::regular, cur, -1};
            return {};
        }
        if (S_ISLNK(st.st_mode)) {
            std::string to(4096, '\0');
            const ssize_t n = ::readlink(cur.c_str(), to.data(), to.size());
            if (n < 0) return "cannot read link " + quoted(cur) + ": " + errno_text();
            to.resize(static_cast<std::size_t>(n));
            if (to.empty()) return "link " + quoted(cur) + " is empty";
            cur = to.front() == '/' ? to : directory_of(cur) + "/" + to;
            continue;
        }
        if (S_ISREG(st.st_mode)) {
            if (auto why = check_creatable_in(directory_of(cur)); !why.empty()) return why;
            target = {OutputTarget::Kind::regular, cur, -1};
            return {};
        }
        if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
            if (::access(cur.c_str(), W_OK) != 0) return quoted(cur) + " is not writable";
            target = {OutputTarget::Kind::special, cur, -1};
            return {};
        }
        if (S_ISDIR(st.st_mode)) return quoted(cur) + " is a directory, not a file";
        if (S_ISSOCK(st.st_mode)) return quoted(cur) + " is a socket; sockets cannot be written as files";
        if (S_ISBLK(st.st_mode)) return quoted(cur) + " is a block device; refusing to overwrite it";
        return quoted(cur) + " is not a file that can be written";
    }
    return quoted(path) + ": more than " + std::to_string(kMaxLinks) + " symbolic links (a loop?)";
}

std::string check_writable(const std::string& path) {
    OutputTarget t;
    return resolve_output(path, t);
}

std::string check_output_dir(const std::string& dir) {
    if (dir.empty()) return "empty path; give an existing directory";
    return check_creatable_in(dir);
}

std::string write_file_atomic(const std::string& path, std::string_view data) {
    OutputTarget t;
    if (auto why = resolve_output(path, t); !why.empty()) return why;
    switch (t.kind) {
    case OutputTarget::Kind::descriptor:
        return write_descriptor(t.fd, data, path);
    case OutputTarget::Kind::special:
        return write_special(t.path, data);
    case OutputTarget::Kind::regular:
        break;
    }
    return write_regular(t.path, data);
}

} // namespace fv
