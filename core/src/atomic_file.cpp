#include "fv/atomic_file.hpp"

#include "fv/printable_text.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
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

// A path in a message: quoted, printable and bounded whatever bytes it holds.
std::string quoted(const std::string& path) {
    return quoted_text(path, 400);
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

// The temporary files open right now, for the SIGINT/SIGTERM handler: fixed slots of plain bytes, since a
// handler may not allocate or lock. A slot is 2 once its path is complete, so the handler never reads a
// half-copied one.
constexpr int kTempSlots = 64;
struct TempSlot {
    std::atomic<int> state{0}; // 0 free, 1 being filled, 2 a path to remove on a signal
    char path[4096];
};
TempSlot g_temps[kTempSlots];

int register_temp(const std::string& path) {
    if (path.size() >= sizeof TempSlot::path) return -1;
    for (int k = 0; k < kTempSlots; ++k) {
        int expected = 0;
        if (!g_temps[k].state.compare_exchange_strong(expected, 1)) continue;
        std::memcpy(g_temps[k].path, path.c_str(), path.size() + 1);
        g_temps[k].state = 2;
        return k;
    }
    return -1; // more than 64 writes at once: that one is not cleaned up on a signal
}

void unregister_temp(int slot) {
    if (slot >= 0) g_temps[slot].state = 0;
}

extern "C" void remove_temps_and_exit(int sig) {
    for (TempSlot& t : g_temps)
        if (t.state.load() == 2) ::unlink(t.path);
    ::_exit(128 + sig);
}

// mkstemp in `dir` with the prefix, registered for removal on a signal; -1 and errno on failure.
int make_temp(const std::string& dir, const char* prefix, std::string& path, int& slot) {
    path = dir + "/" + prefix + "XXXXXX";
    // Signals are held while the file exists but is not yet registered, so none can slip in between.
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    const int fd = ::mkstemp(path.data());
    slot = fd >= 0 ? register_temp(path) : -1;
    const int saved = errno;
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    errno = saved;
    return fd;
}

void remove_temp(const std::string& path, int& slot) {
    ::unlink(path.c_str());
    unregister_temp(slot);
    slot = -1;
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
    std::string probe;
    int slot = -1;
    const int fd = make_temp(dir, ".fv-probe-", probe, slot);
    if (fd < 0) return "cannot create files in directory " + quoted(dir) + ": " + errno_text();
    ::close(fd);
    remove_temp(probe, slot);
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
    OutputStream out;
    if (std::string why = out.open(path); !why.empty()) return why;
    if (std::string why = out.write(data); !why.empty()) return why;
    return out.commit();
}

std::string write_file_new(const std::string& path, std::string_view data) {
    OutputStream out;
    if (std::string why = out.open(path); !why.empty()) return why;
    if (std::string why = out.write(data); !why.empty()) return why;
    return out.commit(false);
}

std::string write_numbered_file(const std::function<std::string(int)>& name_of, std::string_view data,
                                std::string& written, int max_tries) {
    for (int n = 1; n <= max_tries; ++n) {
        const std::string name = name_of(n);
        struct stat st {};
        if (::lstat(name.c_str(), &st) == 0) continue; // taken (a file, a link, anything): the next number
        const std::string why = write_file_new(name, data);
        if (why.empty()) {
            written = name;
            return {};
        }
        if (why.find(" already exists") == std::string::npos) return why; // else taken meanwhile: the next
    }
    return "no free name from " + quoted(name_of(1)) + " to " + quoted(name_of(max_tries)) +
           "; remove some of those files";
}

OutputStream::~OutputStream() {
    abort();
}

std::string OutputStream::open(const std::string& path) {
    abort();
    if (std::string why = resolve_output(path, target_); !why.empty()) return why;
    switch (target_.kind) {
    case OutputTarget::Kind::descriptor:
        // Whatever the program already printed to stdio goes first, as it would with `> file`.
        std::fflush(nullptr);
        fd_ = target_.fd;
        return {};
    case OutputTarget::Kind::special:
        // O_NONBLOCK: opening a FIFO for writing blocks until a reader opens it; non-blocking it fails with
        // ENXIO instead, which is reported rather than waited for. No O_CREAT, no O_TRUNC: the file exists
        // and is not a regular file.
        fd_ = ::open(target_.path.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd_ < 0) {
            if (errno == ENXIO) return "FIFO " + quoted(target_.path) + " has no reader";
            return "cannot open " + quoted(target_.path) + ": " + errno_text();
        }
        // Once open, write with ordinary blocking semantics (a full pipe waits for its reader).
        ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
        return {};
    case OutputTarget::Kind::regular:
        break;
    }
    struct stat old {};
    exists_ = ::stat(target_.path.c_str(), &old) == 0;
    mode_ = old.st_mode & 07777, uid_ = old.st_uid, gid_ = old.st_gid;
    // The temporary file lives in the target's directory so that rename() stays on one file system.
    const std::string dir = directory_of(target_.path);
    fd_ = make_temp(dir, ".fv-tmp-", temp_, slot_);
    if (fd_ < 0) {
        temp_.clear();
        return "cannot create a temporary file in " + quoted(dir) + ": " + errno_text();
    }
    return {};
}

std::string OutputStream::write(std::string_view data) {
    if (fd_ < 0) return "cannot write " + quoted(target_.path) + ": not open";
    return write_all(fd_, data, quoted(target_.path));
}

std::string OutputStream::commit(bool replace) {
    if (fd_ < 0) return "cannot write " + quoted(target_.path) + ": not open";
    const std::string& path = target_.path;
    std::string error;
    if (target_.kind == OutputTarget::Kind::descriptor) {
        fd_ = -1; // the process's own descriptor stays open
        return {};
    }
    if (target_.kind == OutputTarget::Kind::special) {
        if (::close(fd_) != 0) error = "cannot close " + quoted(path) + ": " + errno_text();
        fd_ = -1;
        return error;
    }
    if (::fsync(fd_) != 0) error = "cannot flush " + quoted(path) + ": " + errno_text();
    // mkstemp creates 0600. A replaced file keeps its mode and, where allowed (root), its owner; a new one
    // gets what open() would have given it.
    if (error.empty()) {
        ::fchmod(fd_, exists_ && replace ? mode_ : new_file_mode());
        // Only root may give a file away; anyone else keeps the new file as their own, which is no damage.
        if (exists_ && replace && (uid_ != ::geteuid() || gid_ != ::getegid()) &&
            ::fchown(fd_, uid_, gid_) != 0)
            errno = 0;
    }
    if (::close(fd_) != 0 && error.empty()) error = "cannot close " + quoted(path) + ": " + errno_text();
    fd_ = -1;
    int saved = 0;
    if (error.empty()) {
        if (replace) {
            if (::rename(temp_.c_str(), path.c_str()) != 0)
                error = "cannot replace " + quoted(path) + ": " + errno_text();
            else
                temp_.clear(); // it is the target now
        } else if (::link(temp_.c_str(), path.c_str()) != 0) {
            saved = errno;
            // A file system without hard links (FAT, some FUSE mounts, the browser's MEMFS): look, then
            // rename; a name taken between the two is the only race left, and only there.
            struct stat st {};
            const bool no_links = saved == EMLINK || saved == EPERM || saved == ENOSYS || saved == EOPNOTSUPP;
            if (no_links && ::lstat(path.c_str(), &st) != 0 && errno == ENOENT) {
                saved = 0;
                if (::rename(temp_.c_str(), path.c_str()) != 0)
                    saved = errno, error = "cannot create " + quoted(path) + ": " + errno_text();
                else
                    temp_.clear();
            } else if (saved == EEXIST || no_links) {
                saved = EEXIST;
                error = quoted(path) + " already exists; not replaced";
            } else {
                errno = saved;
                error = "cannot create " + quoted(path) + ": " + errno_text();
            }
        }
    }
    if (!temp_.empty()) remove_temp(temp_, slot_);
    unregister_temp(slot_);
    slot_ = -1;
    temp_.clear();
    errno = saved;
    return error;
}

void OutputStream::abort() {
    if (target_.kind != OutputTarget::Kind::descriptor && fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temp_.empty()) remove_temp(temp_, slot_);
    temp_.clear();
}

void install_interrupt_cleanup() {
    struct sigaction sa {};
    sa.sa_handler = remove_temps_and_exit;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM}) ::sigaction(sig, &sa, nullptr);
}

} // namespace fv
