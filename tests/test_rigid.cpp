// Rigid Coulomb model, Eqs. (9)-(11): the quadrature against the paper's closed forms, exact values and
// symmetries derived by hand, and an independent brute-force rule.
#include "fv/params.hpp"
#include "fv/rigid.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using fv::kPi;

TEST_CASE("Eq. (10): quadrature of Eq. (9) at theta = 0 matches (2/pi) asin(zeta), 1 above zeta = 1",
          "[rigid]") {
    for (double z : {0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999, 1.0, 1.000001, 1.2, 2.0, 10.0}) {
        CAPTURE(z);
        const auto r = fv::rigid_ratio(z, 0);
        CHECK(std::abs(r.rx - fv::rigid_rx_parallel(z)) < 1e-9);
        CHECK(std::abs(r.ry) < 1e-12);
    }
}

TEST_CASE("Eq. (11): quadrature at theta = pi/2 matches the elliptic-integral closed form", "[rigid]") {
    for (double z : {0.0, 0.001, 0.02, 0.1, 0.5, 1.0, 1.5, 3.0, 20.0}) {
        CAPTURE(z);
        const auto r = fv::rigid_ratio(z, kPi / 2);
        CHECK(std::abs(r.rx - fv::rigid_rx_perpendicular(z)) < 1e-9);
        CHECK(std::abs(r.ry) < 1e-12); // mirror symmetry y -> -y over a period
    }
}

TEST_CASE("Closed forms at values known by hand", "[rigid]") {
    // asin(1/2) = pi/6, so r_x(1/2, 0) = 1/3 exactly.
    CHECK(fv::rigid_rx_parallel(0.5) == Approx(1.0 / 3).margin(1e-15));
    // asin(sqrt(2)/2) = pi/4 -> 1/2.
    CHECK(fv::rigid_rx_parallel(std::sqrt(0.5)) == Approx(0.5).margin(1e-15));
    // Eq. (11) at zeta = 1: (2/pi)(1/sqrt 2) K(m = 1/2); K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi)).
    const double K_half = std::pow(std::tgamma(0.25), 2) / (4 * std::sqrt(kPi));
    CHECK(fv::rigid_rx_perpendicular(1.0) == Approx(2 / kPi / std::sqrt(2.0) * K_half).margin(1e-14));
    // Eq. (11) with the standard library's K (which takes the modulus k = sqrt(m)).
    for (double z : {0.05, 0.4, 2.0}) {
        const double k = 1 / std::sqrt(1 + z * z);
        CHECK(fv::rigid_rx_perpendicular(z) ==
              Approx(2 / kPi * z / std::sqrt(1 + z * z) * std::comp_ellint_1(k)).margin(1e-14));
    }
    // zeta -> 0: K(k) ~ ln(4/k') with k' = zeta/sqrt(1+zeta^2), so r_x ~ (2/pi) zeta ln(4/zeta) -> 0.
    const double z = 1e-12;
    CHECK(fv::rigid_rx_perpendicular(z) == Approx(2 / kPi * z * std::log(4 / z)).epsilon(1e-9));
}

TEST_CASE("Oblique angles: quadrature agrees with a dense midpoint rule", "[rigid]") {
    // The integrand is smooth (analytic, periodic) for 0 < theta < pi and zeta > 0 away from the
    // near-singular theta -> 0 corner, so the plain midpoint rule converges geometrically: an independent
    // check.
    for (double th_deg : {15.0, 30.0, 45.0, 60.0, 75.0, 120.0})
        for (double z : {0.1, 0.5, 0.9, 1.3}) {
            const double th = th_deg * kPi / 180, c = std::cos(th), s = std::sin(th);
            const int n = 200000;
            double sx = 0, sy = 0;
            for (int k = 0; k < n; ++k) {
                const double u = std::cos((k + 0.5) * 2 * kPi / n);
                const double w = std::hypot(z + c * u, s * u);
                sx += (z + c * u) / w;
                sy += s * u / w;
            }
            CAPTURE(th_deg, z);
            const auto r = fv::rigid_ratio(z, th);
            CHECK(std::abs(r.rx - sx / n) < 1e-9);
            CHECK(std::abs(r.ry - sy / n) < 1e-9);
        }
}

TEST_CASE("Symmetry theta -> pi - theta keeps r_x and flips r_y", "[rigid]") {
    // tau -> tau + pi maps the velocity at pi - theta onto the mirror image (y -> -y) of the one at theta.
    for (double th : {0.2, 0.7, 1.1})
        for (double z : {0.2, 0.8, 1.7}) {
            const auto a = fv::rigid_ratio(z, th), b = fv::rigid_ratio(z, kPi - th);
            CHECK(a.rx == Approx(b.rx).margin(1e-11));
            CHECK(a.ry == Approx(-b.ry).margin(1e-11));
        }
}

TEST_CASE("Lateral force: nonzero and pointing away from the vibration axis for oblique angles", "[rigid]") {
    // At theta = 30 deg, zeta = 0.5 the body moves backwards (along -(cos, sin)) during part of each period,
    // when it is slow: friction then points mostly along -y, and the time average keeps a negative r_y.
    const auto r = fv::rigid_ratio(0.5, kPi / 6);
    CHECK(r.ry < -0.1);
    // Far above zeta = 1 the vibration hardly turns the velocity: r_x -> 1, r_y -> 0.
    const auto fast = fv::rigid_ratio(100, kPi / 4);
    CHECK(fast.rx > 0.9999);
    CHECK(std::abs(fast.ry) < 1e-3);
}

TEST_CASE("Near theta = 0 the kink is resolved: r_x is continuous in theta", "[rigid]") {
    for (double z : {0.3, 0.95}) {
        const double at0 = fv::rigid_rx_parallel(z);
        const double near0 = fv::rigid_ratio(z, 1e-7).rx;
        CHECK(std::abs(near0 - at0) < 1e-6);
    }
}
