// Standalone validation of theta0_exact.{hpp,cpp}; not part of the CMake build.
//
//   g++ -std=c++17 -O2 -I tests/reference tests/reference/self_check.cpp tests/reference/theta0_exact.cpp
//       -o /tmp/self_check && /tmp/self_check            (add --quick for the two coarser resolutions only)
//
// 1. Brute force: integrate the 1-D ODE from rest (L = 0) with classical RK4 on a uniform grid of N steps per
//    period, until the state repeats from one period to the next, then compare r_x (integrated as a second
//    ODE component, Q' = L/z) and L at every grid point of one further period with the exact functions. Steps
//    are split where P reverses (tau = +-acos(-zeta) mod 2 pi, the only points where the right-hand side of
//    the i = 1 equation has a kink). i = 0 is integrated as a hybrid system: stick (L' = P') until |L| hits
//    z (event located by bisection on the RK4 sub-step), slip (L' = 0) until P reverses.
// 2. Exact transfer identities of the lag functions over arbitrary monotone stretches of P.
// 3. Independent quadrature of the lag functions (r_x; for i = 1 also int |P'| L = 2 pi zeta z).
// 4. Limits and special cases.
#include "theta0_exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

using namespace fv::ref;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

double pos(double zeta, double tau) {
    return zeta * tau + std::sin(tau);
}
double vel(double zeta, double tau) {
    return zeta + std::cos(tau);
}
double rigid(double zeta) {
    return zeta >= 1.0 ? 1.0 : (2.0 / kPi) * std::asin(zeta);
}

// -----------------------------------------------------------------------------------------------------------
// 1. ODE integration
struct Y {
    double L = 0;
    double Q = 0; // int L/z dtau
};

struct Ode {
    double zeta;
    double z;
    int model;    // 0 or 1
    int mode = 0; // i = 0 only: 0 stick, +1 slipping forward (L = z), -1 slipping backward (L = -z)

    Y rhs(double tau, const Y& y) const {
        const double v = vel(zeta, tau);
        Y d;
        if (model == 1) {
            d.L = v - std::fabs(v) * y.L / z;
        } else {
            d.L = (mode == 0) ? v : 0.0;
        }
        d.Q = y.L / z;
        return d;
    }

    // Increment of one classical RK4 step.
    Y rk4_increment(double tau, const Y& y, double h) const {
        const Y k1 = rhs(tau, y);
        const Y k2 = rhs(tau + 0.5 * h, {y.L + 0.5 * h * k1.L, y.Q + 0.5 * h * k1.Q});
        const Y k3 = rhs(tau + 0.5 * h, {y.L + 0.5 * h * k2.L, y.Q + 0.5 * h * k2.Q});
        const Y k4 = rhs(tau + h, {y.L + h * k3.L, y.Q + h * k3.Q});
        return {h / 6.0 * (k1.L + 2.0 * k2.L + 2.0 * k3.L + k4.L),
                h / 6.0 * (k1.Q + 2.0 * k2.Q + 2.0 * k3.Q + k4.Q)};
    }
    Y rk4(double tau, const Y& y, double h) const {
        const Y d = rk4_increment(tau, y, h);
        return {y.L + d.L, y.Q + d.Q};
    }
    // i = 1: L is accumulated with Kahan compensation. Near L = +-z the increments h P' (1 -+ L/z) z fall
    // below half an ulp of L and a plain update would stagnate about eps/(h |P'|) away from the limit.
    double carry = 0.0;
    Y rk4_compensated(double tau, Y y, double h) {
        const Y d = rk4_increment(tau, y, h);
        const double yk = d.L - carry;
        const double t = y.L + yk;
        carry = (t - y.L) - yk;
        y.L = t;
        y.Q += d.Q;
        return y;
    }

    // Advance over [ta, tb], on which P is monotone.
    Y advance_monotone(double ta, double tb, Y y) {
        if (!(tb > ta)) return y;
        if (model == 1) return rk4_compensated(ta, y, tb - ta);
        const double v = vel(zeta, 0.5 * (ta + tb));
        // Mode at the start of the stretch.
        if (mode == 0 && y.L >= z && v > 0) mode = 1;
        if (mode == 0 && y.L <= -z && v < 0) mode = -1;
        if (mode == 1 && v < 0) mode = 0;
        if (mode == -1 && v > 0) mode = 0;
        if (mode != 0) {
            y.L = mode * z;
            y.Q += mode * (tb - ta);
            return y;
        }
        Y end = rk4(ta, y, tb - ta);
        if (std::fabs(end.L) <= z) return end;
        // |L| reaches z inside: locate the sub-step s with bisection.
        double lo = 0.0;
        double hi = tb - ta;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            if (std::fabs(rk4(ta, y, mid).L) <= z)
                lo = mid;
            else
                hi = mid;
        }
        Y at = rk4(ta, y, lo);
        const int sign = end.L > 0 ? 1 : -1;
        at.L = sign * z;
        mode = sign;
        at.Q += sign * (tb - ta - lo);
        return at;
    }

    // Advance over [ta, tb] (one grid step), split where P reverses.
    Y advance(double ta, double tb, Y y) {
        if (zeta < 1.0) {
            const double r1 = std::acos(-zeta);
            const double r2 = kTwoPi - r1;
            std::vector<double> cuts;
            const double k0 = std::floor(ta / kTwoPi) - 1.0;
            for (double k = k0; k <= k0 + 3.0; k += 1.0) {
                for (double r : {r1, r2}) {
                    const double t = r + kTwoPi * k;
                    if (t > ta && t < tb) cuts.push_back(t);
                }
            }
            std::sort(cuts.begin(), cuts.end());
            double t = ta;
            for (double c : cuts) {
                y = advance_monotone(t, c, y);
                t = c;
            }
            return advance_monotone(t, tb, y);
        }
        return advance_monotone(ta, tb, y);
    }
};

struct OdeResult {
    double rx = 0;
    double dr = 0; // rx - exact
    double dl = 0; // max |L - L_exact| / z over the grid of the last period
    long periods = 0;
};

OdeResult run_ode(int model, double zeta, double rdisp, int n) {
    Ode ode{zeta, 1.0 / rdisp, model};
    const double h = kTwoPi / n;
    double dl = 0.0;
    Y y;
    // One period starting at tau = 2 pi k; returns r_x of that period. Q is integrated per step (Q reset to
    // 0) and summed with Kahan compensation, so rounding does not accumulate over the n steps.
    const auto period = [&](long k, bool record) {
        const double t0 = kTwoPi * static_cast<double>(k);
        double sum = 0.0;
        double carry = 0.0;
        for (int j = 0; j < n; ++j) {
            const double tb = t0 + (j + 1) * h;
            y.Q = 0.0;
            y = ode.advance(t0 + j * h, tb, y);
            const double yk = y.Q - carry;
            const double t = sum + yk;
            carry = (t - sum) - yk;
            sum = t;
            if (record) {
                const double ex =
                    model == 1 ? lag_theta0_i1(zeta, rdisp, tb) : lag_theta0_i0(zeta, rdisp, tb);
                dl = std::max(dl, std::fabs(y.L - ex) / ode.z);
            }
        }
        return sum / kTwoPi;
    };
    double l_prev = 1e300;
    double r_prev = 1e300;
    int calm = 0;
    long k = 0;
    const double tol = 1e-14;
    for (; k < 200000; ++k) {
        const double r = period(k, false);
        const bool same = std::fabs(y.L - l_prev) <= tol * ode.z && std::fabs(r - r_prev) <= tol;
        calm = same ? calm + 1 : 0;
        l_prev = y.L;
        r_prev = r;
        if (calm >= 3) break;
    }
    ++k;
    // One more period, recorded.
    OdeResult res;
    res.rx = period(k, true);
    res.dr = res.rx - (model == 1 ? rx_theta0_i1(zeta, rdisp) : rx_theta0_i0(zeta, rdisp));
    res.dl = dl;
    res.periods = k + 1;
    return res;
}

// -----------------------------------------------------------------------------------------------------------
// 2./3. Quadrature and identities on the lag functions
double lag(int model, double zeta, double rdisp, double tau) {
    return model == 1 ? lag_theta0_i1(zeta, rdisp, tau) : lag_theta0_i0(zeta, rdisp, tau);
}

// Composite 8-point Gauss-Legendre on [a, b] with m panels.
template <class F> double composite_gauss(const F& f, double a, double b, int m) {
    static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                0.1012285362903763};
    const double hp = (b - a) / m;
    double sum = 0.0;
    double carry = 0.0; // Kahan summation over the panels
    for (int p = 0; p < m; ++p) {
        const double c = a + (p + 0.5) * hp;
        double panel = 0.0;
        for (int q = 0; q < 4; ++q) panel += w[q] * (f(c - 0.5 * hp * x[q]) + f(c + 0.5 * hp * x[q]));
        const double yk = panel - carry;
        const double t = sum + yk;
        carry = (t - sum) - yk;
        sum = t;
    }
    return 0.5 * hp * sum;
}

// int over one period of f, split at the reversal points of P.
template <class F> double period_integral(const F& f, double zeta, int m) {
    if (zeta >= 1.0) return composite_gauss(f, 0.0, kTwoPi, m);
    const double t1 = std::acos(-zeta);
    const double t2 = kTwoPi - t1;
    return composite_gauss(f, 0.0, t1, m) + composite_gauss(f, t1, t2, m) + composite_gauss(f, t2, kTwoPi, m);
}

// i = 0: r_x by quadrature of the lag function alone, split at the reversals of P and at the points where the
// lag itself first sits at +-z (found by bisection on the predicate "lag == +-z", i.e. from its output only).
double rx_i0_from_lag(double zeta, double r, int m) {
    const auto f = [&](double t) { return lag_theta0_i0(zeta, r, t) * r; };
    if (zeta >= 1.0) return composite_gauss(f, 0.0, kTwoPi, m) / kTwoPi;
    const double z = 1.0 / r;
    const double t1 = std::acos(-zeta);
    const double t2 = kTwoPi - t1;
    // First tau in [a, b] with lag == target (b if none), assuming once reached it stays.
    const auto first_at = [&](double a, double b, double target) {
        if (lag_theta0_i0(zeta, r, b) != target) return b;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (a + b);
            if (!(mid > a && mid < b)) break;
            if (lag_theta0_i0(zeta, r, mid) == target)
                b = mid;
            else
                a = mid;
        }
        return b;
    };
    const double ks = first_at(t1, t2, -z);         // back phase: slips backwards from here (if at all)
    const double kf = first_at(t2 - kTwoPi, t1, z); // forward phase: slips forwards from here
    return (composite_gauss(f, t2 - kTwoPi, kf, m) + composite_gauss(f, kf, t1, m) +
            composite_gauss(f, t1, ks, m) + composite_gauss(f, ks, t2, m)) /
           kTwoPi;
}

// Max violation, in units of the check's own rounding (1e-13 + 16 eps (1 + |tau|) rdisp in L/z), of the exact
// transfer over random monotone stretches [ta, tb] of P:
//   i = 0: L(tb) = clamp(L(ta) + P(tb) - P(ta), -z, z)
//   i = 1: z - s L(tb) = (z - s L(ta)) exp(-|P(tb) - P(ta)|/z), s = sgn P'
double transfer_violation(int model, double zeta, double rdisp, std::mt19937_64& rng) {
    const double z = 1.0 / rdisp;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int t = 0; t < 2000; ++t) {
        double a0 = 0.0;
        double b0 = kTwoPi;
        double sgn = 1.0;
        if (zeta < 1.0) {
            const double t1 = std::acos(-zeta);
            const double t2 = kTwoPi - t1;
            if (t % 2 == 0) {
                a0 = t1;
                b0 = t2;
                sgn = -1.0;
            } else {
                a0 = t2 - kTwoPi;
                b0 = t1;
            }
        }
        const double shift = kTwoPi * std::floor(20.0 * u(rng));
        double ta = a0 + (b0 - a0) * u(rng);
        double tb = a0 + (b0 - a0) * u(rng);
        if (ta > tb) std::swap(ta, tb);
        ta += shift;
        tb += shift;
        const double la = lag(model, zeta, rdisp, ta);
        const double lb = lag(model, zeta, rdisp, tb);
        const double dp = pos(zeta, tb) - pos(zeta, ta);
        double pred = 0.0;
        if (model == 0) {
            pred = std::clamp(la + dp, -z, z);
        } else {
            pred = sgn * (z - (z - sgn * la) * std::exp(-std::fabs(dp) / z));
        }
        // Rounding of the check itself: P(tb) - P(ta) and the phase reduction lose ~eps (1 + |tb|) in L.
        const double scale = 1e-13 + 16.0 * 2.2e-16 * (1.0 + std::fabs(tb)) * rdisp;
        worst = std::max(worst, std::fabs(lb - pred) / z / scale);
    }
    return worst;
}

int failures = 0;
void expect(bool ok, const char* what) {
    if (!ok) {
        ++failures;
        std::printf("  ** FAILED: %s\n", what);
    }
}

} // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const std::vector<double> zetas = {0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 0.99, 1.0, 1.5, 3.0};
    const std::vector<double> rdisps = {0.2, 0.5, 1, 2, 5, 20, 100};
    std::vector<int> ns = {1000, 4000, 16000};
    if (quick) ns.pop_back();

    // ---- 1. ODE brute force ------------------------------------------------------------------------------
    for (int model : {1, 0}) {
        std::printf(
            "\n=== i = %d: RK4 from rest vs exact; dr = r_x(ODE) - r_x(exact), dL = max|L - L_exact|/z_ss\n",
            model);
        std::printf("%6s %6s %10s %8s", "zeta", "rdisp", "rx_exact", "periods");
        for (int n : ns) std::printf("   dr(N=%-5d)", n);
        for (int n : ns) std::printf("   dL(N=%-5d)", n);
        std::printf("\n");
        std::vector<double> max_dr(ns.size(), 0.0);
        std::vector<double> max_dl(ns.size(), 0.0);
        for (double zeta : zetas) {
            for (double r : rdisps) {
                std::vector<OdeResult> res;
                for (int n : ns) res.push_back(run_ode(model, zeta, r, n));
                const double ex = model == 1 ? rx_theta0_i1(zeta, r) : rx_theta0_i0(zeta, r);
                std::printf("%6.2f %6.1f %10.7f %8ld", zeta, r, ex, res.back().periods);
                for (std::size_t j = 0; j < ns.size(); ++j) {
                    std::printf("   %12.3e", res[j].dr);
                    max_dr[j] = std::max(max_dr[j], std::fabs(res[j].dr));
                }
                for (std::size_t j = 0; j < ns.size(); ++j) {
                    std::printf("   %12.3e", res[j].dl);
                    max_dl[j] = std::max(max_dl[j], res[j].dl);
                }
                std::printf("\n");
            }
        }
        std::printf("%6s %6s %10s %8s", "max", "", "", "");
        for (double v : max_dr) std::printf("   %12.3e", v);
        for (double v : max_dl) std::printf("   %12.3e", v);
        std::printf("\n");
        expect(max_dr.back() < 1e-7 && max_dl.back() < 1e-7, "ODE agreement at the finest N");
    }

    // Special cases through the ODE: zeta = 0 (unique cases), B = 2 z_ss exactly.
    std::printf("\n=== special cases through the ODE (N = %d)\n", ns.back());
    {
        struct Case {
            int model;
            double zeta;
            double r;
            const char* note;
        };
        const double b05 = back_travel_theta0(0.5);
        const double b01 = back_travel_theta0(0.1);
        const std::vector<Case> cases = {
            {1, 0.0, 0.5, "zeta = 0, i = 1 (unique)"},
            {1, 0.0, 5.0, "zeta = 0, i = 1 (unique)"},
            {0, 0.0, 1.0, "zeta = 0, i = 0, rdisp = 1 (unique, L = sin tau)"},
            {0, 0.0, 3.0, "zeta = 0, i = 0, rdisp = 3 (unique)"},
            {0, 0.5, 2.0 / b05, "zeta = 0.5, i = 0, B = 2 z_ss exactly"},
            {0, 0.1, 2.0 / b01, "zeta = 0.1, i = 0, B = 2 z_ss exactly"},
            {1, 0.5, 2.0 / b05, "zeta = 0.5, i = 1, same rdisp"},
            {0, 0.999, 3.0, "zeta = 0.999, i = 0"},
            {1, 0.999, 3.0, "zeta = 0.999, i = 1"},
            {0, 0.01, 0.3, "zeta = 0.01, i = 0, long sticking transient"},
        };
        for (const Case& c : cases) {
            const OdeResult o = run_ode(c.model, c.zeta, c.r, ns.back());
            std::printf("  %-48s rdisp=%-10.6g rx=%.12f dr=%10.2e dL=%10.2e periods=%ld\n", c.note, c.r, o.rx,
                        o.dr, o.dl, o.periods);
            expect(std::fabs(o.dr) < 1e-7 && o.dl < 1e-7, c.note);
        }
        // zeta = 0, i = 0, rdisp < 1: start-dependent; document the two answers.
        const OdeResult o = run_ode(0, 0.0, 0.5, 1000);
        std::printf(
            "  zeta = 0, i = 0, rdisp = 0.5 (NOT unique): ODE from rest rx=%.3e, reference (zeta->0+) "
            "rx=%.15f, at zeta=1e-9: %.15f\n",
            o.rx, rx_theta0_i0(0.0, 0.5), rx_theta0_i0(1e-9, 0.5));
    }

    // ---- 2./3. Identities and independent quadrature of the lag functions
    // ------------------------------------
    std::printf("\n=== lag functions: exact transfer identities, r_x by composite Gauss quadrature of L\n");
    std::printf("%6s %8s %12s %12s %12s %12s %12s\n", "zeta", "rdisp", "transf i=0", "transf i=1",
                "quad-rx i=0", "quad-rx i=1", "|P'|L i=1");
    std::mt19937_64 rng(12345);
    double worst_transfer = 0.0;
    double worst_quad1 = 0.0;
    double worst_quad0 = 0.0;
    double worst_weighted = 0.0;
    const std::vector<double> zq = {0.0, 0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 0.99, 0.999999, 1.0, 1.5, 3.0};
    const std::vector<double> rq = {0.001, 0.2, 0.5, 1, 2, 5, 20, 100, 1e4};
    for (double zeta : zq) {
        for (double r : rq) {
            const double t0 = transfer_violation(0, zeta, r, rng);
            const double t1 = transfer_violation(1, zeta, r, rng);
            // i = 1 is smooth between the reversals: composite Gauss converges fast once panels resolve
            // sqrt(z).
            const int m = 4096;
            const double q1 =
                period_integral([&](double t) { return lag_theta0_i1(zeta, r, t) * r; }, zeta, m) / kTwoPi -
                rx_theta0_i1(zeta, r);
            // i = 0: split also at the kinks where the lag starts to slip.
            const double q0 = rx_i0_from_lag(zeta, r, m) - rx_theta0_i0(zeta, r);
            const double wgt =
                period_integral(
                    [&](double t) { return std::fabs(vel(zeta, t)) * lag_theta0_i1(zeta, r, t) * r; }, zeta,
                    m) /
                    kTwoPi -
                zeta;
            std::printf("%6.6g %8.6g %12.2e %12.2e %12.2e %12.2e %12.2e\n", zeta, r, t0, t1, q0, q1, wgt);
            worst_transfer = std::max({worst_transfer, t0, t1});
            worst_quad1 = std::max(worst_quad1, std::fabs(q1));
            worst_quad0 = std::max(worst_quad0, std::fabs(q0));
            worst_weighted = std::max(worst_weighted, std::fabs(wgt));
        }
    }
    std::printf("max transfer violation %.2e (units of rounding scale); max |quad - rx|: i=0 "
                "%.2e, i=1 %.2e; "
                "max |<|P'|L/z> - zeta| %.2e\n",
                worst_transfer, worst_quad0, worst_quad1, worst_weighted);
    expect(worst_transfer < 1.0, "transfer identities");
    expect(worst_quad1 < 1e-12 && worst_weighted < 1e-12, "i = 1 quadrature of the lag");
    expect(worst_quad0 < 1e-12, "i = 0 quadrature of the lag");

    // ---- 4. Limits
    // --------------------------------------------------------------------------------------------
    std::printf("\n=== rdisp -> infinity: r_x - (2/pi) asin(zeta)\n%6s", "zeta");
    const std::vector<double> big = {1e2, 1e3, 1e4, 1e6, 1e8};
    for (double r : big) std::printf("   i0(r=%-6.0e)   i1(r=%-6.0e)", r, r);
    std::printf("\n");
    for (double zeta : {0.0, 0.02, 0.1, 0.5, 0.9, 0.99, 1.0}) {
        std::printf("%6.2f", zeta);
        for (double r : big)
            std::printf("   %13.3e   %13.3e", rx_theta0_i0(zeta, r) - rigid(zeta),
                        rx_theta0_i1(zeta, r) - rigid(zeta));
        std::printf("\n");
        expect(std::fabs(rx_theta0_i0(zeta, 1e8) - rigid(zeta)) < 1e-6 &&
                   std::fabs(rx_theta0_i1(zeta, 1e8) - rigid(zeta)) < 1e-6,
               "rigid limit");
    }

    std::printf(
        "\n=== rdisp -> 0: i = 0 -> 1, i = 1 -> 2 pi zeta / int|P'| (int|P'| computed by quadrature)\n");
    for (double zeta : {0.02, 0.1, 0.5, 0.9, 0.99}) {
        const double absv = period_integral([&](double t) { return std::fabs(vel(zeta, t)); }, zeta, 64);
        const double lim1 = kTwoPi * zeta / absv;
        std::printf("  zeta=%.2f:", zeta);
        for (double r : {1e-2, 1e-4, 1e-6})
            std::printf("  r=%.0e: i0-1=%10.2e i1-lim=%10.2e", r, rx_theta0_i0(zeta, r) - 1.0,
                        rx_theta0_i1(zeta, r) - lim1);
        std::printf("\n");
        expect(std::fabs(rx_theta0_i1(zeta, 1e-6) - lim1) < 1e-5, "i = 1 compliant limit");
    }

    std::printf("\n=== i = 0, B <= 2 z_ss: (1 - r_x)/rdisp is constant in rdisp (deficit linear in rdisp)\n");
    for (double zeta : {0.02, 0.3, 0.8, 0.99}) {
        const double rstar = 2.0 / back_travel_theta0(zeta);
        const double c1 = (1.0 - rx_theta0_i0(zeta, 1e-3 * rstar)) / (1e-3 * rstar);
        const double c2 = (1.0 - rx_theta0_i0(zeta, 0.5 * rstar)) / (0.5 * rstar);
        const double c3 = (1.0 - rx_theta0_i0(zeta, rstar)) / rstar;
        std::printf("  zeta=%.2f rdisp*=2/B=%-10.6g slopes %.15f %.15f %.15f\n", zeta, rstar, c1, c2, c3);
        expect(std::fabs(c1 - c3) < 1e-9 * std::fabs(c3) + 1e-12, "linear regime");
    }

    std::printf("\n=== continuity: across B = 2 z_ss (i = 0), zeta -> 1-, zeta -> 0+\n");
    for (double zeta : {0.1, 0.5, 0.9}) {
        const double rstar = 2.0 / back_travel_theta0(zeta);
        const double eps = 1e-9;
        const double lo = rx_theta0_i0(zeta, rstar * (1 - eps));
        const double mid = rx_theta0_i0(zeta, rstar);
        const double hi = rx_theta0_i0(zeta, rstar * (1 + eps));
        std::printf("  zeta=%.1f at rdisp*(1-1e-9), rdisp*, rdisp*(1+1e-9): %.15f %.15f %.15f\n", zeta, lo,
                    mid, hi);
        expect(std::fabs(hi - lo) < 1e-8, "continuity at B = 2 z_ss");
    }
    for (double r : {0.5, 2.0, 100.0}) {
        std::printf("  rdisp=%5.1f zeta=1-1e-4, 1-1e-8, 1-1e-12, 1:", r);
        for (double zeta : {1 - 1e-4, 1 - 1e-8, 1 - 1e-12, 1.0})
            std::printf("  (%.15f, %.15f)", rx_theta0_i0(zeta, r), rx_theta0_i1(zeta, r));
        std::printf("\n");
        expect(std::fabs(rx_theta0_i1(1 - 1e-12, r) - 1.0) < 1e-9, "zeta -> 1-");
        std::printf("  rdisp=%5.1f zeta=0, 1e-12, 1e-9: i0 %.15f %.15f %.15f   i1 %.15f %.15f %.15f\n", r,
                    rx_theta0_i0(0.0, r), rx_theta0_i0(1e-12, r), rx_theta0_i0(1e-9, r), rx_theta0_i1(0.0, r),
                    rx_theta0_i1(1e-12, r), rx_theta0_i1(1e-9, r));
    }

    std::printf("\n=== invalid arguments throw\n");
    int thrown = 0;
    for (auto f :
         {+[] { return rx_theta0_i0(-0.1, 1.0); }, +[] { return rx_theta0_i1(0.5, 0.0); },
          +[] { return lag_theta0_i0(0.5, 1.0, NAN); }, +[] { return rx_theta0_i1(INFINITY, 1.0); }}) {
        try {
            (void)f();
        } catch (const std::exception&) {
            ++thrown;
        }
    }
    std::printf("  %d of 4 threw\n", thrown);
    expect(thrown == 4, "invalid arguments");

    std::printf("\n%s (%d failures)\n", failures == 0 ? "ALL CHECKS PASSED" : "SOME CHECKS FAILED", failures);
    return failures == 0 ? 0 : 1;
}
