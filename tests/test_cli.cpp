// The real executable: exit codes, one-line errors naming the flag and range, nothing written on failure.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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

// `env`: assignments put before the command, e.g. "FV_TEST_FORCE_STATUS=not_converged" (which runs the
// executable with the test hooks, frictionviz_forced: the shipped one ignores the variable).
Run run(const std::string& args, const std::string& env = "") {
    const std::string o = scratch_dir() + "/stdout", e = scratch_dir() + "/stderr";
    const bool forced = env.find("FV_TEST_FORCE_STATUS") != std::string::npos;
    const std::string cmd = (env.empty() ? "" : "env " + env + " ") +
                            std::string(forced ? FV_EXE_FORCED : FV_EXE) + " " + args + " >" + o + " 2>" + e +
                            " </dev/null";
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
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --tolerance 0", "--tolerance"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --tolerance 1e-3", "--tolerance"},
             Case{"ratio --zeta 0.3 --theta 90 --rdisp 2 --i 1 --scheme paper --tolerance 1e-6",
                  "--tolerance"},
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
    // Target in a missing directory / a directory / empty: refused up front with exit 2 (special files and
    // links: tests/reliability).
    for (const std::string& out : {dir + "/nope/x.csv", dir, std::string()}) {
        const Run r = run(std::string("ratio ") + kGood + " --format csv --out '" + out + "'");
        CAPTURE(out, r.err);
        CHECK(r.code == 2);
        CHECK(r.err.find("--out") != std::string::npos);
    }
    CHECK(::access((dir + "/nope").c_str(), F_OK) != 0);
}

TEST_CASE("CLI: ratio formats carry the documented columns", "[cli]") {
    const Run csv = run(std::string("ratio ") + kGood + " --format csv");
    REQUIRE(csv.code == 0);
    CHECK(csv.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                        "multiplier,states\ndahl,1,45,2,0.3,",
                        0) == 0);
    CHECK(lines(csv.out) == 2);
    const Run js = run(std::string("ratio ") + kGood + " --format json");
    REQUIRE(js.code == 0);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(j["model"] == "dahl");
    CHECK(j["status"] == "ok");
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
    CHECK(csv.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                    "multiplier,states\n",
                    0) == 0);
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
    CHECK(header == "tau,Px,Py,Tx,Ty,z,Fx,Fy,status");
    int rows = 0;
    double first_tau = 0, last_tau = 0;
    while (std::getline(in, line)) {
        CHECK(line.substr(line.rfind(',')) == ",ok");
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
    const std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) +
                            " gui --platform window --frames 2 >/dev/null 2>" + err;
    const int status = std::system(cmd.c_str());
    CHECK(WEXITSTATUS(status) == 1);
    const std::string text = slurp(err);
    CHECK(lines(text) == 1);
    CHECK(text.find("frictionviz render") != std::string::npos);
    // No subcommand at all means the window, too.
    const int status2 = std::system(
        ("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) + " >/dev/null 2>&1").c_str());
    CHECK(WEXITSTATUS(status2) == 1);
    // --platform auto (the default) runs headless when there is no display and a number of frames is given.
    const std::string shot = scratch_dir() + "/auto-headless.png";
    const int status3 = std::system(("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FV_EXE) +
                                     " gui --frames 2 --screenshot " + shot + " >/dev/null 2>&1")
                                        .c_str());
    CHECK(WEXITSTATUS(status3) == 0);
    CHECK(::access(shot.c_str(), F_OK) == 0);
}

TEST_CASE("CLI: gui --data checks the file before any window opens", "[cli][gui][data]") {
    const std::string bad = scratch_dir() + "/gui-bad.csv", shot = scratch_dir() + "/gui-data.png";
    std::ofstream(bad) << "zeta,r_x\n0.1,0.5\n0.2,abc\n";
    std::remove(shot.c_str());
    Run r = run("gui --headless --frames 2 --screenshot " + shot + " --data " + bad);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(bad + ":3:5: ") != std::string::npos);
    CHECK(!std::ifstream(shot)); // nothing rendered, nothing written
    r = run("gui --headless --frames 2 --data " + scratch_dir() + "/no-such.csv");
    CHECK(r.code == 2);
    CHECK(r.err.find("no-such.csv") != std::string::npos);
    // A vb column is converted with the window's vibration: 0.1 um at 1 kHz (v_v = 0.63 mm/s) puts these
    // points (v_b up to 0.32 m/s) past zeta = 100.
    r = run("gui --headless --frames 2 --amplitude 0.1 --frequency 1 --data " FV_TEST_DATA_DIR
            "/synthetic_theta0_rdisp1_i1_vb.csv");
    CHECK(r.code == 2);
    CHECK(r.err.find("allowed: zeta in [0, 100]") != std::string::npos);
    // A good file opens and the session runs.
    r = run("gui --headless --frames 2 --screenshot " + shot +
            " --data " FV_TEST_DATA_DIR "/synthetic_theta90_rdisp3_i0.csv");
    CHECK(r.code == 0);
    CHECK(std::ifstream(shot));
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
    CHECK(r.err.find(bad + ":4:6: r_x = 'nan' is not a decimal number") != std::string::npos);
    CHECK(slurp(out) == "keep\n");

    std::ofstream(bad) << "vb,r_x\n0.1,0.5\n";
    r = run("fit --data " + bad + " --theta 90");
    CHECK(r.code == 2);
    CHECK(r.err.find(bad + ":1:1: column 'vb' (m/s) needs the vibration amplitude") != std::string::npos);

    r = run("fit --data " + scratch_dir() + "/no-such.csv --theta 90");
    CHECK(r.code == 2);
    CHECK(r.err.find("does not exist") != std::string::npos);

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

TEST_CASE("CLI: render --figure map writes the grid and the best-angle curve", "[cli][render][map][long]") {
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

TEST_CASE("CLI: render --figure fig19 plots data over the fitted models, bad data is a usage error",
          "[cli][render][fit][long]") {
    const std::string dir = scratch_dir() + "/fig19";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const std::string data = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";
    const Run r = run("render --figure fig19 --data " + data + " --size 480x320 --out " + dir);
    REQUIRE(r.code == 0);
    const std::string csv = slurp(dir + "/fig19.csv");
    CHECK(csv.rfind("line,theta_deg,zeta,r_x,sigma,model_i0,residual_i0,model_i1,residual_i1\n", 0) == 0);
    CHECK(lines(csv) == 1 + 16);
    // Two angles: one panel each (the PNG is twice as busy), one fit, every point in the CSV with its angle.
    const Run two = run("render --figure fig19 --data " + std::string(FV_TEST_DATA_DIR) +
                        "/synthetic_two_angles_rdisp2_i0.csv --size 640x320 --out " + dir);
    REQUIRE(two.code == 0);
    const std::string csv2 = slurp(dir + "/fig19.csv");
    CHECK(lines(csv2) == 1 + 24);
    CHECK(csv2.find("\n12,90,") != std::string::npos);
    CHECK(csv2.find("\n24,0,") != std::string::npos); // the first row of the second part
    // Five angles are more panels than a figure holds: a usage error that says to split the file.
    std::ofstream(dir + "/five.csv") << "zeta,r_x,theta_deg\n0.1,0.2,0\n0.1,0.2,10\n0.1,0.2,20\n0.1,0.2,30\n"
                                        "0.1,0.2,40\n";
    const Run five = run("render --figure fig19 --data " + dir + "/five.csv --out " + dir);
    CHECK(five.code == 2);
    CHECK(five.err.find("at most 4") != std::string::npos);
    CHECK(run("render --figure fig19 --out " + dir).code == 2);
    std::ofstream(dir + "/bad.csv") << "zeta,r_x\n0.1,oops\n";
    const Run bad = run("render --figure fig19 --theta 90 --data " + dir + "/bad.csv --out " + dir);
    CHECK(bad.code == 2);
    CHECK(bad.err.find("bad.csv:2:") != std::string::npos);
}

TEST_CASE("CLI: fig19 applies --amplitude and --frequency (v_b axis, z_ss) and calls only files that say so "
          "synthetic",
          "[cli][render][fit][long]") {
    const std::string dir = scratch_dir() + "/fig19-units";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const std::string data = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";
    auto caption = [&](const std::string& flags) {
        const Run r =
            run("render --figure fig19 --data " + data + " " + flags + " --size 480x320 --out " + dir);
        REQUIRE(r.code == 0);
        return nlohmann::json::parse(slurp(dir + "/fig19.json"));
    };
    // v_v = 2 pi f A: 0.2639 m/s at 0.7 um, 60 kHz (the default), 0.1319 m/s at 1.4 um, 15 kHz.
    const nlohmann::json paper = caption(""), other = caption("--amplitude 1.4 --frequency 15");
    const std::string c0 = paper.at("caption"), c1 = other.at("caption");
    CHECK(c0.find("v_v = 2π f A = 0.2639 m/s") != std::string::npos);
    CHECK(c1.find("v_v = 2π f A = 0.1319 m/s") != std::string::npos);
    CHECK(c1.find("A = 1.4 µm, f = 15 kHz") != std::string::npos);
    // z_ss = A/r_disp doubles with A (the fitted r_disp of a zeta column does not depend on A).
    auto zss = [](const std::string& c) {
        const std::size_t at = c.find("z_ss = A/r_disp = ");
        REQUIRE(at != std::string::npos);
        return std::stod(c.substr(at + 18));
    };
    CHECK(zss(c1) == Approx(2 * zss(c0)).epsilon(2e-3));
    CHECK(std::string(paper.at("title")).find("synthetic example data") != std::string::npos);
    // The same points without the file's comment lines: the user's own data, called measurements.
    std::ifstream in(data);
    std::ofstream own(dir + "/own.csv");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("#", 0) != 0) own << line << "\n";
    own.close();
    const Run r = run("render --figure fig19 --data " + dir + "/own.csv --size 480x320 --out " + dir);
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir + "/fig19.json"));
    CHECK(std::string(j.at("title")).find("model vs. measurements") != std::string::npos);
    CHECK(std::string(j.at("caption")).find("synthetic") == std::string::npos);
}

// ---- The figure registry through the executable: --list, every id rendered, captions, unknown ids

namespace {

// The ids of `render --list` (ID<TAB>TITLE per line), in order.
std::vector<std::string> listed_ids() {
    const Run r = run("render --list");
    REQUIRE(r.code == 0);
    std::vector<std::string> ids;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        const auto tab = line.find('\t');
        REQUIRE(tab != std::string::npos);
        CHECK(tab > 0);
        CHECK(tab + 1 < line.size()); // a title
        ids.push_back(line.substr(0, tab));
    }
    return ids;
}

std::vector<std::string> files_in(const std::string& dir) {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d))
            if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") names.push_back(e->d_name);
        ::closedir(d);
    }
    return names;
}

} // namespace

TEST_CASE("CLI registry: render --list prints every figure once, --figure and its messages take the same ids",
          "[cli][render][registry]") {
    const std::vector<std::string> ids = listed_ids();
    std::vector<std::string> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()); // unique
    for (const char* id :
         {"fig4",   "fig5",   "fig6",  "fig8",  "fig9",  "fig10", "fig11", "fig12", "fig13", "fig14",
          "fig14a", "fig14b", "fig15", "fig16", "fig17", "fig18", "fig19", "scene", "map",   "ry"})
        CHECK(std::count(ids.begin(), ids.end(), id) == 1);
    // The unknown-id message and --help name exactly the listed ids (and "all").
    const std::string dir = scratch_dir() + "/registry-unknown";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const Run bad = run("render --figure fig5,nope --out " + dir);
    CHECK(bad.code == 2);
    CHECK(bad.out.empty());
    CHECK(lines(bad.err) == 1);
    CHECK(bad.err.find("'nope'") != std::string::npos);
    std::string allowed = "all";
    for (const std::string& id : ids) allowed += ", " + id;
    CHECK(bad.err.find("allowed: " + allowed + "\n") != std::string::npos);
    CHECK(files_in(dir).empty()); // nothing written, not even fig5
    const Run help = run("render --help");
    CHECK(help.code == 0);
    CHECK(help.out.find(allowed) != std::string::npos);
    // The markdown table has one row per listed id, in the same order.
    const Run md = run("render --list markdown");
    REQUIRE(md.code == 0);
    std::size_t at = 0;
    for (const std::string& id : ids) {
        at = md.out.find("| [" + id + "](screenshots/" + id + ".png) | ", at);
        CHECK(at != std::string::npos);
    }
    CHECK(lines(md.out) == static_cast<long>(ids.size()) + 2);
    CHECK(run("render --list xml").code == 2);
    // A figure that needs flags says which.
    const Run scene = run("render --figure scene --out " + dir);
    CHECK(scene.code == 2);
    CHECK(scene.err.find("--zeta or --vb") != std::string::npos);
    CHECK(files_in(dir).empty());
    // Named among others with none of its flags, it is drawn with its example values, as --figure all draws
    // it; given some of them it still needs all.
    const Run some = run("render --figure fig5,scene --zeta 0.3 --size 320x240 --out " + dir);
    CHECK(some.code == 2);
    CHECK(some.err.find("--figure scene needs --theta") != std::string::npos);
    CHECK(files_in(dir).empty());
    const std::string listed = dir + "/listed";
    REQUIRE(std::system(("mkdir -p " + listed).c_str()) == 0);
    const Run list = run("render --figure fig5,scene --out " + listed);
    CHECK(list.code == 0);
    CHECK(list.err.find("scene: none of") != std::string::npos);
    // screenshots/scene.png is what --figure all draws (the snapshot and readme tests hold it so).
    CHECK_FALSE(slurp(listed + "/scene.png").empty());
    CHECK(slurp(listed + "/scene.png") ==
          slurp(std::string(FV_TEST_DATA_DIR) + "/../../screenshots/scene.png"));
}

TEST_CASE("CLI render: SOURCE_DATE_EPOCH makes a PDF the same bytes run after run", "[cli][render]") {
    const std::string a = scratch_dir() + "/pdf-a", b = scratch_dir() + "/pdf-b";
    REQUIRE(std::system(("mkdir -p " + a + " " + b).c_str()) == 0);
    for (const std::string& d : {a, b})
        REQUIRE(run("render --figure fig5 --format pdf --size 320x240 --out " + d, "SOURCE_DATE_EPOCH=86400")
                    .code == 0);
    const std::string pdf = slurp(a + "/fig5.pdf");
    // One day after the epoch, UTC (cairo writes the date without the "D:" of its own dates; pdfinfo reads
    // it).
    CHECK(pdf.find("/CreationDate (19700102000000Z)") != std::string::npos);
    CHECK(pdf == slurp(b + "/fig5.pdf"));
}

TEST_CASE("CLI registry: --figure all renders every listed id with its CSV and a caption JSON",
          "[cli][render][registry][long]") {
    const std::vector<std::string> ids = listed_ids();
    const std::string dir = scratch_dir() + "/registry-all";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const Run r = run("render --figure all --data " + std::string(FV_TEST_DATA_DIR) +
                      "/synthetic_two_angles_rdisp2_i0.csv --amplitude 0.7 --size 320x240 --out " + dir);
    REQUIRE(r.code == 0);
    CHECK(lines(r.out) == static_cast<long>(ids.size())); // one "wrote" line per figure
    const std::vector<std::string> written = files_in(dir);
    for (const std::string& id : ids) {
        CAPTURE(id);
        CHECK(slurp(dir + "/" + id + ".png").substr(1, 3) == "PNG");
        const nlohmann::json j = nlohmann::json::parse(slurp(dir + "/" + id + ".json"));
        CHECK(j.at("id") == id);
        const std::string title = j.at("title"), caption = j.at("caption");
        CHECK_FALSE(title.empty());
        CHECK(title.find("_{") == std::string::npos); // plain text, no markup
        // Every parameter named: the model(s), the solver, a tolerance, the sampling.
        for (const char* word : {"Parameters: ", "model", "θ", "r_disp", "tolerance"})
            CHECK(caption.find(word) != std::string::npos);
        CHECK((caption.find("i = ") != std::string::npos ||
               caption.find("i does not apply") != std::string::npos));
        CHECK(j.at("status") == "ok");
        CHECK(std::string(j.at("version")).rfind("frictionviz ", 0) == 0);
        // The files it lists are the ones written, the image and the JSON among them.
        const std::vector<std::string> files = j.at("files");
        CHECK(std::count(files.begin(), files.end(), id + ".png") == 1);
        CHECK(std::count(files.begin(), files.end(), id + ".json") == 1);
        CHECK(std::count(files.begin(), files.end(), id + ".csv") == 1);
        for (const std::string& f : files) CHECK(std::count(written.begin(), written.end(), f) == 1);
    }
    // Fixed figures' captions name every parameter by value.
    const std::string fig15 = nlohmann::json::parse(slurp(dir + "/fig15.json")).at("caption");
    for (const char* v : {"ζ = 0.15", "θ = 90°", "r_disp = 2", "i = 1", "1024"})
        CHECK(fig15.find(v) != std::string::npos);
    // Every figure again from the parameters of its ID.json (render --spec): the same files byte for byte.
    const std::string again = scratch_dir() + "/registry-spec";
    REQUIRE(std::system(("mkdir -p " + again).c_str()) == 0);
    for (const std::string& id : ids) {
        CAPTURE(id);
        const Run s = run("render --spec " + dir + "/" + id + ".json --out " + again);
        REQUIRE(s.code == 0);
        const std::vector<std::string> files =
            nlohmann::json::parse(slurp(dir + "/" + id + ".json")).at("files");
        for (const std::string& f : files) {
            CAPTURE(f);
            CHECK(slurp(again + "/" + f) == slurp(dir + "/" + f));
        }
    }
}

TEST_CASE("CLI spec: ID.json parameters hold every input exactly and render --spec gives the same files",
          "[cli][render][spec]") {
    const std::string a = scratch_dir() + "/spec-a", b = scratch_dir() + "/spec-b";
    REQUIRE(std::system(("mkdir -p " + a + " " + b).c_str()) == 0);
    struct Case {
        std::string id, flags;
    };
    // Values that are not short decimals (0.1 + 0.2, 1/3 typed with all its digits), lists, a log range, the
    // other start, vector formats and another page.
    for (const Case& c :
         {Case{"fig4", "--zeta 0.30000000000000004 --theta 33.333333333333336 --format png,svg"},
          Case{"rx", "--theta 0,90 --rdisp 2 --i 0,1 --model rigid,dahl --zeta 0.01:10 --start "
                     "sliding --size 640x400 --scale 0.5"},
          Case{"fig10", "--format pdf --size 400x300"}}) {
        CAPTURE(c.id, c.flags);
        const Run r = run("render --figure " + c.id + " " + c.flags + " --out " + a);
        REQUIRE(r.code == 0);
        const nlohmann::json j = nlohmann::json::parse(slurp(a + "/" + c.id + ".json"));
        const nlohmann::json& p = j.at("parameters");
        CHECK(p.at("id") == c.id);
        if (c.id == "fig4") {
            CHECK(p.at("zeta").get<double>() == 0.1 + 0.2);
            CHECK(p.at("theta").get<double>() == 100.0 / 3);
            CHECK(p.at("format") == nlohmann::json{"png", "svg"});
        } else if (c.id == "rx") {
            CHECK(p.at("theta") == nlohmann::json{0.0, 90.0});
            CHECK(p.at("model") == nlohmann::json{"rigid", "dahl"});
            CHECK(p.at("zeta") == nlohmann::json{0.01, 10.0});
            CHECK(p.at("start") == "sliding");
            CHECK(p.at("size") == nlohmann::json{640, 400});
            CHECK(p.at("scale") == 0.5);
        } else {
            CHECK(p.size() == 4); // id, size, scale, format: a fixed figure has no other input
        }
        const Run s = run("render --spec " + a + "/" + c.id + ".json --out " + b);
        REQUIRE(s.code == 0);
        // A PDF names the time it was written (cairo's /CreationDate): every other byte is the same.
        auto undated = [](std::string text) {
            const std::size_t at = text.find("/CreationDate (D:");
            if (at != std::string::npos) text.erase(at, text.find(')', at) - at);
            return text;
        };
        for (const std::string& f : j.at("files").get<std::vector<std::string>>()) {
            CAPTURE(f);
            CHECK(undated(slurp(b + "/" + f)) == undated(slurp(a + "/" + f)));
        }
    }
    // The parameters object alone is a spec too; --format given replaces the file's.
    std::ofstream(a + "/alone.json") << R"({"id": "fig4", "zeta": 0.5, "theta": 30})";
    const Run s = run("render --spec " + a + "/alone.json --format svg --out " + b);
    CHECK(s.code == 0);
    const nlohmann::json j = nlohmann::json::parse(slurp(b + "/fig4.json"));
    CHECK(j.at("parameters").at("format") == nlohmann::json{"svg"});
    CHECK(j.at("parameters").at("theta") == 30.0);
}

TEST_CASE("CLI spec: a bad spec file is a one-line usage error naming the key and nothing is written",
          "[cli][render][spec]") {
    const std::string dir = scratch_dir() + "/spec-bad", out = dir + "/out";
    REQUIRE(std::system(("mkdir -p " + out).c_str()) == 0);
    struct Case {
        const char* json;
        const char* says;
    };
    for (const Case& c : {
             Case{R"({"zeta": 0.5})", "id is missing"},
             Case{R"({"id": "fig99"})", "unknown figure 'fig99'; allowed: fig4"},
             Case{R"({"id": 4})", "id: expected a string, got a number"},
             Case{R"({"id": "fig4", "zeta": "0.5"})", "zeta: expected a number, got a string"},
             Case{R"({"id": "fig4", "theta": [30, 60]})", "theta has 2 values; fig4 takes one"},
             Case{R"({"id": "fig4", "zeta": 1e9})", "zeta = 1000000000 is out of range"},
             Case{R"({"id": "fig4", "zeta": 0.5, "colour": "red"})",
                  "unknown key 'colour' for fig4; allowed: id, zeta"},
             Case{R"({"id": "fig10", "zeta": 0.5})", "unknown key 'zeta' for fig10"},
             Case{R"({"id": "scene", "theta": 30, "rdisp": 2, "i": 1})", "zeta is missing: scene needs it"},
             Case{R"({"id": "rx", "theta": [30, "60"]})", "theta: expected a list of numbers"},
             Case{R"({"id": "rx", "theta": [30, 30]})", "theta has 30 twice"},
             Case{R"({"id": "rx", "theta": []})", "theta is an empty list"},
             Case{R"({"id": "rx", "zeta": [3, 1]})", "zeta = 3:1 is reversed"},
             Case{R"({"id": "rx", "zeta": [1]})", "zeta: expected a range [FROM, TO]"},
             Case{R"({"id": "rx", "model": ["dahl", "soft"]})", "'soft' is not a model"},
             Case{R"({"id": "rx", "theta": [10, 20, 30], "rdisp": [1, 2, 3], "i": [0, 1]})", "at most 12"},
             Case{R"({"id": "map", "rdisp": [1, 2, 1]})", "rdisp has 1 twice"},
             Case{R"({"id": "map", "rdisp": [1, 2, 3], "i": [0.5, 1], "model": ["dahl", "rigid"]})",
                  "r_disp 3 × i 2 = 6 Dahl maps + 1 rigid = 7 maps; allowed: at most 6 maps"},
             Case{R"({"id": "map", "start": "later"})", "'later' is not a start; allowed: rest, sliding"},
             Case{R"({"id": "fig5", "size": [10, 10]})", "size"},
             Case{R"({"id": "fig5", "size": "big"})", "size"},
             Case{R"({"id": "fig5", "scale": 100})", "--scale"},
             Case{R"({"id": "fig5", "format": ["png", "gif"]})", "unknown format 'gif'"},
             Case{R"({"id": "fig5", "format": 3})", "format: expected a string or a list of strings"},
             Case{R"({"parameters": 3})", "parameters: expected an object"},
             Case{"[1, 2]", "expected a JSON object"},
             Case{"{\"id\": \"fig5\",\n\n", "not JSON"},
             Case{"", "not JSON"},
             Case{R"({"id": "fig4", "zeta": 1e400})", "not JSON"},
         }) {
        CAPTURE(c.json);
        std::ofstream(dir + "/spec.json") << c.json;
        const Run r = run("render --spec " + dir + "/spec.json --out " + out);
        CHECK(r.code == 2);
        CHECK(lines(r.err) == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
        CHECK(r.err.find("spec.json") != std::string::npos);
        CHECK(files_in(out).empty());
    }
    // --spec takes the figure and its parameters from the file.
    std::ofstream(dir + "/spec.json") << R"({"id": "fig5"})";
    for (const char* more : {"--figure fig5", "--theta 30", "--rdisp 2", "--data x.csv", "--start rest"}) {
        CAPTURE(more);
        const Run r = run("render --spec " + dir + "/spec.json " + more + " --out " + out);
        CHECK(r.code == 2);
        CHECK(lines(r.err) == 1);
        CHECK(r.err.find("--spec and") != std::string::npos);
    }
    CHECK(run("render --spec " + dir + "/missing.json --out " + out).code == 2);
    CHECK(files_in(out).empty());
}

TEST_CASE("CLI families: lists of rx, ry and map through core's reader, one-line errors, no file written",
          "[cli][render][family]") {
    const std::string out = scratch_dir() + "/family-bad";
    REQUIRE(std::system(("mkdir -p " + out).c_str()) == 0);
    struct Case {
        const char* args;
        const char* says;
    };
    for (const Case& c : {
             Case{"--figure rx --theta 30,,60", "--theta: '30,,60' has an empty item (number 2)"},
             Case{"--figure rx --theta 30,60,30", "30 twice (items 1 and 3)"},
             Case{"--figure rx --rdisp 1,0", "out of range"},
             Case{"--figure rx --i 1,x", "not a decimal number"},
             Case{"--figure rx --zeta 3:1", "reversed (FROM > TO)"},
             Case{"--figure rx --zeta 1:1", "empty (FROM == TO)"},
             Case{"--figure rx --zeta 0:1:5", "not a range"},
             Case{"--figure rx --model dahl,dahl", "dahl twice"},
             Case{"--figure rx --theta 10,20,30 --rdisp 1,2,3 --i 0,1", "= 21 curves; allowed: at most 12"},
             Case{"--figure rx --zeta 0.5", "--zeta has"},
             Case{"--figure ry --theta 10,20,30,40,50,60,70", "at most 12"},
             Case{"--figure map --rdisp 1,2,3 --i 0.5,1,2",
                  "r_disp 3 × i 3 = 9 Dahl maps = 9 maps; allowed: at most 6 maps in one figure"},
             Case{"--figure map --rdisp 1,2,1", "1 twice (items 1 and 3)"},
             Case{"--figure map --rdisp 1,2 --zss 0.3 --amplitude 1", "--rdisp and --zss"},
             Case{"--figure scene --zeta 0.3 --theta 30,60 --rdisp 2 --i 1", "scene takes one"},
             Case{"--figure scene --zeta 0.1:1 --theta 30 --rdisp 2 --i 1", "scene takes one"},
             Case{"--figure rx --zeta 0.1:1 --vb 1 --amplitude 1 --frequency 1", "--vb"},
         }) {
        CAPTURE(c.args);
        const Run r = run(std::string("render ") + c.args + " --out " + out);
        CHECK(r.code == 2);
        CHECK(lines(r.err) == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
    }
    CHECK(files_in(out).empty());
}

// ---- Physical units: --vb (m/s), --amplitude (um), --frequency (kHz), --zss (um)
// ----------------------------

namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;

// Printed with all the digits a double has, so that the program reads back exactly this number.
std::string exact(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The line of a text report that starts with `key` (e.g. "r_x "), or "" if there is none.
std::string report_line(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) return line;
    return "";
}

// A CSV with a header: one map column -> field per row.
std::vector<std::map<std::string, std::string>> parse_csv(const std::string& csv) {
    std::istringstream in(csv);
    std::string line;
    std::vector<std::string> header;
    auto split = [](const std::string& s) {
        std::vector<std::string> f;
        std::string cur;
        std::istringstream ls(s);
        while (std::getline(ls, cur, ',')) f.push_back(cur);
        if (!s.empty() && s.back() == ',') f.push_back("");
        return f;
    };
    std::getline(in, line);
    header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const auto f = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < header.size(); ++k) row[header[k]] = k < f.size() ? f[k] : "";
        rows.push_back(row);
    }
    return rows;
}

// True for an existing directory without entries.
bool slurp_dir_empty(const std::string& dir) {
    DIR* d = ::opendir(dir.c_str());
    if (!d) return false;
    int n = 0;
    while (const dirent* e = ::readdir(d))
        if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") ++n;
    ::closedir(d);
    return n == 0;
}

// Exit code 2 and one line on stderr that contains each of `names`.
void check_usage_error(const Run& r, const std::vector<std::string>& names) {
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(lines(r.err) == 1);
    for (const std::string& n : names) {
        CAPTURE(n, r.err);
        CHECK(r.err.find(n) != std::string::npos);
    }
}

double field(const std::map<std::string, std::string>& row, const std::string& col) {
    const auto it = row.find(col);
    REQUIRE(it != row.end());
    return std::stod(it->second);
}

} // namespace

// r_x of the rigid model at theta = 0 (Eq. 10): 2/pi asin(zeta) below zeta = 1, 1 above.
static double rigid_rx_theta0(double zeta) {
    return zeta < 1 ? 2 / 3.14159265358979323846 * std::asin(zeta) : 1.0;
}

TEST_CASE("CLI: a family of maps (lists of --rdisp, --i, --model): one grid per map in one CSV, the best "
          "angles with the inputs that vary, ID.json's lists, render --spec byte for byte",
          "[cli][render][map][family][long]") {
    const std::string a = scratch_dir() + "/map-family", b = scratch_dir() + "/map-family-spec",
                      one = scratch_dir() + "/map-family-one";
    REQUIRE(std::system(("mkdir -p " + a + " " + b + " " + one).c_str()) == 0);
    const Run r = run("render --figure map --rdisp 1,3 --i 0.5 --model dahl,rigid --size 640x400 --format "
                      "png,svg --out " +
                      a);
    REQUIRE(r.code == 0);
    // The grid: 3 maps of 200 x 91 cells, Dahl r_disp = 1, then 3, then the rigid model (no r_disp, i).
    const auto rows = parse_csv(slurp(a + "/map.csv"));
    REQUIRE(rows.size() == 3 * 200 * 91);
    CHECK(rows.front().at("model") == "dahl");
    CHECK(rows.front().at("rdisp") == "1");
    CHECK(rows.at(200 * 91).at("rdisp") == "3");
    CHECK(rows.at(200 * 91).at("i") == "0.5");
    const auto& rigid0 = rows.at(2 * 200 * 91);
    CHECK(rigid0.at("model") == "rigid");
    CHECK(rigid0.at("rdisp").empty());
    CHECK(rigid0.at("i").empty());
    // The rigid map at theta = 0 against Eq. (10), every zeta of the grid (the first row of that map).
    for (std::size_t k = 2 * 200 * 91; k < 2 * 200 * 91 + 200; ++k) {
        const auto& row = rows.at(k);
        REQUIRE(field(row, "theta_deg") == 0);
        CHECK(field(row, "r_x") == Approx(rigid_rx_theta0(field(row, "zeta"))).margin(1e-9));
    }
    // The best angles: the inputs that vary in front (the model and r_disp; i is the same for all), the
    // rigid map's own best angle its rigid one.
    const auto best = parse_csv(slurp(a + "/map-best-angle.csv"));
    REQUIRE(best.size() == 3 * 200);
    CHECK(slurp(a + "/map-best-angle.csv").rfind("model,rdisp,zeta,theta_star_deg,r_x_min,", 0) == 0);
    for (std::size_t k = 400; k < 600; ++k) {
        CHECK(best[k].at("model") == "rigid");
        CHECK(best[k].at("rdisp").empty());
        CHECK(best[k].at("theta_star_deg") == best[k].at("theta_star_rigid_deg"));
    }
    // Each Dahl map of the family is the map of its r_disp and i alone.
    REQUIRE(run("render --figure map --rdisp 3 --i 0.5 --size 640x400 --out " + one).code == 0);
    const auto alone = parse_csv(slurp(one + "/map.csv"));
    REQUIRE(alone.size() == 200 * 91);
    for (std::size_t k = 0; k < alone.size(); k += 97) {
        CAPTURE(k);
        CHECK(alone[k] == rows.at(200 * 91 + k));
    }
    // ID.json: the lists as lists, the one i as a number (as the map of one r_disp and i has always written).
    const nlohmann::json j = nlohmann::json::parse(slurp(a + "/map.json"));
    const nlohmann::json& p = j.at("parameters");
    CHECK(p.at("rdisp") == nlohmann::json{1.0, 3.0});
    CHECK(p.at("i") == 0.5);
    CHECK(p.at("model") == nlohmann::json{"dahl", "rigid"});
    CHECK(std::string(j.at("caption"))
              .find("3 maps in 1 × 3 panels on one colour scale: Dahl model, r_disp = 1, 3, i = 0.5") !=
          std::string::npos);
    CHECK(std::string(j.at("title")).find("Dahl model (i = 0.5) and rigid model") != std::string::npos);
    // render --spec map.json: every file again, byte for byte.
    const Run s = run("render --spec " + a + "/map.json --out " + b);
    REQUIRE(s.code == 0);
    for (const std::string& f : j.at("files").get<std::vector<std::string>>()) {
        CAPTURE(f);
        CHECK(slurp(b + "/" + f) == slurp(a + "/" + f));
    }
}

TEST_CASE(
    "CLI units: ratio with --vb/--amplitude/--frequency/--zss equals ratio with the converted zeta, rdisp",
    "[cli][units]") {
    // v_b = 0.1 m/s, A = 0.7 um at f = 60 kHz, z_ss = 0.35 um (the paper's Sec. 4 vibration).
    const double vb = 0.1, amp = 0.7, freq = 60, zss = 0.35;
    const double zeta = vb / (kTwoPi * freq * 1e3 * amp * 1e-6), rdisp = amp / zss;
    const std::string units = "--vb 0.1 --amplitude 0.7 --frequency 60 --zss 0.35";
    for (const char* rest : {"--theta 60 --i 1", "--theta 90 --i 0", "--theta 30 --i 1 --scheme paper"}) {
        CAPTURE(rest);
        const Run u = run(std::string("ratio ") + units + " " + rest);
        const Run z = run("ratio --zeta " + exact(zeta) + " --rdisp " + exact(rdisp) + " " + rest);
        REQUIRE(u.code == 0);
        REQUIRE(z.code == 0);
        CHECK(!report_line(u.out, "r_x ").empty());
        CHECK(report_line(u.out, "r_x ") == report_line(z.out, "r_x "));
        CHECK(report_line(u.out, "r_y ") == report_line(z.out, "r_y "));
        // Both views: the dimensionless report plus the physical lines.
        CHECK(report_line(u.out, "v_b ") == "v_b           0.1 m/s   (zeta v_v)");
        CHECK(report_line(u.out, "z_ss ") == "z_ss          0.35 um   (A/rdisp)");
        CHECK(report_line(u.out, "amplitude ") == "amplitude     0.7 um");
        CHECK(report_line(u.out, "frequency ") == "frequency     60 kHz");
        const std::string vv = report_line(u.out, "v_v ");
        REQUIRE(vv.size() > 14);
        CHECK(std::stod(vv.substr(14)) == Approx(kTwoPi * 60e3 * 0.7e-6).epsilon(1e-11));
        CHECK(report_line(z.out, "v_b ").empty()); // no unit flags: no physical view
    }
    // CSV: the extra columns are the physical values of the printed zeta and rdisp.
    const Run csv = run(std::string("ratio ") + units + " --theta 60 --i 1 --format csv");
    REQUIRE(csv.code == 0);
    CHECK(csv.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                        "multiplier,states,vb_m_s,zss_um\n",
                        0) == 0);
    const auto rows = parse_csv(csv.out);
    REQUIRE(rows.size() == 1);
    CHECK(field(rows[0], "zeta") == Approx(zeta).epsilon(1e-11));
    CHECK(field(rows[0], "rdisp") == Approx(rdisp).epsilon(1e-11));
    CHECK(field(rows[0], "vb_m_s") ==
          Approx(field(rows[0], "zeta") * kTwoPi * freq * amp * 1e-3).epsilon(1e-11));
    CHECK(field(rows[0], "zss_um") == Approx(amp / field(rows[0], "rdisp")).epsilon(1e-11));
    // JSON: the same keys.
    const Run js = run(std::string("ratio ") + units + " --theta 60 --i 1 --format json");
    REQUIRE(js.code == 0);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(j["vb_m_s"].get<double>() == Approx(vb).epsilon(1e-12));
    CHECK(j["zss_um"].get<double>() == Approx(zss).epsilon(1e-12));
    CHECK(j["zeta"].get<double>() == Approx(zeta).epsilon(1e-12));
}

TEST_CASE("CLI units: --amplitude/--frequency with plain --zeta/--rdisp add the physical view",
          "[cli][units]") {
    const std::string base = "ratio --zeta 0.3 --theta 45 --rdisp 2 --i 1 --format csv";
    // Amplitude and frequency: both columns.
    Run r = run(base + " --amplitude 0.5 --frequency 40");
    REQUIRE(r.code == 0);
    auto rows = parse_csv(r.out);
    REQUIRE(rows.size() == 1);
    CHECK(field(rows[0], "vb_m_s") == Approx(0.3 * kTwoPi * 40 * 0.5 * 1e-3).epsilon(1e-11));
    CHECK(field(rows[0], "zss_um") == Approx(0.5 / 2).epsilon(1e-11));
    // Amplitude alone: z_ss only.
    r = run(base + " --amplitude 0.5");
    REQUIRE(r.code == 0);
    CHECK(r.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                      "multiplier,states,zss_um\n",
                      0) == 0);
    // Frequency alone is accepted and changes nothing (it needs the amplitude to say anything).
    r = run(base + " --frequency 40");
    REQUIRE(r.code == 0);
    CHECK(r.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                      "multiplier,states\n",
                      0) == 0);
    // The rigid model has no z_ss: the column is there but empty (null in JSON).
    r = run("ratio --model rigid --zeta 0.5 --theta 0 --amplitude 0.5 --frequency 40 --format csv");
    REQUIRE(r.code == 0);
    rows = parse_csv(r.out);
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].at("zss_um").empty());
    CHECK(field(rows[0], "vb_m_s") == Approx(0.5 * kTwoPi * 40 * 0.5 * 1e-3).epsilon(1e-11));
    r = run("ratio --model rigid --zeta 0.5 --theta 0 --amplitude 0.5 --format json");
    REQUIRE(r.code == 0);
    CHECK(nlohmann::json::parse(r.out)["zss_um"].is_null());
    CHECK(!nlohmann::json::parse(r.out).contains("vb_m_s"));
    // The rigid model needs no --rdisp or --zss, with units as without.
    r = run("ratio --model rigid --vb 0.05 --amplitude 0.5 --frequency 40 --theta 0 --format json");
    REQUIRE(r.code == 0);
    CHECK(nlohmann::json::parse(r.out)["zeta"].get<double>() ==
          Approx(0.05 / (kTwoPi * 40e3 * 0.5e-6)).epsilon(1e-12));
}

TEST_CASE("CLI units: without unit flags the output is the dimensionless one", "[cli][units]") {
    const Run csv = run(std::string("ratio ") + kGood + " --format csv");
    REQUIRE(csv.code == 0);
    CHECK(
        csv.out.substr(0, csv.out.find('\n')) ==
        "model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_multiplier,states");
    const Run js = run(std::string("ratio ") + kGood + " --format json");
    REQUIRE(js.code == 0);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(!j.contains("vb_m_s"));
    CHECK(!j.contains("zss_um"));
    const Run txt = run(std::string("ratio ") + kGood);
    CHECK(report_line(txt.out, "v_b ").empty());
    CHECK(report_line(txt.out, "z_ss ").empty());
    CHECK(report_line(txt.out, "amplitude ").empty());
    const Run sw = run("sweep --zeta 0.1:0.5:3 --theta 90 --rdisp 2 --i 1");
    REQUIRE(sw.code == 0);
    CHECK(
        sw.out.substr(0, sw.out.find('\n')) ==
        "model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_multiplier,states");
}

TEST_CASE("CLI units: sweep --vb FROM:TO:COUNT and --zss lists equal the converted zeta range and rdisp list",
          "[cli][units]") {
    const double amp = 0.7, freq = 60;
    const double vv = kTwoPi * freq * 1e3 * amp * 1e-6;
    const double z0 = 0.05 / vv, z1 = 0.25 / vv;
    const std::string common = " --theta 0,90 --i 0,1 --steps-per-period 256";
    const Run u = run("sweep --vb 0.05:0.25:5 --amplitude 0.7 --frequency 60 --zss 0.35,0.7" + common);
    const Run z = run("sweep --zeta " + exact(z0) + ":" + exact(z1) + ":5 --rdisp " + exact(amp / 0.35) +
                      "," + exact(amp / 0.7) + common);
    REQUIRE(u.code == 0);
    REQUIRE(z.code == 0);
    CHECK(u.out.rfind("model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_"
                      "multiplier,states,vb_m_s,zss_um\n",
                      0) == 0);
    const auto ru = parse_csv(u.out), rz = parse_csv(z.out);
    REQUIRE(ru.size() == 2 * 2 * 2 * 5);
    REQUIRE(rz.size() == ru.size());
    for (std::size_t k = 0; k < ru.size(); ++k) {
        CAPTURE(k);
        for (const char* col : {"i", "theta_deg", "rdisp", "zeta"})
            CHECK(field(ru[k], col) == Approx(field(rz[k], col)).epsilon(1e-11));
        CHECK(field(ru[k], "r_x") == Approx(field(rz[k], "r_x")).margin(1e-9));
        CHECK(field(ru[k], "r_y") == Approx(field(rz[k], "r_y")).margin(1e-9));
        CHECK(field(ru[k], "vb_m_s") ==
              Approx(field(ru[k], "zeta") * kTwoPi * freq * amp * 1e-3).epsilon(1e-11));
        CHECK(field(ru[k], "zss_um") == Approx(amp / field(ru[k], "rdisp")).epsilon(1e-11));
    }
    // The v_b grid is the evenly spaced one asked for: 0.05, 0.1, ..., 0.25 m/s.
    const double grid[] = {0.05, 0.1, 0.15, 0.2, 0.25};
    for (std::size_t k = 0; k < 5; ++k) CHECK(field(ru[k], "vb_m_s") == Approx(grid[k]).epsilon(1e-11));
    CHECK(field(ru[0], "zss_um") == Approx(0.35).epsilon(1e-12));
    CHECK(field(ru[5], "zss_um") == Approx(0.7).epsilon(1e-12));
    // Rigid: zss_um empty, vb_m_s present; no --rdisp or --zss needed.
    const Run rig =
        run("sweep --model rigid --vb 0:0.2:3 --amplitude 0.7 --frequency 60 --theta 0 --format json");
    REQUIRE(rig.code == 0);
    const auto arr = nlohmann::json::parse(rig.out);
    REQUIRE(arr.size() == 3);
    CHECK(arr[2]["vb_m_s"].get<double>() == Approx(0.2).epsilon(1e-12));
    CHECK(arr[2]["zeta"].get<double>() == Approx(0.2 / vv).epsilon(1e-12));
    CHECK(arr[2]["zss_um"].is_null());
}

TEST_CASE("CLI units: trace with --vb/--zss equals trace with the converted zeta, rdisp", "[cli][units]") {
    const double amp = 0.5, freq = 20, vb = 0.03, zss = 0.2;
    const double zeta = vb / (kTwoPi * freq * 1e3 * amp * 1e-6), rdisp = amp / zss;
    const Run u = run("trace --vb 0.03 --amplitude 0.5 --frequency 20 --zss 0.2 --theta 60 --i 1");
    const Run z = run("trace --zeta " + exact(zeta) + " --rdisp " + exact(rdisp) + " --theta 60 --i 1");
    REQUIRE(u.code == 0);
    REQUIRE(z.code == 0);
    const auto ru = parse_csv(u.out), rz = parse_csv(z.out);
    REQUIRE(ru.size() == 1024);
    REQUIRE(rz.size() == ru.size());
    for (std::size_t k = 0; k < ru.size(); k += 37)
        for (const char* col : {"tau", "Px", "Py", "Tx", "Ty", "z", "Fx", "Fy"}) {
            CAPTURE(k, col);
            CHECK(field(ru[k], col) == Approx(field(rz[k], col)).margin(1e-9));
        }
}

TEST_CASE("CLI units: render scene and map with --vb/--zss give the bytes of the equivalent --zeta/--rdisp",
          "[cli][units][render][long]") {
    // Exact in floating point: v_b = v_v/2 with v_v = 2 pi f A computed as fv::units does, so that
    // zeta = v_b/v_v = 1/2 exactly; r_disp = 0.75/0.25 = 3 exactly.
    const double vv = 2 * 3.14159265358979323846 * 40 * 0.75 * 1e-3;
    const std::string vb = exact(vv / 2);
    const Run check = run("ratio --vb " + vb +
                          " --amplitude 0.75 --frequency 40 --zss 0.25 --theta 30 --i 0 "
                          "--format json");
    REQUIRE(check.code == 0);
    REQUIRE(nlohmann::json::parse(check.out)["zeta"].get<double>() == 0.5);
    REQUIRE(nlohmann::json::parse(check.out)["rdisp"].get<double>() == 3);

    const std::string a = scratch_dir() + "/units-scene-a", b = scratch_dir() + "/units-scene-b";
    REQUIRE(std::system(("mkdir -p " + a + " " + b).c_str()) == 0);
    const Run ru =
        run("render --figure scene,map --vb " + vb +
            " --amplitude 0.75 --frequency 40 --zss 0.25 --theta 30 --i 0 --size 400x300 --out " + a);
    const Run rz =
        run("render --figure scene,map --zeta 0.5 --rdisp 3 --theta 30 --i 0 --size 400x300 --out " + b);
    REQUIRE(ru.code == 0);
    REQUIRE(rz.code == 0);
    for (const char* f : {"/scene.png", "/scene.csv", "/scene-ratio.csv", "/map.png", "/map.csv"}) {
        CAPTURE(f);
        const std::string x = slurp(a + f), y = slurp(b + f);
        CHECK(!x.empty());
        CHECK(x == y);
    }
}

TEST_CASE(
    "CLI units: conflicts, missing flags and out-of-range conversions are usage errors, nothing written",
    "[cli][units]") {
    struct Case {
        std::string args;
        std::vector<std::string> names; // each must appear in the message
    };
    const std::string m = " --theta 90 --i 1", vf = " --amplitude 0.7 --frequency 60";
    const std::vector<Case> cases{
        // --zeta / --vb
        {"ratio --zeta 0.3 --vb 0.1" + vf + " --rdisp 2" + m, {"--zeta", "--vb", "not both"}},
        {"ratio --vb 0.1 --frequency 60 --rdisp 2" + m, {"--vb", "--amplitude", "--frequency", "2 pi f A"}},
        {"ratio --vb 0.1 --amplitude 0.7 --rdisp 2" + m, {"--vb", "--frequency"}},
        {"ratio --rdisp 2" + vf + m, {"--zeta", "--vb", "required"}},
        {"ratio --vb 30" + vf + " --rdisp 2" + m,
         {"--vb 30 m/s", "--amplitude 0.7", "--frequency 60", "113.68", "[0, 100]"}},
        {"ratio --vb -1" + vf + " --rdisp 2" + m, {"--vb"}},
        {"ratio --vb nan" + vf + " --rdisp 2" + m, {"--vb"}},
        {"ratio --vb 1e7" + vf + " --rdisp 2" + m, {"--vb"}},
        {"ratio --vb 1 --amplitude 0 --frequency 60 --rdisp 2" + m, {"--amplitude"}},
        {"ratio --vb 1 --amplitude 0.7 --frequency inf --rdisp 2" + m, {"--frequency"}},
        // A conversion outside the doubles (v_v underflows): a usage error, with and without --vb.
        {"ratio --vb 1 --amplitude 1e-300 --frequency 1e-300 --rdisp 2" + m,
         {"--vb", "--amplitude", "--frequency"}},
        {"ratio --zeta 1 --amplitude 1e-300 --frequency 1e-300 --rdisp 2" + m,
         {"--amplitude", "--frequency"}},
        // --rdisp / --zss
        {"ratio --zeta 0.3 --rdisp 2 --zss 0.35 --amplitude 0.7" + m, {"--rdisp", "--zss", "not both"}},
        {"ratio --zeta 0.3 --zss 0.35" + m, {"--zss", "--amplitude", "A/z_ss"}},
        {"ratio --zeta 0.3 --amplitude 0.7" + m, {"--rdisp", "--zss", "Dahl"}},
        {"ratio --zeta 0.3 --zss 0.00001 --amplitude 0.7" + m,
         {"--zss", "--amplitude", "70000", "(0, 10000]"}},
        {"ratio --zeta 0.3 --zss 0 --amplitude 0.7" + m, {"--zss"}},
        {"ratio --model rigid --zeta 0.3 --rdisp 2 --zss 1 --amplitude 1 --theta 0", {"--rdisp", "--zss"}},
        // sweep
        {"sweep --zeta 0:1:3 --vb 0:0.1:3" + vf + " --rdisp 2" + m, {"--zeta", "--vb", "not both"}},
        {"sweep --vb 0:30:3" + vf + " --rdisp 2" + m, {"--vb", "113.68", "[0, 100]"}},
        {"sweep --vb 0:0.1:3 --amplitude 0.7 --rdisp 2" + m, {"--vb", "--frequency"}},
        {"sweep --vb 0:0.1" + vf + " --rdisp 2" + m, {"--vb"}},
        {"sweep --vb 0.2:0.1:3" + vf + " --rdisp 2" + m, {"--vb"}},
        {"sweep --rdisp 2" + m, {"--zeta", "--vb"}},
        {"sweep --zeta 0:1:3 --zss 0.35,abc --amplitude 0.7" + m, {"--zss"}},
        {"sweep --zeta 0:1:3 --zss 0.35,1e-6 --amplitude 0.7" + m, {"--zss", "(0, 10000]"}},
        {"sweep --zeta 0:1:3 --zss 0.35" + m, {"--zss", "--amplitude"}},
        {"sweep --zeta 0:1:3 --rdisp 2 --zss 0.35 --amplitude 0.7" + m, {"--rdisp", "--zss"}},
        {"sweep --zeta 0:1:3" + m, {"--rdisp", "--zss"}},
        // trace
        {"trace --zeta 0.3 --vb 0.1" + vf + " --rdisp 2" + m, {"--zeta", "--vb"}},
        {"trace --vb 0.1 --amplitude 0.7 --rdisp 2" + m, {"--vb", "--frequency"}},
        {"trace --zeta 0.3 --zss 0.35" + m, {"--zss", "--amplitude"}},
    };
    for (const Case& c : cases) {
        const std::string out = scratch_dir() + "/units-never.csv";
        CAPTURE(c.args);
        const Run r = run(c.args + " --out " + out);
        check_usage_error(r, c.names);
        CHECK(::access(out.c_str(), F_OK) != 0);
    }
    // render: nothing in the output directory.
    const std::string dir = scratch_dir() + "/units-render-never";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const std::vector<Case> render_cases{
        {"--figure scene --vb 0.1 --theta 90 --zss 0.35 --i 1", {"--vb", "--amplitude"}},
        {"--figure scene --theta 90 --zss 0.35 --amplitude 0.7 --i 1", {"--zeta or --vb"}},
        {"--figure scene --vb 0.1" + vf + " --theta 90 --i 1", {"--rdisp or --zss"}},
        {"--figure scene --zeta 0.3 --vb 0.1" + vf + " --theta 90 --rdisp 2 --i 1", {"--zeta", "--vb"}},
        {"--figure scene --vb 30" + vf + " --theta 90 --rdisp 2 --i 1", {"--vb", "[0, 100]"}},
        {"--figure map --rdisp 2 --zss 0.35 --amplitude 0.7", {"--rdisp", "--zss"}},
        {"--figure map --zss 0.35", {"--zss", "--amplitude"}},
        {"--figure map --zss 1e-6 --amplitude 0.7", {"--zss", "(0, 10000]"}},
    };
    for (const Case& c : render_cases) {
        CAPTURE(c.args);
        const Run r = run("render " + c.args + " --size 320x240 --out " + dir);
        check_usage_error(r, c.names);
    }
    CHECK(slurp_dir_empty(dir));
}

TEST_CASE("CLI units: gui takes --vb/--amplitude/--frequency/--zss for its initial values",
          "[cli][units][gui]") {
    const std::string shot = scratch_dir() + "/units-gui.png";
    const Run ok =
        run("gui --headless --frames 2 --vb 0.1 --amplitude 0.7 --frequency 60 --zss 0.35 --theta 90");
    CHECK(ok.code == 0);
    struct Case {
        const char* args;
        std::vector<std::string> names;
    };
    for (const Case& c : {
             Case{"--vb 0.1", {"--vb", "--amplitude", "--frequency"}},
             Case{"--zeta 0.3 --vb 0.1 --amplitude 0.7 --frequency 60", {"--zeta", "--vb"}},
             Case{"--vb 30 --amplitude 0.7 --frequency 60", {"--vb", "[0, 100]"}},
             Case{"--zss 0.35", {"--zss", "--amplitude"}},
             Case{"--rdisp 2 --zss 0.35 --amplitude 0.7", {"--rdisp", "--zss"}},
             Case{"--amplitude 1e-300 --frequency 1e-300", {"--amplitude", "--frequency"}},
         }) {
        CAPTURE(c.args);
        const Run r = run(std::string("gui --headless --frames 2 --screenshot ") + shot + " " + c.args);
        check_usage_error(r, c.names);
        CHECK(::access(shot.c_str(), F_OK) != 0);
    }
}

TEST_CASE("CLI units: fit keeps --amplitude/--frequency for a vb column", "[cli][units][fit]") {
    const std::string data = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta0_rdisp1_i1_vb.csv";
    const Run r = run("fit --data " + data + " --amplitude 0.7 --frequency 60 --format json");
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["best"]["rdisp"].get<double>() == Approx(1).epsilon(0.02));
    CHECK(j["best"]["zss_um"].get<double>() == Approx(0.7 / j["best"]["rdisp"].get<double>()));
    check_usage_error(run("fit --data " + data + " --amplitude 0.7"), {"frequency"});
}

// ---- Numerical failure: exit status 3, output still written, every result with its status ----------------
// FV_TEST_FORCE_STATUS=REASON[@ZETA] (app/cli/test_hook.hpp) marks results as failed after they are computed,
// so these tests do not depend on parameters where the solver happens to fail.

namespace {

const char* kForceNotConverged = "FV_TEST_FORCE_STATUS=not_converged";

} // namespace

TEST_CASE("CLI status: --help documents the exit statuses, 3 included", "[cli][status]") {
    for (const char* a : {"--help", "ratio --help", "sweep --help", "render --help", "fit --help"}) {
        CAPTURE(a);
        const Run r = run(a);
        CHECK(r.code == 0);
        CHECK(r.out.find("Exit status: 0 success") != std::string::npos);
        CHECK(r.out.find("2 usage error") != std::string::npos);
        CHECK(r.out.find("3 numerical failure") != std::string::npos);
    }
}

TEST_CASE("CLI status: a normal run exits 0 with status ok everywhere", "[cli][status]") {
    const Run txt = run(std::string("ratio ") + kGood);
    REQUIRE(txt.code == 0);
    CHECK(txt.err.empty());
    CHECK(report_line(txt.out, "status ") == "status        ok");
    const Run csv = run(std::string("ratio ") + kGood + " --format csv");
    REQUIRE(csv.code == 0);
    CHECK(parse_csv(csv.out).at(0).at("status") == "ok");
    // Ordinary parameters (zeta = 0 and other edges of the model are the solver tests' business).
    const Run sw = run("sweep --zeta 0.1:1.5:8 --theta 0,60,90 --rdisp 2,5 --i 0,1");
    REQUIRE(sw.code == 0);
    CHECK(sw.err.empty());
    const auto rows = parse_csv(sw.out);
    REQUIRE(rows.size() == 8 * 3 * 2 * 2);
    for (const auto& row : rows) CHECK(row.at("status") == "ok");
    const Run js = run("sweep --zeta 0.1:1.5:4 --theta 0,90 --rdisp 2 --i 1 --scheme paper --format json");
    REQUIRE(js.code == 0);
    for (const auto& row : nlohmann::json::parse(js.out)) CHECK(row["status"] == "ok");
    const Run rig = run("sweep --model rigid --zeta 0:2:5 --theta 0,45");
    REQUIRE(rig.code == 0);
    for (const auto& row : parse_csv(rig.out)) CHECK(row.at("status") == "ok");
    const Run tr = run("trace --zeta 0.3 --theta 60 --rdisp 2 --i 1 --format json");
    REQUIRE(tr.code == 0);
    CHECK(nlohmann::json::parse(tr.out)["status"] == "ok");
    // The hook set to nothing changes nothing.
    CHECK(run(std::string("ratio ") + kGood, "FV_TEST_FORCE_STATUS=").code == 0);
    // The shipped executable has no test hooks: the variable, even a bad value, is ignored.
    const std::string o = scratch_dir() + "/shipped";
    const int status = std::system(("env FV_TEST_FORCE_STATUS=not_converged " + std::string(FV_EXE) +
                                    " ratio " + kGood + " --format csv >" + o + " 2>&1 </dev/null")
                                       .c_str());
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(parse_csv(slurp(o)).at(0).at("status") == "ok");
    CHECK(std::system(("env FV_TEST_FORCE_STATUS=bogus " + std::string(FV_EXE) + " ratio " + kGood +
                       " >/dev/null 2>&1 </dev/null")
                          .c_str()) == 0);
}

TEST_CASE("CLI status: ratio writes a failed result with its status and exits 3", "[cli][status]") {
    const Run txt = run(std::string("ratio ") + kGood, kForceNotConverged);
    CHECK(txt.code == 3);
    CHECK(!report_line(txt.out, "r_x ").empty());
    CHECK(
        report_line(txt.out, "status ").rfind("status        not_converged (steady state not verified", 0) ==
        0);
    CHECK(lines(txt.err) == 1);
    CHECK(txt.err.find("numerical failure: not_converged at zeta=0.3 theta=45 deg rdisp=2 i=1") !=
          std::string::npos);

    const Run csv =
        run(std::string("ratio ") + kGood + " --format csv", "FV_TEST_FORCE_STATUS=integration_failed");
    CHECK(csv.code == 3);
    auto rows = parse_csv(csv.out);
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].at("status") == "integration_failed");
    CHECK(field(rows[0], "r_x") > 0); // the best value is kept
    CHECK(lines(csv.err) == 1);
    CHECK(csv.err.find("integration_failed") != std::string::npos);

    // Not finite: empty cells (null in JSON), never "nan".
    const std::string out = scratch_dir() + "/status-ratio.csv";
    std::remove(out.c_str());
    const Run nf =
        run(std::string("ratio ") + kGood + " --format csv --out " + out, "FV_TEST_FORCE_STATUS=non_finite");
    CHECK(nf.code == 3);
    rows = parse_csv(slurp(out));
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].at("status") == "non_finite");
    CHECK(rows[0].at("r_x").empty());
    CHECK(rows[0].at("r_y").empty());
    const Run js = run(std::string("ratio ") + kGood + " --format json", "FV_TEST_FORCE_STATUS=non_finite");
    CHECK(js.code == 3);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(j["status"] == "non_finite");
    CHECK(j["r_x"].is_null());

    // The rigid model goes through the same door.
    const Run rig = run("ratio --model rigid --zeta 0.5 --theta 0 --format json", kForceNotConverged);
    CHECK(rig.code == 3);
    CHECK(nlohmann::json::parse(rig.out)["status"] == "not_converged");

    // A misspelt hook is a usage error, not a silent pass.
    const Run bad = run(std::string("ratio ") + kGood, "FV_TEST_FORCE_STATUS=not_convergd");
    CHECK(bad.code == 2);
    CHECK(bad.out.empty());
}

TEST_CASE("CLI status: sweep writes every row with a status column and exits 3 if any failed",
          "[cli][status]") {
    const std::string out = scratch_dir() + "/status-sweep.csv";
    std::remove(out.c_str());
    const Run r = run("sweep --zeta 0.1:0.5:3 --theta 0,90 --rdisp 2 --i 0,1 --out " + out,
                      "FV_TEST_FORCE_STATUS=not_converged@0.3");
    CHECK(r.code == 3);
    CHECK(r.out.empty());
    const auto rows = parse_csv(slurp(out));
    REQUIRE(rows.size() == 3 * 2 * 2);
    int failed = 0;
    for (const auto& row : rows) {
        CAPTURE(row.at("zeta"));
        const bool at = field(row, "zeta") == Approx(0.3);
        CHECK(row.at("status") == (at ? "not_converged" : "ok"));
        CHECK(!row.at("r_x").empty()); // failed rows keep their best values
        failed += at;
    }
    CHECK(failed == 4);
    // One line per failed row, then the count.
    CHECK(lines(r.err) == 5);
    CHECK(r.err.find("failed: not_converged at zeta=0.3 theta=90 deg rdisp=2 i=1") != std::string::npos);
    CHECK(r.err.find("numerical failure: 4 of 12 rows failed (not_converged 4)") != std::string::npos);

    // JSON rows carry "status" too; non-finite values are null.
    const Run js = run("sweep --zeta 0.1:0.5:3 --theta 90 --rdisp 2 --i 1 --format json",
                       "FV_TEST_FORCE_STATUS=non_finite@0.5");
    CHECK(js.code == 3);
    const auto arr = nlohmann::json::parse(js.out);
    REQUIRE(arr.size() == 3);
    CHECK(arr[0]["status"] == "ok");
    CHECK(arr[1]["status"] == "ok");
    CHECK(arr[2]["status"] == "non_finite");
    CHECK(arr[2]["r_x"].is_null());
    CHECK(arr[1]["r_x"].is_number());

    // Many failures: a few lines and how many more, not one line per row.
    const Run many = run("sweep --model rigid --zeta 0:1:40 --theta 0,90", kForceNotConverged);
    CHECK(many.code == 3);
    CHECK(parse_csv(many.out).size() == 80);
    CHECK(lines(many.err) == 12);
    CHECK(many.err.find("... and 70 more failed") != std::string::npos);
    CHECK(many.err.find("80 of 80 rows failed") != std::string::npos);
}

TEST_CASE("CLI status: trace writes the period and exits 3 when its steady state failed", "[cli][status]") {
    const Run r = run("trace --zeta 0.3 --theta 60 --rdisp 2 --i 1", kForceNotConverged);
    CHECK(r.code == 3);
    CHECK(parse_csv(r.out).size() == 1024);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find("not_converged") != std::string::npos);
    const Run js = run("trace --zeta 0.3 --theta 60 --rdisp 2 --i 1 --format json", kForceNotConverged);
    CHECK(js.code == 3);
    CHECK(nlohmann::json::parse(js.out)["status"] == "not_converged");
}

TEST_CASE("CLI status: render writes every figure, names the failed points and exits 3",
          "[cli][status][render]") {
    const std::string dir = scratch_dir() + "/status-render";
    REQUIRE(std::system(("mkdir -p " + dir + " && rm -f " + dir + "/*").c_str()) == 0);
    const Run r = run("render --figure fig5,fig15 --size 400x300 --out " + dir,
                      "FV_TEST_FORCE_STATUS=not_converged@0.5");
    CHECK(r.code == 3);
    for (const char* f : {"/fig5.png", "/fig5.csv", "/fig15.png", "/fig15.csv"}) {
        CAPTURE(f);
        CHECK(::access((dir + f).c_str(), F_OK) == 0);
    }
    const auto rows = parse_csv(slurp(dir + "/fig5.csv"));
    REQUIRE(!rows.empty());
    int failed = 0;
    for (const auto& row : rows) failed += row.at("status") == "not_converged";
    CHECK(failed == 5); // five angles at zeta = 0.5
    CHECK(r.err.find("fig5: failed: not_converged at zeta=0.5") != std::string::npos);
    CHECK(r.err.find("numerical failure: 1 of 2 figures have failed points (fig5: 5 of") !=
          std::string::npos);
    CHECK(r.err.find("fig15") == std::string::npos);

    // Without failures the same figures exit 0, every ratio row ok.
    const Run good = run("render --figure fig5 --size 400x300 --out " + dir);
    CHECK(good.code == 0);
    for (const auto& row : parse_csv(slurp(dir + "/fig5.csv"))) CHECK(row.at("status") == "ok");
}

TEST_CASE("CLI status: fit exits 3 when its model evaluations failed, output written", "[cli][status][fit]") {
    const std::string out = scratch_dir() + "/status-fit.json";
    std::remove(out.c_str());
    const std::string data = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";
    const Run r = run("fit --data " + data + " --i 0 --format json --out " + out, kForceNotConverged);
    CHECK(r.code == 3);
    const auto j = nlohmann::json::parse(slurp(out));
    CHECK(j["status"] == "not_converged");
    CHECK(j["best"]["unsteady"].get<int>() > 0);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find("fit: not_converged (i = 0: ") != std::string::npos);
    const Run ok = run("fit --data " + data + " --i 0 --format json");
    CHECK(ok.code == 0);
    CHECK(nlohmann::json::parse(ok.out)["status"] == "ok");
    const Run txt = run("fit --data " + data + " --i 0");
    CHECK(txt.code == 0);
    CHECK(report_line(txt.out, "status ") == "status        ok");
}

// Which steady state (docs/model.md): --start names the history; where two stable states coexist (theta = 90
// deg, rdisp = 0.001, i = 10: the small state from rest, the saturated one r_x = 1 - r^2/4 from sliding),
// the text counts them and JSON lists both with the start that reaches each.
TEST_CASE("CLI: --start names the history and coexisting states are listed", "[cli][states]") {
    const std::string point = "ratio --zeta 0.001 --theta 90 --rdisp 0.001 --i 10";
    const Run bad = run(point + " --start moving");
    CHECK(bad.code == 2);
    CHECK(bad.err.find("--start") != std::string::npos);
    const Run rest = run(point);
    REQUIRE(rest.code == 0);
    CHECK(rest.out.find("start         rest") != std::string::npos);
    CHECK(rest.out.find("2 stable steady states") != std::string::npos);
    const Run js = run(point + " --start sliding --format json");
    REQUIRE(js.code == 0);
    const auto j = nlohmann::json::parse(js.out);
    CHECK(j.at("start") == "sliding");
    CHECK(j.at("start_reaches") == true);
    CHECK(j.at("r_x").get<double>() == Approx(1 - 0.25e-6).margin(1e-9));
    REQUIRE(j.at("states").size() == 2);
    const auto& small = j.at("states").at(0);
    const auto& saturated = j.at("states").at(1);
    CHECK(small.at("reached_from") == nlohmann::json::array({"rest"}));
    CHECK(saturated.at("reached_from") == nlohmann::json::array({"sliding"}));
    CHECK(saturated.at("r_x").get<double>() == Approx(1 - 0.25e-6).margin(1e-9));
    CHECK(saturated.at("slow") == true); // on the circle with i > 1: |mu| = 1, approached algebraically
}
