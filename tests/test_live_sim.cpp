// The app's live simulation: same scheme as the steady-state solver, continuous under slider edits,
// bounded memory.
#include "fv/live_sim.hpp"
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"

#include <catch2/catch.hpp>

using fv::kPi;

TEST_CASE("LiveSim: its period mean converges to the steady r_x of the same scheme", "[live]") {
    const fv::Params p{0.3, 1.0, 2, 1};
    fv::LiveSim sim(fv::Model::dahl, p);
    for (int k = 0; k < 40; ++k) sim.step(sim.steps_per_period());
    fv::SteadyOptions o;
    o.steps_per_period = sim.steps_per_period();
    o.tolerance = 1e-12;
    const auto ref = fv::dahl_steady(p, o);
    CHECK(sim.last_period_mean().x() == Approx(ref.rx).margin(1e-9));
    CHECK(sim.last_period_mean().y() == Approx(ref.ry).margin(1e-9));
    CHECK(sim.periods() == 40);
}

TEST_CASE("LiveSim: rigid model averages the unit velocity, Eq. (9)", "[live]") {
    fv::LiveSim sim(fv::Model::rigid, {0.5, kPi / 3, 2, 1});
    sim.step(sim.steps_per_period());
    const auto r = fv::rigid_ratio(0.5, kPi / 3);
    CHECK(sim.last_period_mean().x() == Approx(r.rx).margin(5e-3)); // rectangle rule at 360 steps
    CHECK(sim.force().norm() == Approx(1).epsilon(1e-12));
}

TEST_CASE("LiveSim: a parameter edit keeps P in place and the deflection within the new z_ss", "[live]") {
    fv::LiveSim sim(fv::Model::dahl, {0.2, kPi / 2, 1, 0});
    sim.step(1000);
    const fv::Vec2 P0 = sim.P();
    sim.apply(fv::Model::dahl, {1.5, 0.3, 10, 1}); // z_ss 1 -> 0.1
    CHECK((sim.P() - P0).norm() < 1e-12);
    CHECK(sim.z() <= 0.1 + 1e-12);
    sim.step(10);
    CHECK((sim.P() - P0).norm() < 0.2); // no jump: 10 small steps away
}

TEST_CASE("LiveSim: history keeps only the requested number of periods", "[live]") {
    fv::LiveSim sim(fv::Model::dahl, {0.2, 1.0, 2, 1});
    sim.set_history_periods(1.5);
    sim.step(sim.steps_per_period() * 5);
    const auto& h = sim.history();
    CHECK(h.back().tau - h.front().tau <= 1.5 * 2 * kPi + 1e-9);
    CHECK(h.back().tau - h.front().tau >= 1.5 * 2 * kPi - 2 * sim.dtau());
}

TEST_CASE("LiveSim: reset to the sliding start puts P - T = z_ss along +x, the force F_c along v_b",
          "[live]") {
    const fv::Params p{0.075, kPi / 2, 0.1, 5}; // z_ss = 10 x_v
    fv::LiveSim sim(fv::Model::dahl, p);
    sim.step(500);
    sim.reset(fv::Start::sliding);
    CHECK(sim.tau() == 0);
    CHECK(sim.periods() == 0);
    CHECK(sim.history().size() == 1);
    const fv::Vec2 lag = sim.P() - sim.T();
    CHECK(lag.x() == Approx(p.zss()).epsilon(1e-15));
    CHECK(lag.y() == 0);
    CHECK(sim.z() == Approx(10).epsilon(1e-15));
    CHECK(sim.force().x() == Approx(1).epsilon(1e-15));
    CHECK(sim.force().y() == 0);
    CHECK(sim.slipping());
    // The rest start: T = P, no force. The rigid model has no lag: both starts are the same.
    sim.reset(fv::Start::rest);
    CHECK((sim.P() - sim.T()).norm() == 0);
    CHECK(sim.force().norm() == 0);
    fv::LiveSim rigid(fv::Model::rigid, p);
    rigid.reset(fv::Start::sliding);
    CHECK((rigid.P() - rigid.T()).norm() == 0);
}

TEST_CASE("LiveSim: where two stable states coexist, each start's animation lands on its own", "[live]") {
    // zeta 0.075, theta 90 deg, rdisp 0.1, i 5: r_x = 0.034177 from rest, 0.997508 from sliding (the
    // brute-force RK4 reference, tests/data/steady_reference.csv). The animation steps the paper's scheme
    // at its fixed step: a few 1e-3 off the dtau -> 0 limit.
    const fv::Params p{0.075, kPi / 2, 0.1, 5};
    for (const auto& [start, rx] :
         {std::pair{fv::Start::rest, 0.034177137581669}, std::pair{fv::Start::sliding, 0.997507926210302}}) {
        INFO(fv::to_string(start));
        fv::LiveSim sim(fv::Model::dahl, p);
        sim.reset(start);
        for (int k = 0; k < 100; ++k) sim.step(sim.steps_per_period());
        CHECK(sim.last_period_mean().x() == Approx(rx).margin(3e-3));
    }
}
