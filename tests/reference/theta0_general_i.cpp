// Exact steady state for theta = 0 and any shape exponent i; the derivation is in theta0_general_i.hpp.
#include "theta0_general_i.hpp"

#include "theta0_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fv::ref {
namespace {

using detail::Geometry;
using detail::kPi;
using detail::kTwoPi;
using detail::make_geometry;
using detail::solve_increasing;

void check_args(double zeta, double rdisp, double i) {
    if (!std::isfinite(zeta) || zeta < 0.0)
        throw std::invalid_argument("fv::ref: zeta must be finite and >= 0");
    if (!std::isfinite(rdisp) || rdisp <= 0.0)
        throw std::invalid_argument("fv::ref: rdisp must be finite and > 0");
    if (!std::isfinite(i) || i < 0.0) throw std::invalid_argument("fv::ref: i must be finite and >= 0");
}

// Exponent of the decay u = u0 exp(-e): e(u0, x) = log1p(c x u0^c)/c with c = i - 1 (e = x for i = 1).
// Returns +infinity when u has reached 0 (i < 1 only).
double decay_exponent(double u0, double x, double i) {
    if (i == 1.0) return x;
    const double c = i - 1.0;
    const double y = c * x * std::pow(u0, c);
    if (!(y > -1.0)) return INFINITY; // i < 1: the edge is reached within this travel
    return std::log1p(y) / c;
}

// The law du/dx = -u^i over a travel x >= 0 from u0 in [0, 2] (see the header).
double transfer(double u0, double x, double i) {
    if (!(u0 > 0.0)) return 0.0;
    if (!(x > 0.0)) return u0;
    if (i == 0.0) return std::max(u0 - x, 0.0);
    return u0 * std::exp(-decay_exponent(u0, x, i));
}

// u0 - transfer(u0, x), accurate to rounding relative to itself also for tiny x.
double drop(double u0, double x, double i) {
    if (!(u0 > 0.0) || !(x > 0.0)) return 0.0;
    if (i == 0.0) return std::min(u0, x);
    const double e = decay_exponent(u0, x, i);
    if (std::isinf(e)) return u0;
    return -u0 * std::expm1(-e);
}

// Travel after which u reaches 0 from u0 (i < 1), else +infinity.
double travel_to_edge(double u0, double i) {
    if (i >= 1.0) return INFINITY;
    if (!(u0 > 0.0)) return 0.0;
    return std::pow(u0, 1.0 - i) / (1.0 - i);
}

// Gauss-Kronrod 7-15 (QUADPACK's nodes and weights).
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.0};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <class F> void gk15(const F& f, double a, double b, double& kronrod, double& gauss) {
    const double c = 0.5 * (a + b);
    const double r = 0.5 * (b - a);
    const double fc = f(c);
    double k = kWgk[7] * fc;
    double g = kWg[3] * fc;
    for (int j = 0; j < 7; ++j) {
        const double x = r * kXgk[j];
        const double sum = f(c - x) + f(c + x);
        k += kWgk[j] * sum;
        if (j % 2 == 1) g += kWg[j / 2] * sum;
    }
    kronrod = r * k;
    gauss = r * g;
}

// Adaptive bisection; accepts a panel when Kronrod and Gauss agree to 1e-14 relative or 1e-15 per unit
// length (the integrands are in [0, 2] and carry rounding noise of a few 1e-16; the Kronrod value is far more
// accurate than the difference). `budget` caps the panels (never reached in the tests' range).
template <class F> double integrate_panel(const F& f, double a, double b, int depth, long& budget) {
    double k = 0.0;
    double g = 0.0;
    gk15(f, a, b, k, g);
    --budget;
    if (depth >= 50 || budget <= 0 || std::fabs(k - g) <= 1e-14 * std::fabs(k) + 1e-15 * (b - a)) return k;
    const double m = 0.5 * (a + b);
    if (!(m > a && m < b)) return k;
    return integrate_panel(f, a, m, depth + 1, budget) + integrate_panel(f, m, b, depth + 1, budget);
}

// int_0^len transfer(u0, x(h), i) dh for an increasing travel x(h) with x(0) = 0: ends where u reaches 0
// (i < 1), panels split where x = 2^k, k = -3..17.
template <class X> double integrate_phase(const X& x, double len, double u0, double i) {
    if (!(u0 > 0.0)) return 0.0;
    double end = len;
    const double x_edge = travel_to_edge(u0, i);
    if (x_edge < x(len)) end = solve_increasing(x, x_edge, 0.0, len);
    const auto f = [&](double h) { return transfer(u0, x(h), i); };
    const double x_end = x(end);
    long budget = 1000000;
    double a = 0.0;
    double sum = 0.0;
    for (int k = -3; k <= 17; ++k) {
        const double xk = std::ldexp(1.0, k);
        if (!(xk < x_end)) break;
        const double b = solve_increasing(x, xk, a, end);
        if (b > a) sum += integrate_panel(f, a, b, 0, budget);
        a = b;
    }
    if (end > a) sum += integrate_panel(f, a, end, 0, budget);
    return sum;
}

// Periodic state for 0 <= zeta < 1: w1 = 1 + L(tau1)/z, u2 = 1 - L(tau2)/z.
struct Periodic {
    double w1 = 2;
    double u2 = 0;
};

Periodic periodic_state(const Geometry& g, double z, double i) {
    const double a = g.A / z;
    const double b = g.B / z;
    // f(u1) = drop(2 - u1, b) - drop(u1 + drop(2 - u1, b), a): non-increasing, f(0) >= 0 >= f(2).
    const auto f = [&](double u1) {
        const double db = drop(2.0 - u1, b, i);
        const double u2 = std::min(u1 + db, 2.0);
        return db - drop(u2, a, i);
    };
    double lo = 0.0;
    double hi = 2.0;
    double u1 = 0.0;
    if (f(lo) > 0.0) {
        for (int it = 0; it < 4000; ++it) {
            const double mid = lo + 0.5 * (hi - lo);
            if (!(mid > lo && mid < hi)) break;
            if (f(mid) > 0.0)
                lo = mid;
            else
                hi = mid;
        }
        u1 = lo + 0.5 * (hi - lo);
    }
    Periodic p;
    p.w1 = 2.0 - u1;
    p.u2 = std::min(u1 + drop(p.w1, b, i), 2.0);
    return p;
}

} // namespace

Theta0Steady::Theta0Steady(double zeta, double rdisp, double i) : zeta_(zeta), rdisp_(rdisp), i_(i) {
    check_args(zeta, rdisp, i);
    saturated_ = zeta >= 1.0;
    if (saturated_) return;
    const Periodic st = periodic_state(make_geometry(zeta), 1.0 / rdisp, i);
    w1_ = st.w1;
    u2_ = st.u2;
}

double Theta0Steady::rx() const {
    if (saturated_) return 1.0;
    const Geometry g = make_geometry(zeta_);
    const double z = 1.0 / rdisp_;
    const double ib = integrate_phase([&g, z](double h) { return -g.d_b(h) / z; }, g.len_b, w1_, i_);
    const double jf = integrate_phase([&g, z](double h) { return g.d_f(h) / z; }, g.len_f, u2_, i_);
    return g.rigid() + (ib - jf) / kTwoPi;
}

double Theta0Steady::lag(double tau) const {
    if (!std::isfinite(tau)) throw std::invalid_argument("fv::ref: tau must be finite");
    const double z = 1.0 / rdisp_;
    if (saturated_) return z;
    const Geometry g = make_geometry(zeta_);
    double t = std::fmod(tau, kTwoPi);
    if (t < 0.0) t += kTwoPi;
    double h = t - g.tau1;
    if (h < 0.0) h += kTwoPi;
    if (h >= kTwoPi) h -= kTwoPi;
    if (h <= g.len_b) return z * (transfer(w1_, -g.d_b(h) / z, i_) - 1.0);
    return z * (1.0 - transfer(u2_, g.d_f(h - g.len_b) / z, i_));
}

double rx_theta0_general(double zeta, double rdisp, double i) {
    return Theta0Steady(zeta, rdisp, i).rx();
}

double lag_theta0_general(double zeta, double rdisp, double i, double tau) {
    return Theta0Steady(zeta, rdisp, i).lag(tau);
}

double compliant_limit_theta0(double zeta, double i) {
    check_args(zeta, 1.0, i);
    if (zeta >= 1.0 || i == 0.0) return 1.0;
    const Geometry g = make_geometry(zeta);
    const double q = std::pow(g.B / g.A, 1.0 / i);
    return (1.0 - q) / (1.0 + q);
}

double mean_abs_velocity_theta0(double zeta) {
    check_args(zeta, 1.0, 0.0);
    if (zeta >= 1.0) return zeta;
    return (2.0 / kPi) * (zeta * std::asin(zeta) + std::sqrt((1.0 - zeta) * (1.0 + zeta)));
}

} // namespace fv::ref
