// The output-path policy: every file the program writes (CLI, app, tests' tools) goes through here, so that a
// failed or killed run never leaves a half-written file, never clobbers something it was not asked to write,
// and never hangs on a special file.
//
//   path                         what happens
//   ---------------------------  -------------------------------------------------------------------------
//   empty, or ending in '/'      refused
//   regular file or new name     written to a temporary file beside it, flushed, renamed over it (atomic);
//                                an existing file keeps its permission bits (and owner, where allowed)
//   symbolic link (any chain)    followed; its final target is replaced atomically, the link itself is kept
//   /dev/stdout, /dev/fd/N,      the process's own open descriptor N is written directly (what a shell
//   /proc/self/fd/N                redirect `>` set up stays in charge; nothing is renamed or truncated)
//   character device, FIFO       written directly (nothing to make atomic); a FIFO without a reader is an
//                                error, never a hang
//   directory, socket,           refused
//   block device, a missing or
//   unwritable directory
//
// docs/reliability.md explains the choices; tests/reliability checks them.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace fv {

// Where an output path leads once symbolic links are followed.
struct OutputTarget {
    enum class Kind {
        regular,    // replaced atomically: `path` is the resolved file (it may not exist yet)
        special,    // character device or FIFO at `path`: opened and written directly
        descriptor, // the process's own descriptor `fd` (/dev/stdout, /dev/fd/N, /proc/self/fd/N)
    };
    Kind kind = Kind::regular;
    std::string path;
    int fd = -1;
};

// Resolves `path` by the policy above into `target`. Returns an empty string, or a one-line reason why the
// path cannot be written (nothing is created or changed either way, apart from a probe file created and
// removed at once in the target's directory to learn whether files can be created there).
std::string resolve_output(const std::string& path, OutputTarget& target);

// Empty if `path` can be written by the policy above, else a one-line reason. Used to reject a bad --out
// before any work is done.
std::string check_writable(const std::string& path);

// Empty if `dir` is an existing directory (symbolic links followed) in which files can be created, else a
// one-line reason. For commands that write several files into a directory.
std::string check_output_dir(const std::string& dir);

// Writes `data` to `path` by the policy above. Returns an empty string on success, else a one-line reason;
// on failure a regular target is untouched and no temporary file is left behind.
std::string write_file_atomic(const std::string& path, std::string_view data);

// The same, but an existing file (or a link to one) at `path` is never replaced: "… already exists" instead.
// The check and the creation are one step (link(2) of the finished temporary file), so two writers racing for
// one name cannot both succeed.
std::string write_file_new(const std::string& path, std::string_view data);

// Writes `data` to the first free name `name_of(1)`, `name_of(2)`, … (at most `max_tries`) in the current
// or given directory, never replacing a file; `written` is the name taken. For the app's screenshots and
// trail exports ("frictionviz-screenshot-3.png" when 1 and 2 exist, from this or an earlier run).
std::string write_numbered_file(const std::function<std::string(int)>& name_of, std::string_view data,
                                std::string& written, int max_tries = 100000);

// An output written in pieces (sweep's rows, as they are computed), by the same policy: a regular target is
// written to a temporary file beside it and renamed over the target by commit(); until then the target is
// untouched, and the temporary file is removed by abort(), the destructor, or a SIGINT/SIGTERM (see
// install_interrupt_cleanup).
class OutputStream {
  public:
    OutputStream() = default;
    ~OutputStream(); // abort() unless committed
    OutputStream(const OutputStream&) = delete;
    OutputStream& operator=(const OutputStream&) = delete;

    std::string open(const std::string& path); // "" or a one-line reason (nothing created then)
    std::string write(std::string_view data);
    // Regular target: fsync, the replaced file's mode and owner, rename (replace = false: link(2), refused
    // with "… already exists" if the name is taken). Special or descriptor: close.
    std::string commit(bool replace = true);
    void abort();
    const std::string& target() const { return target_.path; }

  private:
    OutputTarget target_;
    std::string temp_; // regular targets: the temporary file
    int fd_ = -1, slot_ = -1;
    bool exists_ = false;
    unsigned mode_ = 0, uid_ = 0, gid_ = 0;
};

// Installs handlers for SIGINT and SIGTERM that remove every temporary file an OutputStream has open (and
// a probe file check_writable may have), then end the process with status 128 + signal (130, 143), as a shell
// reports a job it interrupted. The targets are untouched: they are replaced only by commit(). Call once,
// early in main.
void install_interrupt_cleanup();

} // namespace fv
