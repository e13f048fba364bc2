// The geometry of one period of P(tau) = zeta tau + sin tau (theta = 0, 0 <= zeta < 1), shared by the exact
// theta = 0 references (theta0_exact.*, theta0_general_i.*): P' < 0 on (tau1, tau2), tau1 = pi - alpha,
// tau2 = pi + alpha, alpha = arccos(zeta). The derivations are in theta0_exact.hpp.
#pragma once

#include <cmath>

namespace fv::ref::detail {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

// S1(h) = h - sin h, without cancellation for small |h|: sum_{k>=1} (-1)^(k+1) h^(2k+1) / (2k+1)!.
inline double h_minus_sin(double h) {
    if (std::fabs(h) >= 0.5) return h - std::sin(h);
    const double h2 = h * h;
    double term = h * h2 / 6.0;
    double sum = 0.0;
    for (int k = 1; k <= 12; ++k) {
        sum += term;
        term *= -h2 / static_cast<double>((2 * k + 2) * (2 * k + 3));
    }
    return sum;
}

// 1 - cos h.
inline double one_minus_cos(double h) {
    const double sh = std::sin(0.5 * h);
    return 2.0 * sh * sh;
}

// C2(H) = int_0^H (h - sin h) dh = H^2/2 - (1 - cos H) = sum_{k>=2} (-1)^k H^(2k) / (2k)!.
inline double c2(double h) {
    if (std::fabs(h) >= 0.5) return 0.5 * h * h - one_minus_cos(h);
    const double h2 = h * h;
    double term = h2 * h2 / 24.0;
    double sum = 0.0;
    for (int k = 2; k <= 11; ++k) {
        sum += term;
        term *= -h2 / static_cast<double>((2 * k + 1) * (2 * k + 2));
    }
    return sum;
}

struct Geometry {
    double zeta = 0;
    double s = 1;     // sqrt(1 - zeta^2) = sin(alpha)
    double alpha = 0; // arccos(zeta)
    double tau1 = 0;  // pi - alpha: P has its maximum, the back phase starts
    double B = 0;     // back travel
    double len_b = 0; // 2 alpha: duration of the back phase
    double len_f = 0; // 2 pi - 2 alpha: duration of the forward phase
    double A = 0;     // forward travel 2 pi zeta + B

    // P(tau1 + h) - P(tau1), h in [0, len_b]; <= 0 and decreasing.
    double d_b(double h) const { return zeta * h_minus_sin(h) - s * one_minus_cos(h); }
    // P(tau2 + h) - P(tau2), h in [0, len_f]; >= 0 and increasing.
    double d_f(double h) const { return zeta * h_minus_sin(h) + s * one_minus_cos(h); }
    // int_0^H d_b(h) dh and int_0^H d_f(h) dh.
    double int_d_b(double big_h) const { return zeta * c2(big_h) - s * h_minus_sin(big_h); }
    double int_d_f(double big_h) const { return zeta * c2(big_h) + s * h_minus_sin(big_h); }
    // (2 pi - 4 alpha) / (2 pi) = (2/pi) asin(zeta), the rigid result Eq. (10).
    double rigid() const { return (2.0 / kPi) * std::atan2(zeta, s); }
};

inline Geometry make_geometry(double zeta) {
    Geometry g;
    g.zeta = zeta;
    g.s = std::sqrt((1.0 - zeta) * (1.0 + zeta));
    g.alpha = std::atan2(g.s, zeta);
    g.tau1 = kPi - g.alpha;
    // B/2 = sin(alpha) - alpha cos(alpha) = alpha (1 - cos alpha) - (alpha - sin alpha): fine for small
    // alpha.
    g.B = 2.0 * (g.alpha * one_minus_cos(g.alpha) - h_minus_sin(g.alpha));
    g.len_b = 2.0 * g.alpha;
    g.len_f = kTwoPi - g.len_b;
    g.A = kTwoPi * zeta + g.B;
    return g;
}

// Root of the increasing function f(h) = target on [lo, hi] by bisection down to adjacent doubles.
// Targets outside [f(lo), f(hi)] return the nearer end.
template <class F> double solve_increasing(const F& f, double target, double lo, double hi) {
    if (!(target > f(lo))) return lo;
    if (!(target < f(hi))) return hi;
    for (int it = 0; it < 4000; ++it) {
        const double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo && mid < hi)) break;
        if (f(mid) < target)
            lo = mid;
        else
            hi = mid;
    }
    return lo + 0.5 * (hi - lo);
}

} // namespace fv::ref::detail
