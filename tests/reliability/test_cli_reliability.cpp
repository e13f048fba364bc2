// The real executable, run as a careless script would: empty and odd output paths, inputs that could block,
// odd spellings of numbers. Each case: the exit status, the one-line message, and that nothing else changed.
#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using fv::test::Scratch;
using fv::test::slurp;

namespace {

struct Run {
    int code;
    std::string out, err;
    double seconds;
};

// Runs `frictionviz ARGS` through sh in `cwd`; stdout and stderr are captured in files there unless `args`
// redirects stdout itself; stdin is `stdin_from`; `env`: assignments put before the command.
Run run(const Scratch& cwd, const std::string& args, bool capture_stdout = true,
        const std::string& stdin_from = "/dev/null", const std::string& env = "") {
    const std::string o = cwd / ".stdout", e = cwd / ".stderr";
    // FV_TEST_FORCE_STATUS: the executable with the test hooks (app/cli/test_hook.hpp).
    const bool forced = env.find("FV_TEST_FORCE_STATUS") != std::string::npos;
    const std::string cmd = "cd '" + cwd.dir() + "' && " + (env.empty() ? "" : "env " + env + " ") +
                            std::string(forced ? FV_EXE_FORCED : FV_EXE) + " " + args +
                            (capture_stdout ? " >" + o : std::string()) + " 2>" + e + " <" + stdin_from;
    const auto t0 = std::chrono::steady_clock::now();
    const int status = std::system(cmd.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(o), slurp(e), s};
    ::unlink(o.c_str());
    ::unlink(e.c_str());
    return r;
}

const std::string kRatio = "ratio --zeta 0.3 --theta 45 --rdisp 2 --i 1 --format csv";
const std::string kData = FV_TEST_DATA_DIR "/synthetic_theta90_rdisp3_i0.csv";

} // namespace

TEST_CASE("CLI reliability: an empty --out is a usage error for every command, nothing is written",
          "[reliability]") {
    Scratch s;
    for (const std::string& cmd :
         {kRatio, std::string("sweep --zeta 0:1:3 --theta 0 --rdisp 2 --i 1"),
          std::string("trace --zeta 0.3 --theta 45 --rdisp 2 --i 1"), "fit --data " + kData,
          std::string("render --figure fig5 --size 320x240")}) {
        const Run r = run(s, cmd + " --out ''");
        CAPTURE(cmd, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::StartsWith("frictionviz: --out: empty path"));
        CHECK(r.out.empty());
        CHECK(s.entries().empty()); // not the working directory either (render used to write into "/")
    }
    // "-" is standard output where the command documents it.
    const Run r = run(s, kRatio + " --out -");
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Catch::StartsWith("model,i,theta_deg"));
}

TEST_CASE("CLI reliability: --out through a symbolic link replaces its target and keeps the link",
          "[reliability]") {
    Scratch s;
    s.write("result.csv", "old\n");
    s.symlink("result.csv", "latest.csv");
    const Run r = run(s, kRatio + " --out latest.csv");
    CHECK(r.code == 0);
    CHECK(s.is_symlink("latest.csv"));
    CHECK_THAT(slurp(s / "result.csv"), Catch::StartsWith("model,i,theta_deg"));
    CHECK(s.entries() == std::vector<std::string>{"latest.csv", "result.csv"});
}

TEST_CASE("CLI reliability: --out /dev/stdout writes into the redirect and leaves /dev/stdout alone",
          "[reliability]") {
    Scratch s;
    s.write("log.txt", "first line\n");
    const Run r = run(s, kRatio + " --out /dev/stdout >> log.txt", false);
    CHECK(r.code == 0);
    const std::string log = slurp(s / "log.txt");
    CHECK_THAT(log, Catch::StartsWith("first line\nmodel,i,theta_deg"));
    struct stat st {};
    REQUIRE(::lstat("/dev/stdout", &st) == 0);
    CHECK(S_ISLNK(st.st_mode));
}

TEST_CASE("CLI reliability: render's directory must exist, be a directory and take files", "[reliability]") {
    Scratch s;
    s.write("file", "x");
    s.mkdir("out");
    s.symlink("out", "out-link");
    struct Case {
        std::string dir, reason;
    };
    for (const Case& c : {Case{"none", "does not exist"}, Case{"file", "is not a directory"},
                          Case{"/proc", "cannot create files"}}) {
        const Run r = run(s, "render --figure fig5 --size 320x240 --out " + c.dir);
        CAPTURE(c.dir, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains("--out") && Catch::Contains(c.reason));
    }
    const Run r = run(s, "render --figure fig5 --size 320x240 --out out-link");
    CHECK(r.code == 0);
    CHECK(s.is_symlink("out-link"));
    CHECK(::access((s / "out/fig5.png").c_str(), F_OK) == 0);
}

TEST_CASE("CLI reliability: fit --data names a directory, and gives up on a FIFO with no writer",
          "[reliability]") {
    Scratch s;
    Run r = run(s, "fit --data " + s.dir());
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("is a directory"));
    REQUIRE(::mkfifo((s / "fifo").c_str(), 0600) == 0);
    r = run(s, "fit --data fifo");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("fifo: no data within"));
    CHECK(r.seconds < 20);
    // Data through a pipe (/dev/stdin) are fine.
    r = run(s, "fit --data /dev/stdin", true, kData);
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("data          /dev/stdin (16 points"));
}

TEST_CASE("CLI reliability: numbers are decimal, what is refused says why", "[reliability]") {
    Scratch s;
    struct Case {
        std::string args, message;
    };
    for (const Case& c : {
             Case{"--theta 0x10", "'0x10' is not a decimal number; allowed: a number in [0, 180]"},
             Case{"--theta 0x1p3", "'0x1p3' is not a decimal number"},
             Case{"--rdisp 1e-400", "--rdisp: 1e-400 is out of range (beyond double precision)"},
             Case{"--zeta 1e400", "--zeta: 1e400 is out of range"},
         }) {
        std::string args = "ratio --zeta 0.3 --theta 45 --rdisp 2 --i 1 " + c.args;
        const Run r = run(s, args);
        CAPTURE(args);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
    // A subnormal r_disp is a finite number inside (0, 1e4]: taken, not called "not a finite number".
    const Run tiny = run(s, "ratio --zeta 0.3 --theta 45 --rdisp 5e-324 --i 1 --format csv");
    CHECK(tiny.code != 2);
    CHECK_THAT(tiny.out, Catch::Contains(",4.94065645841e-324,"));
    // -0 is 0.
    const Run zero = run(s, "ratio --zeta 0.3 --theta -0 --rdisp 2 --i 1");
    CHECK_THAT(zero.out, Catch::Contains("theta         0 deg"));
    // Empty list items are refused, not skipped.
    for (const char* list : {"0,,30", "0,30,", ",0"}) {
        const Run r = run(s, std::string("sweep --zeta 0:1:2 --rdisp 2 --i 1 --theta ") + list);
        CAPTURE(list);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains("has an empty item"));
    }
}

TEST_CASE("CLI reliability: messages name what is allowed", "[reliability]") {
    Scratch s;
    const Run fig = run(s, "render --figure nope --out .");
    CHECK(fig.code == 2);
    for (const char* id : {"all", "scene", "map", "fig19", "fig5", "fig18"})
        CHECK_THAT(fig.err, Catch::Contains(id));
    // Without a display, the window's message names the headless way.
    const std::string cmd =
        "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) + " gui --platform window --frames 1 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    std::string err;
    char buf[512];
    while (p && std::fgets(buf, sizeof buf, p)) err += buf;
    const int status = p ? ::pclose(p) : -1;
    CHECK(WEXITSTATUS(status) == 1);
    CHECK_THAT(err, Catch::Contains("--headless"));
}

TEST_CASE("CLI reliability: render's status reaches trace CSVs and the exit status", "[reliability]") {
    Scratch s;
    const std::string cmd =
        "render --figure fig8,scene --zeta 0.3 --theta 30 --rdisp 2 --i 1 --size 320x240 --out .";
    Run r = run(s, cmd);
    CHECK(r.code == 0);
    CHECK_THAT(slurp(s / "fig8.csv"),
               Catch::StartsWith("tau,Px,Py,Tx,Ty,z,Fx,Fy,status\n") && Catch::EndsWith(",ok\n"));
    r = run(s, cmd, true, "/dev/null", "FV_TEST_FORCE_STATUS=integration_failed");
    CHECK(r.code == 3);
    CHECK_THAT(r.err, Catch::Contains("fig8: failed: integration_failed"));
    CHECK_THAT(slurp(s / "fig8.csv"), Catch::EndsWith(",integration_failed\n"));
    CHECK_THAT(slurp(s / "scene.csv"), Catch::EndsWith(",integration_failed\n"));
}

TEST_CASE("CLI reliability: progress lines are out before the run ends (a kill -9 keeps them)",
          "[reliability]") {
    // stdout is a pipe here, where the C library would buffer by blocks: the first "wrote" line must arrive
    // while the run is still busy with the next figures (at this size one frame is encoded at a time, so the
    // last figure's PNG cannot exist yet when the first line is printed), and killing it then keeps the line.
    Scratch s;
    const std::string out = s.dir();
    int p[2];
    REQUIRE(::pipe(p) == 0);
    const pid_t child = ::fork();
    if (child == 0) {
        ::dup2(p[1], 1);
        ::close(p[0]);
        ::close(p[1]);
        ::execl(FV_EXE, FV_EXE, "render", "--figure", "fig5,fig8,fig9", "--size", "3840x2160", "--out",
                out.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(p[1]);
    std::string line;
    char c = 0;
    while (::read(p[0], &c, 1) == 1 && c != '\n') line += c;
    const bool last_written = ::access((s / "fig9.png").c_str(), F_OK) == 0;
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::close(p[0]);
    CHECK_THAT(line, Catch::StartsWith("wrote " + out + "/fig5.png"));
    CHECK_FALSE(last_written); // the line came before the end
    CHECK(WIFSIGNALED(status));
}
