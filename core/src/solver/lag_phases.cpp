#include "lag_phases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv::solver {
namespace {

constexpr double kMinStick = 1e-9;

// Smallest t in (0, T] where the cubic q(t) = g0 + g1 t + g2 t^2/2 + g3 t^3/6 (g3 > 0) reaches 0 from below,
// or T when it stays negative on (0, T]. q(0) = g0 <= 0.
double cubic_first_root(double g0, double g1, double g2, double g3, double T) {
    auto q = [&](double t) { return g0 + t * (g1 + t * (0.5 * g2 + t * g3 / 6)); };
    // q' = g1 + g2 t + g3 t^2 / 2: its roots split (0, T] into monotone pieces.
    double cuts[4];
    int n = 0;
    const double disc = g2 * g2 - 2 * g3 * g1;
    if (disc >= 0) {
        const double sq = std::sqrt(disc);
        for (double t : {(-g2 - sq) / g3, (-g2 + sq) / g3})
            if (t > 0 && t < T) cuts[n++] = t;
    }
    cuts[n++] = T;
    double lo = 0;
    for (int k = 0; k < n; ++k) {
        const double hi = cuts[k];
        if (q(hi) >= 0) {
            // q increases through 0 on (lo, hi]: bisection (q(lo) < 0 or lo = 0 with q(0) = 0 leaving
            // downwards).
            double a = lo, b = hi;
            if (lo == 0 && g0 >= 0) {
                // q(0) = 0: the first crossing is the trivial one unless q dips first.
                if (g1 > 0 || (g1 == 0 && g2 > 0) || (g1 == 0 && g2 == 0)) return 0;
            }
            for (int it = 0; it < 80; ++it) {
                const double m = 0.5 * (a + b);
                (q(m) < 0 ? a : b) = m;
            }
            return a; // still below the root: never beyond it
        }
        lo = hi;
    }
    return T;
}

} // namespace

std::optional<double> stick_slip_time(const LagModel& m, double tau_a, Vec2 l_a, double tau_end) {
    const double r = m.r;
    double tau = tau_a;
    // Whole stuck stretches: while |c + r zeta t e_x| + r < 1 (c = l_a - r sin(tau_a) u) the oscillation
    // cannot reach the circle.
    if (r < 1) {
        const Vec2 c = l_a - r * std::sin(tau_a) * m.u();
        const double lim = 1 - r;
        if (c.norm() < lim) {
            if (!(m.zeta > 0)) return std::nullopt; // no drift: the tip never slips
            const double t = (-c.x() + std::sqrt(lim * lim - c.y() * c.y())) / (r * m.zeta);
            tau = tau_a + std::max(0.0, t);
            if (tau >= tau_end) return std::nullopt;
        }
    }
    const double g3 = 2 * r * (3 * r * (1 + m.zeta) + 1); // bound on |g'''| inside the disc
    double creep = kMinStick;
    for (int it = 0; it < 1000000; ++it) {
        const Vec2 l = l_a + r * m.dispP(tau_a, tau);
        const Vec2 w = r * m.dP(tau);
        const double g0 = l.squaredNorm() - 1;
        const double g1 = 2 * l.dot(w);
        const double g2 = 2 * (w.squaredNorm() + r * l.dot(m.ddP(tau)));
        // On the circle (to rounding) and moving outwards: the slip starts here.
        if (g0 >= -1e-15 && (g1 > 0 || (g1 == 0 && g2 > 0))) return tau;
        const double T = tau_end - tau;
        if (T <= 0) return std::nullopt;
        const double t = cubic_first_root(std::min(g0, 0.0), g1, g2, g3, T);
        if (t >= T) return std::nullopt;
        // Converged onto the root (the bound is tight to third order there).
        if (t <= 4 * std::numeric_limits<double>::epsilon() * (1 + std::abs(tau))) return tau + t;
        if (t < creep && g0 > -1e-12) {
            // On the circle to rounding while the body barely moves (P' ~ 0): the bound creeps. Step on by
            // `creep` (doubling while this lasts) and slip there if the tip is outside by then: late by less
            // than a creep step, while the body moves by ~|P'| times that, which is what makes it creep.
            const double tn = std::min(T, creep);
            creep *= 2;
            const Vec2 ln = l_a + r * m.dispP(tau_a, tau + tn);
            if (ln.squaredNorm() >= 1 && ln.dot(m.dP(tau + tn)) > 0) return tau + tn;
            tau += tn;
            continue;
        }
        tau += t;
        creep = kMinStick;
    }
    return tau;
}

} // namespace fv::solver
