// Continuous-time steady-state solver (fv::ode_steady): the lag ODE is the dtau -> 0 limit of the paper's
// scheme (Eqs. (17)-(27)); its periodic state is checked against the exact theta = 0 references, the
// paper's scheme extrapolated to dtau -> 0, closed-form switching instants and physical invariants.
#include "reference/theta0_exact.hpp"

#include "../core/src/solver/lag_phases.hpp" // the solver's own sin/cos
#include "fv/ode_solver.hpp"
#include "fv/paper_scheme.hpp"
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using fv::kPi;
using fv::OdeEventKind;
using fv::Params;
using fv::Vec2;

namespace {

// Root of a monotone function on [a, b] by bisection (the tests' own closed-form instants).
template <class F> double bisect(F f, double a, double b) {
    const double fa = f(a);
    for (int k = 0; k < 200; ++k) {
        const double m = 0.5 * (a + b);
        if ((f(m) > 0) == (fa > 0))
            a = m;
        else
            b = m;
    }
    return 0.5 * (a + b);
}

double exact_rx(double zeta, double rdisp, double i) {
    return i == 0 ? fv::ref::rx_theta0_i0(zeta, rdisp) : fv::ref::rx_theta0_i1(zeta, rdisp);
}

} // namespace

TEST_CASE("ODE: the solver's sin/cos is within 2 ulp of the library's (1e-30 next to the zeros)",
          "[ode][math]") {
    std::mt19937_64 gen(7);
    auto ulps = [](double got, double ref) {
        if (std::abs(got - ref) <= 1e-30)
            return 0.0; // a tiny reduced argument: relative digits lost, not absolute
        const double ulp = std::nextafter(std::abs(ref), INFINITY) - std::abs(ref);
        return std::abs(got - ref) / ulp;
    };
    std::vector<double> xs = {0.0,       -0.0,    1e-300,   1e-8, kPi / 4, kPi / 2, kPi,
                              1.5 * kPi, 2 * kPi, -kPi / 2, 1e6,  -1e6,    1e7,     1e300};
    for (double range : {1.0, 10.0, 1e3, 1e6}) {
        std::uniform_real_distribution<double> u(-range, range);
        for (int k = 0; k < 200000; ++k) xs.push_back(u(gen));
    }
    double worst = 0;
    for (double x : xs) {
        const Vec2 cs = fv::solver::cos_sin(x);
        worst = std::max({worst, ulps(cs.x(), std::cos(x)), ulps(cs.y(), std::sin(x))});
    }
    CHECK(worst <= 2);
    CHECK(std::isnan(fv::solver::cos_sin(std::nan("")).x()));
}

TEST_CASE("ODE: The lag ODE is the dtau -> 0 limit of one step of the paper's scheme", "[ode][derivation]") {
    // One step of Eqs. (17)-(27) from lag L at tau = 0 changes the lag by dL = rate * dtau + O(dtau^2):
    // compare the difference quotient of the paper's stepper with the ODE's right-hand side at two step
    // sizes (the error must shrink ~ dtau).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), th(0, kPi), ex(0, 3);
    for (int trial = 0; trial < 200; ++trial) {
        const double i = trial % 4 == 0 ? 0.0 : (trial % 4 == 1 ? 1.0 : ex(rng));
        const Params p{0.5 + 0.5 * u(rng), th(rng), 2, i};
        const Vec2 L = 0.67 * p.zss() * Vec2(u(rng), u(rng)); // |L| < 0.95 z_ss: strictly inside the disc
        const Vec2 rate = fv::ode_lag_rate(p, 0.0, L, false);
        double err[2];
        for (int k = 0; k < 2; ++k) {
            const int n = (1 << 16) << k;
            fv::PaperStepper st(p, n, L);
            st.step();
            err[k] = ((st.lag() - L) / st.dtau() - rate).norm();
        }
        CAPTURE(p.zeta, p.theta, i, L.x(), L.y(), err[0], err[1]);
        REQUIRE(err[1] < 2e-3);
        REQUIRE(err[1] < 0.75 * err[0] + 1e-9); // first order in dtau
    }
    // On z = z_ss with v > 0 (full deflection) both laws are pursuit: T follows along e, |L| stays z_ss.
    for (double i : {0.0, 0.5, 1.0, 2.0}) {
        const Params p{0.8, 1.0, 2, i};
        const Vec2 L = p.zss() * Vec2(std::cos(0.4), std::sin(0.4)); // v = e . P'(0) > 0
        REQUIRE(L.dot(fv::body_velocity(p, 0)) > 0);
        const Vec2 rate = fv::ode_lag_rate(p, 0.0, L, true);
        fv::PaperStepper st(p, 1 << 18, L);
        st.step();
        CAPTURE(i);
        CHECK(((st.lag() - L) / st.dtau() - rate).norm() < 1e-3);
        CHECK(std::abs(rate.dot(L)) < 1e-14); // tangential: the deflection does not change
    }
}

TEST_CASE("ODE: z -> 0: the right-hand side tends to P' and stays finite", "[ode][robust]") {
    for (double i : {0.0, 0.3, 1.0, 2.7}) {
        const Params p{0.3, 0.7, 3, i};
        const Vec2 dp = fv::body_velocity(p, 1.1);
        CHECK((fv::ode_lag_rate(p, 1.1, Vec2::Zero(), false) - dp).norm() == 0);
        for (double z : {1e-3, 1e-8, 1e-300}) {
            const Vec2 r = fv::ode_lag_rate(p, 1.1, Vec2(z, -z), false);
            REQUIRE(std::isfinite(r.x()));
            REQUIRE(std::isfinite(r.y()));
            CHECK((r - dp).norm() <= 2 * (i + 1) * z * std::sqrt(2.0) * p.rdisp * dp.norm() + 1e-15);
        }
    }
}

TEST_CASE("ODE: theta = 0: r_x agrees with the exact steady state to ~1e-9", "[ode][theta0][exact]") {
    fv::OdeOptions o;
    o.tolerance = 1e-10;
    for (double i : {0.0, 1.0})
        for (double rdisp : {0.2, 1.0, 5.0, 40.0})
            for (double zeta : {0.02, 0.1, 0.4, 0.8, 0.97, 1.2, 3.0}) {
                const auto r = fv::ode_steady({zeta, 0.0, rdisp, i}, o);
                const double e = exact_rx(zeta, rdisp, i);
                CAPTURE(i, rdisp, zeta, r.rx, e, r.error_estimate, r.periods);
                REQUIRE(r.status == fv::SteadyStatus::converged);
                CHECK(std::abs(r.rx - e) < 2e-9);
                CHECK(std::abs(r.ry) < 1e-12);
            }
}

TEST_CASE("ODE: theta = 0: the recorded steady period follows the exact lag L(tau)", "[ode][theta0][exact]") {
    fv::OdeOptions o;
    o.tolerance = 1e-10;
    o.record_period = true;
    o.record_samples = 500;
    for (double i : {0.0, 1.0})
        for (auto [zeta, rdisp] : {std::pair{0.35, 3.0}, std::pair{0.1, 0.5}}) {
            const auto r = fv::ode_steady({zeta, 0.0, rdisp, i}, o);
            REQUIRE(r.period.size() == 500);
            double worst = 0, worst_f = 0;
            for (const auto& s : r.period) {
                const double L = i == 0 ? fv::ref::lag_theta0_i0(zeta, rdisp, s.tau)
                                        : fv::ref::lag_theta0_i1(zeta, rdisp, s.tau);
                worst = std::max(worst, std::abs((s.P.x() - s.T.x()) - L) * rdisp); // force units
                worst_f = std::max(worst_f, s.F.norm());
            }
            CAPTURE(i, zeta, rdisp, worst);
            CHECK(worst < 1e-7); // dense output between steps: 4th order, about the local tolerance
            CHECK(worst_f <= 1 + 1e-12);
            CHECK(r.period.back().tau == Approx(2 * kPi).epsilon(1e-15));
        }
}

TEST_CASE("ODE: theta = 0, i = 0: located events match the closed-form switching instants", "[ode][events]") {
    // P = zeta tau + sin tau moves back on (tau1, tau2), cos tau1 = cos tau2 = -zeta (tau1 = pi - alpha,
    // tau2 = pi + alpha). In steady state the tip slips forward with L = +z until P turns back at tau1
    // (leave_zss), sticks while P comes back; then
    //   B <= 2z: it sticks until P has come forward again by the back travel B (reach_zss at tau2 + h_f,
    //            d_f(h_f) = B);
    //   B > 2z:  it reaches L = -z at tau1 + h_s (d_b(h_s) = -2z) and slips backwards until tau2
    //            (leave_zss), then sticks until P has come forward by 2z (reach_zss at tau2 + h_f).
    fv::OdeOptions o;
    o.tolerance = 1e-10;
    o.record_period = true;
    for (const auto& point : {std::pair{0.3, 2.0}, std::pair{0.6, 0.5}, std::pair{0.15, 10.0}}) {
        const double zeta = point.first, rdisp = point.second; // named (lambdas capture no bindings in C++17)
        const double z = 1 / rdisp, s = std::sqrt(1 - zeta * zeta), alpha = std::acos(zeta);
        const double tau1 = kPi - alpha, tau2 = kPi + alpha;
        auto d_b = [&](double h) { return zeta * (h - std::sin(h)) - s * (1 - std::cos(h)); };
        auto d_f = [&](double h) { return zeta * (h - std::sin(h)) + s * (1 - std::cos(h)); };
        const double B = -d_b(2 * alpha);
        REQUIRE(B == Approx(fv::ref::back_travel_theta0(zeta)).epsilon(1e-12));
        std::vector<std::pair<double, OdeEventKind>> expect;
        expect.push_back({tau1, OdeEventKind::leave_zss});
        if (B <= 2 * z) {
            const double hf = bisect([&](double h) { return d_f(h) - B; }, 0, 2 * kPi - 2 * alpha);
            expect.push_back({tau2 + hf, OdeEventKind::reach_zss});
        } else {
            const double hs = bisect([&](double h) { return d_b(h) + 2 * z; }, 0, 2 * alpha);
            const double hf = bisect([&](double h) { return d_f(h) - 2 * z; }, 0, 2 * kPi - 2 * alpha);
            expect.push_back({tau1 + hs, OdeEventKind::reach_zss});
            expect.push_back({tau2, OdeEventKind::leave_zss});
            expect.push_back({tau2 + hf, OdeEventKind::reach_zss});
        }
        const auto sol = fv::ode_solve({zeta, 0.0, rdisp, 0}, o);
        CAPTURE(zeta, rdisp, B, 2 * z);
        REQUIRE(sol.events.size() == expect.size());
        for (std::size_t k = 0; k < expect.size(); ++k) {
            CAPTURE(k, sol.events[k].tau, expect[k].first);
            CHECK(sol.events[k].kind == expect[k].second);
            CHECK(std::abs(sol.events[k].tau - expect[k].first) < 1e-7);
        }
        // Between the events the lag is what the phases say: +z at tau1, -z or z - B at tau2.
        CHECK(sol.events[0].lag.x() == Approx(z).epsilon(1e-12));
    }
}

TEST_CASE("ODE: Agrees with the paper's scheme extrapolated to dtau -> 0", "[ode][paper]") {
    // dahl_steady's automatic mode extrapolates four resolutions to dtau -> 0 and reports an error
    // estimate; the two must agree within the two estimates (plus a small allowance).
    const std::vector<Params> cases{{0.15, kPi / 2, 2, 1},   {0.15, kPi / 2, 2, 0},   {0.5, kPi / 2, 2, 0},
                                    {0.3, 0.0, 2, 1},        {0.4, kPi / 6, 1.5, 2},  {0.3, 0.5, 2, 0.5},
                                    {0.02, kPi / 2, 0.2, 0}, {0.05, 0.3, 0.2, 2.5},   {0.8, 2.5, 5, 1},
                                    {1.5, kPi / 4, 0.7, 0},  {0.1, 2.0, 20, 0},       {0.25, 1.0, 4, 1.3},
                                    {0.03, kPi / 3, 0.4, 1}, {0.6, 5 * kPi / 6, 1, 0}};
    for (const Params& p : cases) {
        const auto a = fv::ode_steady(p);
        const auto b = fv::dahl_steady(p);
        CAPTURE(p.zeta, p.theta, p.rdisp, p.i, a.rx, b.rx, a.ry, b.ry, a.error_estimate, b.error_estimate);
        REQUIRE(a.status == fv::SteadyStatus::converged);
        REQUIRE(b.status == fv::SteadyStatus::converged);
        const double allowed = a.error_estimate + b.error_estimate + 1e-7;
        CHECK(std::abs(a.rx - b.rx) <= allowed);
        CHECK(std::abs(a.ry - b.ry) <= allowed);
    }
}

TEST_CASE("ODE: The steady state does not depend on the initial lag", "[ode]") {
    fv::OdeOptions o;
    o.tolerance = 1e-10;
    for (double i : {0.0, 0.5, 1.0, 2.0})
        for (double th : {0.0, 0.5, kPi / 2, 2.4}) {
            const Params p{0.3, th, 2, i};
            const auto a = fv::ode_steady(p, o);
            for (Vec2 L0 : {Vec2(0.9 * p.zss(), 0), Vec2(-0.3 * p.zss(), 0.8 * p.zss()),
                            Vec2(-3 * p.zss(), -3 * p.zss()) /* outside the disc: pulled back */}) {
                o.initial_lag = L0;
                const auto b = fv::ode_steady(p, o);
                CAPTURE(i, th, L0.x(), L0.y());
                CHECK(a.rx == Approx(b.rx).margin(1e-8));
                CHECK(a.ry == Approx(b.ry).margin(1e-8));
            }
            o.initial_lag = Vec2::Zero();
        }
}

TEST_CASE("ODE: Invariants: |F| <= 1, z <= z_ss, mirror symmetry theta -> pi - theta", "[ode][invariants]") {
    fv::OdeOptions o;
    o.record_period = true;
    o.record_samples = 256;
    for (double i : {0.0, 0.3, 1.0, 2.5, 3.0}) {
        const Params p{0.25, 1.0, 4, i};
        const auto r = fv::ode_steady(p, o);
        for (const auto& s : r.period) {
            REQUIRE(s.F.norm() <= 1 + 1e-9);
            REQUIRE(s.z <= p.zss() * (1 + 1e-9));
            REQUIRE((s.P - fv::body_point(p, s.tau)).norm() < 1e-12);
        }
        const auto m = fv::ode_steady({0.25, kPi - 1.0, 4, i});
        CAPTURE(i);
        CHECK(r.rx == Approx(m.rx).margin(1e-7));
        CHECK(r.ry == Approx(-m.ry).margin(1e-7));
        CHECK(std::abs(fv::ode_steady({0.25, kPi / 2, 4, i}).ry) < 1e-7);
    }
}

TEST_CASE("ODE: Limits: rigid for rdisp -> infinity, r_x = 1 at theta = 0 for zeta >= 1 and every i",
          "[ode][limit]") {
    for (double i : {0.0, 1.0})
        for (double th : {0.0, kPi / 3}) {
            const double rigid = fv::rigid_ratio(0.4, th).rx;
            double prev = 1;
            for (double rdisp : {5.0, 50.0, 500.0}) {
                const double gap = std::abs(fv::ode_steady({0.4, th, rdisp, i}).rx - rigid);
                CAPTURE(i, th, rdisp, gap);
                CHECK(gap < prev);
                prev = gap;
            }
            CHECK(prev < 5e-3);
        }
    // The tip ends up slipping forward at full deflection: for i > 1 the paper's scheme gets there only
    // algebraically, the fixed point is found directly.
    for (double i : {0.0, 0.5, 1.0, 2.0, 3.0}) {
        const auto r = fv::ode_steady({1.5, 0.0, 0.5, i});
        CAPTURE(i);
        CHECK(r.status == fv::SteadyStatus::converged);
        CHECK(r.rx == Approx(1).margin(1e-9));
    }
}

TEST_CASE("ODE: Sweeps: warm-started families give the cold-start results", "[ode][sweep]") {
    const auto zetas = fv::linspace(0.02, 1.5, 12);
    const auto pts = fv::ode_sweep_zeta(zetas, {0.0, kPi / 2}, {0.5, 5}, {0.0, 1.0}, {}, 2);
    REQUIRE(pts.size() == 12 * 2 * 2 * 2);
    for (const auto& sp : pts) {
        const auto cold = fv::ode_steady(sp.params);
        CAPTURE(sp.params.zeta, sp.params.theta, sp.params.rdisp, sp.params.i);
        CHECK(sp.result.status == fv::SteadyStatus::converged);
        CHECK(sp.result.rx == Approx(cold.rx).margin(1e-7));
        CHECK(sp.result.ry == Approx(cold.ry).margin(1e-7));
        CHECK(sp.result.period.empty());
    }
    // Order: i, theta, rdisp, zeta (zeta fastest), like fv::sweep.
    CHECK(pts[1].params.zeta == zetas[1]);
    CHECK(pts[12].params.rdisp == 5);
    CHECK(pts[24].params.theta == kPi / 2);
    CHECK(pts[48].params.i == 1);
}

TEST_CASE("ODE: Every case ends with a clear status, bad parameters are refused", "[ode][status]") {
    for (const Params& p :
         {Params{0.02, 0.0, 0.2, 0}, Params{0.02, kPi / 2, 0.2, 1}, Params{1.5, 0, 0.5, 3},
          Params{0.0, kPi / 3, 0.3, 2}, Params{0.05, 0.3, 0.2, 2.5}, Params{3, 0.1, 100, 1}}) {
        const auto r = fv::ode_steady(p);
        CAPTURE(p.zeta, p.theta, p.rdisp, p.i, r.periods, r.error_estimate, fv::to_string(r.status));
        CHECK(std::isfinite(r.rx));
        CHECK(std::isfinite(r.ry));
        if (r.status == fv::SteadyStatus::converged) CHECK(r.error_estimate < 1e-6);
    }
    fv::OdeOptions o;
    o.max_periods = 1; // one period cannot show that the state is periodic
    const auto r = fv::ode_steady({0.3, 0.5, 2, 1}, o);
    CHECK(r.status == fv::SteadyStatus::not_converged);
    CHECK(r.error_estimate > o.tolerance);
    CHECK_THROWS_AS(fv::ode_steady({-1, 0, 1, 1}), std::invalid_argument);
    CHECK_THROWS_AS(fv::ode_steady({0.5, 0, 0, 1}), std::invalid_argument);
    CHECK_THROWS_AS(fv::ode_steady({0.5, 0, 1, -0.5}), std::invalid_argument);
}
