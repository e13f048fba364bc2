// The classroom app's time and explanation, without a window: rewinding shows the past
// from the history, replay returns to the live state, the jump lands on the solver's steady state, and the
// spring's colour is stick or slip where the 1-D law (theta = 0, i = 0) says so.
#include "gui/app_state.hpp"
#include "gui/dashboard.hpp"

#include "fv/ode_solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fv;
using namespace fv::app;

namespace {

void run_periods(AppState& a, double periods) {
    UiEdits e;
    e.playing = true;
    e.speed = 1;
    a.sync(e);
    for (int k = 0; k < static_cast<int>(periods * 60); ++k) a.advance(1.0 / 60);
}

// The spring P-T of the top view: the unlabelled zigzag series ending at P.
const SeriesData* spring(const PanelData& panel, const Vec2& P) {
    for (const SeriesData& s : panel.series)
        if (s.label.empty() && s.x.size() > 10 && s.x.back() == P.x() && s.y.back() == P.y()) return &s;
    return nullptr;
}

// Root of f on [a, b] by bisection (f(a), f(b) of opposite signs).
template <class F> double bisect(F f, double a, double b) {
    for (int k = 0; k < 200; ++k) {
        const double m = 0.5 * (a + b);
        (f(a) < 0) == (f(m) < 0) ? a = m : b = m;
    }
    return 0.5 * (a + b);
}

} // namespace

TEST_CASE("App time: rewind shows the past, replay returns to the live state, a frame back pauses",
          "[gui][time]") {
    AppState a(Model::dahl, Params{0.3, kPi / 3, 2, 1}, 0.7, 60);
    run_periods(a, 3);
    const double live = a.sim().tau();
    REQUIRE(max_rewind(a.sim()) > 2 * kPi);
    UiEdits e;
    e.rewind = kPi;
    a.sync(e);
    CHECK_FALSE(a.ui().session.playing); // scrubbing pauses
    const SimMoment m = moment_at(a.sim(), a.ui().session.view.rewind);
    CHECK(m.tau == Approx(live - kPi).margin(a.sim().dtau()));
    // The moment is the history's sample: P, T and the force of that time, not of now.
    CHECK((m.P - m.T).norm() == Approx(m.z));
    CHECK(std::abs(m.P.x() - a.sim().P().x()) > 0.1); // P drifted at v_b since
    a.advance(1.0);                                   // paused: nothing moves
    CHECK(a.sim().tau() == live);
    // Replay: the shown time moves towards now at the speed, the simulation waits.
    UiEdits play;
    play.playing = true;
    a.sync(play);
    a.advance(0.25); // a quarter period at 1 period/s
    CHECK(a.sim().tau() == live);
    CHECK(a.ui().session.view.rewind == Approx(kPi - kPi / 2).margin(1e-12));
    for (int k = 0; k < 60; ++k) a.advance(1.0 / 60);
    CHECK(a.ui().session.view.rewind == 0);
    CHECK(a.sim().tau() > live); // live again, and running
    // One frame back pauses and shows 1/60 s of animation earlier; it never reaches past the history.
    UiEdits back;
    back.step_back = true;
    a.sync(back);
    CHECK_FALSE(a.ui().session.playing);
    CHECK(a.ui().session.view.rewind == Approx(a.ui().session.speed * 2 * kPi / 60));
    UiEdits far;
    far.rewind = 1e6;
    a.sync(far);
    CHECK(a.ui().session.view.rewind == Approx(max_rewind(a.sim())));
    // Any parameter change shows the live state again.
    UiEdits change;
    Params p = a.ui().session.params;
    p.zeta = 0.5;
    change.params = p;
    a.sync(change);
    CHECK(a.ui().session.view.rewind == 0);
}

TEST_CASE("App time: 'steady state' lands on the solver's periodic state", "[gui][time]") {
    // The animation (the paper's scheme at a fixed step) started on the solver's L*: its period mean of F_x
    // is the solver's r_x up to the scheme's step error, at once, where from rest it takes periods to settle.
    for (const Params& p : {Params{0.3, kPi / 2, 2, 1}, Params{0.15, kPi / 4, 5, 0}, Params{0.8, 0, 1, 2}}) {
        AppState a(Model::dahl, p, 0.7, 60);
        UiEdits e;
        e.jump_steady = true;
        a.sync(e);
        const SteadyResult exact = ode_steady(p);
        INFO("zeta " << p.zeta << " theta " << p.theta << " rdisp " << p.rdisp << " i " << p.i);
        REQUIRE(std::isfinite(a.sim().last_period_mean().x()));
        CHECK(a.sim().last_period_mean().x() == Approx(exact.rx).margin(3e-3));
        CHECK(a.sim().last_period_mean().y() == Approx(exact.ry).margin(3e-3));
    }
    // The rigid model has no transient: nothing to jump over, and it says so.
    AppState r(Model::rigid, Params{0.3, kPi / 2, 2, 1}, 0.7, 60);
    UiEdits e;
    e.jump_steady = true;
    r.sync(e);
    CHECK(r.ui().status.find("no transient") != std::string::npos);
}

TEST_CASE("App scene: the spring is green while the tip sticks and reddish purple while it slips (theta = 0, "
          "i = 0)",
          "[gui][scene]") {
    // theta = 0, i = 0 is a 1-D stick-slip element: P = zeta tau + sin tau (in x_v). In the steady state with
    // 2 z_ss longer than P's backward travel, the tip slips forward until P turns back (zeta + cos tau = 0 at
    // tau1), sticks while P goes back and forth, and slips again once P has come back to where it turned
    // (tau3 with P(tau3) = P(tau1)).
    const Params p{0.3, 0, 1, 0};
    const double tau1 = std::acos(-p.zeta), tau2 = 2 * kPi - tau1;
    auto P = [&](double t) { return p.zeta * t + std::sin(t); };
    REQUIRE(P(tau1) - P(tau2) < 2 * p.zss()); // never slips backwards
    const double tau3 = bisect([&](double t) { return P(t) - P(tau1); }, tau2, tau1 + 2 * kPi);
    LiveSim sim(Model::dahl, p);
    sim.start_steady(ode_solve(p).lag);
    sim.step(sim.steps_per_period()); // one steady period: tau = 2 pi k
    auto at = [&](double phase) {
        const double target = std::ceil(sim.tau() / (2 * kPi)) * 2 * kPi + phase;
        sim.step(static_cast<int>(std::lround((target - sim.tau()) / sim.dtau())));
        return top_view_panel(sim, ViewState{});
    };
    struct Case {
        double phase;
        bool slips;
    };
    for (const Case c : {Case{0.5 * (tau1 + tau3), false}, Case{tau2, false},
                         Case{0.5 * (tau3 + tau1 + 2 * kPi), true}, Case{1.0, true}}) {
        const PanelData panel = at(std::fmod(c.phase, 2 * kPi));
        INFO("phase " << std::fmod(c.phase, 2 * kPi) << ", tau1 " << tau1 << ", tau3 " << tau3);
        const SeriesData* s = spring(panel, sim.P());
        REQUIRE(s != nullptr);
        CHECK(s->ink == (c.slips ? Ink::slip : Ink::pull));
        REQUIRE(panel.circles.size() == 1);
        CHECK(panel.circles[0].ink == (c.slips ? Ink::slip : Ink::pull));
        CHECK(sim.slipping() == c.slips);
    }
}

TEST_CASE("App loop: the energy per period is what the friction law dissipates", "[gui][loop]") {
    // i = 0: the tip only moves while it slips, pulled with |F| = F_c along P - T, and the spring's energy
    // returns to its value after a period, so the work against friction is F_c times the path of T.
    for (const Params& p : {Params{0.3, kPi / 3, 2, 0}, Params{0.1, kPi / 2, 5, 0}, Params{0.6, 0, 1, 0}}) {
        LiveSim sim(Model::dahl, p);
        sim.start_steady(ode_solve(p).lag);
        sim.step(sim.steps_per_period());
        const LoopData loop = hysteresis_loop(sim);
        REQUIRE(loop.complete);
        double path = 0;
        const auto& h = sim.history();
        for (std::size_t k = 1; k < h.size(); ++k)
            if (h[k].tau > sim.tau() - 2 * kPi + 1e-9) path += (h[k].T - h[k - 1].T).norm();
        INFO("zeta " << p.zeta << " theta " << p.theta << " rdisp " << p.rdisp);
        CHECK(loop.work > 0);
        CHECK(loop.work == Approx(path).epsilon(0.01));
    }
    // Rigid: F_c against the velocity at every instant, so W is the length of P's path over a period.
    const Params p{0.4, kPi / 4, 2, 1};
    LiveSim sim(Model::rigid, p);
    sim.step(2 * sim.steps_per_period());
    double length = 0;
    constexpr int kN = 200000;
    for (int k = 0; k < kN; ++k) length += body_velocity(p, 2 * kPi * (k + 0.5) / kN).norm() * 2 * kPi / kN;
    CHECK(hysteresis_loop(sim).work == Approx(length).epsilon(0.005));
}

TEST_CASE("App pins: up to six r_x(zeta) curves kept with their parameters, cleared at once", "[gui][pins]") {
    AppState a(Model::dahl, Params{0.3, kPi / 3, 2, 0}, 0.7, 60);
    UiEdits pin;
    pin.pin = true;
    a.sync(pin, true);
    REQUIRE(a.ui().session.pins.size() == 1);
    CHECK(a.ui().session.pins[0].label.find("θ = 60°") != std::string::npos);
    CHECK(a.ui().session.pins[0].label.find("i = 0") != std::string::npos);
    const auto curves = a.worker().latest();
    REQUIRE(curves);
    CHECK(a.ui().session.pins[0].rx == curves->model_rx);
    for (int k = 0; k < 8; ++k) {
        UiEdits e;
        Params p = a.ui().session.params;
        p.theta = (10.0 + 10 * k) * kPi / 180;
        e.params = p;
        e.pin = true;
        a.sync(e, true);
    }
    CHECK(a.ui().session.pins.size() == kMaxPins);
    CHECK(a.ui().status.find("clear") != std::string::npos);
    UiEdits clear;
    clear.clear_pins = true;
    a.sync(clear);
    CHECK(a.ui().session.pins.empty());
}

TEST_CASE("App presentation: every length of a panel grows by the factor, its data do not",
          "[gui][present]") {
    LiveSim sim(Model::dahl, Params{0.3, kPi / 3, 2, 0});
    sim.step(200);
    const PanelData a = top_view_panel(sim, ViewState{});
    const PanelData b = enlarged(a, 1.4f);
    CHECK(b.text_scale == Approx(1.4));
    REQUIRE(a.series.size() == b.series.size());
    for (std::size_t k = 0; k < a.series.size(); ++k) {
        CHECK(b.series[k].width == Approx(1.4 * a.series[k].width));
        CHECK(b.series[k].x == a.series[k].x);
    }
    for (std::size_t k = 0; k < a.points.size(); ++k)
        CHECK(b.points[k].size == Approx(1.4 * a.points[k].size));
    for (std::size_t k = 0; k < a.arrows.size(); ++k)
        CHECK(b.arrows[k].width == Approx(1.4 * a.arrows[k].width));
    CHECK(b.x_min == a.x_min);
    CHECK(b.y_max == a.y_max);
}

TEST_CASE("App mechanism: the live arrows are the velocity and the friction on the body now",
          "[gui][mechanism]") {
    const Params p{0.5, kPi / 2, 2, 1};
    LiveSim rigid(Model::rigid, p);
    rigid.step(100);
    MechanismBase base;
    const PanelData m = mechanism_panel_live(rigid, base);
    REQUIRE(m.arrows.size() >= 2);
    // Eq. (1): v/v_v = (zeta + cos tau cos theta, cos tau sin theta); Eq. (2): friction -F_c v/|v|.
    const double c = std::cos(rigid.tau());
    const Vec2 v{p.zeta + c * std::cos(p.theta), c * std::sin(p.theta)};
    const ArrowData& vel = m.arrows[m.arrows.size() - 2];
    const ArrowData& fr = m.arrows.back();
    CHECK((vel.to - v).norm() < 1e-12);
    CHECK((fr.to + v / v.norm()).norm() < 1e-12);
    // Dahl: the friction on the body is -F, F = (P - T)/z_ss.
    LiveSim dahl(Model::dahl, p);
    dahl.step(100);
    const PanelData d = mechanism_panel_live(dahl, base);
    CHECK((d.arrows.back().to + (dahl.P() - dahl.T()) / p.zss()).norm() < 1e-9);
}
