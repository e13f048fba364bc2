// The real executable: exit codes, one-line errors naming the flag and range, nothing written on failure.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct Run {
    int code;
    std::string out, err;
};

std::string slurp(const std::string& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::string scratch_dir() {
    static std::string dir = [] {
        char tmpl[] = "/tmp/fv-cli-XXXXXX";
        return std::string(::mkdtemp(tmpl));
    }();
    return dir;
}

Run run(const std::string& args) {
    const std::string o = scratch_dir() + "/stdout", e = scratch_dir() + "/stderr";
    const std::string cmd = std::string(FV_EXE) + " " + args + " >" + o + " 2>" + e + " </dev/null";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(o), slurp(e)};
}

long lines(const std::string& s) {
    return std::count(s.begin(), s.end(), '\n');
}

const char* kGood = "--zeta 0.3 --theta 45 --rdisp 2 --i 1";

} // namespace

TEST_CASE("CLI: bad numbers are usage errors naming the flag and the allowed range", "[cli]") {
    struct Case {
        const char* args;
        const char* flag;
    };
    for (const Case& c : {
             Case{"ratio --zeta abc --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"ratio --zeta nan --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"ratio --zeta inf --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"ratio --zeta -0.1 --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"ratio --zeta 0.3 --theta 1e999 --rdisp 2 --i 1", "--theta"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 0 --i 1", "--rdisp"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp -2 --i 1", "--rdisp"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i -1", "--i"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2", "--i"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --steps-per-period 0", "--steps-per-period"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --steps-per-period 12.5",
                  "--steps-per-period"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --model soft", "--model"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --format xml", "--format"},
             Case{"sweep --zeta 1:0.5:10 --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"sweep --zeta 0.5:0.5:10 --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"sweep --zeta 0:1:0 --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"sweep --zeta 0:1 --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"sweep --zeta 0:1:x --theta 90 --rdisp 2 --i 1", "--zeta"},
             Case{"sweep --zeta 0:1:5 --theta 0,abc --rdisp 2 --i 1", "--theta"},
             Case{"sweep --zeta 0:1:5 --theta 0 --rdisp 2,0 --i 1", "--rdisp"},
             Case{"trace --zeta 0.3 --theta 90 --rdisp nan --i 1", "--rdisp"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --bogus", "--bogus"},
             Case{"frobnicate --zeta 1", "frobnicate"},
             Case{"render --figure fig99 --out /tmp", "fig10"}, // the message lists the valid ids
             Case{"render --figure fig5 --out /tmp --size 10x10", "--size"},
             Case{"render --figure fig5 --out /tmp --size big", "--size"},
             Case{"render --figure fig5 --out /nonexistent-dir", "--out"},
             Case{"render --figure scene --out /tmp --zeta 0.3", "--theta"},
             Case{"render --figure fig5", "--out"},
         }) {
        CAPTURE(c.args);
        const Run r = run(c.args);
        CHECK(r.code == 2);
        CHECK(r.out.empty());
        CHECK(lines(r.err) == 1);
        CHECK(r.err.find(c.flag) != std::string::npos);
    }
}

TEST_CASE("CLI: help and version exit 0", "[cli]") {
    for (const char* a : {"--help", "ratio --help", "sweep --help", "trace --help"}) {
        const Run r = run(a);
        CAPTURE(a);
        CHECK(r.code == 0);
        CHECK(r.out.find("--") != std::string::npos);
    }
    const Run v = run("--version");
    CHECK(v.code == 0);
    CHECK(v.out.find("frictionviz") != std::string::npos);
}

TEST_CASE("CLI: a failed run writes nothing and clobbers nothing", "[cli]") {
    const std::string dir = scratch_dir(), keep = dir + "/keep.csv";
    std::ofstream(keep) << "precious\n";
    // Bad input with an existing target: file untouched.
    CHECK(run(std::string("sweep --zeta 1:0:3 --theta 0 --rdisp 2 --i 1 --out ") + keep).code == 2);
    CHECK(slurp(keep) == "precious\n");
    // Target in a missing directory / a directory / a device: refused up front with exit 2.
    for (const std::string& out : {dir + "/nope/x.csv", dir, std::string("/dev/null")}) {
        const Run r = run(std::string("ratio ") + kGood + " --format csv --out " + out);
        CAPTURE(out, r.err);
        CHECK(r.code == 2);
        CHECK(r.err.find("--out") != std::string::npos);
    }
    CHECK(::access((dir + "/nope").c_str(), F_OK) != 0);
}

TEST_CASE("CLI: ratio formats carry the documented columns", "[cli]") {
    const Run csv = run(std::string("ratio ") + kGood + " --format csv");
    REQUIRE(csv.code == 0);
    CHECK(csv.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate\ndahl,1,45,2,0.3,", 0) ==
          0);
    CHECK(lines(csv.out) == 2);
    const Run js = run(std::string("ratio ") + kGood + " --format json");
    REQUIRE(js.code == 0);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(j["model"] == "dahl");
    CHECK(j["status"] == "converged");
    CHECK(j["theta_deg"].get<double>() == 45);
    const Run txt = run(std::string("ratio ") + kGood);
    CHECK(txt.out.find("r_x") != std::string::npos);
    // The rigid model through the CLI: r_x(1/2, 0) = (2/pi) asin(1/2) = 1/3 (Eq. (10)).
    const Run rig = run("ratio --model rigid --zeta 0.5 --theta 0 --format json");
    REQUIRE(rig.code == 0);
    CHECK(nlohmann::json::parse(rig.out)["r_x"].get<double>() == Approx(1.0 / 3).margin(1e-12));
}

TEST_CASE("CLI: sweep writes one row per point, atomically to --out", "[cli]") {
    const std::string out = scratch_dir() + "/sweep.csv";
    const Run r =
        run("sweep --zeta 0.1:1.5:4 --theta 0,90 --rdisp 1,10 --i 0,1 --steps-per-period 256 --out " + out);
    REQUIRE(r.code == 0);
    CHECK(r.out.empty());
    const std::string csv = slurp(out);
    CHECK(csv.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate\n", 0) == 0);
    CHECK(lines(csv) == 1 + 4 * 2 * 2 * 2);
    const Run j = run("sweep --model rigid --zeta 0:2:5 --theta 0,30 --format json");
    REQUIRE(j.code == 0);
    const auto arr = nlohmann::json::parse(j.out);
    REQUIRE(arr.size() == 10);
    CHECK(arr[4]["r_x"].get<double>() == Approx(1).margin(1e-12)); // theta = 0, zeta = 2 > 1
    CHECK(arr[0]["rdisp"].is_null());                              // not a parameter of the rigid model
}

TEST_CASE("CLI: trace gives one steady period with the documented columns", "[cli]") {
    const Run r = run("trace --zeta 0.5 --theta 90 --rdisp 2 --i 0 --steps-per-period 500");
    REQUIRE(r.code == 0);
    std::istringstream in(r.out);
    std::string header, line;
    std::getline(in, header);
    CHECK(header == "tau,Px,Py,Tx,Ty,z,Fx,Fy");
    int rows = 0;
    double first_tau = 0, last_tau = 0;
    while (std::getline(in, line)) {
        const double tau = std::stod(line.substr(0, line.find(',')));
        if (rows++ == 0) first_tau = tau;
        last_tau = tau;
    }
    CHECK(rows == 500);
    CHECK(last_tau - first_tau == Approx(2 * 3.14159265358979 * 499 / 500).epsilon(1e-9));
}

TEST_CASE("CLI: render writes a PNG and its CSV, and fails cleanly without OSMesa", "[cli][render]") {
    const std::string dir = scratch_dir() + "/render";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const Run r =
        run("render --figure fig5,scene --zeta 0.4 --theta 30 --rdisp 3 --i 0 --size 400x300 --out " + dir);
    REQUIRE(r.code == 0);
    const std::string png = slurp(dir + "/fig5.png");
    REQUIRE(png.size() > 24);
    CHECK(png.substr(1, 3) == "PNG");
    // IHDR: width and height as big-endian 32-bit integers at bytes 16 and 20.
    auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
               (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
    };
    CHECK(be32(16) == 400);
    CHECK(be32(20) == 300);
    CHECK(slurp(dir + "/fig5.csv").rfind("model,i,theta_deg,rdisp,zeta,r_x", 0) == 0);
    CHECK(slurp(dir + "/scene.csv").rfind("tau,Px,Py,Tx,Ty,z,Fx,Fy", 0) == 0);
    CHECK(slurp(dir + "/scene-ratio.csv").rfind("model,i,theta_deg", 0) == 0);

    // No OSMesa: one line, exit 1, no PNG.
    const std::string dir2 = scratch_dir() + "/render2";
    REQUIRE(std::system(("mkdir -p " + dir2).c_str()) == 0);
    const std::string cmd = "FV_OSMESA_LIBRARY=/nonexistent/libOSMesa.so " + std::string(FV_EXE) +
                            " render --figure fig5 --out " + dir2 + " >/dev/null 2>" + dir2 + "/err.txt";
    const int status = std::system(cmd.c_str());
    CHECK(WEXITSTATUS(status) == 1);
    const std::string err = slurp(dir2 + "/err.txt");
    CHECK(lines(err) == 1);
    CHECK(err.find("OSMesa") != std::string::npos);
    CHECK(::access((dir2 + "/fig5.png").c_str(), F_OK) != 0);
}

TEST_CASE("CLI: gui without a display says what to run instead", "[cli][gui]") {
    const std::string err = scratch_dir() + "/gui-err.txt";
    const std::string cmd =
        "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) + " gui --frames 2 >/dev/null 2>" + err;
    const int status = std::system(cmd.c_str());
    CHECK(WEXITSTATUS(status) == 1);
    const std::string text = slurp(err);
    CHECK(lines(text) == 1);
    CHECK(text.find("frictionviz render") != std::string::npos);
    // No subcommand at all means the window, too.
    const int status2 = std::system(
        ("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) + " >/dev/null 2>&1").c_str());
    CHECK(WEXITSTATUS(status2) == 1);
}

TEST_CASE("CLI: a malformed gui script is a usage error naming file and line", "[cli][gui]") {
    const std::string script = scratch_dir() + "/bad-script.txt";
    std::ofstream(script) << "0 zeta 0.3\n5 warp 9\n";
    const Run r = run("gui --headless --frames 3 --script " + script);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(script + ":2") != std::string::npos);
}

TEST_CASE("CLI: render is deterministic: the same command gives byte-identical PNGs", "[cli][render]") {
    const std::string a = scratch_dir() + "/det-a", b = scratch_dir() + "/det-b";
    REQUIRE(std::system(("mkdir -p " + a + " " + b).c_str()) == 0);
    REQUIRE(run("render --figure fig14b,fig15 --size 480x320 --out " + a).code == 0);
    REQUIRE(run("render --figure fig14b,fig15 --size 480x320 --out " + b).code == 0);
    for (const char* f : {"/fig14b.png", "/fig15.png", "/fig15.csv"}) {
        const std::string x = slurp(a + f), y = slurp(b + f);
        CAPTURE(f);
        CHECK(!x.empty());
        CHECK(x == y);
    }
}

TEST_CASE("CLI: fit recovers r_disp and i of the synthetic data, as JSON", "[cli][fit]") {
    const std::string out = scratch_dir() + "/fit.json";
    const Run r = run(std::string("fit --data ") + FV_TEST_DATA_DIR +
                      "/synthetic_theta90_rdisp3_i0.csv --amplitude 0.7 --format json --out " + out);
    REQUIRE(r.code == 0);
    CHECK(r.err.empty());
    const auto j = nlohmann::json::parse(slurp(out));
    CHECK(j["best"]["i"] == 0);
    CHECK(j["best"]["rdisp"].get<double>() == Approx(3).epsilon(0.02));
    CHECK(j["best"]["zss_um"].get<double>() == Approx(0.7 / j["best"]["rdisp"].get<double>()));
    CHECK(j["best"]["points"].size() == 16);
    CHECK(j["candidates"].size() == 2);
}

TEST_CASE("CLI: fit of a malformed file exits 2 with FILE:LINE:COL: message", "[cli][fit]") {
    const std::string bad = scratch_dir() + "/bad-data.csv", out = scratch_dir() + "/fit-out.txt";
    std::ofstream(bad) << "# comment\nzeta,r_x\n0.1,0.5\n0.2, nan\n";
    std::ofstream(out) << "keep\n";
    Run r = run("fit --data " + bad + " --theta 90 --i 0 --out " + out);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(bad + ":4:6: 'r_x' 'nan' is not finite") != std::string::npos);
    CHECK(slurp(out) == "keep\n");

    std::ofstream(bad) << "vb,r_x\n0.1,0.5\n";
    r = run("fit --data " + bad + " --theta 90");
    CHECK(r.code == 2);
    CHECK(r.err.find(bad + ":1:1: column 'vb' (m/s) needs the vibration amplitude") != std::string::npos);

    r = run("fit --data " + scratch_dir() + "/no-such.csv --theta 90");
    CHECK(r.code == 2);
    CHECK(r.err.find("cannot open") != std::string::npos);

    std::ofstream(bad) << "zeta,r_x\n0.1,0.5\n";
    for (const char* args :
         {" --i 2", " --theta 200", " --amplitude 0", " --frequency -1", " --format csv", ""}) {
        CAPTURE(args);
        r = run("fit --data " + bad + args);
        CHECK(r.code == 2);
        CHECK(lines(r.err) == 1);
    }
    CHECK(run("fit --theta 90").code == 2); // --data is required
}

TEST_CASE("CLI: render --figure map writes the grid and the best-angle curve", "[cli][render][map]") {
    const std::string dir = scratch_dir() + "/map";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const Run r = run("render --figure map --rdisp 1 --i 0 --size 640x400 --out " + dir);
    REQUIRE(r.code == 0);
    const std::string grid = slurp(dir + "/map.csv"), best = slurp(dir + "/map-best-angle.csv");
    CHECK(grid.rfind("model,i,theta_deg,rdisp,zeta,r_x", 0) == 0);
    CHECK(lines(grid) == 1 + 200 * 91);
    CHECK(best.rfind("zeta,theta_star_deg,r_x_min,theta_star_rigid_deg,r_x_rigid_min", 0) == 0);
    CHECK(lines(best) == 1 + 200);
}

TEST_CASE("CLI: render --figure fig19 plots data over the fitted models; bad data is a usage error",
          "[cli][render][fit]") {
    const std::string dir = scratch_dir() + "/fig19";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const std::string data = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";
    const Run r = run("render --figure fig19 --data " + data + " --size 480x320 --out " + dir);
    REQUIRE(r.code == 0);
    const std::string csv = slurp(dir + "/fig19.csv");
    CHECK(csv.rfind("line,zeta,r_x,sigma,model_i0,residual_i0,model_i1,residual_i1\n", 0) == 0);
    CHECK(lines(csv) == 1 + 16);
    CHECK(run("render --figure fig19 --out " + dir).code == 2);
    std::ofstream(dir + "/bad.csv") << "zeta,r_x\n0.1,oops\n";
    const Run bad = run("render --figure fig19 --theta 90 --data " + dir + "/bad.csv --out " + dir);
    CHECK(bad.code == 2);
    CHECK(bad.err.find("bad.csv:2:") != std::string::npos);
}
