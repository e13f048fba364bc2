// Which steady state (docs/model.md, "Which steady state"): the start that decides between coexisting states,
// period-k motion, motion that does not repeat, Floquet multipliers, and a looser tolerance that never turns
// an answer into a failure. References are independent of the solver: closed forms, and long integrations by
// another integrator (quoted where used).
#include "fv/ode_solver.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

constexpr double kDeg = fv::kPi / 180;

fv::SteadyResult solve(double zeta, double theta_deg, double rdisp, double i, fv::Start start,
                       double tol = fv::kDefaultOdeTolerance) {
    fv::OdeOptions o;
    o.start = start;
    o.tolerance = tol;
    return fv::ode_steady({zeta, theta_deg * kDeg, rdisp, i}, o);
}

} // namespace

// Vibration switched on during steady sliding at theta = 90 deg with zeta > 0: the tip stays on the circle
// (v = e . P' ~ zeta > 0 all along) and its angle obeys phi' = r (cos tau cos phi - zeta sin phi). Expanded
// in r: phi = r sin tau + r^2 zeta cos tau + O(r^3) with zero means, so r_x = mean cos phi = 1 - r^2/4 +
// O(r^4 (1 + zeta^2)) for every i: the saturated state, not the one reached from rest.
TEST_CASE("Start sliding at 90 deg gives the saturated state 1 - r^2/4", "[states]") {
    for (const double i : {0.5, 2.0, 10.0})
        for (const double r : {1e-3, 1e-2}) {
            const double zeta = 0.5;
            const auto s = solve(zeta, 90, r, i, fv::Start::sliding);
            CAPTURE(i, r, s.rx, s.error_estimate, fv::status_word(s));
            REQUIRE(fv::ok(s.status));
            CHECK(s.start == fv::Start::sliding);
            CHECK(std::abs(s.rx - (1 - r * r / 4)) <= r * r * r * r * (1 + zeta * zeta) + s.error_estimate);
            CHECK(std::abs(s.ry) <= 1e-9);
            // On the circle the radial multiplier is the approach from inside: 1 for i > 1 (algebraic),
            // so the state is reported as slow; for i < 1 it is 0 (reached in finite time).
            REQUIRE(s.have_multipliers);
            if (i > 1) {
                CHECK(s.largest_multiplier() == Approx(1));
                CHECK(s.slow());
            }
            CHECK(std::abs(s.multipliers[1]) <= std::abs(s.multipliers[0]));
        }
}

// From rest the paper's procedure (step until periodic from T = P) reaches the small state at zeta = 0.001,
// theta = 90 deg, rdisp = 0.001, i = 10: an independent implementation of the scheme gives 0.00018968 after
// 652 periods. The sliding start reaches the saturated state 1 - r^2/4: two states, told apart by the start.
TEST_CASE("Two starts two states at 90 deg", "[states]") {
    const auto sliding = solve(0.001, 90, 0.001, 10, fv::Start::sliding);
    REQUIRE(fv::ok(sliding.status));
    CHECK(sliding.rx == Approx(1 - 0.25e-6).margin(1e-9));
    fv::SteadyOptions paper;
    paper.scheme = fv::Scheme::paper;
    paper.start = fv::Start::rest;
    const auto rest = fv::steady_ratio(fv::Model::dahl, {0.001, 90 * kDeg, 0.001, 10}, paper);
    CHECK(rest.start == fv::Start::rest);
    CHECK(rest.rx == Approx(0.00018968).margin(2e-7));
}

// Where the 1-period state is unstable through a multiplier below -1 the motion from rest repeats every 2 or
// 4 periods (4 pi or 8 pi); means over them from an independent long integration (thousands of periods):
// 0.2149399 and 0.2629884.
TEST_CASE("Period-k motion is found and reported as period_k", "[states]") {
    const struct { double zeta, theta, rx; } cases[] = {{0.405, 32, 0.2149399}, {0.45, 30, 0.2629884}};
    for (const auto& c : cases) {
        const auto s = solve(c.zeta, c.theta, 2, 10, fv::Start::rest);
        CAPTURE(c.zeta, c.theta, s.rx, s.error_estimate, fv::status_word(s));
        REQUIRE(s.status == fv::SteadyStatus::periodic);
        CHECK(fv::ok(s.status));
        CHECK((s.period_k == 2 || s.period_k == 4));
        CHECK(fv::status_word(s) == "period_" + std::to_string(s.period_k));
        CHECK(s.rx == Approx(c.rx).margin(1e-6));
        CHECK(s.error_estimate <= 1e-8);
        REQUIRE(s.have_multipliers);
        CHECK(s.largest_multiplier() < 1);
    }
}

// zeta = 0.075, theta = 30 deg, rdisp = 100, i = 10: the motion never repeats (the paper's scheme and an RK4
// integration wander, long-time mean 0.0601 +- 5e-4). Exit status 3 with the long-time mean and its error.
TEST_CASE("Motion that does not repeat is not_periodic with a standard error", "[states]") {
    const auto s = solve(0.075, 30, 100, 10, fv::Start::rest);
    CAPTURE(s.rx, s.mean_standard_error, fv::status_word(s));
    REQUIRE(s.status == fv::SteadyStatus::not_periodic);
    CHECK_FALSE(fv::ok(s.status));
    CHECK(s.window >= 1000);
    CHECK(s.mean_standard_error > 0);
    CHECK(std::abs(s.rx - 0.0601) <= 3 * std::hypot(s.mean_standard_error, 5e-4));
}

// A point verified at the default tolerance is verified at every looser one (the solver falls back to the
// default's answer), and the value agrees within the looser tolerance.
TEST_CASE("A looser tolerance never fails where the default succeeds", "[states]") {
    const struct {
        double zeta, theta, rdisp, i;
    } pts[] = {{0.5, 45, 1, 10}, {0.405, 32, 2, 10}, {0.3, 40, 1, 1}, {2, 90, 1000, 1}};
    for (const auto& q : pts) {
        const auto ref = solve(q.zeta, q.theta, q.rdisp, q.i, fv::Start::rest);
        REQUIRE(fv::ok(ref.status));
        for (const double tol : {1e-6, 1e-5, 1e-4}) {
            const auto s = solve(q.zeta, q.theta, q.rdisp, q.i, fv::Start::rest, tol);
            CAPTURE(q.zeta, q.theta, q.rdisp, q.i, tol, fv::status_word(s), s.rx, ref.rx);
            CHECK(fv::ok(s.status));
            CHECK(std::abs(s.rx - ref.rx) <= tol + ref.error_estimate);
        }
    }
}

// The check, on a whole i = 10 grid (1050 points over the period-k and slow bands): wherever the
// default tolerance verifies a state, 1e-6 does too, within 1e-6 (plus the default's own estimate) of it.
TEST_CASE("A looser tolerance never fails where the default succeeds: the i = 10 grid",
          "[states][slow][long]") {
    std::vector<fv::Params> pts;
    for (const double rdisp : {0.1, 1.0, 2.0, 10.0, 100.0, 1000.0})
        for (int t = 0; t <= 6; ++t)
            for (int z = 0; z < 25; ++z) pts.push_back({0.05 + 0.04 * z, 15.0 * t * kDeg, rdisp, 10});
    REQUIRE(pts.size() == 1050);
    std::vector<fv::SteadyResult> tight(pts.size()), loose(pts.size());
    fv::parallel_for(static_cast<int>(pts.size()), [&](int k) {
        const auto u = static_cast<std::size_t>(k);
        fv::OdeOptions o;
        tight[u] = fv::ode_steady(pts[u], o);
        o.tolerance = 1e-6;
        loose[u] = fv::ode_steady(pts[u], o);
    });
    int verified = 0;
    for (std::size_t u = 0; u < pts.size(); ++u) {
        if (!fv::ok(tight[u].status)) continue;
        ++verified;
        CAPTURE(pts[u].zeta, pts[u].theta / kDeg, pts[u].rdisp, fv::status_word(loose[u]), loose[u].rx,
                tight[u].rx);
        CHECK(fv::ok(loose[u].status));
        CHECK(std::abs(loose[u].rx - tight[u].rx) <= 1e-6 + tight[u].error_estimate);
    }
    CHECK(verified >= 1000);
}

// The two schemes from the same start agree where both vouch for a state: the continuous-time solver and the
// paper's stepping scheme (Eqs. 17-27, extrapolated to dtau -> 0), both from rest, within the sum of their
// error estimates (the ode's with its safety factor). The grid covers theta = 90 deg with r_disp <= 0.01 and
// i >= 2, where the start decides the state (the ode solver once reported the saturated state there), and the
// i = 10 band of period-k and slow cells.
TEST_CASE("The ode solver and the paper's scheme agree from rest wherever both vouch for a state",
          "[states][long]") {
    std::vector<fv::Params> pts;
    for (const double rdisp : {0.001, 0.01})
        for (const double i : {2.0, 5.0, 10.0})
            for (const double zeta : {0.001, 0.01, 0.1}) pts.push_back({zeta, 90 * kDeg, rdisp, i});
    for (const double zeta : {0.2, 0.3, 0.5})
        for (const double theta : {30.0, 60.0}) pts.push_back({zeta, theta * kDeg, 2, 10});
    std::vector<fv::SteadyResult> ode(pts.size()), paper(pts.size());
    fv::parallel_for(static_cast<int>(pts.size()), [&](int k) {
        const auto u = static_cast<std::size_t>(k);
        ode[u] = fv::steady_ratio(fv::Model::dahl, pts[u]);
        fv::SteadyOptions o;
        o.scheme = fv::Scheme::paper;
        paper[u] = fv::steady_ratio(fv::Model::dahl, pts[u], o);
    });
    int compared = 0, theta90_small = 0;
    for (std::size_t u = 0; u < pts.size(); ++u) {
        CAPTURE(pts[u].zeta, pts[u].theta / kDeg, pts[u].rdisp, pts[u].i, fv::status_word(ode[u]), ode[u].rx,
                ode[u].error_estimate, fv::status_word(paper[u]), paper[u].rx, paper[u].error_estimate);
        CHECK(ode[u].start == fv::Start::rest);
        if (!fv::ok(ode[u].status) || !fv::ok(paper[u].status)) continue;
        ++compared;
        if (pts[u].rdisp <= 0.01) ++theta90_small;
        const double bound = fv::kErrorSafety * ode[u].error_estimate + paper[u].error_estimate;
        CHECK(std::abs(ode[u].rx - paper[u].rx) <= bound);
        CHECK(std::abs(ode[u].ry - paper[u].ry) <= bound);
    }
    // The paper's scheme stops short where the motion from rest climbs slowly (i >= 2, zeta >= 0.01 at
    // r_disp 0.001): 12 of the 24 points are compared, 7 of them at theta = 90 deg with r_disp <= 0.01.
    CHECK(compared >= 12);
    CHECK(theta90_small >= 7);
}

// The paper's Figs. 10-13 lie where the steady state is unique: along every curve both starts reach one
// state (docs/cli.md, "Which steady state", says so, and the figures are the same from either start).
TEST_CASE("Along the curves of Figs. 10-13 both starts reach one steady state", "[states][long]") {
    std::vector<fv::Params> pts;
    for (const double theta : {0.0, 90.0})
        for (const double i : {0.0, 1.0})
            for (const double rdisp : {0.5, 1.0, 2.0, 5.0, 20.0})
                for (int z = 0; z < 50; ++z) pts.push_back({0.02 + 0.06 * z, theta * kDeg, rdisp, i});
    std::vector<fv::SteadyResult> res(pts.size());
    fv::parallel_for(static_cast<int>(pts.size()), [&](int k) {
        fv::SteadyOptions o;
        o.list_states = true;
        res[static_cast<std::size_t>(k)] =
            fv::steady_ratio(fv::Model::dahl, pts[static_cast<std::size_t>(k)], o);
    });
    for (std::size_t u = 0; u < pts.size(); ++u) {
        CAPTURE(pts[u].zeta, pts[u].theta / kDeg, pts[u].rdisp, pts[u].i, fv::status_word(res[u]));
        REQUIRE(fv::ok(res[u].status));
        CHECK(res[u].states.size() == 1);
        CHECK(res[u].states.at(0).from_rest);
        CHECK(res[u].states.at(0).from_sliding);
    }
}
