// The guided lesson (app/gui/lessons.json): the shipped steps are valid, their quoted numbers are the paper's
// closed forms at their setups, a bad file is refused with a message naming the step, and a step reaches the
// app's state through the one sync point as any other edit.
#include "gui/app_state.hpp"
#include "gui/lessons.hpp"
#include "gui/script.hpp"
#include "gui/session.hpp"

#include "fv/measurements.hpp"
#include "fv/param_ranges.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <string>

using namespace fv;
using namespace fv::app;

namespace {

// Eq. (10) and Eq. (11) of the paper, written out here (not core's rigid model): r_x at theta = 0 and 90 deg.
double rx_parallel(double zeta) {
    return zeta <= 1 ? 2 / kPi * std::asin(zeta) : 1;
}
double rx_perpendicular(double zeta) {
    const double m = 1 / (1 + zeta * zeta); // K's parameter; std::comp_ellint_1 takes the modulus sqrt(m)
    return 2 / kPi * zeta / std::sqrt(1 + zeta * zeta) * std::comp_ellint_1(std::sqrt(m));
}

// The percentages a text quotes ("19 %").
std::vector<int> percentages(const std::string& text) {
    std::vector<int> out;
    const std::regex pct("([0-9]+) %");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pct); it != std::sregex_iterator(); ++it)
        out.push_back(std::stoi((*it)[1].str()));
    return out;
}

std::string step_json(const std::string& setup, const std::string& extra = "") {
    return R"({"steps": [{"id": "a", "title": "T", "text": "words", "details": "d", )" + extra +
           R"("setup": )" + setup + "}]}";
}

} // namespace

TEST_CASE("lessons: the shipped steps are a guided sequence of 6-8 valid steps in plain words",
          "[gui][lessons]") {
    const auto& steps = lesson_steps();
    REQUIRE(steps.size() >= 6);
    REQUIRE(steps.size() <= 8);
    std::set<std::string> ids;
    for (const LessonStep& s : steps) {
        INFO(s.id);
        CHECK(ids.insert(s.id).second);
        CHECK(range_error(s.setup.params).empty());
        // Plain words first: the equations go behind the details toggle.
        CHECK(s.text.find('=') == std::string::npos);
        CHECK(s.text.find("Eq.") == std::string::npos);
        CHECK(s.details.find("Eq") != std::string::npos); // every step's equations cite the paper
        CHECK_FALSE(s.tip.empty());
        CHECK(s.text.size() < 600); // a card, not a page: read aloud in under a minute
    }
    CHECK(lesson_range_text() == "1-" + std::to_string(steps.size()));
    REQUIRE(find_lesson_step("along"));
    CHECK(find_lesson_step("along")->setup.params.theta == 0);
    CHECK_FALSE(find_lesson_step("fig10"));
}

TEST_CASE("lessons: the percentages a step quotes are Eqs. (10) and (11) at its setup", "[gui][lessons]") {
    int checked = 0;
    for (const LessonStep& s : lesson_steps()) {
        const LessonSetup& u = s.setup;
        if (u.model != Model::rigid) continue;
        const double deg = u.params.theta * 180 / kPi;
        const double rx = deg == 0    ? rx_parallel(u.params.zeta)
                          : deg == 90 ? rx_perpendicular(u.params.zeta)
                                      : -1;
        for (const std::string* t : {&s.text, &s.details}) {
            for (int pct : percentages(*t)) {
                INFO(s.id << ": " << pct << " %, r_x = " << rx);
                REQUIRE(rx >= 0);
                CHECK(std::lround(100 * rx) == pct);
                ++checked;
            }
        }
    }
    CHECK(checked >= 3); // "100 %" (zeta > 1 along the motion), 19 % along, 49 % across
    // Eq. (11)'s value is the one a direct quadrature of Eq. (9) gives (a check of the transcription above).
    double sum = 0;
    const int n = 200000;
    for (int k = 0; k < n; ++k) {
        const double c = std::cos(2 * kPi * (k + 0.5) / n);
        sum += 0.3 / std::sqrt(0.09 + c * c);
    }
    CHECK(sum / n == Approx(rx_perpendicular(0.3)).epsilon(1e-6));
}

TEST_CASE("lessons: a bad lessons file is refused with the step, what was wrong and what is allowed",
          "[gui][lessons]") {
    const std::string ok = R"({"model": "rigid", "zeta": 0.3, "theta": 0, "rdisp": 2, "i": 1})";
    CHECK(parse_lessons(step_json(ok)).size() == 1);
    CHECK_THROWS_WITH(parse_lessons("{"), Catch::StartsWith("lessons: not JSON"));
    CHECK_THROWS_WITH(parse_lessons(R"({"steps": []})"),
                      "lessons: missing \"steps\"; allowed: a non-empty array of steps");
    CHECK_THROWS_WITH(
        parse_lessons(step_json(R"({"model": "rigid", "zeta": 200, "theta": 0, "rdisp": 2, "i": 1})")),
        Catch::StartsWith("lessons: step 1 (a): zeta = 200 is out of range; allowed: zeta in [0, 100]"));
    CHECK_THROWS_WITH(
        parse_lessons(step_json(R"({"model": "lugre", "zeta": 0.3, "theta": 0, "rdisp": 2, "i": 1})")),
        "lessons: step 1 (a): model \"lugre\"; allowed: dahl, rigid");
    CHECK_THROWS_WITH(
        parse_lessons(
            step_json(R"({"model": "rigid", "zeta": 0.3, "theta": 0, "rdisp": 2, "i": 1, "panel": "big"})")),
        "lessons: step 1 (a): panel \"big\"; allowed: curves, map, loop, why, setup");
    CHECK_THROWS_WITH(parse_lessons(step_json(ok, R"("colour": "red", )")),
                      Catch::StartsWith("lessons: step 1 (a): unknown key \"colour\""));
    CHECK_THROWS_WITH(parse_lessons(step_json(R"({"model": "rigid", "theta": 0, "rdisp": 2, "i": 1})")),
                      "lessons: step 1 (a): missing \"zeta\"; allowed: zeta in [0, 100]");
    const std::string twice =
        R"({"steps": [{"id": "a", "title": "T", "text": "w", "details": "d", "setup": )" + ok +
        R"(}, {"id": "a", "title": "T", "text": "w", "details": "d", "setup": )" + ok + "}]}";
    CHECK_THROWS_WITH(parse_lessons(twice),
                      "lessons: step 2 (a): id \"a\" is used twice; allowed: unique ids");
}

TEST_CASE("lessons: a step goes through the sync point: setup, panel, speed, played from its start",
          "[gui][lessons][state]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits pause;
    pause.playing = false;
    a.sync(pause);
    UiEdits go;
    go.lesson = 3;
    const LessonSetup& u = lesson_steps()[2].setup;
    CHECK(a.ui().session.lesson == 0); // queued, not applied
    a.sync(go);
    CHECK(a.ui().session.lesson == 3);
    CHECK(a.ui().session.model == u.model);
    CHECK(a.ui().session.params.zeta == u.params.zeta);
    CHECK(a.ui().session.params.theta == u.params.theta);
    CHECK(a.sim().params().theta == u.params.theta);
    CHECK(a.ui().session.panel == u.panel);
    CHECK(a.ui().session.speed == u.speed);
    CHECK(a.ui().session.playing);
    CHECK(a.sim().tau() == 0); // from its start

    // A step that does not exist changes nothing and says what is allowed.
    UiEdits bad;
    bad.lesson = 99;
    a.sync(bad);
    CHECK(a.ui().session.lesson == 3);
    CHECK(a.ui().session.params.zeta == u.params.zeta);
    CHECK(a.ui().status == "lesson step 99 does not exist; allowed: " + lesson_range_text());

    // Close: the card goes, the setup stays.
    UiEdits close;
    close.lesson = 0;
    a.sync(close);
    CHECK(a.ui().session.lesson == 0);
    CHECK(a.ui().session.params.zeta == u.params.zeta);

    // A concept preset is the step's setup without the card.
    UiEdits preset;
    preset.preset = "stick-slip";
    a.sync(preset);
    const LessonSetup& st = find_lesson_step("stick-slip")->setup;
    CHECK(a.ui().session.lesson == 0);
    CHECK(a.ui().session.params.i == st.params.i);
    CHECK(a.ui().session.panel == st.panel);
}

TEST_CASE("lessons: the script's lesson N, checked when loaded", "[gui][lessons][script]") {
    char tmpl[] = "/tmp/fv-lesson-script-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    const std::string good = dir + "/good.txt";
    std::ofstream(good) << "0 lesson 2\n5 lesson 0\n6 preset across\n";
    const Script s = load_script(good);
    const UiState ui;
    CHECK(script_edits(s, 0, ui).lesson == 2);
    CHECK(script_edits(s, 5, ui).lesson == 0);
    CHECK(script_edits(s, 6, ui).preset == "across");
    const std::string bad = dir + "/bad.txt";
    std::ofstream(bad) << "0 lesson 99\n";
    CHECK_THROWS_WITH(load_script(bad), Catch::StartsWith(bad + ":1: lesson = 99 is out of range"));
    std::ofstream(bad) << "0 lesson two\n";
    CHECK_THROWS_WITH(load_script(bad), Catch::StartsWith(bad + ":1: lesson = 'two' is not an integer"));
}

TEST_CASE("lessons: the mean step shows compare mode, A across and B along: both r_x are Eqs. (11) and (10)",
          "[gui][lessons][compare]") {
    const LessonStep* mean = find_lesson_step("mean");
    REQUIRE(mean);
    REQUIRE(mean->setup.b);
    const Setup& b = *mean->setup.b;
    CHECK(b.model == mean->setup.model); // what the step leaves out is A's
    CHECK(b.params.zeta == mean->setup.params.zeta);
    CHECK(b.params.theta == 0);
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    int n = 0;
    for (const LessonStep& s : lesson_steps()) {
        ++n;
        if (&s == mean) break;
    }
    UiEdits go;
    go.lesson = n;
    a.sync(go);
    REQUIRE(a.ui().session.compare);
    CHECK(a.sim().tau() == 0);
    CHECK(a.sim_b().tau() == 0); // one time base: both from their start
    CHECK(a.sim_b().params().theta == 0);
    a.worker().wait_idle();
    a.worker_b().wait_idle();
    const auto ca = a.worker().latest(), cb = a.worker_b().latest();
    REQUIRE(ca);
    REQUIRE(cb);
    const double zeta = mean->setup.params.zeta;
    CHECK(ca->current.rx == Approx(rx_perpendicular(zeta)).epsilon(1e-6));
    CHECK(cb->current.rx == Approx(rx_parallel(zeta)).epsilon(1e-6));
    // The next step has no B: compare mode goes off with it.
    UiEdits next;
    next.lesson = n + 1;
    a.sync(next);
    CHECK_FALSE(a.ui().session.compare);
}

TEST_CASE(
    "lessons: the measurements step brings the synthetic file's points as an example and the user's data win",
    "[gui][lessons][data]") {
    const LessonStep* m = find_lesson_step("measurements");
    REQUIRE(m);
    REQUIRE(m->setup.data);
    // The points are tests/data's synthetic set (fitted in test_gui_data.cpp: r_disp 3, i 0), called
    // synthetic, and the step's own curve is not theirs (Fit has something to do).
    const MeasurementSet file = read_measurements(FV_TEST_DATA_DIR "/synthetic_theta90_rdisp3_i0.csv");
    const MeasurementSet& ex = *m->setup.data;
    CHECK(ex.synthetic);
    REQUIRE(ex.points.size() == file.points.size());
    for (std::size_t k = 0; k < ex.points.size(); ++k) {
        CHECK(ex.points[k].zeta == file.points[k].zeta);
        CHECK(ex.points[k].rx == file.points[k].rx);
        CHECK(ex.points[k].sigma == file.points[k].sigma);
        CHECK(ex.points[k].theta_deg == file.points[k].theta_deg);
    }
    CHECK((m->setup.params.rdisp != 3 || m->setup.params.i != 0));

    const int step = static_cast<int>(m - lesson_steps().data()) + 1;
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits go;
    go.lesson = step;
    a.sync(go);
    REQUIRE(a.ui().data);
    CHECK(a.ui().data->points.size() == ex.points.size());
    CHECK(a.ui().data_is_example);
    CHECK(session_of(a.ui()).data_file.empty()); // no file behind them to save
    // A session or a link during the step brings them back.
    AppState reopened(session_of(a.ui()), std::nullopt);
    REQUIRE(reopened.ui().data);
    CHECK(reopened.ui().data_is_example);

    // Back: a step without example points takes them away.
    UiEdits back;
    back.lesson = step - 1;
    a.sync(back);
    CHECK_FALSE(a.ui().data);

    // Data the user opened stay over the step's example and are what a session saves.
    UiEdits load;
    load.load_data = FV_TEST_DATA_DIR "/synthetic_theta0_rdisp1_i1_vb.csv";
    a.sync(load);
    REQUIRE(a.ui().data);
    const std::size_t n = a.ui().data->points.size();
    a.sync(go);
    REQUIRE(a.ui().data);
    CHECK_FALSE(a.ui().data_is_example);
    CHECK(a.ui().data->points.size() == n);
    CHECK(a.ui().data->from_vb);
    a.sync(back);
    CHECK(a.ui().data);
    CHECK_FALSE(session_of(a.ui()).data_file.empty());
}

TEST_CASE("lessons: a step's bad example data are refused with the step and the file's line",
          "[gui][lessons][data]") {
    const std::string setup = R"({"model": "dahl", "zeta": 0.3, "theta": 90, "rdisp": 2, "i": 1, "data": )";
    CHECK(parse_lessons(step_json(setup + R"({"name": "x", "lines": ["zeta,r_x", "0.1,0.3"]}})"))
              .front()
              .setup.data->points.size() == 1);
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"({"name": "x", "lines": ["zeta,r_x", "0.1,7"]}})")),
                      Catch::StartsWith("lessons: step 1 (a): data: x:2:"));
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"({"name": "x", "lines": ["zeta,r_x"]}})")),
                      Catch::StartsWith("lessons: step 1 (a): data: x:2:1: no data rows"));
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"({"name": "x", "lines": []}})")),
                      Catch::StartsWith("lessons: step 1 (a): data: x:"));
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"({"name": "x", "lines": ["vb,r_x", "0.1,0.3"]}})")),
                      Catch::Contains("column 'vb' (m/s) needs the vibration amplitude"));
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"("x.csv"})")),
                      Catch::StartsWith("lessons: step 1 (a): \"data\" is not an object"));
    CHECK_THROWS_WITH(parse_lessons(step_json(setup + R"({"name": "x", "rows": []}})")),
                      Catch::StartsWith("lessons: step 1 (a): unknown key \"rows\""));
}
