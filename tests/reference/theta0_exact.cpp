// Exact steady state for theta = 0; the derivation is in theta0_exact.hpp.
#include "theta0_exact.hpp"

#include "theta0_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace fv::ref {
namespace {

using detail::Geometry;
using detail::kPi;
using detail::kTwoPi;
using detail::make_geometry;
using detail::solve_increasing;

void check_args(double zeta, double rdisp) {
    if (!std::isfinite(zeta) || zeta < 0.0)
        throw std::invalid_argument("fv::ref: zeta must be finite and >= 0");
    if (!std::isfinite(rdisp) || rdisp <= 0.0)
        throw std::invalid_argument("fv::ref: rdisp must be finite and > 0");
}

void check_tau(double tau) {
    if (!std::isfinite(tau)) throw std::invalid_argument("fv::ref: tau must be finite");
}

// 20-point Gauss-Legendre nodes and weights on [-1, 1] (Newton on the three-term recurrence).
constexpr int kGaussN = 20;
struct GaussLegendre {
    std::array<double, kGaussN> x{};
    std::array<double, kGaussN> w{};
};

GaussLegendre make_gauss_legendre() {
    GaussLegendre g;
    const int n = kGaussN;
    const double dn = static_cast<double>(n);
    for (int k = 0; k < (n + 1) / 2; ++k) {
        double x = std::cos(kPi * (static_cast<double>(k) + 0.75) / (dn + 0.5));
        double dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0;
            double p1 = x;
            for (int j = 2; j <= n; ++j) {
                const double dj = static_cast<double>(j);
                const double p2 = ((2.0 * dj - 1.0) * x * p1 - (dj - 1.0) * p0) / dj;
                p0 = p1;
                p1 = p2;
            }
            dp = dn * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / dp;
            x -= dx;
            if (std::fabs(dx) < 1e-17) break;
        }
        // Recompute P_n' at the converged node for the weight.
        double p0 = 1.0;
        double p1 = x;
        for (int j = 2; j <= n; ++j) {
            const double dj = static_cast<double>(j);
            const double p2 = ((2.0 * dj - 1.0) * x * p1 - (dj - 1.0) * p0) / dj;
            p0 = p1;
            p1 = p2;
        }
        dp = dn * (x * p1 - p0) / (x * x - 1.0);
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        const auto lo = static_cast<std::size_t>(k);
        const auto hi = static_cast<std::size_t>(n - 1 - k);
        g.x[lo] = x;
        g.x[hi] = -x;
        g.w[lo] = w;
        g.w[hi] = w;
    }
    return g;
}

const GaussLegendre& gauss_legendre() {
    static const GaussLegendre g = make_gauss_legendre();
    return g;
}

template <class F> double gauss_panel(const F& f, double a, double b) {
    const GaussLegendre& g = gauss_legendre();
    const double c = 0.5 * (a + b);
    const double r = 0.5 * (b - a);
    double sum = 0.0;
    for (std::size_t k = 0; k < g.x.size(); ++k) sum += g.w[k] * f(c + r * g.x[k]);
    return r * sum;
}

// Adaptive bisection of Gauss-Legendre panels for a positive integrand bounded by 1: accept when the two
// halves agree with the whole to 4e-15 relative (or 1e-18 per unit length absolute, for negligible tails).
template <class F> double gauss_adaptive(const F& f, double a, double b, double whole, int depth) {
    const double m = 0.5 * (a + b);
    const double left = gauss_panel(f, a, m);
    const double right = gauss_panel(f, m, b);
    const double both = left + right;
    if (depth >= 24 || std::fabs(both - whole) <= 4e-15 * std::fabs(both) + 1e-18 * (b - a)) return both;
    return gauss_adaptive(f, a, m, left, depth + 1) + gauss_adaptive(f, m, b, right, depth + 1);
}

template <class F> double integrate(const F& f, double a, double b) {
    if (!(b > a)) return 0.0;
    return gauss_adaptive(f, a, b, gauss_panel(f, a, b), 0);
}

// int_0^H exp(-x(h)) dh for increasing x with x(0) = 0, split where x = 1, 2, ..., 48 so that the
// integrand drops by at most a factor e on each panel (beyond x = 48 it is below 1.5e-21).
template <class X> double integrate_decay(const X& x, double big_h) {
    const auto f = [&x](double h) { return std::exp(-x(h)); };
    const double x_end = x(big_h);
    double a = 0.0;
    double sum = 0.0;
    for (int k = 1; k <= 48 && static_cast<double>(k) < x_end; ++k) {
        const double b = solve_increasing(x, static_cast<double>(k), a, big_h);
        sum += integrate(f, a, b);
        a = b;
    }
    return sum + integrate(f, a, big_h);
}

// Phase h = tau - tau1 reduced to [0, 2 pi).
double phase_from_tau1(double tau, double tau1) {
    double t = std::fmod(tau, kTwoPi);
    if (t < 0.0) t += kTwoPi;
    double h = t - tau1;
    if (h < 0.0) h += kTwoPi;
    if (h >= kTwoPi) h -= kTwoPi;
    return h;
}

// i = 1: K_b = z + L(tau1), K_f = z - L(tau2) of the periodic solution.
struct ExpPhases {
    double kb = 0;
    double kf = 0;
};

ExpPhases exp_phases(const Geometry& g, double z) {
    const double ea = g.A / z;
    const double eb = g.B / z;
    const double a = std::exp(-ea);
    const double b = std::exp(-eb);
    const double one_minus_b = -std::expm1(-eb);
    const double one_minus_ab = -std::expm1(-(ea + eb));
    const double u = 2.0 * z * a * one_minus_b / one_minus_ab; // z - L1
    ExpPhases e;
    e.kb = 2.0 * z - u;
    e.kf = 2.0 * z - e.kb * b;
    return e;
}

} // namespace

double back_travel_theta0(double zeta) {
    check_args(zeta, 1.0);
    if (zeta >= 1.0) return 0.0;
    return make_geometry(zeta).B;
}

double rx_theta0_i1(double zeta, double rdisp) {
    check_args(zeta, rdisp);
    if (zeta >= 1.0) return 1.0;
    const Geometry g = make_geometry(zeta);
    const double z = 1.0 / rdisp;
    const ExpPhases e = exp_phases(g, z);
    const double ib = integrate_decay([&g, z](double h) { return -g.d_b(h) / z; }, g.len_b);
    const double jf = integrate_decay([&g, z](double h) { return g.d_f(h) / z; }, g.len_f);
    return g.rigid() + (e.kb * rdisp * ib - e.kf * rdisp * jf) / kTwoPi;
}

double rx_theta0_i0(double zeta, double rdisp) {
    check_args(zeta, rdisp);
    if (zeta >= 1.0) return 1.0;
    const Geometry g = make_geometry(zeta);
    const double z = 1.0 / rdisp;
    const auto d_f = [&g](double h) { return g.d_f(h); };
    if (g.B <= 2.0 * z) {
        // Sticks during the whole back travel; L2 = z - B; forward stick until d_f(h_f) = B.
        const double h_f = solve_increasing(d_f, g.B, 0.0, g.len_f);
        return 1.0 + (g.int_d_b(g.len_b) + g.int_d_f(h_f) - g.B * h_f) * rdisp / kTwoPi;
    }
    // Slips backwards too: back stick until d_b(h_s) = -2z, forward stick until d_f(h_f) = 2z.
    const double h_s = solve_increasing([&g](double h) { return -g.d_b(h); }, 2.0 * z, 0.0, g.len_b);
    const double h_f = solve_increasing(d_f, 2.0 * z, 0.0, g.len_f);
    return g.rigid() + (2.0 * (h_s - h_f) + (g.int_d_b(h_s) + g.int_d_f(h_f)) * rdisp) / kTwoPi;
}

double lag_theta0_i1(double zeta, double rdisp, double tau) {
    check_args(zeta, rdisp);
    check_tau(tau);
    const double z = 1.0 / rdisp;
    if (zeta >= 1.0) return z;
    const Geometry g = make_geometry(zeta);
    const ExpPhases e = exp_phases(g, z);
    const double h = phase_from_tau1(tau, g.tau1);
    if (h <= g.len_b) return -z + e.kb * std::exp(g.d_b(h) / z);
    return z - e.kf * std::exp(-g.d_f(h - g.len_b) / z);
}

double lag_theta0_i0(double zeta, double rdisp, double tau) {
    check_args(zeta, rdisp);
    check_tau(tau);
    const double z = 1.0 / rdisp;
    if (zeta >= 1.0) return z;
    const Geometry g = make_geometry(zeta);
    const double h = phase_from_tau1(tau, g.tau1);
    if (h <= g.len_b) return std::max(z + g.d_b(h), -z);
    const double l2 = std::max(z - g.B, -z);
    return std::min(l2 + g.d_f(h - g.len_b), z);
}

} // namespace fv::ref
