// The release-grade promises of docs/reliability.md, each tried on the real executable as a careless user or
// a hostile file would: sessions and links that used to crash or mislead, writes that failed and exited 0,
// names that were clobbered, work without bound, signals during a write.
#include "exe_under_test.hpp"
#include "scratch.hpp"

#include "../tools/child_peak_rss.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using fv::test::Scratch;
using fv::test::slurp;

using fv::test::exe;

namespace {

struct Run {
    int code;
    std::string out, err;
};

// `frictionviz ARGS` through sh in the scratch directory, stdout and stderr captured.
Run run(const Scratch& s, const std::string& args) {
    const std::string o = s / ".out", e = s / ".err";
    const int status = std::system(
        ("cd '" + s.dir() + "' && " + exe() + " " + args + " >'" + o + "' 2>'" + e + "' </dev/null").c_str());
    Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1000 - WTERMSIG(status), slurp(o), slurp(e)};
    ::unlink(o.c_str());
    ::unlink(e.c_str());
    return r;
}

// The names in the scratch directory, without the captured output.
std::vector<std::string> files(const Scratch& s) {
    return s.entries();
}

std::string nested(const std::string& open, const std::string& close, int depth) {
    std::string t;
    for (int k = 0; k < depth; ++k) t += open;
    for (int k = 0; k < depth; ++k) t += close;
    return t;
}

const std::string kHeadless = "gui --headless --frames 3 ";

} // namespace

TEST_CASE("1. A session nested 66 000 deep is refused in one short line, by gui --session and File > Open",
          "[reliability][session]") {
    Scratch s;
    s.write("version.json", "{\"version\": " + nested("[", "]", 66000) + "}");
    s.write("pan.json", "{\"version\": 1, \"view\": {\"pan\": " + nested("[", "]", 66000) + "}}");
    s.write("deep_unknown.json", "{\"version\": 1, \"x\": " + nested("{\"a\":", "}", 66000) + "}");
    for (const std::string f : {"version.json", "pan.json", "deep_unknown.json"}) {
        const Run r = run(s, kHeadless + "--session " + f);
        CAPTURE(f, r.err.substr(0, 300));
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains("nested deeper than 16 levels"));
        CHECK(r.err.size() < 300);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        // The app's File > Open session (the script's open-session): the state is kept, the run goes on.
        s.write("open.txt", "1 open-session " + f + "\n");
        const Run app = run(s, kHeadless + "--script open.txt");
        CHECK(app.code == 0);
    }
}

TEST_CASE("2. A data file with a sigma the fit cannot weigh is refused at load, the app's Fit survives it",
          "[reliability][fit]") {
    Scratch s;
    for (const char* sigma : {"1e-200", "1e-160", "5e-324", "0", "1e-7"}) {
        s.write("tiny.csv",
                std::string("zeta,r_x,sigma\n0.1,0.8,0.01\n0.3,0.5,") + sigma + "\n0.6,0.3,0.01\n");
        for (const std::string cmd :
             {"fit --theta 90 --data tiny.csv", "render --figure fig19 --out . --data tiny.csv"}) {
            const Run r = run(s, cmd);
            CAPTURE(sigma, cmd, r.err);
            CHECK(r.code == 2);
            CHECK_THAT(r.err, Catch::Contains("tiny.csv:3:9: sigma = ") &&
                                  Catch::Contains("is out of range; allowed: sigma in [1e-06, 10]"));
            CHECK(r.err.find("nan") == std::string::npos);
        }
        s.write("fit.txt", "1 load tiny.csv\n2 fit\n");
        const Run app = run(s, kHeadless + "--script fit.txt");
        CHECK(app.code == 0); // the load is refused in the status line; the fit has no data to run on
    }
    // The smallest sigma allowed, beside large ones: a finite fit.
    s.write("edge.csv",
            "zeta,r_x,sigma,theta_deg\n0.05,0.93,1e-6,90\n0.2,0.62,10,90\n0.4,0.4,10,90\n0.8,0.2,10,90\n");
    const Run r = run(s, "fit --data edge.csv --format json");
    CAPTURE(r.err);
    CHECK(r.code == 0);
    CHECK(r.out.find("nan") == std::string::npos);
    s.write("fit.txt", "1 load edge.csv\n2 fit\n");
    CHECK(run(s, kHeadless + "--script fit.txt").code == 0);
}

TEST_CASE("3. Screenshots and trace exports take the next free name and never replace a file",
          "[reliability][app]") {
    Scratch s;
    s.write("frictionviz-screenshot-1.png", "mine");
    s.write("frictionviz-trace-1.csv", "mine too");
    s.write("keys.txt", "1 screenshot\n1 export-trace\n2 screenshot\n");
    const Run r = run(s, kHeadless + "--script keys.txt");
    CAPTURE(r.err);
    CHECK(r.code == 0);
    CHECK(slurp(s / "frictionviz-screenshot-1.png") == "mine");
    CHECK(slurp(s / "frictionviz-trace-1.csv") == "mine too");
    CHECK(slurp(s / "frictionviz-screenshot-2.png").substr(1, 3) == "PNG");
    CHECK(slurp(s / "frictionviz-screenshot-3.png").substr(1, 3) == "PNG");
    CHECK(slurp(s / "frictionviz-trace-2.csv").rfind("tau,Px,Py", 0) == 0);
    // A second run goes on from there, and a dangling link is a taken name, not a way out of the directory.
    s.symlink("/tmp/fv-nowhere-" + std::to_string(::getpid()), "frictionviz-screenshot-4.png");
    CHECK(run(s, kHeadless + "--script keys.txt").code == 0);
    CHECK(::access(("/tmp/fv-nowhere-" + std::to_string(::getpid())).c_str(), F_OK) != 0);
    CHECK(slurp(s / "frictionviz-screenshot-5.png").substr(1, 3) == "PNG");
    CHECK(slurp(s / "frictionviz-screenshot-6.png").substr(1, 3) == "PNG");
}

TEST_CASE("5. Failed writes are exit 1 with the reason: --screenshot, a script's save-session and animate",
          "[reliability][app]") {
    Scratch s;
    // /dev/full: every write fails with ENOSPC, as on a full disk.
    Run r = run(s, kHeadless + "--screenshot /dev/full");
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("No space left on device"));
    s.write("save.txt", "1 save-session /dev/full\n");
    r = run(s, kHeadless + "--script save.txt");
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("No space left on device"));
    // animate: a missing or read-only directory is refused when the script is loaded (exit 2, nothing run),
    // a write that fails later is exit 1.
    for (const char* path : {"missing/a.gif", "/proc/a.gif"}) {
        s.write("anim.txt", std::string("1 animate ") + path + "\n");
        r = run(s, kHeadless + "--script anim.txt");
        CAPTURE(path, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains("animate") && Catch::Contains(path));
    }
    s.write("full.gif", "");
    ::unlink((s / "full.gif").c_str());
    ::symlink("/dev/full", (s / "full.gif").c_str());
    s.write("anim.txt", "1 animate full.gif\n");
    r = run(s, kHeadless + "--script anim.txt");
    CAPTURE(r.err);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("animation not written") && Catch::Contains("No space left on device"));
}

TEST_CASE("6. sweep: the grid's size is checked as a whole, rows stream, so memory stays flat",
          "[reliability][sweep]") {
    Scratch s;
    Run r = run(
        s, "sweep --zeta 0:1:100000 --theta 0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,"
           "24,25,26,27,28,29,30,31,32,33,34,35,36,37,38,39,40,41,42,43,44,45,46,47,48,49,50,51,52,53,54,55,"
           "56,57,58,59,60,61,62,63,64,65,66,67,68,69,70,71,72,73,74,75,76,77,78,79,80,81,82,83,84,85,86,87,"
           "88,89,90,91,92,93,94,95,96,97,98,99,100,101,102,103,104,105,106,107,108,109,110,111,112,113,114,"
           "115,116,117,118,119,120,121,122,123,124,125,126,127,128,129,130,131,132,133,134,135,136,137,138,"
           "139,140,141,142,143,144,145,146,147,148,149,150,151,152,153,154,155,156,157,158,159,160,161,162,"
           "163,164,165,166,167,168,169,170,171,172,173,174,175,176,177,178,179,180 --rdisp 1,2 --i 1");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("zeta 100000 x theta 181 x rdisp 2 x i 1 = 36200000 rows; allowed: at "
                                      "most 10000000 rows in one sweep"));
    CHECK(r.out.empty());
    // Memory: the rigid model's rows are cheap, so 100x the rows shows what grows with them.
    // (AddressSanitizer would hold freed memory in its 256 MiB quarantine and count it; other builds ignore
    // the option.)
    const char* asan = std::getenv("ASAN_OPTIONS");
    ::setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + ":quarantine_size_mb=0").c_str(), 1);
    auto peak = [&](int count) {
        const fv::testing::ChildRun c =
            fv::testing::run_child({exe(), "sweep", "--model", "rigid", "--zeta",
                                    "0:2:" + std::to_string(count), "--theta", "0,45,90"});
        REQUIRE(c.exit_code == 0);
        return c.peak_rss_kb;
    };
    const long small = peak(1000), big = peak(100000);
    INFO("peak RSS " << small << " KiB for 3000 rows, " << big << " KiB for 300000 rows");
    CHECK(big - small < 8 * 1024); // all rows held (and their CSV) took about 60 MiB more
}

namespace {

// Starts `frictionviz ARGS` in the scratch directory with stdout into `stdout_path`, sends `sig` once
// `ready()` holds (polled every 20 ms for at most 120 s: a sanitizer build on a loaded machine is slow), and
// returns the exit status (-1 if it did not exit).
int interrupted(const Scratch& s, const std::vector<std::string>& args, const std::string& stdout_path,
                int sig, const std::function<bool()>& ready) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::chdir(s.dir().c_str()) != 0) ::_exit(126);
        const int out = ::open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        std::vector<char*> argv{const_cast<char*>(exe())};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(exe(), argv.data());
        ::_exit(127);
    }
    for (int k = 0; k < 6000 && !ready(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::vector<std::string> kSlowSweep = {
    "sweep", "--zeta", "0.01:3:100000", "--theta", "30,60,90", "--rdisp", "2", "--i", "1", "--threads", "1"};

} // namespace

TEST_CASE("6. sweep interrupted on standard output leaves whole rows in grid order, exit 130",
          "[reliability][sweep][signals]") {
    Scratch s;
    // Interrupted once the first block of rows is out (the header is 71 bytes, a row about 80).
    const int code = interrupted(s, kSlowSweep, s / "rows.csv", SIGINT, [&] {
        std::error_code ec;
        const auto size = std::filesystem::file_size(s / "rows.csv", ec);
        return !ec && size > 2000;
    });
    CHECK(code == 130);
    std::ifstream in(s / "rows.csv");
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(
        line ==
        "model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_multiplier,states");
    int rows = 0;
    std::pair<double, double> last{-1, -1}; // (theta, zeta): the grid's order, zeta fastest
    const std::string all = slurp(s / "rows.csv");
    CHECK(all.back() == '\n'); // no half row at the end
    while (std::getline(in, line)) {
        CAPTURE(rows, line);
        std::vector<std::string> f;
        std::istringstream fields(line);
        for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
        REQUIRE(f.size() == 13);
        CHECK(f[9] == "ok");
        const std::pair<double, double> at{std::stod(f[2]), std::stod(f[4])};
        CHECK(at > last);
        last = at;
        ++rows;
    }
    INFO(rows << " rows before the interrupt");
    CHECK(rows >= 256); // at least the first block was out
}

TEST_CASE("8. SIGINT or SIGTERM during a write: the temporary file goes, the target stays, exit 130 / 143",
          "[reliability][signals]") {
    Scratch s;
    for (const int sig : {SIGINT, SIGTERM}) {
        s.write("target.csv", "the old result\n");
        std::vector<std::string> args = kSlowSweep;
        args.insert(args.end(), {"--out", "target.csv"});
        // Interrupted while the temporary file is there (it is from the start until the last row).
        const int code = interrupted(s, args, "/dev/null", sig, [&] {
            for (const std::string& name : s.entries())
                if (name.rfind(".fv-tmp-", 0) == 0) return true;
            return false;
        });
        CHECK(code == 128 + sig);
        CHECK(slurp(s / "target.csv") == "the old result\n");
        CHECK(files(s) == std::vector<std::string>{"target.csv"}); // no .fv-tmp-* left
    }
}

TEST_CASE("7. render checks every file of every figure before computing, and stops at the first failed write",
          "[reliability][render]") {
    Scratch s;
    s.mkdir("out");
    s.mkdir("out/fig8.csv"); // a directory where a table goes
    Run r = run(s, "render --figure fig5,fig8 --size 320x240 --out out");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("fig8.csv") && Catch::Contains("is a directory"));
    CHECK(std::vector<std::string>{"fig8.csv"} == [&] {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(s / "out"))
            names.push_back(e.path().filename());
        return names;
    }());
    // The second figure's image cannot be written (a full disk, here /dev/full behind its name): the first
    // figure is written, the third is not even computed.
    std::filesystem::remove(s / "out/fig8.csv");
    ::symlink("/dev/full", (s / "out/fig8.png").c_str());
    r = run(s, "render --figure fig5,fig8,fig9 --size 320x240 --out out");
    CAPTURE(r.out, r.err);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("No space left on device") && Catch::Contains("stopped"));
    CHECK(std::filesystem::exists(s / "out/fig5.png"));
    CHECK_FALSE(std::filesystem::exists(s / "out/fig9.png"));
    CHECK_FALSE(std::filesystem::exists(s / "out/fig9.json"));
    CHECK_THAT(r.out, Catch::Contains("wrote out/fig5.") && !Catch::Contains("fig9"));
}

TEST_CASE("9. Scripts read numbers as the command line does, and refuse bad ones before the run",
          "[reliability][script]") {
    Scratch s;
    for (const auto& [line, says] : std::vector<std::pair<std::string, std::string>>{
             {"1 zeta 1e-400",
              "zeta = 1e-400 is out of range (beyond double precision); allowed: zeta in [0, 100]"},
             {"1 zeta 0x10", "zeta = '0x10' is not a decimal number"},
             {"1 theta 200", "theta = 200 is out of range; allowed: theta in [0, 180]"},
             {"99999999999999999999 zeta 1", "frame = 99999999999999999999 is out of range"},
             {"1 speed 0.01", "speed = 0.01 is out of range; allowed: speed in [0.05, 10]"},
             {"1 preset fig5", "unknown preset 'fig5'; allowed: sliding, along, across"},
         }) {
        s.write("bad.txt", line + "\n");
        const Run r = run(s, kHeadless + "--script bad.txt");
        CAPTURE(line, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains("bad.txt:1: " + says));
    }
}

TEST_CASE("10. Messages show control bytes and NUL escaped, never raw", "[reliability][messages]") {
    Scratch s;
    s.write("esc.json", "{\"version\": 1, \"model\": \"\\u001b[31mRED\\u0007\"}");
    s.write("nul.json", std::string("{\"version\": 1, \"model\": \"rigid\\u0000x\"}"));
    for (const auto& [args, says] : std::vector<std::pair<std::string, std::string>>{
             {"--link '?model=%1B[31mRED%07'", "model = '\\x1B[31mRED\\x07'; allowed: dahl, rigid"},
             {"--link '?model=rigid%00x'", "model = 'rigid\\x00x'; allowed: dahl, rigid"},
             {"--session esc.json", "model = \"\\u001b[31mRED\\u0007\"; allowed: dahl, rigid"},
             {"--session nul.json", "model = \"rigid\\u0000x\"; allowed: dahl, rigid"},
             {"--theta \"$(printf '1\\033[2J')\"", "'1\\x1B[2J' is not a decimal number"},
         }) {
        const Run r = run(s, kHeadless + args);
        CAPTURE(args, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains(says));
        for (const char c : r.err) CHECK((c == '\n' || static_cast<unsigned char>(c) >= 0x20));
    }
}

TEST_CASE("11. Sessions read numbers as the command line does, nothing after a NUL, no NaN in the app",
          "[reliability][session]") {
    Scratch s;
    for (const auto& [json, says] : std::vector<std::pair<std::string, std::string>>{
             {"{\"version\": 1, \"zeta\": 1e-400}",
              "s.json:1:24: zeta = 1e-400 is out of range (beyond double"},
             {"{\"version\": 1, \"zeta\": -1e-400}",
              "s.json:1:24: zeta = -1e-400 is out of range (beyond double"},
             {std::string("{\"version\": 1}\0garbage", 23),
              "s.json:1:15: a NUL byte; a session file is JSON text"},
             {"{\"version\": 1, \"rdisp\": 5e-324}", "rdisp = 5e-324 with amplitude 0.7 um gives z_ss = A / "
                                                     "rdisp = inf um; allowed: z_ss in (0, 1e+06] um"},
             {"{\"version\": 1, \"speed\": 0.01}",
              "speed = 0.01 is out of range; allowed: speed in [0.05, 10]"},
         }) {
        s.write("s.json", json);
        const Run r = run(s, kHeadless + "--session s.json");
        CAPTURE(json, r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Catch::Contains(says));
    }
    // -0 reads as 0 and saves back as 0, not -0.0.
    s.write("s.json", "{\"version\": 1, \"zeta\": -0, \"theta\": -0.0}");
    s.write("save.txt", "1 save-session out.json\n");
    CHECK(run(s, kHeadless + "--session s.json --script save.txt").code == 0);
    CHECK(slurp(s / "out.json").find("-0") == std::string::npos);
    // A default the user never typed is not blamed on a flag they never gave.
    const Run r = run(s, kHeadless + "--rdisp 5e-324");
    CHECK(r.code == 2);
    CHECK(r.err.find("--amplitude 0.7") == std::string::npos);
    CHECK_THAT(r.err, Catch::Contains("rdisp = 5e-324 with amplitude 0.7 um") && Catch::Contains("default"));
}

TEST_CASE("12. A link's fragment is ignored as a browser ignores it", "[reliability][link]") {
    Scratch s;
    Run r = run(s, kHeadless + "--link '#?zeta=0.5'");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("no parameters before the '#' (a fragment, which a browser ignores)"));
    r = run(s, kHeadless + "--link 'https://example.org/app/?zeta=0.5#theta=3'");
    CHECK(r.code == 0);
}

TEST_CASE("13. A pinned curve's label is capped: a 1 MB label is refused in one line",
          "[reliability][session]") {
    Scratch s;
    s.write("s.json", "{\"version\": 1, \"pins\": [{\"label\": \"" + std::string(1000000, 'x') +
                          "\", \"zeta\": [0.1], \"r_x\": [0.5]}]}");
    Run r = run(s, kHeadless + "--session s.json");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("label: 1000000 bytes; allowed: printable text of at most 80 bytes"));
    CHECK(r.err.size() < 200);
    s.write("d.csv", "zeta,r_x,label\n0.1,0.5," + std::string(81, 'y') + "\n");
    r = run(s, "fit --theta 90 --data d.csv");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("d.csv:2:9: label: 81 bytes"));
}
