// Session files (app/gui/session.hpp) without a window: every field through JSON and back, defaults for
// missing keys, each refusal pointing at its line and column, and opening one in the app (AppState::sync):
// the state replaced and the simulation restarted, or, for a bad file, nothing changed. The pixel round
// trip through the real executable is in test_gui_session.cpp.
#include "gui/app_state.hpp"
#include "gui/lessons.hpp"
#include "gui/script.hpp"
#include "gui/session.hpp"
#include "gui/session_link.hpp"

#include "fv/live_panels.hpp" // ratio_zeta_max
#include "fv/param_ranges.hpp"
#include "fv/pinned_curve.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace fv;
using namespace fv::app;

namespace {

const std::string& scratch() {
    static const std::string dir = [] {
        char tmpl[] = "/tmp/fv-session-XXXXXX";
        return std::string(::mkdtemp(tmpl));
    }();
    return dir;
}

std::string write(const std::string& name, const std::string& text) {
    const std::string path = scratch() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

std::string read(const std::string& path) {
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

const std::string kData = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";

// Every field away from its default, so that a field lost on the way shows.
Session unusual() {
    Session s;
    s.model = Model::rigid;
    s.params = Params{0.731, 37.5 * kPi / 180, 12.5, 0.25};
    s.start = Start::sliding;
    s.amplitude_um = 1.3;
    s.frequency_khz = 45;
    s.speed = 2.5;
    s.playing = false;
    s.panel = LowerPanel::map;
    s.view.zoom = 2.5;
    s.view.pan = Vec2(0.3, -1.25);
    s.view.follow = false;
    s.view.trail_periods = 3.5;
    s.view.frame = FrameChoice::ground;
    s.presentation = true;
    s.lesson = 4;
    s.pins.push_back({"Dahl, θ = 60°, r_{disp} = 2, i = 0",
                      {0, 0.5, 1.0 / 3},
                      {0.1, std::nan(""), 0.7},
                      PinSource{Model::dahl, kPi / 3, 2, 0, Start::sliding}});
    s.pins.push_back({"rigid, θ = 90°", {0.25}, {0.2 + 0.1}});
    s.data_file = kData;
    return s;
}

void check_same(const Session& a, const Session& b) {
    CHECK(a.model == b.model);
    CHECK(a.start == b.start);
    CHECK(a.params.zeta == b.params.zeta);
    CHECK(a.params.theta == b.params.theta);
    CHECK(a.params.rdisp == b.params.rdisp);
    CHECK(a.params.i == b.params.i);
    CHECK(a.amplitude_um == b.amplitude_um);
    CHECK(a.frequency_khz == b.frequency_khz);
    CHECK(a.speed == b.speed);
    CHECK(a.playing == b.playing);
    CHECK(a.panel == b.panel);
    CHECK(a.view.zoom == b.view.zoom);
    CHECK(a.view.pan.x() == b.view.pan.x());
    CHECK(a.view.pan.y() == b.view.pan.y());
    CHECK(a.view.follow == b.view.follow);
    CHECK(a.view.trail_periods == b.view.trail_periods);
    CHECK(a.view.frame == b.view.frame);
    CHECK(a.presentation == b.presentation);
    CHECK(a.lesson == b.lesson);
    REQUIRE(a.pins.size() == b.pins.size());
    for (std::size_t k = 0; k < a.pins.size(); ++k) {
        CHECK(a.pins[k].label == b.pins[k].label);
        CHECK(a.pins[k].zeta == b.pins[k].zeta);
        REQUIRE(a.pins[k].source.has_value() == b.pins[k].source.has_value());
        if (a.pins[k].source) {
            CHECK(a.pins[k].source->model == b.pins[k].source->model);
            CHECK(a.pins[k].source->theta == b.pins[k].source->theta);
            CHECK(a.pins[k].source->rdisp == b.pins[k].source->rdisp);
            CHECK(a.pins[k].source->i == b.pins[k].source->i);
            CHECK(a.pins[k].source->start == b.pins[k].source->start);
        }
        REQUIRE(a.pins[k].rx.size() == b.pins[k].rx.size());
        for (std::size_t n = 0; n < a.pins[k].rx.size(); ++n) // NaN: a gap on both sides
            CHECK((a.pins[k].rx[n] == b.pins[k].rx[n] ||
                   (std::isnan(a.pins[k].rx[n]) && std::isnan(b.pins[k].rx[n]))));
    }
    CHECK(a.data_file == b.data_file);
}

std::string refusal(const std::string& text) {
    try {
        parse_session(text, "s.json");
    } catch (const SessionError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("session JSON: every field goes through the file and back unchanged", "[gui][session]") {
    const Session s = unusual();
    // Each field differs from the default: a field the writer or the reader dropped would come back as it.
    const Session d;
    CHECK(s.model != d.model);
    CHECK(s.start != d.start);
    CHECK(s.params.zeta != d.params.zeta);
    CHECK(s.params.theta != d.params.theta);
    CHECK(s.params.rdisp != d.params.rdisp);
    CHECK(s.params.i != d.params.i);
    CHECK(s.amplitude_um != d.amplitude_um);
    CHECK(s.frequency_khz != d.frequency_khz);
    CHECK(s.speed != d.speed);
    CHECK(s.playing != d.playing);
    CHECK(s.panel != d.panel);
    CHECK(s.view.zoom != d.view.zoom);
    CHECK(s.view.pan.x() != d.view.pan.x());
    CHECK(s.view.pan.y() != d.view.pan.y());
    CHECK(s.view.follow != d.view.follow);
    CHECK(s.view.trail_periods != d.view.trail_periods);
    CHECK(s.view.frame != d.view.frame);
    CHECK(s.pins.size() != d.pins.size());
    CHECK(s.presentation != d.presentation);
    CHECK(s.lesson != d.lesson);
    CHECK(s.data_file != d.data_file);

    const std::string text = session_json(s);
    INFO(text);
    check_same(parse_session(text, "s.json"), s);
    // The documented keys, theta in degrees, the panel by name.
    for (const char* key : {"\"version\": 1",
                            "\"model\": \"rigid\"",
                            "\"zeta\": 0.731",
                            "\"theta\": 37.5",
                            "\"rdisp\": 12.5",
                            "\"i\": 0.25",
                            "\"start\": \"sliding\"",
                            "\"amplitude_um\": 1.3",
                            "\"frequency_khz\": 45.0",
                            "\"speed\": 2.5",
                            "\"playing\": false",
                            "\"panel\": \"map\"",
                            "\"zoom\": 2.5",
                            "\"follow\": false",
                            "\"trail_periods\": 3.5",
                            "\"frame\": \"ground\"",
                            "\"data\": \"",
                            "\"pan\": [0.3, -1.25]",
                            "\"presentation\": true",
                            "\"r_x\": [0.1, null, 0.7]",
                            "\"zeta\": [0.25]"})
        CHECK(text.find(key) != std::string::npos);
    // Every panel by its name.
    for (const LowerPanel p : kLowerPanels) {
        Session other = s;
        other.panel = p;
        check_same(parse_session(session_json(other), "s.json"), other);
        CHECK(session_json(other).find(std::string("\"panel\": \"") + panel_name(p) + "\"") !=
              std::string::npos);
    }
    // Numbers that are not short decimals come back bit for bit too.
    Session odd = s;
    odd.params.zeta = 0.1 + 0.2;
    odd.params.theta = 1.0; // radians: 57.29577951308232 degrees
    odd.view.pan = Vec2(1.0 / 3, -2.0 / 3);
    check_same(parse_session(session_json(odd), "s.json"), odd);

    // Through the app: a state started from the session gives the session back.
    AppState app(s);
    Session back = session_of(app.ui());
    CHECK(back.data_file.empty()); // no data given to the app
    back.data_file = s.data_file;
    check_same(back, s);
}

TEST_CASE("session JSON: missing keys take the app's defaults, a relative data path is the session's "
          "neighbour",
          "[gui][session]") {
    check_same(parse_session("{\"version\": 1}", "s.json"), Session{});
    const UiState ui;
    const Session d = parse_session("{\"version\": 1}", "s.json");
    CHECK(d.params.zeta == ui.session.params.zeta);
    CHECK(d.speed == ui.session.speed);
    CHECK(d.view.trail_periods == ui.session.view.trail_periods);
    CHECK(parse_session(R"({"version": 1, "data": "m.csv"})", "dir/sub/s.json").data_file == "dir/sub/m.csv");
    CHECK(parse_session(R"({"version": 1, "data": "../m.csv"})", "dir/sub/s.json").data_file == "dir/m.csv");
    CHECK(parse_session(R"({"version": 1, "data": "/abs/m.csv"})", "dir/s.json").data_file == "/abs/m.csv");
    CHECK(parse_session(R"({"version": 1, "data": null})", "dir/s.json").data_file.empty());
}

TEST_CASE("session JSON: the start goes through the file, a session from before it starts from rest",
          "[gui][session]") {
    // A whole session as saved before the start could be chosen (no "start" key): the paper's start.
    const std::string old = R"({
  "version": 1,
  "model": "dahl",
  "zeta": 0.075,
  "theta": 90.0,
  "rdisp": 0.1,
  "i": 5.0,
  "amplitude_um": 0.7,
  "frequency_khz": 60.0,
  "speed": 0.25,
  "playing": true,
  "panel": "curves",
  "view": {"zoom": 1.0, "pan": [0.0, 0.0], "follow": true, "trail_periods": 1.5, "presentation": false},
  "pins": [],
  "data": null
})";
    CHECK(parse_session(old, "old.json").start == Start::rest);
    for (const Start start : {Start::rest, Start::sliding}) {
        Session s = parse_session(old, "old.json");
        s.start = start;
        const std::string text = session_json(s);
        INFO(text);
        CHECK(text.find(std::string("\"start\": \"") + to_string(start) + "\"") != std::string::npos);
        CHECK(parse_session(text, "s.json").start == start);
    }
    CHECK(parse_session(R"({"version": 1, "start": "sliding"})", "s.json").start == Start::sliding);
    CHECK(parse_session(R"({"version": 1, "start": "rest"})", "s.json").start == Start::rest);

    // Opened in the app: the animation starts from the session's start (P - T = z_ss e_x from sliding).
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits e;
    e.open_session = write("sliding.json", R"({"version": 1, "zeta": 0.075, "rdisp": 0.1, "i": 5,
 "start": "sliding"})");
    a.sync(e);
    CHECK(a.ui().session.start == Start::sliding);
    CHECK(a.sim().tau() == 0);
    CHECK((a.sim().P() - a.sim().T()).x() == Approx(10).epsilon(1e-15));
    CHECK(session_of(a.ui()).start == Start::sliding);
    // The top view's frame likewise: body when missing (as before it could be chosen), a bad name refused.
    CHECK(parse_session(old, "old.json").view.frame == FrameChoice::body);
    CHECK(parse_session(R"({"version": 1, "view": {"frame": "ground"}})", "s.json").view.frame ==
          FrameChoice::ground);
    CHECK(refusal(R"({"version": 1, "view": {"frame": "floor"}})").find("frame") != std::string::npos);
}

TEST_CASE("session JSON: a bad file is refused with FILE:LINE:COL at the offending key or value",
          "[gui][session]") {
    struct Case {
        const char* text;
        const char* message;
    };
    for (const Case& c : {
             Case{"{\n  \"version\": 1,\n  \"zeta\": 0.2,\n  \"theta\" 3\n}",
                  "s.json:4:11: not valid JSON: syntax error while parsing object separator"},
             Case{"{\n  \"version\": 1,\n  \"zeta\": 0.2,\n}", "s.json:4:1: not valid JSON: syntax error"},
             Case{"",
                  "s.json:1:1: not valid JSON: syntax error while parsing value - unexpected end of input"},
             Case{"{\"version\": 1, \"rdisp\": 1e400}", "s.json:1:25: rdisp = 1e400 is out of range (beyond "
                                                        "double precision); allowed: rdisp in (0, 10000]"},
             Case{"{\n  \"version\": 1,\n  \"zeta\": 200\n}",
                  "s.json:3:11: zeta = 200 is out of range; allowed: zeta in [0, 100]"},
             Case{"{\"version\": 1,\n \"rdisp\": 0}",
                  "s.json:2:11: rdisp = 0 is out of range; allowed: rdisp in (0, 10000]"},
             Case{"{\"version\": 1,\n \"theta\": 270}",
                  "s.json:2:11: theta = 270 is out of range; allowed: theta in [0, 180]"},
             Case{"{\"version\": 1,\n \"i\": -1}",
                  "s.json:2:7: i = -1 is out of range; allowed: i in [0, 10]"},
             Case{"{\"version\": 1,\n \"speed\": 100}",
                  "s.json:2:11: speed = 100 is out of range; allowed: speed in [0.05, 10]"},
             Case{"{\"version\": 1,\n \"amplitude_um\": 0}",
                  "s.json:2:18: amplitude_um = 0 is out of range; allowed: amplitude_um in (0, 1e+06]"},
             Case{"{\"version\": 1,\n \"zeta\": \"0.3\"}",
                  "s.json:2:10: zeta: expected a number, got a string"},
             Case{"{\"version\": 1,\n \"playing\": 1}",
                  "s.json:2:13: playing: expected true or false, got a number"},
             Case{"{\"version\": 1,\n \"model\": \"coulomb\"}",
                  "s.json:2:11: model = \"coulomb\"; allowed: dahl, rigid"},
             Case{"{\"version\": 1,\n \"model\": 1}", "s.json:2:11: model: expected a string, got a number"},
             Case{"{\"version\": 1,\n \"start\": \"moving\"}",
                  "s.json:2:11: start = \"moving\"; allowed: rest, sliding"},
             Case{"{\"version\": 1,\n \"start\": true}",
                  "s.json:2:11: start: expected a string, got true/false"},
             Case{"{\"version\": 1,\n \"panel\": \"plot\"}",
                  "s.json:2:11: panel = \"plot\"; allowed: curves, map, loop, why, setup"},
             Case{"{\"version\": 1,\n \"zetta\": 1}",
                  "s.json:2:2: unknown key \"zetta\"; allowed: version, model, zeta"},
             Case{"{\"version\": 1,\n \"view\": {\"zoom\": 2, \"tilt\": 1}}",
                  "s.json:2:22: unknown key \"tilt\" in \"view\"; allowed: zoom, pan, follow, trail_periods, "
                  "frame, "
                  "presentation"},
             Case{"{\"version\": 1,\n \"view\": {\"zoom\": 50}}",
                  "s.json:2:19: zoom = 50 is out of range; allowed: zoom in [0.05, 20]"},
             Case{"{\"version\": 1,\n \"view\": {\"pan\": [1]}}",
                  "s.json:2:18: pan: expected [x, y], got [1]"},
             Case{"{\"version\": 1,\n \"view\": {\"pan\": [1, \"a\"]}}",
                  "s.json:2:22: pan y: expected a number, got a string"},
             Case{"{\"version\": 1,\n \"view\": 3}", "s.json:2:10: view: expected an object"},
             Case{"{\"version\": 1,\n \"zeta\": 1,\n \"zeta\": 2}",
                  "s.json:3:2: key \"zeta\" is given twice; each key at most once"},
             Case{"{\"zeta\": 1}", "s.json:1:1: no \"version\""},
             Case{"{\"version\": 2}", "s.json:1:13: version 2 is not one this frictionviz reads; allowed: 1"},
             Case{"{\"version\": \"1\"}", "s.json:1:13: version \"1\" is not one this frictionviz reads"},
             Case{"[1, 2]", "s.json:1:1: a session is a JSON object"},
             Case{"{\"version\": 1,\n \"data\": \"\"}", "s.json:2:10: data: an empty path"},
             Case{"{\"version\": 1,\n \"data\": 5}", "s.json:2:10: data: expected a string, got a number"},
             Case{"{\"version\": 1,\n \"pins\": {}}", "s.json:2:10: pins: expected an array of curves"},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"zeta\": [0.1],\n \"r_x\": [0.5, 0.6]}]}",
                  "s.json:2:9: r_x: 2 values for 1 zeta values; allowed: one per zeta"},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\",\n \"zeta\": [0.1, 101], \"r_x\": [0.5, "
                  "0.6]}]}",
                  "s.json:2:16: zeta = 101 is out of range; allowed: zeta in [0, 100]"},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"zeta\": [0.1], \"r_x\": [\"x\"]}]}",
                  "s.json:1:63: r_x: expected a number or null (a gap), got a string"},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"zeta\": []}]}",
                  "s.json:1:25: pin without \"r_x\""},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"zeta\": [], \"r_x\": []}]}",
                  "s.json:1:48: zeta: expected an array of 1 to 100000 numbers, got 0 items"},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"colour\": 1, \"zeta\": [1], \"r_x\": "
                  "[1]}]}",
                  "s.json:1:40: unknown key \"colour\" in \"pins/0\""},
             Case{"{\"version\": 1, \"pins\": [{\"label\": \"a\", \"zeta\": [1], \"r_x\": [1],\n \"link\": "
                  "\"dahl:60\"}]}",
                  "s.json:2:10: link: a Dahl pin is dahl:THETA:RDISP:I[:START]"},
             Case{"{\"version\": 1, \"pins\": [1, 2, 3, 4, 5, 6, 7]}",
                  "s.json:1:24: pins: 7 curves; allowed: at most 6"},
         }) {
        INFO(c.text);
        const std::string why = refusal(c.text);
        INFO(why);
        CHECK(why.rfind(c.message, 0) == 0);
        CHECK(why.find('\n') == std::string::npos);
    }
}

TEST_CASE("session file: read by the input policy, its data file loaded or refused where it is named",
          "[gui][session]") {
    const std::string good = write("good.json", session_json(unusual()));
    const LoadedSession l = load_session(good);
    check_same(l.session, unusual());
    REQUIRE(l.data);
    CHECK(l.data->points.size() > 5);

    const std::string missing = write("missing.json", "{\"version\": 1,\n  \"data\": \"nope.csv\"}");
    try {
        load_session(missing);
        FAIL("a missing data file was accepted");
    } catch (const SessionError& e) {
        CHECK(std::string(e.what()) == missing + ":2:11: data: " + scratch() + "/nope.csv: does not exist");
    }
    const std::string bad_data = write("bad.csv", "zeta,r_x\n0.1,abc\n");
    const std::string with_bad = write("with-bad.json", "{\"version\": 1, \"data\": \"bad.csv\"}");
    try {
        load_session(with_bad);
        FAIL("a malformed data file was accepted");
    } catch (const SessionError& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).rfind(with_bad + ":1:24: data: " + bad_data + ":2:5: ", 0) == 0);
    }
    try {
        load_session(scratch());
        FAIL("a directory was read");
    } catch (const SessionError& e) {
        CHECK(std::string(e.what()).find("directory") != std::string::npos);
    }
    const std::string big = write("big.json", "{\"version\": 1}" + std::string(2u << 20, ' '));
    CHECK_THROWS_WITH(load_session(big), Catch::Contains("larger than 1 MiB"));
}

TEST_CASE("session file: written atomically, nothing left behind when the target cannot be written",
          "[gui][session]") {
    const std::string path = scratch() + "/written.json";
    CHECK(write_session(path, unusual()).empty());
    CHECK(read(path) == session_json(unusual()));
    CHECK_FALSE(write_session(scratch() + "/no/such/dir/s.json", unusual()).empty());
    CHECK(::access((scratch() + "/no").c_str(), F_OK) != 0);
    CHECK_FALSE(write_session(scratch(), unusual()).empty()); // a directory
}

TEST_CASE("AppState: opening a session replaces the whole state and restarts the simulation, a bad one "
          "changes nothing",
          "[gui][session]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    a.sync({});
    for (int k = 0; k < 30; ++k) a.advance(1.0 / 60);
    REQUIRE(a.sim().tau() > 0);

    const std::string path = write("open.json", session_json(unusual()));
    UiEdits open;
    open.open_session = path;
    a.sync(open);
    check_same(session_of(a.ui()), unusual());
    CHECK(a.sim().tau() == 0);
    CHECK(a.sim().model() == Model::rigid);
    CHECK(a.sim().params().zeta == unusual().params.zeta);
    CHECK(a.ui().status.rfind("opened session " + path + "; loaded synthetic_theta90_rdisp3_i0.csv", 0) == 0);
    CHECK(std::abs(a.ui().vv_m_s - 2 * kPi * 45e3 * 1.3e-6) < 1e-15); // units converted for the panel

    // A bad session: the status line says where and why, the state is what it was.
    UiEdits play;
    play.playing = true;
    a.sync(play);
    for (int k = 0; k < 10; ++k) a.advance(1.0 / 60);
    const double tau = a.sim().tau();
    REQUIRE(tau > 0);
    const Session before = session_of(a.ui());
    for (const std::string& bad : {write("bad1.json", "{\"version\": 1,\n \"zeta\": 500}"),
                                   write("bad2.json", "{\"version\": 1, \"data\": \"nope.csv\"}"),
                                   scratch() + "/does-not-exist.json"}) {
        UiEdits e;
        e.open_session = bad;
        a.sync(e);
        INFO(a.ui().status);
        CHECK(a.ui().status.rfind(bad + ":", 0) == 0);
        CHECK(a.ui().status.find("session not opened; nothing changed") != std::string::npos);
        check_same(session_of(a.ui()), before);
        CHECK(a.sim().tau() == tau);
    }
    CHECK(a.ui().status.find(":2:9: zeta = 500") == std::string::npos); // the last one: the missing file
}

TEST_CASE("AppState: a session opened with other edits in the same frame lands first, the edits on top",
          "[gui][session]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits e;
    e.open_session = write("first.json", "{\"version\": 1, \"zeta\": 0.5, \"theta\": 30}");
    e.params = Params{0.9, kPi / 2, 2, 1};
    a.sync(e);
    CHECK(a.ui().session.params.zeta == 0.9);
    CHECK(a.ui().session.params.theta == kPi / 2);
}

TEST_CASE("script: save-session and open-session take paths next to the script, an unwritable save is "
          "refused before the run",
          "[gui][session][script]") {
    const std::string script = write("s.txt", "3 save-session out.json\n4 open-session in.json\n");
    const Script s = load_script(script);
    UiState ui;
    CHECK(script_edits(s, 3, ui).save_session == scratch() + "/out.json");
    CHECK(script_edits(s, 4, ui).open_session == scratch() + "/in.json");
    CHECK_FALSE(script_edits(s, 3, ui).open_session);

    const std::string bad = write("bad.txt", "# a comment\n2 save-session no/such/dir/s.json\n");
    CHECK_THROWS_WITH(load_script(bad),
                      Catch::StartsWith(bad + ":2: save-session " + scratch() + "/no/such/dir/s.json: "));
    const std::string novalue = write("novalue.txt", "2 open-session\n");
    CHECK_THROWS_WITH(load_script(novalue), Catch::StartsWith(novalue + ":1: 'open-session' needs a value"));
}

TEST_CASE("docs/app.md: the session example is what the app saves in its default state",
          "[gui][session][readme]") {
    const std::string readme = read(std::string(FV_TEST_DATA_DIR) + "/../../docs/app.md");
    const auto section = readme.find("## Session files");
    REQUIRE(section != std::string::npos);
    const auto from = readme.find("```json\n", section);
    REQUIRE(from != std::string::npos);
    const auto to = readme.find("```\n", from + 8);
    CHECK(readme.substr(from + 8, to - from - 8) == session_json(session_of(UiState{})));
}

TEST_CASE("session JSON: damaged files are refused with one line, never anything else", "[gui][session]") {
    // Bytes changed, dropped and repeated at random in a valid file: parse_session returns a session or
    // throws SessionError "s.json:LINE:COL: ..." (the position scan runs only on text nlohmann accepted).
    const std::string good = session_json(unusual());
    std::mt19937 rng(2006);
    const std::string alphabet = "{}[]\",:0123456789.eE+-truefalsnul \n\\/\"xyz";
    int refused = 0;
    for (int k = 0; k < 20000; ++k) {
        std::string t = good;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits && !t.empty(); ++e) {
            const std::size_t at = rng() % t.size();
            switch (rng() % 3) {
            case 0:
                t[at] = alphabet[rng() % alphabet.size()];
                break;
            case 1:
                t.erase(at, 1 + rng() % 8);
                break;
            default:
                t.insert(at, t.substr(rng() % t.size(), 1 + rng() % 12));
                break;
            }
        }
        try {
            parse_session(t, "s.json");
        } catch (const SessionError& e) {
            const std::string w = e.what();
            INFO(t << "\n-> " << w);
            REQUIRE(w.rfind("s.json:", 0) == 0);
            REQUIRE(w.find('\n') == std::string::npos);
            ++refused;
        }
    }
    CHECK(refused > 15000); // most damage is caught
}

TEST_CASE("docs/app.md names every script action", "[gui][script][docs]") {
    const std::string doc = read(std::string(FV_TEST_DATA_DIR) + "/../../docs/app.md");
    const auto section = doc.find("## Scripts");
    REQUIRE(section != std::string::npos);
    std::string actions = script_actions() + ",";
    for (std::size_t from = 0, comma; (comma = actions.find(',', from)) != std::string::npos;
         from = comma + 2) {
        const std::string item = actions.substr(from, comma - from);
        const std::string name = item.substr(0, item.find(' '));
        CAPTURE(name);
        CHECK(doc.find("`" + name + "`", section) != std::string::npos);
    }
}

TEST_CASE(
    "share link of the app's state: the view and the pins go through a link, a default view adds nothing",
    "[gui][session][link]") {
    // A default view: the link is the five keys, as before the view keys existed.
    Session d;
    CHECK(session_link(d) == share_link(d.model, d.params, d.start));
    CHECK(share_address({}, d) == std::string(kDefaultLinkBase) + share_link(d.model, d.params, d.start));
    // Pins made in the app (the worker's curves), a panel, presentation and a speed: through the link and
    // back, the pins computed again on their own path (compute_pin) come out as the app drew them.
    AppState app(Model::dahl, Params{0.2, kPi / 3, 2, 1}, 0.7, 60);
    app.sync({}, true);
    UiEdits e;
    e.pin = true;
    app.sync(e, true);
    e = {};
    e.model = Model::rigid;
    app.sync(e, true);
    e = {};
    e.pin = true;
    e.panel = LowerPanel::loop;
    e.presentation = true;
    e.speed = 1.5;
    app.sync(e, true);
    const SessionState& s = app.ui().session;
    REQUIRE(s.pins.size() == 2);
    const std::string link = session_link(s);
    CHECK(link == "?zeta=0.2&theta=60&rdisp=2&i=1&model=rigid&panel=loop&present=1&speed=1.5"
                  "&pins=dahl:60:2:1,rigid:60");
    Session opened;
    const ShareLink l = parse_share_link("https://example.org/fv/" + link);
    CHECK(l.notices.empty());
    apply_link(l, opened);
    CHECK(opened.model == Model::rigid);
    CHECK(opened.panel == LowerPanel::loop);
    CHECK(opened.presentation);
    CHECK(opened.speed == 1.5);
    REQUIRE(opened.pins.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
        INFO(k);
        CHECK(opened.pins[k].label == s.pins[k].label);
        CHECK(opened.pins[k].zeta == s.pins[k].zeta);
        REQUIRE(opened.pins[k].rx.size() == s.pins[k].rx.size());
        for (std::size_t n = 0; n < s.pins[k].rx.size(); ++n)
            CHECK((opened.pins[k].rx[n] == s.pins[k].rx[n] ||
                   (std::isnan(opened.pins[k].rx[n]) && std::isnan(s.pins[k].rx[n]))));
    }
    // A pin whose source is not known (an older session file) stays out of the link, and is counted.
    SessionState old = s;
    old.pins[0].source.reset();
    CHECK(session_link(old).find("&pins=rigid:60") != std::string::npos);
    CHECK(pins_not_in_link(old) == 1);
    // Site addresses the desktop's --link-base takes, and what it refuses.
    CHECK(link_base_error("https://example.org/frictionviz/").empty());
    CHECK(link_base_error("http://192.168.1.20:8000/").empty());
    for (const char* bad :
         {"example.org/fv/", "ftp://x/", "https://x/?a=1", "https://x/#top", "https://x/a b", "https://x/\n"})
        CHECK_FALSE(link_base_error(bad).empty());
}

TEST_CASE("share link of a session: every field but the data file goes through a link and back, in and out "
          "of a lesson, and a default field stays out of the link",
          "[gui][session][link]") {
    // A session's fields are what its file holds: two sessions are the same when their files are.
    const auto same_file = [](Session a, Session b) {
        a.data_file.clear();
        b.data_file.clear();
        return session_json(a) == session_json(b);
    };
    const auto through_link = [](const Session& s) {
        Session back;
        const ShareLink l = parse_link(session_link(s));
        CHECK(l.notices.empty());
        apply_link(l, back);
        return back;
    };
    // Every field away from its default (unusual(): units, speed, paused, panel, zoom, pan, follow, trail,
    // ground frame, presentation, the sliding start, lesson 4), pins as the app computes them (the link
    // carries their sources and the reader computes them again), compare mode with a B that starts from rest
    // while A starts sliding (compare_default would give B A's start).
    Session s = unusual();
    const double zmax = ratio_zeta_max(nullptr);
    s.pins = {compute_pin(PinSource{Model::dahl, kPi / 3, 2, 0, Start::sliding}, zmax),
              compute_pin(PinSource{Model::rigid, kPi / 2, 1, 1, Start::rest}, zmax)};
    s.compare = true;
    s.b = Setup{Model::dahl, Params{0.2, 10 * kPi / 180, 3, 2}, Start::rest};
    const int steps = static_cast<int>(lesson_steps().size());
    for (int lesson = 0; lesson <= steps; ++lesson)
        for (const bool compare : {true, false}) {
            s.lesson = lesson;
            s.compare = compare;
            INFO("lesson " << lesson << ", compare " << compare << ": " << session_link(s));
            const Session back = through_link(s);
            CHECK(same_file(s, back));
            check_same(back, [&] {
                Session t = s;
                t.data_file.clear();
                return t;
            }()); // field by field, to say which one
            // From a session file, the same: file -> session -> link -> session.
            CHECK(same_file(s, through_link(parse_session(session_json(s), "s.json"))));
            // In a lesson, a field left at the app's default where the step has another value (why panel,
            // ground frame, compare mode on): the link says the default, so the step's value does not
            // come back in its place.
            Session plain;
            plain.lesson = lesson;
            plain.compare = compare;
            INFO("plain: " << session_link(plain));
            CHECK(same_file(plain, through_link(plain)));
        }
    // A sliding A with a B from rest outside a lesson, and the other way round.
    Session ab;
    ab.start = Start::sliding;
    ab.compare = true;
    ab.b.start = Start::rest;
    CHECK(session_link(ab).find("&b.start=rest") != std::string::npos);
    CHECK(same_file(ab, through_link(ab)));
    ab.start = Start::rest;
    ab.b.start = Start::sliding;
    CHECK(same_file(ab, through_link(ab)));

    // The defaults stay out of the link; each field changed alone adds its own key and no other.
    const Session d;
    const std::string five = share_link(d.model, d.params, d.start);
    CHECK(session_link(d) == five);
    struct One {
        std::function<void(Session&)> set;
        std::string keys;
    };
    for (const One& o : {
             One{[](Session& t) { t.amplitude_um = 1; }, "&amplitude=1"},
             One{[](Session& t) { t.frequency_khz = 40; }, "&frequency=40"},
             One{[](Session& t) { t.playing = false; }, "&play=0"},
             One{[](Session& t) { t.view.trail_periods = 3; }, "&trail=3"},
             One{[](Session& t) { t.view.zoom = 2; }, "&zoom=2"},
             One{[](Session& t) { t.view.pan = Vec2(0.5, -1); }, "&pan=0.5,-1"},
             One{[](Session& t) { t.view.pan = Vec2(0, 0.25); }, "&pan=0,0.25"},
             One{[](Session& t) { t.view.follow = false; }, "&follow=0"},
             One{[](Session& t) { t.speed = 1.5; }, "&speed=1.5"},
             One{[](Session& t) { t.presentation = true; }, "&present=1"},
             One{[](Session& t) { t.panel = LowerPanel::why; }, "&panel=why"},
             One{[](Session& t) { t.view.frame = FrameChoice::ground; }, "&frame=ground"},
             One{[](Session& t) { t.start = Start::sliding; }, "&start=sliding"},
         }) {
        Session t;
        o.set(t);
        INFO(o.keys);
        CHECK(session_link(t) == five + o.keys);
        CHECK(same_file(t, through_link(t)));
    }
    // The link of the unusual session is still short enough to paste into a chat or a slide (pins are
    // the longest part).
    s.lesson = 0;
    INFO(session_link(s));
    CHECK(session_link(s).size() < 300);
}

TEST_CASE("a link opens a lesson step: its setup, the link's own keys over it, the step in sessions",
          "[gui][session][link][lessons]") {
    const int steps = static_cast<int>(lesson_steps().size());
    const LessonSetup& u = lesson_steps()[2].setup; // from lessons.json, the data the menu shows
    // ?lesson=3 alone: step 3 as the Lessons menu sets it up, card on.
    Session s;
    const ShareLink l = parse_link("?lesson=3");
    CHECK(l.notices.empty());
    apply_link(l, s);
    CHECK(s.lesson == 3);
    CHECK(s.model == u.model);
    CHECK(s.params.zeta == u.params.zeta);
    CHECK(s.params.theta == u.params.theta);
    CHECK(s.params.rdisp == u.params.rdisp);
    CHECK(s.params.i == u.params.i);
    CHECK(s.start == u.start);
    CHECK(s.panel == u.panel);
    CHECK(s.speed == u.speed);
    CHECK(s.view.frame == u.frame);
    // The link of that state says lesson=3 (Copy link during a lesson), and reads back to the same state.
    const std::string link = session_link(s);
    CHECK(link.find("&lesson=3") != std::string::npos);
    Session again;
    apply_link(parse_link(link), again);
    CHECK(again.lesson == 3);
    CHECK(again.params.theta == s.params.theta);
    CHECK(again.panel == s.panel);
    // A slider moved during the lesson: the link's own keys win over the step's setup, the card stays.
    Session moved;
    apply_link(parse_link("?lesson=3&zeta=0.45&panel=curves"), moved);
    CHECK(moved.lesson == 3);
    CHECK(moved.params.zeta == 0.45);
    CHECK(moved.params.theta == u.params.theta);
    CHECK(moved.panel == LowerPanel::curves);
    // No lesson: no key (the link of a default view is unchanged).
    CHECK(session_link(Session{}).find("lesson") == std::string::npos);
    // A step that does not exist: a notice naming the steps, the rest applied, no card.
    for (const std::string bad : {"99", "0", "x"}) {
        const ShareLink b = parse_link("?zeta=0.45&lesson=" + bad);
        INFO(bad);
        REQUIRE(b.notices.size() == 1);
        CHECK(b.notices[0].find("allowed: lesson in [1, " + std::to_string(steps) + "]") !=
              std::string::npos);
        Session t;
        apply_link(b, t);
        CHECK(t.lesson == 0);
        CHECK(t.params.zeta == 0.45);
    }
    // The app opened on that state shows the card (what gui --link and the page do).
    AppState app(s);
    CHECK(app.ui().session.lesson == 3);
    // Sessions keep the step; a session without a lesson writes no "lesson" key (files read as before).
    CHECK(parse_session(session_json(s), "s.json").lesson == 3);
    CHECK(session_json(Session{}).find("lesson") == std::string::npos);
    CHECK(refusal("{\"version\": 1, \"lesson\": 99}") ==
          "s.json:1:26: lesson = 99; allowed: 0 (none) or a step " + lesson_range_text());
    CHECK(refusal("{\"version\": 1, \"lesson\": \"3\"}") ==
          "s.json:1:26: lesson = \"3\"; allowed: 0 (none) or a step " + lesson_range_text());
    CHECK(parse_session("{\"version\": 1, \"lesson\": 0}", "s.json").lesson == 0);
}
