// The output-path policy (fv/atomic_file.hpp) case by case: what each kind of path leads to, and that
// nothing but the named target changes.
#include "scratch.hpp"

#include "fv/atomic_file.hpp"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

using fv::test::Scratch;
using fv::test::slurp;

TEST_CASE("output path: a new file and a replaced file, whole, with no temporary left", "[reliability]") {
    Scratch s;
    REQUIRE(fv::write_file_atomic(s / "a.csv", "one\n").empty());
    REQUIRE(fv::write_file_atomic(s / "a.csv", "two\n").empty());
    CHECK(slurp(s / "a.csv") == "two\n");
    CHECK(s.entries() == std::vector<std::string>{"a.csv"});
}

TEST_CASE("output path: a replaced file keeps its permission bits, a new one follows the umask",
          "[reliability]") {
    Scratch s;
    s.write("private.csv", "old\n");
    ::chmod((s / "private.csv").c_str(), 0600);
    REQUIRE(fv::write_file_atomic(s / "private.csv", "new\n").empty());
    struct stat st {};
    ::stat((s / "private.csv").c_str(), &st);
    CHECK((st.st_mode & 07777) == 0600);
    // umask is process-wide and read once by the library: the new file gets 0666 & ~umask.
    const mode_t mask = ::umask(022);
    ::umask(mask);
    REQUIRE(fv::write_file_atomic(s / "new.csv", "x").empty());
    ::stat((s / "new.csv").c_str(), &st);
    CHECK((st.st_mode & 07777) == (0666 & ~mask));
}

TEST_CASE("output path: a symbolic link is followed, its target replaced, the link kept", "[reliability]") {
    Scratch s;
    s.write("target.csv", "old\n");
    s.mkdir("sub");
    s.symlink("target.csv", "link.csv");
    s.symlink("../target.csv", "sub/relative.csv"); // relative to the link's own directory
    s.symlink("link.csv", "chain.csv");             // a link to a link
    for (const char* name : {"link.csv", "sub/relative.csv", "chain.csv"}) {
        CAPTURE(name);
        REQUIRE(fv::write_file_atomic(s / name, std::string("via ") + name).empty());
        CHECK(slurp(s / "target.csv") == std::string("via ") + name);
        CHECK(s.is_symlink(name));
    }
    CHECK(s.is_symlink("link.csv"));
    CHECK(s.entries() == std::vector<std::string>{"chain.csv", "link.csv", "sub", "target.csv"});
}

TEST_CASE("output path: a dangling link creates its target, a link loop is refused", "[reliability]") {
    Scratch s;
    s.symlink("made.csv", "dangling.csv");
    REQUIRE(fv::write_file_atomic(s / "dangling.csv", "made\n").empty());
    CHECK(s.is_symlink("dangling.csv"));
    CHECK(slurp(s / "made.csv") == "made\n");
    s.symlink("loop-b", "loop-a");
    s.symlink("loop-a", "loop-b");
    CHECK_THAT(fv::write_file_atomic(s / "loop-a", "x"), Catch::Contains("symbolic links"));
    s.symlink("missing-dir/x.csv", "into-nowhere.csv");
    CHECK_THAT(fv::write_file_atomic(s / "into-nowhere.csv", "x"), Catch::Contains("does not exist"));
    CHECK(s.entries() ==
          std::vector<std::string>{"dangling.csv", "into-nowhere.csv", "loop-a", "loop-b", "made.csv"});
}

TEST_CASE("output path: refused targets name the reason and change nothing", "[reliability]") {
    Scratch s;
    s.mkdir("dir");
    const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const std::string sock_path = s / "sock";
    REQUIRE(sock_path.size() < sizeof addr.sun_path);
    sock_path.copy(addr.sun_path, sock_path.size());
    REQUIRE(::bind(sock, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0);
    const std::vector<std::string> before = s.entries();
    struct Case {
        std::string path, reason;
    };
    for (const Case& c : {Case{"", "empty path"}, Case{s / "dir", "is a directory"},
                          Case{s / "dir/", "names a directory"}, Case{s / "none/x.csv", "does not exist"},
                          Case{sock_path, "socket"}, Case{"/proc/x.csv", "cannot create files"}}) {
        CAPTURE(c.path);
        CHECK_THAT(fv::check_writable(c.path), Catch::Contains(c.reason));
        CHECK_THAT(fv::write_file_atomic(c.path, "x"), Catch::Contains(c.reason));
    }
    ::close(sock);
    CHECK(s.entries() == before);
    // A block device is never overwritten (as root this would destroy a disk).
    if (::access("/dev/loop0", F_OK) == 0) {
        struct stat st {};
        ::stat("/dev/loop0", &st);
        if (S_ISBLK(st.st_mode))
            CHECK_THAT(fv::check_writable("/dev/loop0"), Catch::Contains("block device"));
    }
}

TEST_CASE("output path: a character device is written directly, never replaced", "[reliability]") {
    struct stat before {
    }, after{};
    REQUIRE(::stat("/dev/null", &before) == 0);
    CHECK(fv::write_file_atomic("/dev/null", "gone\n").empty());
    REQUIRE(::lstat("/dev/null", &after) == 0);
    CHECK(S_ISCHR(after.st_mode));
    CHECK(after.st_rdev == before.st_rdev);
}

TEST_CASE("output path: a FIFO with a reader gets the data, without one it is an error, not a hang",
          "[reliability]") {
    Scratch s;
    REQUIRE(::mkfifo((s / "fifo").c_str(), 0600) == 0);
    // No reader: an error at once.
    CHECK_THAT(fv::write_file_atomic(s / "fifo", "x"), Catch::Contains("no reader"));
    // A reader (a child process) gets every byte.
    int pipefd[2];
    REQUIRE(::pipe(pipefd) == 0);
    const pid_t child = ::fork();
    if (child == 0) {
        const int fd = ::open((s / "fifo").c_str(), O_RDONLY);
        char buf[256];
        ssize_t n = 0;
        while ((n = ::read(fd, buf, sizeof buf)) > 0)
            if (::write(pipefd[1], buf, static_cast<std::size_t>(n)) != n) ::_exit(1);
        ::_exit(0);
    }
    ::close(pipefd[1]);
    // Wait until the child has the FIFO open (opening for writing without a reader fails, so retry).
    std::string err;
    for (int k = 0; k < 500; ++k) {
        err = fv::write_file_atomic(s / "fifo", "through the fifo\n");
        if (err.empty()) break;
        ::usleep(10000);
    }
    CHECK(err.empty());
    std::string got;
    char buf[256];
    ssize_t n = 0;
    while ((n = ::read(pipefd[0], buf, sizeof buf)) > 0) got.append(buf, static_cast<std::size_t>(n));
    ::close(pipefd[0]);
    ::waitpid(child, nullptr, 0);
    CHECK(got == "through the fifo\n");
    struct stat st {};
    ::lstat((s / "fifo").c_str(), &st);
    CHECK(S_ISFIFO(st.st_mode));
}

TEST_CASE("output path: /dev/stdout and /dev/fd/N write the open descriptor, whatever it is",
          "[reliability]") {
    Scratch s;
    s.write("log.txt", "kept\n");
    // A descriptor opened for appending (like the shell's >>): the data go after what is there, the file is
    // neither truncated nor replaced.
    const int fd = ::open((s / "log.txt").c_str(), O_WRONLY | O_APPEND);
    REQUIRE(fd >= 0);
    struct stat before {
    }, after{};
    ::stat((s / "log.txt").c_str(), &before);
    REQUIRE(fv::write_file_atomic("/dev/fd/" + std::to_string(fd), "appended\n").empty());
    REQUIRE(fv::write_file_atomic("/proc/self/fd/" + std::to_string(fd), "again\n").empty());
    ::close(fd);
    ::stat((s / "log.txt").c_str(), &after);
    CHECK(slurp(s / "log.txt") == "kept\nappended\nagain\n");
    CHECK(after.st_ino == before.st_ino);
    // /dev/stdout itself stays the system's symbolic link.
    struct stat link {};
    ::lstat("/dev/stdout", &link);
    CHECK(S_ISLNK(link.st_mode));
    // A descriptor that is not open, or open read-only, is refused.
    CHECK_THAT(fv::check_writable("/dev/fd/987"), Catch::Contains("not open"));
    const int ro = ::open((s / "log.txt").c_str(), O_RDONLY);
    CHECK_THAT(fv::check_writable("/dev/fd/" + std::to_string(ro)), Catch::Contains("read-only"));
    ::close(ro);
}

TEST_CASE("output directory: missing, not a directory, not writable or empty is refused", "[reliability]") {
    Scratch s;
    s.write("file", "x");
    s.mkdir("out");
    s.symlink("out", "out-link");
    CHECK(fv::check_output_dir(s / "out").empty());
    CHECK(fv::check_output_dir(s / "out-link").empty());
    CHECK_THAT(fv::check_output_dir(""), Catch::Contains("empty path"));
    CHECK_THAT(fv::check_output_dir(s / "none"), Catch::Contains("does not exist"));
    CHECK_THAT(fv::check_output_dir(s / "file"), Catch::Contains("not a directory"));
    CHECK_THAT(fv::check_output_dir("/proc"), Catch::Contains("cannot create files"));
}
