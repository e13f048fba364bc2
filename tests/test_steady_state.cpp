// Periodic steady state, Eqs. (30)-(33): limits, invariants and termination.
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using fv::kPi;
using fv::Params;
using fv::SteadyStatus;
using fv::Vec2;

TEST_CASE("r_disp -> infinity approaches the rigid model", "[steady][limit][long]") {
    // A stiff asperity (z_ss -> 0) slips all the time with |F| = F_c along the velocity: Eq. (9).
    for (double i : {0.0, 1.0})
        for (double th : {0.0, kPi / 4, kPi / 2})
            for (double zeta : {0.2, 0.8}) {
                const double rigid = fv::rigid_ratio(zeta, th).rx;
                double prev = 1;
                for (double rdisp : {5.0, 50.0, 500.0}) {
                    const double gap = std::abs(fv::dahl_steady({zeta, th, rdisp, i}).rx - rigid);
                    CAPTURE(i, th, zeta, rdisp, gap);
                    CHECK(gap < prev); // monotonically closer
                    prev = gap;
                }
                CHECK(prev < 5e-3);
            }
}

TEST_CASE("The steady state does not depend on the initial state", "[steady]") {
    for (double i : {0.0, 0.5, 1.0})
        for (double th : {0.0, 0.5, kPi / 2}) {
            const Params p{0.3, th, 2, i};
            fv::SteadyOptions o;
            o.steps_per_period = 2048;
            o.tolerance = 1e-11;
            const auto a = fv::dahl_steady(p, o);
            o.initial_lag = Vec2(0.9 * p.zss(), 0);
            const auto b = fv::dahl_steady(p, o);
            o.initial_lag = Vec2(-0.3 * p.zss(), 0.8 * p.zss());
            const auto c = fv::dahl_steady(p, o);
            CAPTURE(i, th);
            CHECK(a.rx == Approx(b.rx).margin(1e-8));
            CHECK(a.rx == Approx(c.rx).margin(1e-8));
            CHECK(a.ry == Approx(c.ry).margin(1e-8));
        }
}

TEST_CASE("i = 0 and i = 1 agree where the asperity never relaxes (Fig. 17/18)", "[steady]") {
    // If in steady state z = z_ss throughout (the deflection never shrinks), both laws reduce to pure
    // pursuit at distance z_ss: Eq. (27) clamps at z_ss, Eq. (20) has dz = 0 at z = z_ss.
    for (auto [zeta, th] : {std::pair{0.5, kPi / 2}, std::pair{1.5, kPi / 4}}) {
        fv::SteadyOptions o;
        o.record_period = true;
        const auto a = fv::dahl_steady({zeta, th, 2, 0}, o);
        for (const auto& s : a.period) REQUIRE(s.z == Approx(0.5).epsilon(1e-12)); // the premise
        const auto b = fv::dahl_steady({zeta, th, 2, 1}, o);
        CAPTURE(zeta, th);
        CHECK(a.rx == Approx(b.rx).margin(1e-7));
        CHECK(a.ry == Approx(b.ry).margin(1e-7));
    }
    // And where it does relax (Fig. 14, zeta = 0.15) they differ clearly, i = 1 below i = 0.
    const auto a = fv::dahl_steady({0.15, kPi / 2, 2, 0}), b = fv::dahl_steady({0.15, kPi / 2, 2, 1});
    CHECK(b.rx < a.rx - 0.05);
}

TEST_CASE("Mirror symmetries: theta = pi/2 has r_y = 0, theta -> pi - theta flips r_y", "[steady]") {
    // tau -> tau + pi maps P at pi - theta onto the mirror image of P at theta (plus a drift), so the steady
    // states are mirror images.
    for (double i : {0.0, 1.0, 2.0}) {
        const auto q = fv::dahl_steady({0.4, kPi / 2, 1.5, i});
        CHECK(std::abs(q.ry) < 1e-7);
        const auto a = fv::dahl_steady({0.4, kPi / 6, 1.5, i}),
                   b = fv::dahl_steady({0.4, 5 * kPi / 6, 1.5, i});
        CAPTURE(i);
        CHECK(a.rx == Approx(b.rx).margin(2e-6));
        CHECK(a.ry == Approx(-b.ry).margin(2e-6));
        CHECK(std::abs(a.ry) > 1e-3); // oblique vibrations do push sideways
    }
}

TEST_CASE("zeta >= 1 at theta = 0: the body never moves backwards, the tip slips forward, r_x = 1",
          "[steady]") {
    for (double i : {0.0, 1.0, 0.5})
        for (double zeta : {1.0, 1.7}) CHECK(fv::dahl_steady({zeta, 0, 3, i}).rx == Approx(1).margin(1e-6));
}

TEST_CASE("Friction force stays within the Coulomb bound in steady state", "[steady]") {
    fv::SteadyOptions o;
    o.record_period = true;
    for (double i : {0.0, 0.3, 1.0, 2.5}) {
        const auto r = fv::dahl_steady({0.25, 1.0, 4, i}, o);
        for (const auto& s : r.period) REQUIRE(s.F.norm() <= 1 + 1e-12);
        CHECK(std::abs(r.rx) <= 1);
    }
}

TEST_CASE("Every parameter set ends with a clear status within its budget", "[steady][status]") {
    // Slow cases: tiny zeta * rdisp (long sticking before the first slip) and i > 1 (algebraic approach).
    fv::SteadyOptions o;
    o.max_periods = 400;
    for (const Params& p : {Params{0.02, 0.0, 0.2, 0}, Params{0.02, kPi / 2, 0.2, 1}, Params{1.5, 0, 0.5, 3},
                            Params{0.0, kPi / 3, 0.3, 2}, Params{0.05, 0.3, 0.2, 2.5}}) {
        const auto r = fv::dahl_steady(p, o);
        CAPTURE(p.zeta, p.theta, p.rdisp, p.i, r.periods, r.error_estimate, fv::to_string(r.status));
        CHECK(r.periods <= 400);
        CHECK(std::isfinite(r.rx));
        if (r.status == SteadyStatus::converged)
            CHECK(r.error_estimate < 1e-3);
        else
            CHECK(r.error_estimate > o.tolerance); // never converged with a tiny error estimate
    }
    // A budget far too small for a slow case must say so.
    o.max_periods = 3;
    const auto r = fv::dahl_steady({0.02, 0.0, 0.2, 0}, o);
    CHECK(r.status == SteadyStatus::not_converged);
}
