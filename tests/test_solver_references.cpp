// What any steady-state solver behind fv::steady_ratio must get right, checked against references that are
// derived without the solver (tests/reference/*): the exact theta = 0 steady states for i = 0, 1
// (theta0_exact) and for any i (theta0_general_i), the pursuit curve on the circle |L| = z_ss that is the
// steady state at large rdisp for every i (circle_pursuit), closed-form limits, the paper's own scheme
// extrapolated to dtau -> 0, symmetries, and bounds that follow from the model. No expected value here
// comes from the solver under test.
//
// The contract at default options (accuracy_check below): status ok, finite r_x and r_y, a reported
// error_estimate <= 1e-6, and |r - exact| <= max(1e-6, error_estimate).
//
// Each test collects every failing point and reports them together (the worst first), so one run shows how
// far off a solver is over the whole grid rather than stopping at the first point. Tags: [solver-ref] on all;
// [slow] on the three heaviest: the paper's scheme at 2^15 steps per period, the pursuit curve at
// rdisp = 1e4, and the 5880-point grid of bench/domain_speed.cpp (about 1 s, 1 s and 2 s with a solver at
// ~0.2 ms per point; the whole file then takes ~6 s, well under a minute). FV_REF_ALL=1 in the environment
// lists every failing point, not only the 25 worst of each test.
#include "reference/circle_pursuit.hpp"
#include "reference/theta0_exact.hpp"
#include "reference/theta0_general_i.hpp"

#include "fv/paper_scheme.hpp"
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using fv::Params;

namespace {

constexpr double kPi = fv::kPi;
constexpr double kDeg = kPi / 180.0;
constexpr double kTol = 1e-6; // the accuracy every default-options result must meet

// Grids over the whole domain: zeta in [0, 100], rdisp in (0, 1e4].
const std::vector<double> kZetas = {0.0, 1e-3, 0.01, 0.1, 0.5, 0.9, 0.99, 1.0, 1.5, 10.0, 100.0};
const std::vector<double> kRdisps = {1e-9, 1e-6, 1e-3, 0.1, 1.0, 10.0, 100.0, 1e4};

fv::SteadyResult solve(const Params& p) {
    return fv::steady_ratio(fv::Model::dahl, p);
}

std::string describe(const Params& p) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "zeta=%.6g theta=%.6g deg rdisp=%.6g i=%.6g", p.zeta, p.theta / kDeg,
                  p.rdisp, p.i);
    return buf;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[200];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

// Failures of one test, worst first in the report.
class Failures {
  public:
    void fail(const Params& p, const std::string& what, double badness) {
        items_.push_back({badness, describe(p) + ": " + what});
    }
    void fail(const std::string& what, double badness) { items_.push_back({badness, what}); }
    void count() { ++checked_; }
    bool empty() const { return items_.empty(); }
    std::string report() {
        std::stable_sort(items_.begin(), items_.end(),
                         [](const Item& a, const Item& b) { return a.badness > b.badness; });
        std::string s = std::to_string(items_.size()) + " failure(s) in " + std::to_string(checked_) +
                        " checked point(s); the worst:\n";
        // FV_REF_ALL=1 in the environment lists every failure, not only the 25 worst.
        const std::size_t shown = std::getenv("FV_REF_ALL") ? items_.size() : 25;
        for (std::size_t k = 0; k < items_.size() && k < shown; ++k) s += "  " + items_[k].text + "\n";
        return s;
    }

  private:
    struct Item {
        double badness;
        std::string text;
    };
    std::vector<Item> items_;
    int checked_ = 0;
};

#define FV_REPORT(f)                                                                                         \
    do {                                                                                                     \
        INFO((f).report());                                                                                  \
        CHECK((f).empty());                                                                                  \
    } while (false)

// Independent evidence that the motion does not settle (the solver's `unsettled`): the paper's scheme
// (N = 2048 steps per period, from rest) run for 600 periods; the period means of r_x over the last 300 keep
// moving by more than 1e-4, far more than its own discretisation changes them.
bool paper_scheme_wanders(const Params& p) {
    fv::PaperStepper st(p, 2048);
    double lo = 1e9, hi = -1e9;
    for (int m = 0; m < 600; ++m) {
        double sum = 0;
        for (int k = 0; k < 2048; ++k) {
            st.step();
            sum += st.force().x();
        }
        if (m >= 300) lo = std::min(lo, sum / 2048), hi = std::max(hi, sum / 2048);
    }
    return hi - lo > 1e-4;
}

// Status ok, finite, error_estimate <= 1e-6. Returns false (and records why) otherwise. `unsettled` and
// `not_periodic` (no attracting periodic state) are accepted, not a failure, where the paper's scheme
// confirms that the motion does not settle; there is no steady value to compare then.
bool contract_check(Failures& f, const Params& p, const fv::SteadyResult& r) {
    f.count();
    if (r.status == fv::SteadyStatus::unsettled || r.status == fv::SteadyStatus::not_periodic) {
        if (!paper_scheme_wanders(p))
            f.fail(p,
                   std::string("status ") + fv::to_string(r.status) +
                       fmt(", but the paper's scheme settles (r_x=%.10g)", r.rx),
                   1e200);
        return false;
    }
    if (!std::isfinite(r.rx) || !std::isfinite(r.ry) || !std::isfinite(r.error_estimate)) {
        f.fail(p, fmt("non-finite result r_x=%g r_y=%g est=%g", r.rx, r.ry, r.error_estimate), 1e300);
        return false;
    }
    bool good = true;
    if (!fv::ok(r.status)) {
        f.fail(p,
               std::string("status ") + fv::to_string(r.status) +
                   fmt(" (r_x=%.10g est=%.2e)", r.rx, r.error_estimate),
               1e200);
        good = false;
    }
    if (!(r.error_estimate <= kTol)) {
        f.fail(p, fmt("error_estimate %.3e > 1e-6", r.error_estimate), r.error_estimate);
        good = false;
    }
    return good;
}

// |r - exact| <= max(1e-6, error_estimate) (the result is finite).
void error_check(Failures& f, const Params& p, const fv::SteadyResult& r, double rx, double ry) {
    const double err = std::max(std::fabs(r.rx - rx), std::fabs(r.ry - ry));
    const double allowed = std::max(kTol, std::isfinite(r.error_estimate) ? r.error_estimate : 0.0);
    if (!(err <= allowed))
        f.fail(p,
               fmt("r_x=%.12f r_y=%.3e, exact r_x=%.12f: |error| %.3e", r.rx, r.ry, rx, err) +
                   fmt(" > max(1e-6, est=%.2e)", r.error_estimate),
               err);
}

// The whole contract against an exact value.
void accuracy_check(Failures& f, const Params& p, const fv::SteadyResult& r, double rx, double ry) {
    if (!contract_check(f, p, r) && !(std::isfinite(r.rx) && std::isfinite(r.ry))) return;
    error_check(f, p, r, rx, ry);
}

// Direction of P'(0) on the circle |L| = z_ss: a start for the paper's scheme (see the Richardson test).
fv::Vec2 circle_start(const Params& p) {
    return fv::body_velocity(p, 0.0).normalized() * p.zss();
}

double rx_exact_theta0(double zeta, double rdisp, double i) {
    if (i == 0.0) return fv::ref::rx_theta0_i0(zeta, rdisp);
    if (i == 1.0) return fv::ref::rx_theta0_i1(zeta, rdisp);
    return fv::ref::rx_theta0_general(zeta, rdisp, i);
}

} // namespace

// ---------------------------------------------------------------------------------------------------------
// References checked on their own (no solver): the general-i law against the independent i = 0, 1 closed
// forms, against the ODE it solves, and its integral against a plain quadrature of its own lag.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("reference: the general-i theta = 0 law reproduces theta0_exact at i = 0 and i = 1 to 1e-12",
          "[solver-ref][reference]") {
    Failures f;
    std::vector<double> rdisps = kRdisps;
    rdisps.insert(rdisps.end(), {1e-10, 2.0, 1e3});
    for (double zeta : {0.0, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.9, 0.99, 1.0 - 1e-9, 1.0, 1.5, 10.0, 100.0})
        for (double rdisp : rdisps) {
            const double ex[2] = {fv::ref::rx_theta0_i0(zeta, rdisp), fv::ref::rx_theta0_i1(zeta, rdisp)};
            for (int i = 0; i < 2; ++i) {
                f.count();
                const double g = fv::ref::rx_theta0_general(zeta, rdisp, i);
                if (!(std::fabs(g - ex[i]) <= 1e-12))
                    f.fail(Params{zeta, 0, rdisp, double(i)}, fmt("r_x general %.16f exact %.16f", g, ex[i]),
                           std::fabs(g - ex[i]));
                // The lag too (relative to z_ss), at a few instants; only where L = z (1 - u) keeps its
                // digits.
                if (rdisp < 1e-3) continue;
                for (double tau : {0.0, 0.7, 2.0, 3.1, 4.4, 6.0}) {
                    const double lg = fv::ref::lag_theta0_general(zeta, rdisp, i, tau) * rdisp;
                    const double le = (i == 0 ? fv::ref::lag_theta0_i0(zeta, rdisp, tau)
                                              : fv::ref::lag_theta0_i1(zeta, rdisp, tau)) *
                                      rdisp;
                    if (!(std::fabs(lg - le) <= 1e-12))
                        f.fail(Params{zeta, 0, rdisp, double(i)},
                               fmt("L/z at tau=%g: general %.16f exact %.16f", tau, lg, le),
                               std::fabs(lg - le));
                }
            }
        }
    FV_REPORT(f);
}

TEST_CASE("reference: the general-i law is continuous in i at 0 and 1 (no special case hides a jump)",
          "[solver-ref][reference]") {
    // (Not at zeta = 0 with rdisp < 1 and i -> 0: there i = 0 has a whole family of periodic states and the
    // convention picks L(tau1) = z_ss, while every i > 0 has the unique symmetric state with r_x = 0.)
    for (double zeta : {0.0, 0.02, 0.5, 0.95})
        for (double rdisp : {1e-6, 0.3, 3.0, 300.0}) {
            CAPTURE(zeta, rdisp);
            const double r0 = fv::ref::rx_theta0_general(zeta, rdisp, 0.0);
            const double r1 = fv::ref::rx_theta0_general(zeta, rdisp, 1.0);
            if (zeta > 0 || rdisp >= 1)
                CHECK(std::fabs(fv::ref::rx_theta0_general(zeta, rdisp, 1e-9) - r0) < 1e-6);
            CHECK(std::fabs(fv::ref::rx_theta0_general(zeta, rdisp, 1.0 - 1e-9) - r1) < 1e-7);
            CHECK(std::fabs(fv::ref::rx_theta0_general(zeta, rdisp, 1.0 + 1e-9) - r1) < 1e-7);
        }
}

TEST_CASE("reference: the general-i lag solves dL/dtau = P' (1 - sgn(P') L/z)^i, is periodic, and "
          "averages to r_x",
          "[solver-ref][reference]") {
    Failures f;
    for (double i : {0.0, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0})
        for (double zeta : {0.0, 0.05, 0.5, 0.9})
            for (double rdisp : {1e-3, 0.1, 1.0, 10.0, 100.0, 1e4}) {
                const Params p{zeta, 0, rdisp, i};
                const double z = 1.0 / rdisp;
                const fv::ref::Theta0Steady steady(zeta, rdisp, i);
                const auto lag = [&](double t) { return steady.lag(t); };
                const double alpha = std::acos(zeta);
                const double d = 1e-6;
                // At the two reversals P' = 0 and L'' jumps (by up to a factor 2^i): check continuity there
                // instead of the law (a wrong periodic state would show as a jump of L, O(z)).
                for (double t : {kPi - alpha, kPi + alpha}) {
                    f.count();
                    const double jump = std::fabs(lag(t + d) - lag(t - d));
                    if (!(jump <= 4 * d * d * std::pow(2.0, i) + 1e-15 * z))
                        f.fail(p, fmt("L jumps by %.3g at the reversal tau=%.6f", jump, t), jump / z);
                }
                // Elsewhere the law, by central differences at a grid of instants.
                for (int k = 0; k < 97; ++k) {
                    const double t = 2 * kPi * (k + 0.37) / 97;
                    f.count();
                    const double l = lag(t);
                    if (!(std::fabs(l) <= z * (1 + 1e-12)))
                        f.fail(p, fmt("|L|/z = %.3g > 1 at tau=%g", std::fabs(l) / z, t), std::fabs(l) / z);
                    const double fd = (lag(t + d) - lag(t - d)) / (2 * d);
                    const double v = zeta + std::cos(t);
                    const double s = v > 0 ? 1.0 : -1.0;
                    const double base = std::max(0.0, 1.0 - s * l / z);
                    const double rhs = i == 0.0 ? (base > 1e-12 ? v : 0.0) : v * std::pow(base, i);
                    // Allowance: truncation of the difference, and rounding of L (~eps z) over 2 d.
                    const double tol = 1e-6 + 4e-16 * z / d;
                    if (!(std::fabs(fd - rhs) <= tol * (1 + std::fabs(rhs))))
                        f.fail(p, fmt("tau=%.6f: dL/dtau %.10g, law %.10g", t, fd, rhs), std::fabs(fd - rhs));
                }
                // Trapezoidal mean of L/z (error ~ h^2 at the kinks; h = 2 pi / 2^16).
                f.count();
                const int n = 1 << 16;
                double sum = 0;
                for (int k = 0; k < n; ++k) sum += lag(2 * kPi * (k + 0.5) / n) / z;
                const double mean = sum / n;
                const double rx = steady.rx();
                if (!(std::fabs(mean - rx) <= 2e-7))
                    f.fail(p, fmt("mean of L/z %.12f, r_x %.12f", mean, rx), std::fabs(mean - rx));
            }
    FV_REPORT(f);
}

TEST_CASE("reference: mean|zeta + cos tau| = (2/pi)(zeta asin zeta + sqrt(1 - zeta^2)), the i = 1 "
          "compliant limit",
          "[solver-ref][reference]") {
    for (double zeta : {0.0, 0.001, 0.1, 0.5, 0.9, 0.999}) {
        CAPTURE(zeta);
        // Composite Simpson between the kinks tau = arccos(-zeta), 2 pi - arccos(-zeta).
        const double t1 = std::acos(-zeta), t2 = 2 * kPi - t1;
        const auto simpson = [&](double a, double b) {
            const int n = 20000;
            const double h = (b - a) / n;
            double s = std::fabs(zeta + std::cos(a)) + std::fabs(zeta + std::cos(b));
            for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * std::fabs(zeta + std::cos(a + k * h));
            return s * h / 3;
        };
        const double mean = (simpson(0, t1) + simpson(t1, t2) + simpson(t2, 2 * kPi)) / (2 * kPi);
        const double closed = (2 / kPi) * (zeta * std::asin(zeta) + std::sqrt(1 - zeta * zeta));
        CHECK(std::fabs(mean - closed) < 1e-12);
        CHECK(std::fabs(fv::ref::mean_abs_velocity_theta0(zeta) - closed) < 1e-15);
        // The exact i = 1 steady state tends to zeta / mean|P'| as rdisp -> 0.
        if (zeta > 0) CHECK(std::fabs(fv::ref::rx_theta0_i1(zeta, 1e-10) - zeta / closed) < 1e-9);
    }
    // The number.
    CHECK(std::fabs(0.5 / fv::ref::mean_abs_velocity_theta0(0.5) - 0.69638) < 5e-6);
}

// ---------------------------------------------------------------------------------------------------------
// a. theta = 0, i = 0 and i = 1: the closed forms over the whole domain.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("a. theta = 0, i = 0 and 1: steady_ratio meets the exact steady state over the whole domain",
          "[solver-ref][theta0]") {
    Failures f;
    for (double i : {0.0, 1.0})
        for (double zeta : kZetas)
            for (double rdisp : kRdisps) {
                const Params p{zeta, 0.0, rdisp, i};
                accuracy_check(f, p, solve(p), rx_exact_theta0(zeta, rdisp, i), 0.0);
            }
    FV_REPORT(f);
}

TEST_CASE("a. theta = 0: the issue's cases", "[solver-ref][theta0]") {
    Failures f;
    // Small zeta and rdisp with stiction: the long stuck transient.
    const Params p0{0.001, 0.0, 0.001, 0};
    accuracy_check(f, p0, solve(p0), fv::ref::rx_theta0_i0(0.001, 0.001), 0.0);
    // rdisp -> 0 with i = 1: zeta / mean|zeta + cos tau| = 0.69638 (closed form, not the reference's
    // quadrature; the deviation at rdisp = 1e-10 is ~1e-11).
    const Params p1{0.5, 0.0, 1e-10, 1};
    const double limit = 0.5 / ((2 / kPi) * (0.5 * std::asin(0.5) + std::sqrt(0.75)));
    REQUIRE(std::fabs(fv::ref::rx_theta0_i1(0.5, 1e-10) - limit) < 1e-9);
    accuracy_check(f, p1, solve(p1), limit, 0.0);
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// b. theta = 0, general i: the separable 1-D law (tests/reference/theta0_general_i.hpp).
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("b. theta = 0, i = 0.5, 2, 5, 10: steady_ratio meets the separable 1-D law over the whole domain",
          "[solver-ref][theta0][general-i][long]") {
    Failures f;
    std::vector<double> rdisps = kRdisps;
    rdisps.push_back(1e3);
    for (double i : {0.5, 2.0, 5.0, 10.0})
        for (double zeta : kZetas)
            for (double rdisp : rdisps) {
                const Params p{zeta, 0.0, rdisp, i};
                accuracy_check(f, p, solve(p), fv::ref::rx_theta0_general(zeta, rdisp, i), 0.0);
            }
    FV_REPORT(f);
}

TEST_CASE("b. theta = 0, general i: the issue's cases (NaN at i = 5, rdisp = 1000) and zeta >= 1 -> 1",
          "[solver-ref][theta0][general-i]") {
    Failures f;
    for (const Params& p : {Params{0.5, 0, 1000, 5}, Params{0.5, 0, 1e4, 10}, Params{0.5, 0, 1e3, 10},
                            Params{0.2, 0, 1e4, 5}, Params{0.9, 0, 1e3, 2.5}, Params{0.05, 0, 1e4, 7.3}})
        accuracy_check(f, p, solve(p), fv::ref::rx_theta0_general(p.zeta, p.rdisp, p.i), 0.0);
    // zeta >= 1: L == z_ss, r_x = 1 for every i (theta0_general_i.hpp), however slowly a time-stepper
    // would approach it for i > 1.
    for (double i : {0.0, 0.5, 1.0, 2.0, 5.0, 10.0})
        for (double zeta : {1.0, 1.2, 10.0, 100.0})
            for (double rdisp : {1e-9, 1e-3, 1.0, 1e4}) {
                const Params p{zeta, 0, rdisp, i};
                accuracy_check(f, p, solve(p), 1.0, 0.0);
            }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// c. Rigid limit for 0 < theta < 180 deg: r - r_rigid = O(1/rdisp^2) (circle_pursuit.hpp: the first-order
//    term is odd in tau), and at large rdisp the steady state is the pursuit curve on |L| = z_ss for every i.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("c. 0 < theta < 180 deg: r_x -> rigid_ratio as 1/rdisp^2", "[solver-ref][rigid-limit]") {
    // Points where |r - rigid| at rdisp = 1e4 is several times the 1e-6 a solver may be off by, so the
    // ratio is meaningful for any solver meeting the contract (values from circle_pursuit, not the solver):
    // d(1e4) = 2.6e-5, 6.8e-6, 3.4e-6, 2.6e-5; d(1e3)/d(1e4) = 44, 83, 83, 44.
    struct Case {
        double zeta, theta_deg;
    };
    Failures f;
    for (const Case c : {Case{0.05, 30}, Case{0.05, 90}, Case{0.1, 30}, Case{0.05, 150}}) {
        const double theta = c.theta_deg * kDeg;
        const double rigid = fv::rigid_ratio(c.zeta, theta).rx;
        // The reference itself: on the circle (v > 0) and in the 1/rdisp^2 regime.
        const auto ref3 = fv::ref::circle_pursuit(c.zeta, theta, 1e3);
        const auto ref4 = fv::ref::circle_pursuit(c.zeta, theta, 1e4);
        REQUIRE(ref3.min_v > 0.01);
        REQUIRE(ref4.min_v > 0.01);
        const double q_ref = (ref3.rx - rigid) / (ref4.rx - rigid);
        CAPTURE(c.zeta, c.theta_deg, q_ref);
        REQUIRE(q_ref > 30);
        REQUIRE(q_ref < 300);
        REQUIRE(std::fabs(ref4.rx - rigid) > 3e-6);
        for (double i : {0.0, 1.0, 5.0}) {
            const Params p3{c.zeta, theta, 1e3, i}, p4{c.zeta, theta, 1e4, i};
            const auto r3 = solve(p3);
            const auto r4 = solve(p4);
            const bool good3 = contract_check(f, p3, r3);
            const bool good4 = contract_check(f, p4, r4);
            if (!good3 || !good4) continue;
            const double d3 = std::fabs(r3.rx - rigid), d4 = std::fabs(r4.rx - rigid);
            if (!(d4 < 1e-4)) f.fail(p4, fmt("|r_x - rigid| = %.3e >= 1e-4", d4), d4);
            const double q = d3 / d4;
            if (!(q >= 30 && q <= 300))
                f.fail(p4,
                       fmt("|r - rigid| at rdisp 1e3 / at 1e4 = %.3e / %.3e = %.1f, not in [30, 300]", d3, d4,
                           q),
                       std::fabs(std::log(q / 100)));
        }
    }
    FV_REPORT(f);
}

TEST_CASE("c. large rdisp, 0 < theta < 180 deg: the steady state is the pursuit curve on |L| = z_ss, the "
          "same for every i",
          "[solver-ref][rigid-limit][circle][slow]") {
    Failures f;
    int on_circle = 0;
    for (double zeta : {0.05, 0.1, 0.5, 1.0, 3.0})
        for (double theta_deg : {30.0, 90.0, 150.0})
            for (double rdisp : {100.0, 1e3, 1e4}) {
                const double theta = theta_deg * kDeg;
                const auto ref = fv::ref::circle_pursuit(zeta, theta, rdisp);
                REQUIRE(ref.error_estimate < 1e-8);
                if (!(ref.min_v > 1e-3)) continue; // the tip would leave the circle: not this steady state
                ++on_circle;
                for (double i : {0.0, 0.5, 1.0, 2.0, 5.0, 10.0}) {
                    const Params p{zeta, theta, rdisp, i};
                    accuracy_check(f, p, solve(p), ref.rx, ref.ry);
                }
            }
    CHECK(on_circle >= 40);
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// d. Small-amplitude limits rdisp -> 0.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("d. rdisp -> 0, i = 0: r_x -> 1 at every angle (the tip slips at full deflection)",
          "[solver-ref][compliant-limit]") {
    // Once the tip has slipped, |L| stays within ~1 (the vibration amplitude) of z_ss = 1/rdisp and its
    // direction within ~1/z_ss of the x axis (P_y is bounded), so 1 - r_x = O(rdisp): < 1e-5 at 1e-6.
    Failures f;
    for (double zeta : {0.01, 0.1, 0.5, 1.0, 10.0, 100.0})
        for (double theta_deg : {0.0, 30.0, 90.0, 150.0, 180.0})
            for (double rdisp : {1e-9, 1e-6}) {
                const Params p{zeta, theta_deg * kDeg, rdisp, 0};
                const auto r = solve(p);
                if (!contract_check(f, p, r) && !std::isfinite(r.rx)) continue;
                if (!(std::fabs(r.rx - 1) <= 1e-5))
                    f.fail(p, fmt("r_x = %.12f, not within 1e-5 of 1", r.rx), std::fabs(r.rx - 1));
            }
    FV_REPORT(f);
}

TEST_CASE("d. rdisp -> 0, theta = 0: r_x -> zeta / mean|zeta + cos tau| (i = 1), (1 - q)/(1 + q) (any i)",
          "[solver-ref][compliant-limit][long]") {
    Failures f;
    for (double zeta : {1e-3, 0.01, 0.1, 0.5, 0.9, 0.99, 1.0, 1.5, 10.0})
        for (double rdisp : {1e-10, 1e-9, 1e-6}) {
            const double mean_abs =
                zeta >= 1 ? zeta : (2 / kPi) * (zeta * std::asin(zeta) + std::sqrt(1 - zeta * zeta));
            const double limit = zeta / mean_abs;
            // How far from the limit the exact state still is at this rdisp (O(rdisp)).
            REQUIRE(std::fabs(fv::ref::rx_theta0_i1(zeta, rdisp) - limit) < 1e-8);
            const Params p{zeta, 0.0, rdisp, 1};
            accuracy_check(f, p, solve(p), limit, 0.0);
            for (double i : {0.5, 2.0, 5.0, 10.0}) {
                const double lim_i = fv::ref::compliant_limit_theta0(zeta, i);
                REQUIRE(std::fabs(fv::ref::rx_theta0_general(zeta, rdisp, i) - lim_i) < 1e-8);
                const Params pi{zeta, 0.0, rdisp, i};
                accuracy_check(f, pi, solve(pi), lim_i, 0.0);
            }
        }
    FV_REPORT(f);
}

// The small-amplitude limit (rdisp -> 0 at fixed zeta > 0) of the period mean of F, derived here by
// quadrature, not from the solver's closed form: the force hardly moves in a period, T moves only along
// e = l/|l|, and on average it must move along e_x at speed zeta, so e = e_x and rho = |l| balances
// (1/2 pi) int v k(v, rho) dtau = zeta with v = zeta + cos(tau) cos(theta), k = 1 - (1 - sgn(v) rho)^i
// (rho = 1, the circle, when no rho < 1 does). i = 0: the tip slips at full deflection, (1, 0). zeta = 0:
// i > 0 symmetric, (0, 0); i = 0 the zeta -> 0+ lens limit, (1, 0) + O(rdisp).
fv::Vec2 small_amplitude_reference(double zeta, double theta, double i) {
    if (i == 0) return {1, 0};
    if (zeta == 0) return {0, 0};
    const double c = std::cos(theta);
    // v > 0 throughout: the balance is zeta (1 - (1 - rho)^i) = zeta, only rho = 1.
    if (std::fabs(c) <= zeta) return {1, 0};
    // Pieces between the zeros of v, Simpson on each (v k is smooth there).
    std::vector<double> cuts{0.0, 2 * kPi};
    if (std::fabs(c) > zeta) {
        const double t = std::acos(-zeta / c);
        cuts = {0.0, t, 2 * kPi - t, 2 * kPi};
    }
    const auto drift = [&](double rho) {
        double sum = 0;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const int n = 2000;
            const double a = cuts[k], h = (cuts[k + 1] - a) / n;
            const double mid = a + 0.5 * (cuts[k + 1] - a);
            const double sg = zeta + std::cos(mid) * c < 0 ? -1.0 : 1.0;
            const auto g = [&](double tau) {
                const double v = zeta + std::cos(tau) * c;
                return v * (1 - std::pow(1 - sg * rho, i));
            };
            double s = g(a) + g(cuts[k + 1]);
            for (int m = 1; m < n; ++m) s += (m % 2 ? 4 : 2) * g(a + m * h);
            sum += s * h / 3;
        }
        return sum / (2 * kPi) - zeta;
    };
    if (!(drift(1.0) > 0)) return {1, 0};
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (lo + hi);
        (drift(m) > 0 ? hi : lo) = m;
    }
    return {0.5 * (lo + hi), 0};
}

TEST_CASE(
    "d. rdisp -> 0 down to the smallest subnormal: every i, theta, zeta meets the small-amplitude limit",
    "[solver-ref][compliant-limit][long]") {
    // The exact state differs from the limit by O(rdisp): allowed 100 rdisp on top of the error estimate.
    Failures f;
    for (double rdisp : {5e-10, 1e-12, 1e-15, 1e-20, 1e-100, 1e-300, 5e-324})
        for (double i : {0.0, 0.5, 1.0, 2.0, 5.0, 10.0})
            for (double zeta : {0.0, 1e-3, 0.5, 100.0})
                for (double theta_deg : {0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0}) {
                    const Params p{zeta, theta_deg * kDeg, rdisp, i};
                    const auto r = solve(p);
                    if (!contract_check(f, p, r)) continue;
                    const fv::Vec2 lim = small_amplitude_reference(zeta, theta_deg * kDeg, i);
                    const double err = std::max(std::fabs(r.rx - lim.x()), std::fabs(r.ry - lim.y()));
                    if (!(err <= r.error_estimate + 100 * rdisp + 1e-13))
                        f.fail(p,
                               fmt("r_x=%.15f r_y=%.3e, limit r_x=%.15f: |error| %.3e", r.rx, r.ry, lim.x(),
                                   err) +
                                   fmt(" > est %.2e + 100 rdisp", r.error_estimate),
                               err);
                }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// e. The paper's scheme, Richardson-extrapolated to dtau -> 0, at moderate points.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("e. paper scheme at N = 2^13, 2^14, 2^15, extrapolated, agrees with the default solver",
          "[solver-ref][paper][slow]") {
    // The scheme is first order: r(N) = r0 + c/N + O(1/N^2), so R(N) = 2 r(2N) - r(N) = r0 + O(1/N^2).
    // Runs start on the circle |L| = z_ss in the direction of P'(0): the steady state does not depend on the
    // start, and where it lies on the circle (i > 1 here, mostly) a start from rest would reach
    // it only algebraically slowly.
    Failures f;
    for (double i : {0.0, 1.0, 2.0})
        for (double zeta : {0.3, 0.8})
            for (double theta_deg : {30.0, 60.0})
                for (double rdisp : {1.0, 5.0}) {
                    const Params p{zeta, theta_deg * kDeg, rdisp, i};
                    double rx[3], ry[3];
                    bool paper_ok = true;
                    for (int l = 0; l < 3; ++l) {
                        fv::SteadyOptions o;
                        o.scheme = fv::Scheme::paper;
                        o.steps_per_period = 8192 << l;
                        o.max_periods = 3000;
                        o.initial_lag = circle_start(p);
                        const auto r = fv::steady_ratio(fv::Model::dahl, p, o);
                        paper_ok = paper_ok && fv::ok(r.status) && std::isfinite(r.rx);
                        rx[l] = r.rx;
                        ry[l] = r.ry;
                    }
                    // The reference must be sound before it judges anything.
                    REQUIRE(paper_ok);
                    const double d1 = rx[1] - rx[0], d2 = rx[2] - rx[1];
                    CAPTURE(describe(p), rx[0], rx[1], rx[2]);
                    REQUIRE(std::fabs(d2) > 1e-8); // a visible first-order term
                    REQUIRE(d1 / d2 > 1.5);
                    REQUIRE(d1 / d2 < 2.5);
                    const double R1x = 2 * rx[1] - rx[0], R2x = 2 * rx[2] - rx[1];
                    const double R1y = 2 * ry[1] - ry[0], R2y = 2 * ry[2] - ry[1];
                    const double spread = std::max(std::fabs(R1x - R2x), std::fabs(R1y - R2y));
                    REQUIRE(spread < 1e-6); // the extrapolations converge

                    const auto r = solve(p);
                    if (!contract_check(f, p, r) && !std::isfinite(r.rx)) continue;
                    const double diff = std::max(std::fabs(r.rx - R2x), std::fabs(r.ry - R2y));
                    if (!(diff <= 5e-5))
                        f.fail(p, fmt("r_x=%.10f, extrapolated paper %.10f: %.3e > 5e-5", r.rx, R2x, diff),
                               diff);
                    // Sharper: the extrapolation is good to about its spread, the solver to max(1e-6, est).
                    else if (!(diff <= 2e-6 + 4 * spread + r.error_estimate))
                        f.fail(p,
                               fmt("r_x=%.10f, extrapolated paper %.10f: %.3e > 2e-6 + 4 spread + est", r.rx,
                                   R2x, diff),
                               diff);
                }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// f. Mirror symmetry theta -> 180 deg - theta: P(tau + pi; pi - theta) is P(tau; theta) mirrored in y and
//    shifted along x, so the steady state is the mirror image: r_x unchanged, r_y flips.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("f. theta -> 180 deg - theta: r_x unchanged, r_y flips, over random points of the domain",
          "[solver-ref][symmetry]") {
    std::mt19937_64 rng(2006);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double i_set[] = {0.0, 0.5, 1.0, 2.0, 5.0, 10.0};
    Failures f;
    for (int k = 0; k < 40; ++k) {
        const double zeta = std::pow(10.0, -3.0 + 5.0 * u(rng));
        const double theta = 0.5 * kPi * u(rng);
        const double rdisp = std::pow(10.0, -9.0 + 13.0 * u(rng));
        const double i = k % 2 ? i_set[static_cast<int>(6 * u(rng)) % 6] : 10.0 * u(rng);
        const Params a{zeta, theta, rdisp, i}, b{zeta, kPi - theta, rdisp, i};
        const auto ra = solve(a), rb = solve(b);
        const bool ga = contract_check(f, a, ra);
        const bool gb = contract_check(f, b, rb);
        if (!ga && !gb && !(std::isfinite(ra.rx) && std::isfinite(rb.rx))) continue;
        const double dx = std::fabs(ra.rx - rb.rx), dy = std::fabs(ra.ry + rb.ry);
        if (!(dx <= 2e-6 && dy <= 2e-6))
            f.fail(
                a,
                fmt("r(theta) = (%.10f, %.10f), r(180 - theta) = (%.10f, %.10f)", ra.rx, ra.ry, rb.rx, rb.ry),
                std::max(dx, dy));
    }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// g. fv::sweep rows equal single-point calls.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("g. sweep rows equal steady_ratio at the same point (theta 90 deg, rdisp 1e4, i 10 and others)",
          "[solver-ref][sweep]") {
    struct Family {
        std::vector<double> zetas, thetas, rdisps, is;
    };
    const std::vector<Family> families = {
        {fv::linspace(0, 3, 4), {90 * kDeg}, {1e4}, {10}}, // the issue (NaN rows)
        {fv::linspace(0, 2, 9), {90 * kDeg}, {1e4}, {10}},
        {fv::linspace(0, 2, 9), {0.0, 45 * kDeg}, {1e-6, 1.0, 1e3}, {0.0, 1.0, 5.0}},
        {{1e-3, 0.01, 0.1, 1.0, 10.0, 100.0}, {120 * kDeg, 180 * kDeg}, {1e-9, 10.0}, {0.5, 2.0}},
    };
    Failures f;
    for (const Family& fam : families) {
        const auto rows = fv::sweep(fv::Model::dahl, fam.zetas, fam.thetas, fam.rdisps, fam.is, {}, 2);
        REQUIRE(rows.size() == fam.zetas.size() * fam.thetas.size() * fam.rdisps.size() * fam.is.size());
        std::size_t k = 0;
        for (double i : fam.is)
            for (double th : fam.thetas)
                for (double rd : fam.rdisps)
                    for (double z : fam.zetas) {
                        const auto& row = rows[k++];
                        const Params p{z, th, rd, i};
                        REQUIRE(row.params.zeta == z);
                        REQUIRE(row.params.theta == th);
                        REQUIRE(row.params.rdisp == rd);
                        REQUIRE(row.params.i == i);
                        if (!contract_check(f, p, row.result) && !std::isfinite(row.result.rx)) continue;
                        const auto single = solve(p);
                        if (!std::isfinite(single.rx) || !fv::ok(single.status)) {
                            f.fail(p,
                                   std::string("single call: status ") + fv::to_string(single.status) +
                                       fmt(" r_x=%g", single.rx),
                                   1e100);
                            continue;
                        }
                        const double d = std::max(std::fabs(row.result.rx - single.rx),
                                                  std::fabs(row.result.ry - single.ry));
                        if (!(d <= 2e-6))
                            f.fail(p,
                                   fmt("sweep row r_x=%.10f, single call %.10f: %.2e", row.result.rx,
                                       single.rx, d),
                                   d);
                        // Where an independent value exists, the row must meet it too.
                        if (th == 0.0 || th == 180 * kDeg) {
                            if (!(z == 0.0 && i == 0.0 && rd <= 1))
                                error_check(f, p, row.result, fv::ref::rx_theta0_general(z, rd, i), 0.0);
                        } else if (th == 90 * kDeg && z == 0.0) {
                            // P_x == 0: L_x decays to 0 from any start; r_y = 0 by the mirror symmetry.
                            error_check(f, p, row.result, 0.0, 0.0);
                        } else if (rd >= 100 && z > 0.0) {
                            const auto ref = fv::ref::circle_pursuit(z, th, rd);
                            if (ref.min_v > 1e-3) error_check(f, p, row.result, ref.rx, ref.ry);
                        }
                    }
    }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// h. Properties at random points of the whole domain.
//    |F| <= F_c at every instant (|L| <= z_ss is invariant: the deflection law stops growing at z_ss), so
//    hypot(r_x, r_y) <= 1. r_x >= 0 is asserted only where it is proved: theta = 90 deg, zeta > 0, where
//    L_x' = zeta - k L_x/|L| with k >= 0 (T moves toward P), so L_x cannot fall to 0: min L_x > 0. (For
//    other angles no proof is at hand; the rigid model, the theta = 0 laws and every computed case have
//    r_x >= 0, but that is not asserted.) theta = 0 and 180 deg are compared with the exact law.
// ---------------------------------------------------------------------------------------------------------

// What every result must satisfy, whatever the point: |F| <= F_c at every instant, so |r| <= 1; r_x >= 0 at
// theta = 90 deg (proved there, see above); the exact law at theta = 0 and 180 deg where the steady state
// is unique.
void property_check(Failures& f, const Params& p, const fv::SteadyResult& r) {
    const double eps = 1e-9;
    if (!(std::fabs(r.rx) <= 1 + eps && std::fabs(r.ry) <= 1 + eps && std::hypot(r.rx, r.ry) <= 1 + eps))
        f.fail(p, fmt("|r| out of bounds: r_x=%.12f r_y=%.12f", r.rx, r.ry), std::hypot(r.rx, r.ry) - 1);
    if (p.theta == 90 * kDeg && !(r.rx >= -eps))
        f.fail(p, fmt("r_x = %.3e < 0 at theta = 90 deg", r.rx), -r.rx);
    const bool unique = !(p.zeta == 0.0 && p.i == 0.0 && p.rdisp <= 1);
    if ((p.theta == 0.0 || p.theta == 180 * kDeg) && unique)
        error_check(f, p, r, fv::ref::rx_theta0_general(p.zeta, p.rdisp, p.i), 0.0);
}

TEST_CASE("h. property: 300 random points over the domain: finite, ok, |F| bound, exact at theta = 0, 180",
          "[solver-ref][property]") {
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double i_set[] = {0.0, 0.5, 1.0, 2.0, 5.0, 10.0};
    const double special_theta[] = {0.0, 90 * kDeg, 180 * kDeg};
    Failures f;
    for (int k = 0; k < 300; ++k) {
        const double zeta = u(rng) < 0.08 ? 0.0 : std::pow(10.0, -3.0 + 5.0 * u(rng));
        const double theta = u(rng) < 0.15 ? special_theta[static_cast<int>(3 * u(rng)) % 3] : kPi * u(rng);
        const double rdisp = std::pow(10.0, -9.0 + 13.0 * u(rng));
        const double i = u(rng) < 0.5 ? i_set[static_cast<int>(6 * u(rng)) % 6] : 10.0 * u(rng);
        const Params p{zeta, theta, rdisp, i};
        const auto r = solve(p);
        if (!contract_check(f, p, r) && !std::isfinite(r.rx)) continue;
        property_check(f, p, r);
    }
    FV_REPORT(f);
}

// ---------------------------------------------------------------------------------------------------------
// i. The benchmark's grid (bench/domain_speed.cpp): every point meets the contract, the |F| bound, r_x >= 0
//    at 90 deg, the exact law at 0 and 180 deg, and the mirror pairs 30/150 and 60/120 deg agree.
// ---------------------------------------------------------------------------------------------------------

TEST_CASE("i. the whole benchmark grid (5880 points): contract, bounds, exact at 0/180 deg, mirror pairs",
          "[solver-ref][grid][slow][long]") {
    std::vector<double> zetas{0.0};
    for (int k = 0; k <= 8; ++k) zetas.push_back(std::pow(10.0, -3.0 + 5.0 * k / 8));
    // Not judged: zeta = 10^(-15/8) = 0.075, theta = 30 and 150 deg, rdisp = 100, i = 10. There the motion
    // never settles: the paper's scheme (N = 2^11 and 2^15, 20000 periods, three starts) and a plain RK4 of
    // the lag law (2^14 steps per period, 6000 periods) keep wandering, the period means of r_x between about
    // 0.050 and 0.071, so there is no attracting periodic steady state to be "ok" about (a solver may find
    // periodic solutions there, but they are not what the scheme reaches; one solver found different ones at
    // 30 and 150 deg, not mirror images).
    const auto unsettled = [&](double zeta, int k, int e, double i) {
        return zeta == zetas[4] && (k == 1 || k == 5) && e == 2 && i == 10.0;
    };
    Failures f;
    for (double i : {0.0, 0.5, 1.0, 2.0, 5.0, 10.0})
        for (int e = -9; e <= 4; ++e)
            for (double zeta : zetas) {
                const double rdisp = std::pow(10.0, e);
                fv::SteadyResult r[7];
                for (int k = 0; k <= 6; ++k) {
                    const Params p{zeta, 30 * k * kDeg, rdisp, i};
                    r[k] = solve(p);
                    if (unsettled(zeta, k, e, i)) continue;
                    if (!contract_check(f, p, r[k]) && !(std::isfinite(r[k].rx) && std::isfinite(r[k].ry)))
                        continue;
                    property_check(f, p, r[k]);
                }
                for (int k : {1, 2}) {
                    if (unsettled(zeta, k, e, i)) continue;
                    const Params p{zeta, 30 * k * kDeg, rdisp, i};
                    const fv::SteadyResult &a = r[k], &b = r[6 - k];
                    if (!std::isfinite(a.rx) || !std::isfinite(b.rx) || !std::isfinite(a.ry) ||
                        !std::isfinite(b.ry))
                        continue;
                    const double d = std::max(std::fabs(a.rx - b.rx), std::fabs(a.ry + b.ry));
                    if (zeta > 0 && !(d <= 2e-6))
                        f.fail(p,
                               fmt("mirror: r(theta) = (%.10f, %.10f), r(180 - theta) = (%.10f, %.10f)", a.rx,
                                   a.ry, b.rx, b.ry),
                               d);
                }
            }
    FV_REPORT(f);
}
