// The app's state without a window: the range table shared by the CLI, the core and the sliders.
#include "cli/validators.hpp"
#include "gui/controls.hpp"

#include "fv/param_ranges.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace fv;

namespace {

// The message CLI11 gets from the validator of a model flag for `value`.
std::string cli_message(ParamRange r, std::string value) {
    return cli::number_in(r)(value);
}

bool within(ParamRange inner, ParamRange outer) {
    return inside(inner.lo, outer) && inside(inner.hi, outer);
}

} // namespace

TEST_CASE("range table: the CLI's messages, the core's check and the sliders use the same constants",
          "[gui][ranges]") {
    // The CLI quotes the table's ranges...
    CHECK(cli_message(kZetaRange, "200") == "200 is out of range; allowed: a number in [0, 100]");
    CHECK(cli_message(kZetaRange, "100").empty());
    CHECK(cli_message(kRdispRange, "0").find(describe(kRdispRange)) != std::string::npos);
    CHECK(cli_message(kIRange, "11").find(describe(kIRange)) != std::string::npos);
    CHECK(cli_message(kThetaRange, "181").find(describe(kThetaRange)) != std::string::npos);
    // ... the core's check quotes the same ...
    Params p{0.5, kPi / 2, 2, 1};
    CHECK(range_error(p).empty());
    p.zeta = kZetaRange.hi * 2;
    CHECK(range_error(p) == "zeta = 200; allowed: zeta in " + describe(kZetaRange));
    p = {0.5, kPi / 2, kRdispRange.hi * 2, 1};
    CHECK(range_error(p).find("r_disp in " + describe(kRdispRange)) != std::string::npos);
    p = {0.5, kPi / 2, 2, kIRange.hi + 1};
    CHECK(range_error(p).find("i in " + describe(kIRange)) != std::string::npos);
    p = {0.5, kPi, 2, 1}; // 180 degrees, back and forth through radians
    CHECK(range_error(p).empty());
    p.theta = kPi * 1.01;
    CHECK(range_error(p).find("theta in " + describe(kThetaRange)) != std::string::npos);
    // ... and the panel's sliders span parts of those ranges, their ends admissible values.
    CHECK(within(app::kSliders.zeta, kZetaRange));
    CHECK(within(app::kSliders.theta_deg, kThetaRange));
    CHECK(within(app::kSliders.rdisp, kRdispRange));
    CHECK(within(app::kSliders.i, kIRange));
    for (double z : {app::kSliders.zeta.lo, app::kSliders.zeta.hi})
        CHECK(cli_message(kZetaRange, std::to_string(z)).empty());
    for (double r : {app::kSliders.rdisp.lo, app::kSliders.rdisp.hi})
        CHECK(cli_message(kRdispRange, std::to_string(r)).empty());
}

// ---- AppState::sync: the one point per frame where edits take effect ----

#include "gui/app_state.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

using namespace fv::app;

namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;
double vv(double amplitude_um, double frequency_khz) {
    return kTwoPi * (frequency_khz * 1e3) * (amplitude_um * 1e-6);
}

void pause(AppState& a) {
    UiEdits e;
    e.playing = false;
    a.sync(e);
}

} // namespace

TEST_CASE("AppState: edits take effect at sync, once, the later of the same field winning", "[gui][state]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    pause(a);
    const int syncs = a.syncs();
    UiEdits queued;
    Params p = a.ui().session.params;
    p.zeta = 0.3;
    UiEdits panel;
    panel.params = p;
    panel.step = true;
    queued.merge(panel);
    CHECK(a.ui().session.params.zeta == 0.15); // queued, not applied
    CHECK(a.sim().params().zeta == 0.15);
    UiEdits keys;
    keys.step = true; // a second step in the same frame is still one step
    p.zeta = 0.4;
    keys.params = p;
    queued.merge(keys);
    const double tau0 = a.sim().tau();
    a.sync(queued);
    CHECK(a.syncs() == syncs + 1);
    CHECK(a.ui().session.params.zeta == 0.4);
    CHECK(a.sim().params().zeta == 0.4);
    a.advance(1.0); // paused: only the single step, one displayed frame (1/60 s at the speed), whole steps
    const double dtau = a.sim().tau() - tau0;
    CHECK(dtau == Approx(a.ui().session.speed * 2 * kPi / 60).margin(a.sim().dtau() / 2));
    a.sync(UiEdits{});
    a.advance(1.0);
    CHECK(a.sim().tau() - tau0 == Approx(dtau)); // nothing left over from the last frame
    // The physical view follows at the same point.
    CHECK(a.ui().vb_m_s == Approx(0.4 * vv(0.7, 60)).epsilon(1e-14));
    CHECK(a.ui().zss_um == Approx(0.7 / 2).epsilon(1e-14));
}

TEST_CASE("AppState: the mouse's view edits and the loop's status go through the sync like every edit",
          "[gui][state]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits e;
    e.zoom = 3;
    e.pan = Vec2(0.5, -2);
    e.status = "wrote a.png";
    CHECK(a.ui().session.view.zoom == 1); // nothing before the sync
    a.sync(e);
    CHECK(a.ui().session.view.zoom == 3);
    CHECK(a.ui().session.view.pan == Vec2(0.5, -2));
    CHECK(a.ui().status == "wrote a.png");
    // Clamped to the ranges a session file is held to.
    UiEdits far;
    far.zoom = 1e9;
    far.pan = Vec2(-1e9, 1e9);
    a.sync(far);
    CHECK(a.ui().session.view.zoom == kZoomRange.hi);
    CHECK(a.ui().session.view.pan == Vec2(kPanRange.lo, kPanRange.hi));
    // A double-click: the default view, live, the trail kept; this frame's own message wins over the loop's.
    UiEdits trail;
    trail.trail_periods = 3;
    a.sync(trail);
    UiEdits reset;
    reset.reset_view = true;
    reset.status = "older";
    reset.clear_pins = true;
    a.sync(reset);
    CHECK(a.ui().session.view.zoom == 1);
    CHECK(a.ui().session.view.pan == Vec2(0, 0));
    CHECK(a.ui().session.view.follow);
    CHECK(a.ui().session.view.trail_periods == 3);
    CHECK(a.ui().status == "pins cleared");
}

TEST_CASE("AppState: out-of-range edits change nothing and say the table's range", "[gui][state]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    pause(a);
    const Params before = a.ui().session.params;
    auto rejected = [&](const UiEdits& e, const std::string& range) {
        UiEdits cleared = e;
        cleared.status = ""; // what this sync says about e shows over it
        a.sync(cleared);
        CHECK(a.ui().status.find(range) != std::string::npos);
        CHECK(a.ui().session.params.zeta == before.zeta);
        CHECK(a.ui().session.params.rdisp == before.rdisp);
        CHECK(a.ui().session.params.i == before.i);
        CHECK(a.ui().session.params.theta == before.theta);
        CHECK(a.sim().params().zeta == before.zeta);
        CHECK(a.ui().session.amplitude_um == 0.7);
    };
    auto with = [&](auto set) {
        UiEdits e;
        Params p = before;
        set(p);
        e.params = p;
        return e;
    };
    rejected(with([](Params& p) { p.zeta = kZetaRange.hi * 1.01; }), describe(kZetaRange));
    rejected(with([](Params& p) { p.rdisp = kRdispRange.hi * 1.01; }), describe(kRdispRange));
    rejected(with([](Params& p) { p.i = kIRange.hi + 0.5; }), describe(kIRange));
    rejected(with([](Params& p) { p.theta = (kThetaRange.hi + 1) * kPi / 180; }), describe(kThetaRange));
    UiEdits vb;
    vb.vb_m_s = 1.01 * kZetaRange.hi * vv(0.7, 60); // zeta = 101
    rejected(vb, describe(kZetaRange));
    UiEdits zss;
    zss.zss_um = 0.7 / (kRdispRange.hi * 1.01); // r_disp = 1.01e4
    rejected(zss, describe(kRdispRange));
    UiEdits amp;
    amp.amplitude_um = 1e-6; // zeta = 0.15 * 0.7e6
    rejected(amp, describe(kZetaRange));
    // In range: applied, converted with the A and f in effect.
    UiEdits ok;
    ok.vb_m_s = 0.1;
    a.sync(ok);
    CHECK(a.ui().session.params.zeta == Approx(0.1 / vv(0.7, 60)).epsilon(1e-14));
    CHECK(a.sim().params().zeta == a.ui().session.params.zeta);
}

TEST_CASE("AppState: an A or f change converts the kept v_b column, without reading the file again",
          "[gui][state][data]") {
    char tmpl[] = "/tmp/fv-app-state-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    const std::string path = dir + "/vb.csv";
    {
        std::ifstream in(std::string(FV_TEST_DATA_DIR) + "/synthetic_theta0_rdisp1_i1_vb.csv");
        std::ofstream(path) << in.rdbuf();
    }
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    pause(a);
    UiEdits load;
    load.load_data = path;
    a.sync(load);
    REQUIRE(a.ui().data);
    std::vector<double> vbs;
    for (const Measurement& m : a.ui().data->points) {
        REQUIRE(m.vb);
        vbs.push_back(*m.vb);
        CHECK(m.zeta == Approx(*m.vb / vv(0.7, 60)).epsilon(1e-14));
    }
    REQUIRE(vbs.size() == 16);
    REQUIRE(std::remove(path.c_str()) == 0); // the file is gone: a re-read would fail
    UiEdits amp;
    amp.amplitude_um = 0.8;
    a.sync(amp);
    CHECK(a.ui().session.amplitude_um == 0.8);
    REQUIRE(a.ui().data);
    for (std::size_t k = 0; k < vbs.size(); ++k)
        CHECK(a.ui().data->points[k].zeta == Approx(vbs[k] / vv(0.8, 60)).epsilon(1e-14));
    UiEdits freq;
    freq.frequency_khz = 30;
    a.sync(freq);
    CHECK(a.ui().session.frequency_khz == 30);
    for (std::size_t k = 0; k < vbs.size(); ++k)
        CHECK(a.ui().data->points[k].zeta == Approx(vbs[k] / vv(0.8, 30)).epsilon(1e-14));
    ::rmdir(dir.c_str());
}

// ---- The start (docs/model.md, "Which steady state"): where two stable states coexist ----

#include "gui/script.hpp"

namespace {

// zeta 0.075, theta 90 deg, rdisp 0.1, i 5: two stable states, r_x = 0.034177 reached from rest and
// 0.997508 from sliding (the brute-force RK4 reference, tests/data/steady_reference.csv).
const Params kTwoStates{0.075, kPi / 2, 0.1, 5};
constexpr double kRxRest = 0.034177137581669, kRxSliding = 0.997507926210302;

} // namespace

TEST_CASE("AppState: a start edit takes effect at sync, restarts the motion from it and asks for its state",
          "[gui][state][start]") {
    AppState a(Model::dahl, kTwoStates, 0.7, 60);
    CHECK(a.ui().session.start == Start::rest);
    CHECK((a.sim().P() - a.sim().T()).norm() == 0);
    pause(a);
    a.sync(UiEdits{});
    for (int k = 0; k < 5; ++k) a.advance(1.0 / 60), a.sync(UiEdits{});
    UiEdits step;
    step.step = true;
    a.sync(step);
    a.advance(1.0 / 60);
    REQUIRE(a.sim().tau() > 0);

    UiEdits queued, panel, later;
    panel.start = Start::rest;
    later.start = Start::sliding; // the later edit of the same field wins
    queued.merge(panel);
    queued.merge(later);
    CHECK(queued.moves_curves());
    CHECK(a.ui().session.start == Start::rest); // queued, not applied
    a.sync(queued);
    CHECK(a.ui().session.start == Start::sliding);
    CHECK(a.sim().tau() == 0);
    CHECK(a.sim().periods() == 0);
    CHECK((a.sim().P() - a.sim().T()).x() == Approx(kTwoStates.zss()).epsilon(1e-15));
    CHECK((a.sim().P() - a.sim().T()).y() == 0);
    CHECK(a.ui().status.find("steady sliding") != std::string::npos);
    // Reset keeps the chosen start.
    a.sync(step);
    a.advance(1.0 / 60);
    UiEdits reset;
    reset.reset = true;
    a.sync(reset);
    CHECK(a.sim().tau() == 0);
    CHECK((a.sim().P() - a.sim().T()).x() == Approx(kTwoStates.zss()).epsilon(1e-15));
    // The same start again is no edit: the motion runs on.
    a.sync(step);
    a.advance(1.0 / 60);
    const double tau = a.sim().tau();
    UiEdits same;
    same.start = Start::sliding;
    a.sync(same);
    CHECK(a.sim().tau() == tau);

    // The worker computes the sliding start's state, and lists both.
    a.worker().wait_idle();
    const auto curves = a.worker().latest();
    REQUIRE(curves);
    CHECK(curves->request.start == Start::sliding);
    CHECK(curves->current.rx == Approx(kRxSliding).margin(1e-3));
    CHECK(coexisting_states(*curves).size() == 2);
    // The session of the state names it.
    CHECK(session_of(a.ui()).start == Start::sliding);
}

TEST_CASE("AppState: the animation from each start ends in that start's state, and the app says which",
          "[gui][state][start]") {
    for (const auto& [start, rx] : {std::pair{Start::rest, kRxRest}, std::pair{Start::sliding, kRxSliding}}) {
        INFO(to_string(start));
        Session s;
        s.params = kTwoStates;
        s.start = start;
        AppState a(s);
        a.worker().wait_idle();
        const auto curves = a.worker().latest();
        REQUIRE(curves);
        const std::vector<SteadyState>& states = coexisting_states(*curves);
        REQUIRE(states.size() == 2);
        // Ordered by r_x: rest's first, sliding's second.
        CHECK(states[0].rx == Approx(kRxRest).margin(1e-3));
        CHECK(states[0].from_rest);
        CHECK(states[1].rx == Approx(kRxSliding).margin(1e-3));
        CHECK(states[1].from_sliding);
        CHECK(state_of_motion(states, a.sim().last_period_mean().x(), kMotionStateTolerance) == -1); // NaN
        // 600 periods of the animation at the top speed: ten 6-second frames (the paper's scheme at its
        // fixed step lands a few 1e-3 from the reference).
        a.sync([] {
            UiEdits e;
            e.speed = kSpeedRange.hi;
            return e;
        }());
        for (int k = 0; k < 10; ++k) a.advance(6.0);
        const double mean = a.sim().last_period_mean().x();
        CHECK(mean == Approx(rx).margin(3e-3));
        CHECK(state_of_motion(states, mean, kMotionStateTolerance) == (start == Start::rest ? 0 : 1));
    }
}

TEST_CASE("state_of_motion: the nearest state within the tolerance and a third of the gap, else settling",
          "[gui][start]") {
    std::vector<SteadyState> states(2);
    states[0].rx = 0.03;
    states[1].rx = 0.99;
    CHECK(state_of_motion(states, 0.031, 1e-2) == 0);
    CHECK(state_of_motion(states, 0.985, 1e-2) == 1);
    CHECK(state_of_motion(states, 0.5, 1e-2) == -1);   // settling
    CHECK(state_of_motion(states, 0.045, 1e-2) == -1); // nearer the first, not yet within the tolerance
    CHECK(state_of_motion(states, std::nan(""), 1e-2) == -1);
    states[1].rx = 0.036; // close states: a third of their gap is the limit
    CHECK(state_of_motion(states, 0.031, 1e-2) == 0);
    CHECK(state_of_motion(states, 0.0325, 1e-2) == -1);
    CHECK(state_of_motion({}, 0.5, 1e-2) == -1);
}

TEST_CASE("app script: start rest|sliding, checked when loaded", "[gui][script][start]") {
    char tmpl[] = "/tmp/fv-start-script-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    const std::string good = dir + "/good.txt";
    std::ofstream(good) << "0 start sliding\n3 start rest\n";
    const Script s = load_script(good);
    const UiState ui;
    CHECK(script_edits(s, 0, ui).start == Start::sliding);
    CHECK(script_edits(s, 3, ui).start == Start::rest);
    CHECK_FALSE(script_edits(s, 1, ui).start);
    const std::string bad = dir + "/bad.txt";
    std::ofstream(bad) << "0 start moving\n";
    CHECK_THROWS_WITH(load_script(bad), bad + ":1: start = 'moving'; allowed: rest, sliding");
    CHECK(script_actions().find("start WORD") != std::string::npos);
}
