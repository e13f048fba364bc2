// Sessions and share links through the real executable:
// - a session saved in the middle of a scripted run and opened again shows the same pixels as a new run
//   started from that file with --session (both restart the simulation from the session's state);
// - --link gives the same screen as the equivalent flags;
// - bad sessions, links and save paths exit 2 with one line naming where and why, nothing written.
#include "tools/image_files.hpp"
#include "tools/run_command.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace {

const std::string& root() {
    return fv::test::scratch_dir("fv-gui-session");
}

std::string in_scratch(const std::string& name) {
    return root() + "/" + name;
}

// `frictionviz gui ARGS` run in the scratch directory (relative paths are its files).
fv::test::Run run_gui(const std::string& args) {
    return fv::test::run_command("cd '" + root() + "' && " + FV_EXE + " gui " + args, root());
}

bool exists(const std::string& p) {
    return ::access(p.c_str(), F_OK) == 0;
}

void write(const std::string& name, const std::string& text) {
    std::ofstream(in_scratch(name)) << text;
}

std::string read(const std::string& path) {
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

bool same_pixels(const std::string& a, const std::string& b) {
    const fv::gfx::Image x = fv::test::load_png(a), y = fv::test::load_png(b);
    return x.width == y.width && x.height == y.height && x.rgba == y.rgba;
}

int lines(const std::string& s) {
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

} // namespace

TEST_CASE("gui session: saved mid-run and opened again, the same pixels as a run started from the file",
          "[gui][session][long]") {
    // The starting session moves the view, which no script action does, and names its data file relative
    // to itself.
    write("data.csv", read(std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv"));
    write("start.json", R"({
  "version": 1,
  "zeta": 0.2, "theta": 45, "rdisp": 3, "i": 0.5,
  "speed": 0.8,
  "view": {"zoom": 1.6, "pan": [0.4, -0.3], "follow": false, "trail_periods": 2.5},
  "data": "data.csv"
})");
    // Edits at several frames, the session saved at frame 10 and opened at 11: the simulation restarts
    // there, as it does in a run that starts from the file. (The map panel is left out: each map takes
    // seconds; session JSON and AppState tests cover the panel.)
    write("edits.txt", "2 zeta 0.4\n4 theta 75\n5 amplitude 1.2\n6 frequency 40\n7 rdisp 4\n8 i 1\n8 pin\n"
                       "9 speed 1.5\n10 save-session saved.json\n11 open-session saved.json\n");
    const int after = 14; // frames shown after the session is opened
    REQUIRE(run_gui("--headless --session start.json --script edits.txt --frames " +
                    std::to_string(11 + after) + " --screenshot saved-mid-run.png")
                .code == 0);
    const std::string saved = read(in_scratch("saved.json"));
    INFO(saved);
    // The edits and what the start gave are both in the file (the view only came from start.json).
    // (zeta followed A and f at the same v_b.)
    for (const char* kv : {"\"theta\": 75.0", "\"rdisp\": 4.0", "\"i\": 1.0", "\"amplitude_um\": 1.2",
                           "\"frequency_khz\": 40.0", "\"speed\": 1.5", "\"zoom\": 1.6", "\"follow\": false",
                           "\"trail_periods\": 2.5"})
        CHECK(saved.find(kv) != std::string::npos);
    CHECK(saved.find("\"data\": \"" + in_scratch("data.csv") + "\"") != std::string::npos);
    CHECK(saved.find("\"label\": \"Dahl, θ = 75°, r_{disp} = 4, i = 1\"") != std::string::npos); // the pin

    REQUIRE(run_gui("--headless --session saved.json --frames " + std::to_string(after) +
                    " --screenshot reopened.png")
                .code == 0);
    CHECK(same_pixels(in_scratch("saved-mid-run.png"), in_scratch("reopened.png")));

    // The comparison sees the session: another zoom in the same file is another picture.
    std::string zoomed = saved;
    zoomed.replace(zoomed.find("\"zoom\": 1.6"), 11, "\"zoom\": 1.2");
    write("zoomed.json", zoomed);
    REQUIRE(run_gui("--headless --session zoomed.json --frames " + std::to_string(after) +
                    " --screenshot zoomed.png")
                .code == 0);
    CHECK_FALSE(same_pixels(in_scratch("zoomed.png"), in_scratch("reopened.png")));
}

TEST_CASE("gui --link: the same screen as the equivalent flags, also as a whole URL", "[gui][link]") {
    const std::string frames = "--headless --frames 12 --screenshot ";
    REQUIRE(run_gui(frames + "flags.png --zeta 0.45 --theta 30 --rdisp 8 --i 0 --model dahl").code == 0);
    REQUIRE(run_gui(frames + "link.png --link '?zeta=0.45&theta=30&rdisp=8&i=0&model=dahl'").code == 0);
    REQUIRE(run_gui(frames +
                    "url.png --link 'https://example.org/frictionviz/?i=0&rdisp=8&model=dahl&theta=30"
                    "&zeta=0.45#top'")
                .code == 0);
    CHECK(same_pixels(in_scratch("flags.png"), in_scratch("link.png")));
    CHECK(same_pixels(in_scratch("flags.png"), in_scratch("url.png")));
    REQUIRE(run_gui(frames + "other.png --link '?zeta=0.45&theta=31&rdisp=8&i=0&model=dahl'").code == 0);
    CHECK_FALSE(same_pixels(in_scratch("flags.png"), in_scratch("other.png")));
    // The rigid model from a link, against --model rigid.
    REQUIRE(run_gui(frames + "rigid-flags.png --model rigid --zeta 0.3").code == 0);
    REQUIRE(run_gui(frames + "rigid-link.png --link 'model=rigid&zeta=0.3'").code == 0);
    CHECK(same_pixels(in_scratch("rigid-flags.png"), in_scratch("rigid-link.png")));
}

TEST_CASE("gui --session/--link: a bad file or link exits 2 with one line naming where and why, nothing "
          "written",
          "[gui][session][link][cli]") {
    struct Case {
        std::string args, says;
    };
    write("syntax.json", "{\n  \"version\": 1,\n  \"zeta\": 0.3\n  \"theta\": 60\n}\n");
    write("range.json", "{\n  \"version\": 1,\n  \"rdisp\": 20000\n}\n");
    write("type.json", "{\n  \"version\": 1,\n  \"speed\": \"fast\"\n}\n");
    write("model.json", "{\n  \"version\": 1,\n  \"model\": \"coulomb\"\n}\n");
    write("start.json", "{\n  \"version\": 1,\n  \"start\": \"moving\"\n}\n");
    write("unknown.json", "{\n  \"version\": 1,\n  \"zetta\": 0.3\n}\n");
    write("no-data.json", "{\n  \"version\": 1,\n  \"data\": \"missing.csv\"\n}\n");
    write("bad-save.txt", "3 save-session no/such/dir/s.json\n");
    write("good.json", "{\"version\": 1}\n");
    for (const Case& c : {
             Case{"--session syntax.json", "--session: syntax.json:4:9: not valid JSON: syntax error"},
             Case{"--session range.json",
                  "--session: range.json:3:12: rdisp = 20000 is out of range; allowed: rdisp in (0, 10000]"},
             Case{"--session type.json", "--session: type.json:3:12: speed: expected a number, got a string"},
             Case{"--session model.json",
                  "--session: model.json:3:12: model = \"coulomb\"; allowed: dahl, rigid"},
             Case{"--session start.json",
                  "--session: start.json:3:12: start = \"moving\"; allowed: rest, sliding"},
             Case{"--session unknown.json", "--session: unknown.json:3:3: unknown key \"zetta\"; allowed:"},
             Case{"--session no-data.json",
                  "--session: no-data.json:3:11: data: missing.csv: does not exist"},
             Case{"--session nothing-here.json", "--session: nothing-here.json: does not exist"},
             Case{"--session good.json --zeta 0.3", "excludes"},
             Case{"--session good.json --link zeta=1", "excludes"},
             Case{"--link '?zeta=0.3&color=red'",
                  "--link: column 11: unknown key 'color'; allowed: zeta, theta, "
                  "rdisp, i, model"},
             Case{"--link '?zeta=0.3&theta=sixty'",
                  "--link: column 17: theta = 'sixty' is not a decimal number"},
             Case{"--link '?zeta=0.3&i=12'",
                  "--link: column 13: i = 12 is out of range; allowed: i in [0, 10]"},
             Case{"--link '?zeta=0.3&zeta=0.4'", "--link: column 11: 'zeta' is given twice"},
             Case{"--link ''", "--link: column 1: no parameters"},
             Case{"--link zeta=1 --theta 20", "excludes"},
             // The vibration: refused as --amplitude and --frequency refuse it, and not from two places.
             Case{"--link '?zeta=0.3&amplitude=0'",
                  "--link: column 21: amplitude = 0 is out of range; allowed: amplitude in (0, 1e+06]"},
             Case{"--link '?zeta=0.3&amplitude=2e6'",
                  "--link: column 21: amplitude = 2e6 is out of range; allowed: amplitude in (0, 1e+06]"},
             Case{"--link '?zeta=0.3&frequency=-40'",
                  "--link: column 21: frequency = -40 is out of range; allowed: frequency in (0, 1e+06]"},
             Case{"--link '?zeta=0.3&frequency=fast'",
                  "--link: column 21: frequency = 'fast' is not a decimal number; allowed: frequency in"},
             Case{"--amplitude 2 --link '?zeta=0.3&amplitude=1'",
                  "--amplitude and --link's amplitude= both set the amplitude; give one of them"},
             Case{"--link '?zeta=0.3&rdisp=1e-9&amplitude=1000'",
                  "--link amplitude=1000: rdisp = 1e-09 with amplitude 1000 um gives z_ss"},
             Case{"--link '?compare=yes'", "--link: column 10: compare = 'yes'; allowed: 1, 0"},
             Case{"--link '?compare=0&b.theta=0'", "--link: column 2: compare=0 turns compare mode off, yet"},
             Case{"--script bad-save.txt", "bad-save.txt:1: save-session "},
         }) {
        const fv::test::Run r = run_gui("--headless --frames 3 --screenshot never.png " + c.args);
        INFO(c.args << " -> " << r.err);
        CHECK(r.code == 2);
        CHECK(lines(r.err) == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
        CHECK_FALSE(exists(in_scratch("never.png")));
    }
}

TEST_CASE("gui --link: the units and the view through a link, as the app's state and as flags show them",
          "[gui][link]") {
    const std::string frames = "--headless --frames 4 --screenshot ";
    // The app opened on a link with every new key saves a session that holds them (the app's own state).
    write("save.txt", "2 save-session linked.json\n");
    REQUIRE(run_gui(frames +
                    "all.png --script save.txt --link '?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl&amplitude=1"
                    "&frequency=40&play=0&trail=3&zoom=2&pan=0.5,-1&follow=0'")
                .code == 0);
    const std::string saved = read(in_scratch("linked.json"));
    INFO(saved);
    for (const char* kv : {"\"amplitude_um\": 1.0", "\"frequency_khz\": 40.0", "\"playing\": false",
                           "\"zoom\": 2.0", "\"pan\": [0.5, -1.0]", "\"follow\": false",
                           "\"trail_periods\": 3.0", "\"zeta\": 0.3", "\"theta\": 60.0"})
        CHECK(saved.find(kv) != std::string::npos);
    // The units from the link show as the flags' do (the panel's A, f, v_v, v_b, z_ss), and not as the
    // defaults.
    REQUIRE(
        run_gui(frames + "units-link.png --link '?zeta=0.3&theta=60&rdisp=5&i=1&amplitude=1&frequency=40'")
            .code == 0);
    REQUIRE(run_gui(frames + "units-flags.png --link '?zeta=0.3&theta=60&rdisp=5&i=1' --amplitude 1 "
                             "--frequency 40")
                .code == 0);
    REQUIRE(run_gui(frames + "units-default.png --link '?zeta=0.3&theta=60&rdisp=5&i=1'").code == 0);
    CHECK(same_pixels(in_scratch("units-link.png"), in_scratch("units-flags.png")));
    CHECK_FALSE(same_pixels(in_scratch("units-link.png"), in_scratch("units-default.png")));
    // play=0: paused, so more frames show the same picture; running (the default), they do not.
    for (const char* n : {"3", "9"}) {
        REQUIRE(run_gui(std::string("--headless --frames ") + n + " --screenshot paused-" + n +
                        ".png --link '?zeta=0.3&play=0'")
                    .code == 0);
        REQUIRE(run_gui(std::string("--headless --frames ") + n + " --screenshot running-" + n +
                        ".png --link '?zeta=0.3'")
                    .code == 0);
    }
    CHECK(same_pixels(in_scratch("paused-3.png"), in_scratch("paused-9.png")));
    CHECK_FALSE(same_pixels(in_scratch("running-3.png"), in_scratch("running-9.png")));
    // A view value out of its range: the link still opens, the value ignored with one notice naming the key
    // and its range (as speed=100 is).
    const fv::test::Run r = run_gui(frames + "zoom.png --link '?zeta=0.3&zoom=100'");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.err == "frictionviz: --link: column 16: zoom = 100 is out of range; allowed: zoom in [0.05, 20]; "
                   "ignored\n");
}
