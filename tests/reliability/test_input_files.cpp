// Inputs that could block or never end (fv/input_file.hpp): refused by file type, or read with a timeout.
#include "scratch.hpp"

#include "fv/input_file.hpp"
#include "fv/measurements.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using fv::test::Scratch;

TEST_CASE("input file: a FIFO nobody writes to times out instead of hanging", "[reliability]") {
    Scratch s;
    REQUIRE(::mkfifo((s / "fifo").c_str(), 0600) == 0);
    fv::InputLimits lim;
    lim.timeout_ms = 300;
    std::string text;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_THAT(fv::read_input_file(s / "fifo", text, lim), Catch::Contains("no data within"));
    const double s_waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(s_waited >= 0.25);
    CHECK(s_waited < 5);
}

TEST_CASE("input file: a pipe is read to its end", "[reliability]") {
    int p[2];
    REQUIRE(::pipe(p) == 0);
    const std::string data = "zeta,r_x\n0.5,0.4\n";
    REQUIRE(::write(p[1], data.data(), data.size()) == static_cast<ssize_t>(data.size()));
    ::close(p[1]);
    std::string text;
    CHECK(fv::read_input_file("/dev/fd/" + std::to_string(p[0]), text).empty());
    ::close(p[0]);
    CHECK(text == data);
}

TEST_CASE("input file: a directory, a socket, a missing file and an empty path are named", "[reliability]") {
    Scratch s;
    const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    (s / "sock").copy(addr.sun_path, (s / "sock").size());
    REQUIRE(::bind(sock, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0);
    std::string text;
    CHECK(fv::read_input_file(s.dir(), text) == "is a directory, not a file");
    CHECK(fv::read_input_file(s / "sock", text) == "is a socket, not a file");
    CHECK(fv::read_input_file(s / "none", text) == "does not exist");
    CHECK_THAT(fv::read_input_file("", text), Catch::Contains("empty path"));
    ::close(sock);
    // The measurements reader puts the file name first.
    CHECK_THROWS_WITH(fv::read_measurements(s.dir()), s.dir() + ": is a directory, not a file");
}

TEST_CASE("input file: a terminal is refused", "[reliability]") {
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        WARN("no pseudo-terminal available; case skipped");
        return;
    }
    std::string text;
    CHECK_THAT(fv::read_input_file(::ptsname(master), text), Catch::Contains("is a terminal"));
    ::close(master);
}

TEST_CASE("input file: an endless device stops one byte past the limit", "[reliability]") {
    fv::InputLimits lim;
    lim.max_bytes = 1000;
    std::string text;
    CHECK(fv::read_input_file("/dev/zero", text, lim).empty());
    CHECK(text.size() == 1001);
    // The measurements reader turns that into "too large", not an endless read.
    CHECK_THROWS_AS(fv::read_measurements("/dev/zero"), fv::DataError);
}
