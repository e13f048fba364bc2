// How fast the Dahl model's means approach the rigid model, Eq. (9), as rdisp -> infinity: the rates
// derived in docs/model.md, "Rigid limit (r → ∞)", checked on the solver by log-log slopes between rdisp
// values and by the leading constants, which are computed here from their formulas (quadrature of the
// rigid motion only; no value comes from the solver under test).
//
//   gap(r) = r_x(r) - r_x,rigid,  r = rdisp,  a = sqrt(1 - zeta^2) (theta = 0),  gamma = 1/(i - 1).
//
// * Reversals (v = e . P' changes sign every period), theta = 0, 0 < zeta < 1:
//     i > 2:      gap = C_i r^(-gamma) (1 + O(r^(-1/2)))   (the algebraic tail w ~ ((i-1) r X)^(-gamma)
//                 after each reversal; C_i from the travel X after the two reversals)
//     0 <= i < 2: gap = K_i / r (1 + O(1/r))              (the sweep across the disc just after a reversal;
//                 its leading r^(-1/2) part is the same at both reversals and cancels)
//                 K_i = zeta 2^(2-i) / (3 pi (2 - i) (1 - zeta^2))
// * 0 < theta < 180 deg below r_c = 0.227 g / (zeta sin theta)^2 (reversals still occur): along the
//   vibration line the theta = 0 law holds (checked for i = 10 at zeta = 0.01, theta = 10 deg, r_c = 7.5e4).
// * No reversal (v > 0 all period; theta = 90 deg here): gap = K2 / r^2 + K4 / r^4 + O(r^-6), the same for
//   every i; K2, K4 from the slow-manifold expansion of the circle's angle (circle_expansion below).
//
// Tolerances follow from the next-order term of each expansion (computed where it is known: K4; else its
// size with a unit (i > 2) or 4x (0 <= i < 2) allowance for the O(1) coefficient), plus the solver's own
// error estimate relative to the gap:
// a relative error e(r) in gap(r) moves the slope between r1 and r2 by at most (e(r1) + e(r2)) / ln(r2/r1).
#include "fv/params.hpp"
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

namespace {

constexpr double kPi = fv::kPi;
constexpr double kDeg = kPi / 180.0;

struct Gap {
    double x = 0, y = 0; // r - r_rigid
    double err = 0;      // the solver's error estimate
};

Gap solve_gap(double zeta, double theta, double rdisp, double i, double tolerance) {
    fv::SteadyOptions o;
    o.ode_tolerance = tolerance;
    const fv::Params p{zeta, theta, rdisp, i};
    const auto r = fv::steady_ratio(fv::Model::dahl, p, o);
    INFO("zeta " << zeta << "  theta " << theta / kDeg << " deg  rdisp " << rdisp << "  i " << i << ": "
                 << fv::to_string(r.status) << "  error estimate " << r.error_estimate << "  " << r.detail);
    REQUIRE(fv::ok(r.status));
    REQUIRE(r.error_estimate <= tolerance);
    const auto rigid = fv::rigid_ratio(zeta, theta);
    return {r.rx - rigid.rx, r.ry - rigid.ry, r.error_estimate};
}

double slope(double g1, double r1, double g2, double r2) {
    return std::log(g2 / g1) / std::log(r2 / r1);
}

// Composite Simpson on [0, 1] (n even).
double simpson01(const std::function<double(double)>& f, int n) {
    const double h = 1.0 / n;
    double s = f(0) + f(1);
    for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * f(k * h);
    return s * h / 3;
}

// int_0^L X(t)^(-gamma) dt for X(t) = a (1 - cos t) + sgn zeta (t - sin t) (the travel after a reversal at
// theta = 0), 0 < gamma < 1/2. t = L u^p with p = 1/(1 - 2 gamma) takes out the t^(-2 gamma) singularity:
// the integral is L^(1 - 2 gamma) p int_0^1 (X/t^2)^(-gamma) du.
double tail_integral(double zeta, double sgn, double L, double gamma) {
    const double a = std::sqrt(1 - zeta * zeta);
    const double p = 1 / (1 - 2 * gamma);
    auto x_over_t2 = [&](double t) {
        const double q1 = t > 1e-4 ? 2 * std::pow(std::sin(t / 2), 2) / (t * t) : 0.5 - t * t / 24;
        const double q2 =
            t > 1e-2 ? (t - std::sin(t)) / (t * t * t) : 1.0 / 6 - t * t / 120 + t * t * t * t / 5040;
        return a * q1 + sgn * zeta * t * q2;
    };
    return std::pow(L, 1 - 2 * gamma) * p *
           simpson01([&](double u) { return std::pow(x_over_t2(L * std::pow(u, p)), -gamma); }, 20000);
}

// C_i of gap ~ C_i r^(-1/(i-1)), theta = 0, i > 3: the deficit w = ((i-1) r X)^(-gamma) integrated over the
// back leg (length 2 acos(zeta), X_b: minus sign) less the forward leg (2 acos(-zeta), X_f: plus sign).
double tail_constant(double zeta, double i) {
    const double gamma = 1 / (i - 1);
    const double fwd = tail_integral(zeta, +1, 2 * std::acos(-zeta), gamma);
    const double back = tail_integral(zeta, -1, 2 * std::acos(zeta), gamma);
    return std::pow(i - 1, -gamma) * (back - fwd) / (2 * kPi);
}

// K_i of gap ~ K_i / r, theta = 0, 0 <= i < 2.
double sweep_constant(double zeta, double i) {
    return zeta * std::pow(2.0, 2 - i) / (3 * kPi * (2 - i) * (1 - zeta * zeta));
}

// K2 and K4 of gap = K2 / r^2 + K4 / r^4 + O(r^-6) on the circle (no reversal). With A = |P'|, psi its
// direction and the lag delta = psi - phi = d1/r + d2/r^2 + ... of the slow manifold of
// phi' = r A sin(psi - phi):  d1 = psi'/A,  d2 = -d1'/A,  d3 = -d2'/A + d1^3/6,  d4 = -d3'/A + d1^2 d2/2;
// cos(phi) - cos(psi) expanded: K2 = mean[sin(psi) d2 - cos(psi) d1^2/2],
// K4 = mean[cos(psi) (d1^4/24 - (d2^2 + 2 d1 d3)/2) + sin(psi) (d4 - d1^2 d2/2)]; the odd orders vanish
// (d1, d3 are odd in tau, d2, d4 and psi even). Derivatives by 8th-order periodic central differences,
// means by the trapezoidal rule (spectrally accurate for these smooth periodic functions).
struct CircleExpansion {
    double k2 = 0, k4 = 0;
};
CircleExpansion circle_expansion(double zeta, double theta) {
    const int n = 4096;
    const double h = 2 * kPi / n, c = std::cos(theta), s = std::sin(theta);
    std::vector<double> A(n), cpsi(n), spsi(n), d1(n);
    for (int k = 0; k < n; ++k) {
        const double t = k * h;
        const double px = zeta + std::cos(t) * c, py = std::cos(t) * s;
        const double ax = -std::sin(t) * c, ay = -std::sin(t) * s; // P''
        A[k] = std::hypot(px, py);
        cpsi[k] = px / A[k];
        spsi[k] = py / A[k];
        d1[k] = (px * ay - py * ax) / (A[k] * A[k]) / A[k];
    }
    auto deriv = [&](const std::vector<double>& f) {
        static const double w[4] = {4.0 / 5, -1.0 / 5, 4.0 / 105, -1.0 / 280};
        std::vector<double> d(n);
        for (int k = 0; k < n; ++k) {
            double acc = 0;
            for (int j = 1; j <= 4; ++j) acc += w[j - 1] * (f[(k + j) % n] - f[(k - j + n) % n]);
            d[k] = acc / h;
        }
        return d;
    };
    std::vector<double> d2(n), d3(n), d4(n);
    const auto d1p = deriv(d1);
    for (int k = 0; k < n; ++k) d2[k] = -d1p[k] / A[k];
    const auto d2p = deriv(d2);
    for (int k = 0; k < n; ++k) d3[k] = -d2p[k] / A[k] + std::pow(d1[k], 3) / 6;
    const auto d3p = deriv(d3);
    for (int k = 0; k < n; ++k) d4[k] = -d3p[k] / A[k] + d1[k] * d1[k] * d2[k] / 2;
    CircleExpansion out;
    for (int k = 0; k < n; ++k) {
        out.k2 += spsi[k] * d2[k] - cpsi[k] * d1[k] * d1[k] / 2;
        out.k4 += cpsi[k] * (std::pow(d1[k], 4) / 24 - (d2[k] * d2[k] + 2 * d1[k] * d3[k]) / 2) +
                  spsi[k] * (d4[k] - d1[k] * d1[k] * d2[k] / 2);
    }
    out.k2 /= n;
    out.k4 /= n;
    return out;
}

} // namespace

TEST_CASE("rigid gap with reversals at i > 2 falls as rdisp^(-1/(i-1)) with the tail constant",
          "[solver-ref][rigid-limit][rigid-gap]") {
    // The constants themselves (not from the solver): theta = 0, zeta = 0.7.
    const double zeta = 0.7, a = std::sqrt(1 - zeta * zeta);
    for (double i : {10.0, 5.0}) {
        const double gamma = 1 / (i - 1);
        const double C = tail_constant(zeta, i);
        CAPTURE(i, C);
        REQUIRE(C < 0); // the forward leg is the longer one (2 acos(-zeta) > pi): more deficit
        // Next order: relative O((r a)^(-1/2)) (the two sweeps start from different deficits) and
        // O(r^(gamma - 1)) (the 1/r sweep term), both below e(r) = (r a)^(-1/2) for a unit coefficient.
        auto e = [&](double r, const Gap& g) { return 1 / std::sqrt(r * a) + g.err / std::fabs(g.x); };
        const double r1 = 1e2, r2 = 1e3, r3 = 1e4;
        const Gap g1 = solve_gap(zeta, 0, r1, i, 1e-10), g2 = solve_gap(zeta, 0, r2, i, 1e-10),
                  g3 = solve_gap(zeta, 0, r3, i, 1e-10);
        REQUIRE(g1.x < 0);
        REQUIRE(g2.x < 0);
        REQUIRE(g3.x < 0);
        const double s12 = slope(g1.x, r1, g2.x, r2), s23 = slope(g2.x, r2, g3.x, r3);
        CAPTURE(g1.x, g2.x, g3.x, s12, s23);
        CHECK(std::fabs(s12 + gamma) <= (e(r1, g1) + e(r2, g2)) / std::log(r2 / r1));
        CHECK(std::fabs(s23 + gamma) <= (e(r2, g2) + e(r3, g3)) / std::log(r3 / r2));
        for (const auto& [r, g] : {std::pair{r1, g1}, std::pair{r2, g2}, std::pair{r3, g3}}) {
            CAPTURE(r, g.x * std::pow(r, gamma));
            CHECK(std::fabs(g.x * std::pow(r, gamma) / C - 1) <= e(r, g));
        }
    }
}

TEST_CASE("rigid gap with reversals at 0 <= i < 2 falls as 1/rdisp with the sweep constant",
          "[solver-ref][rigid-limit][rigid-gap]") {
    for (double zeta : {0.7, 0.3}) {
        const double a = std::sqrt(1 - zeta * zeta);
        // Next order: relative O(1/(r a)) and O(zeta^2 / (r a^3)) (the t^4 and squared t^3 terms of the
        // travel after a reversal); allowance 4x their sum.
        auto e = [&](double r, const Gap& g) {
            return 4 * (1 + zeta * zeta / (a * a)) / (r * a) + g.err / std::fabs(g.x);
        };
        for (double i : {1.0, 0.5, 0.0}) {
            const double K = sweep_constant(zeta, i);
            CAPTURE(zeta, i, K);
            const double r1 = 1e3, r2 = 1e4;
            const Gap g1 = solve_gap(zeta, 0, r1, i, 1e-10), g2 = solve_gap(zeta, 0, r2, i, 1e-10);
            REQUIRE(g1.x > 0); // compliance raises r_x here
            REQUIRE(g2.x > 0);
            const double s = slope(g1.x, r1, g2.x, r2);
            CAPTURE(g1.x, g2.x, s);
            CHECK(std::fabs(s + 1) <= (e(r1, g1) + e(r2, g2)) / std::log(r2 / r1));
            CHECK(std::fabs(g1.x * r1 / K - 1) <= e(r1, g1));
            CHECK(std::fabs(g2.x * r2 / K - 1) <= e(r2, g2));
        }
    }
}

TEST_CASE("rigid gap with reversals at theta = 10 deg keeps rdisp^(-1/9) along the vibration line at i = 10",
          "[solver-ref][rigid-limit][rigid-gap]") {
    // zeta = 0.01: P' passes the origin at h = zeta sin theta = 1.7e-3 with |P''| = g ~ 1, so the tip leaves
    // the circle up to r_c = 0.227 g / h^2 = 7.5e4. The gap's component along the line (cos, sin theta) is
    // the deficit tail (the turns' cross-line part is removed), O(r^(-1/2)) relative corrections as at 0.
    const double zeta = 0.01, theta = 10 * kDeg, i = 10, gamma = 1 / (i - 1);
    const double h = zeta * std::sin(theta), g = std::sqrt(1 - std::pow(zeta * std::cos(theta), 2));
    REQUIRE(0.227 * g / (h * h) > 5e4);
    auto along = [&](const Gap& d) { return d.x * std::cos(theta) + d.y * std::sin(theta); };
    auto e = [&](double r, const Gap& d) { return 1 / std::sqrt(r * g) + 2 * d.err / std::fabs(along(d)); };
    const double r1 = 1e2, r2 = 1e4;
    const Gap g1 = solve_gap(zeta, theta, r1, i, 1e-10), g2 = solve_gap(zeta, theta, r2, i, 1e-10);
    REQUIRE(along(g1) < 0);
    REQUIRE(along(g2) < 0);
    const double s = slope(along(g1), r1, along(g2), r2);
    CAPTURE(g1.x, g1.y, g2.x, g2.y, s);
    CHECK(std::fabs(s + gamma) <= (e(r1, g1) + e(r2, g2)) / std::log(r2 / r1));
}

TEST_CASE("rigid gap without reversals falls as 1/rdisp^2 with the second-order lag constant for every i",
          "[solver-ref][rigid-limit][rigid-gap]") {
    struct Case {
        double zeta, theta_deg;
    };
    for (const Case c : {Case{0.5, 90}, Case{2.0, 90}}) {
        const double theta = c.theta_deg * kDeg;
        const auto ce = circle_expansion(c.zeta, theta);
        CAPTURE(c.zeta, c.theta_deg, ce.k2, ce.k4);
        REQUIRE(ce.k2 > 0);
        // Next order: relative K4/(K2 r^2); twice that covers it and the O(r^-4) rest while it is small.
        auto e = [&](double r, const Gap& d) {
            return 2 * std::fabs(ce.k4 / ce.k2) / (r * r) + d.err / std::fabs(d.x);
        };
        const double r1 = 1e2, r2 = 1e3;
        REQUIRE(std::fabs(ce.k4 / ce.k2) / (r1 * r1) < 0.01);
        for (double i : {0.0, 1.0, 10.0}) {
            CAPTURE(i);
            const Gap g1 = solve_gap(c.zeta, theta, r1, i, 1e-10),
                      g2 = solve_gap(c.zeta, theta, r2, i, 1e-10);
            REQUIRE(g1.x > 0);
            REQUIRE(g2.x > 0);
            const double s = slope(g1.x, r1, g2.x, r2);
            CAPTURE(g1.x, g2.x, s);
            CHECK(std::fabs(s + 2) <= (e(r1, g1) + e(r2, g2)) / std::log(r2 / r1));
            CHECK(std::fabs(g1.x * r1 * r1 / ce.k2 - 1) <= e(r1, g1));
            CHECK(std::fabs(g2.x * r2 * r2 / ce.k2 - 1) <= e(r2, g2));
        }
    }
}
