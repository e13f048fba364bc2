// The paper's stepping scheme, Eqs. (17)-(29): kinematics, invariants and the stick phase of Eq. (27).
#include "fv/paper_scheme.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using fv::kPi;
using fv::Params;
using fv::Vec2;

TEST_CASE("Eqs. (28)-(29): P drifts by 2 pi zeta per period and oscillates along theta", "[scheme]") {
    const Params p{0.3, 0.6, 2, 1};
    const Vec2 a = fv::body_point(p, 0.4), b = fv::body_point(p, 0.4 + 2 * kPi);
    CHECK((b - a - Vec2(2 * kPi * 0.3, 0)).norm() < 1e-13);
    // At tau = pi/2 the vibration is at its amplitude (1 = x_v) along (cos theta, sin theta).
    const Vec2 q = fv::body_point(p, kPi / 2) - Vec2(0.3 * kPi / 2, 0);
    CHECK((q - Vec2(std::cos(0.6), std::sin(0.6))).norm() < 1e-14);
    // dP/dtau by central difference.
    const double h = 1e-6;
    const Vec2 fd = (fv::body_point(p, 1.0 + h) - fv::body_point(p, 1.0 - h)) / (2 * h);
    CHECK((fd - fv::body_velocity(p, 1.0)).norm() < 1e-8);
}

TEST_CASE("The stepper follows P exactly and keeps its time", "[scheme]") {
    fv::PaperStepper st({0.7, 1.0, 3, 1}, 64);
    for (int k = 0; k < 64 * 3 + 5; ++k) st.step();
    CHECK(st.period() == 3);
    CHECK(st.phase_step() == 5);
    CHECK(st.tau() == Approx((64 * 3 + 5) * 2 * kPi / 64));
    CHECK((st.P() - fv::body_point(st.params(), st.tau())).norm() < 1e-12);
    CHECK((st.P() - st.T() - st.lag()).norm() < 1e-12);
}

TEST_CASE("Eq. (27): with i = 0 the tip does not move while |P - T| < z_ss", "[scheme][stiction]") {
    // z_ss = 5 x_v: P moves at most 1 + 2 pi zeta away from T(0) = P(0) in the first period.
    const Params p{0.1, 0.8, 0.2, 0};
    fv::PaperStepper st(p, 500);
    const Vec2 T0 = st.T();
    for (int k = 0; k < 500; ++k) {
        st.step();
        REQUIRE((st.P() - T0).norm() < p.zss());
        REQUIRE((st.T() - T0).norm() < 1e-12);
    }
}

TEST_CASE("Eq. (27): once slipping at i = 0 the deflection is exactly z_ss and T lies on the pull line",
          "[scheme][stiction]") {
    const Params p{2.0, 0.0, 5, 0}; // zeta > 1: P only moves forward, the tip must end up slipping
    fv::PaperStepper st(p, 256);
    for (int k = 0; k < 256 * 3; ++k) st.step();
    CHECK(st.z() == Approx(p.zss()).epsilon(1e-14));
    CHECK(std::abs(st.lag().y()) < 1e-14);
}

TEST_CASE("Invariants |F| <= F_c and z <= z_ss hold for every exponent, even with coarse steps", "[scheme]") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> zeta(0, 3), theta(0, kPi), logr(std::log(0.2), std::log(100.0)),
        expo(0, 3);
    for (int trial = 0; trial < 60; ++trial) {
        Params p{zeta(rng), theta(rng), std::exp(logr(rng)), trial % 5 == 0 ? 0.0 : expo(rng)};
        const int n = trial % 3 == 0 ? 8 : 200; // n = 8 lets P jump far past z_ss in one step
        fv::PaperStepper st(p, n);
        CAPTURE(p.zeta, p.theta, p.rdisp, p.i, n);
        for (int k = 0; k < n * 20; ++k) {
            st.step();
            REQUIRE(std::isfinite(st.z()));
            REQUIRE(st.z() <= p.zss() * (1 + 1e-12));
            REQUIRE(st.force().norm() <= 1 + 1e-12);
        }
    }
}

TEST_CASE("Eq. (20) with i = 1 stretches less and relaxes more than i = 0 in one step", "[scheme]") {
    // From the same state (z = z_ss / 2, purely along x), one step forward along x: i = 0 follows P fully
    // (stick), i = 1 only by the factor (1 - z/z_ss) = 1/2 of Eq. (17).
    const double zss = 0.5;
    for (double i : {0.0, 1.0}) {
        fv::PaperStepper st({1.0, 0.0, 1 / zss, i}, 100000, Vec2(zss / 2, 0));
        const Vec2 before = st.lag();
        st.step();
        const double dP = fv::body_point(st.params(), st.dtau()).x() - fv::body_point(st.params(), 0).x();
        const double dz = st.lag().x() - before.x();
        CHECK(dz == Approx(i == 0 ? dP : 0.5 * dP).epsilon(1e-9));
    }
}
