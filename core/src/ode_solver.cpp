// Continuous-time limit of the paper's scheme and its periodic steady state (see ode_solver.hpp).
//
// ---------------------------------------------------------------------------------------------------------
// Derivation of the lag ODE from Eqs. (17)-(27)
//   State: the lag L = P - T, z = |L| (Eq. (18)), e = L/z, F/F_c = L/z_ss (Eqs. (23)-(24)), z_ss = 1/rdisp.
//   One step of the scheme moves P by dP = P'(tau) dtau + O(dtau^2) (Eqs. (28)-(29)); the tip is pulled
//   along the line T(t) P(t+dt), i.e. along pull = L + dP, of length
//     d = |L + dP| = z + e . dP + |dP - (e . dP) e|^2 / (2 z) + ... = z + (e . P') dtau + O(dtau^2),
//   so Eq. (19) gives v dtau = d - z -> v = e . P' (the rate at which P moves away from T).
//   i > 0, Eq. (20): z_new = z + v dtau (1 - sgn(v) z/z_ss)^i, hence dz/dtau = v (1 - sgn(v) z/z_ss)^i
//     (Eq. (16)); the base is >= 0 for z <= z_ss (clamped at 0 so that pow() stays finite).
//   i = 0, Eq. (27): z_new = min(d, z_ss): dz/dtau = v while z < z_ss, and at z = z_ss also while v < 0
//     (d < z_ss then); dz/dtau = 0 at z = z_ss with v >= 0 (slip at full deflection).
//   Direction, Eqs. (21)-(22): L_new = pull z_new/d, so e_new = (L + dP)/|L + dP| and
//     de/dtau = (P' - (e . P') e)/z: the part of P' normal to e rotates L, only the part along e changes z.
//   Together dL/dtau = d(z e)/dtau = (dz/dtau) e + P' - v e:
//       dL/dtau = P' - (v - dz/dtau) e,                                                  (*)
//   i.e. T moves only along e, with speed v - dz/dtau (dT/dtau = (v - dz/dtau) e). Special cases:
//     stick (i = 0, z < z_ss or v < 0):     dL/dtau = P'            (T fixed)
//     full deflection (z = z_ss, v >= 0):   dL/dtau = P' - (e . P') e (pure pursuit: |L| stays z_ss);
//       for every i this is what (*) gives at z = z_ss, v >= 0, since then dz/dtau = 0.
//     i = 1:                               dL/dtau = P' - |e . P'| L / z_ss.
//   As z -> 0, v - dz/dtau = v (1 - (1 - sgn(v) z/z_ss)^i) = O(z), so dL/dtau -> P': continuous at L = 0
//   (e undefined there, but its coefficient vanishes); we return P' exactly at z = 0.
//   The period means (Eq. (33) with dtau -> 0) are r = (1/2 pi) int_0^{2 pi} F dtau: integrated as
//   Q' = F alongside L, so they carry the integrator's accuracy.
//   The right-hand side depends on tau only through P' (Eq. (1)), which is 2 pi-periodic: the period map
//   Phi: L(0) -> L(2 pi) does not depend on the period number.
//
// Events: instants where (*) is not smooth
//   velocity_sign: for i > 0 and z < z_ss, sgn(v) in Eq. (16) flips where g = L . P' changes sign: the
//     right-hand side is continuous there (v -> 0 in both branches) but has a kink.
//   reach_zss: z reaches z_ss (g = |L| - z_ss crosses 0 upwards). For i = 0 the law switches from stick
//     (dL = P') to pursuit: a jump in the right-hand side. For 0 < i < 1 z arrives in finite time with
//     limited smoothness (z_ss - z ~ (tau* - tau)^(1/(1-i))); from then on the state is pinned to the circle.
//     For i >= 1 z only approaches z_ss (exponentially for i = 1, algebraically for i > 1); the event
//     fires only if rounding pushes z onto z_ss, where pursuit is the exact motion anyway.
//   leave_zss: on z = z_ss, v = e . P' turns negative (g = L . P' crosses 0 downwards): the deflection
//     starts to shrink (i = 0: the tip sticks again; i > 0: relaxation at rate v 2^i).
//   On z = z_ss the state is kept exactly on the circle (projection after each step).
//   Every event is located on the step's dense output (Illinois root finding to rounding level), the
//   step is cut there, and the integration restarts from the event with the new law.
// ---------------------------------------------------------------------------------------------------------
#include "fv/ode_solver.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fv {

const char* to_string(OdeEventKind k) {
    switch (k) {
    case OdeEventKind::velocity_sign:
        return "velocity_sign";
    case OdeEventKind::reach_zss:
        return "reach_zss";
    case OdeEventKind::leave_zss:
        return "leave_zss";
    }
    return "?";
}

namespace {

using State = Eigen::Matrix<double, 4, 1>; // (L_x, L_y, Q_x, Q_y), Q = int F dtau

constexpr double kTwoPi = 2 * kPi;

// Dormand-Prince 5(4) tableau (Dormand & Prince 1980) and its continuous extension of order 4
// (Shampine 1986, as in Hairer's DOPRI5).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                 d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                 d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;

class LagOde {
  public:
    LagOde(const Params& p, double tolerance)
        : zeta_(p.zeta), cth_(std::cos(p.theta)), sth_(std::sin(p.theta)), zss_(p.zss()), rdisp_(p.rdisp),
          i_(p.i), tol_(tolerance) {
        // A first step that resolves the fastest relaxation (rate |P'|/z_ss <= (1 + zeta)/z_ss); the
        // controller adapts it from there and keeps it between periods.
        h_ = std::min(0.05, 0.05 * zss_ / (1 + zeta_));
    }

    double zss() const { return zss_; }

    // dP/dtau, Eq. (1) divided by v_v, and its derivative.
    Vec2 dP(double tau) const {
        const double c = std::cos(tau);
        return {zeta_ + c * cth_, c * sth_};
    }
    Vec2 ddP(double tau) const {
        const double s = std::sin(tau);
        return {-s * cth_, -s * sth_};
    }

    // Eq. (*) of the header comment. `branch` is sgn(v) of the current piece between velocity events (0:
    // take it from v). Holding it fixed over a step makes the right-hand side the smooth continuation of
    // the piece's law, so a step never straddles the kink at v = 0: the kink is only ever met as a located
    // event (same for the other laws: stick and pursuit are smooth, the switch between them is an event).
    Vec2 rate(double tau, const Vec2& L, bool saturated, int branch = 0) const {
        const Vec2 dp = dP(tau);
        if (saturated) {
            // z = z_ss and v >= 0: dz/dtau = 0 for every i, T follows along e at speed v (pursuit).
            const double z = L.norm();
            const Vec2 e = L / z;
            return dp - e.dot(dp) * e;
        }
        // Below z_ss with i = 0 the tip sticks (Eq. (27), first case): dz = v dtau exactly, T fixed.
        if (i_ == 0) return dp;
        const double z = L.norm();
        if (!(z > 0)) return dp; // e undefined, but its coefficient v - dz/dtau = O(z) vanishes
        const Vec2 e = L / z;
        const double v = e.dot(dp);
        const double s = branch != 0 ? branch : (v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0));
        // Eq. (16); base clamped >= 0 so that a stage that strays past z_ss cannot make pow() NaN. For
        // i > 0, pow(0, i) = 0: no pow(0, 0) here (i = 0 is handled above).
        const double base = std::max(0.0, 1 - s * z / zss_);
        const double keep =
            i_ == 1 ? base : (i_ == 2 ? base * base : (i_ == 3 ? base * base * base : std::pow(base, i_)));
        return dp - (v * (1 - keep)) * e; // T moves along e at v - dz/dtau = v (1 - base^i)
    }

    State f(double tau, const State& y, bool saturated, int branch) const {
        const Vec2 L = y.head<2>();
        const Vec2 dL = rate(tau, L, saturated, branch);
        State out;
        out << dL.x(), dL.y(), rdisp_ * L.x(), rdisp_ * L.y(); // Q' = F = L / z_ss, Eqs. (23)-(24)
        return out;
    }

    OdePeriod period(Vec2 lag0, std::vector<OdeEvent>* events, std::vector<Sample>* samples, int n_samples,
                     const Params& p);

  private:
    double zeta_, cth_, sth_, zss_, rdisp_, i_, tol_;
    double h_;
};

// Continuous extension of one accepted step.
struct Dense {
    double tau0 = 0, h = 0;
    State y0, r2, r3, r4, r5;
    State at(double th) const {
        const double u = 1 - th;
        return y0 + th * (r2 + u * (r3 + th * (r4 + u * r5)));
    }
};

int sign_of(double x) {
    return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

// Root of g on the dense output in [lo, hi] (g(lo) on the side `old_sign`, or ~0 right after an event;
// g(hi) strictly on the other side). Illinois variant of regula falsi; returns a theta on the new-sign side,
// so that the restarted integration begins with g already on its new side and cannot find the same root
// again.
template <class G>
double locate(const G& g, double lo, double hi, double flo, double fhi, int old_sign, double h, double tau0) {
    if (sign_of(flo) != old_sign) flo = old_sign * std::numeric_limits<double>::min();
    int side = 0;
    const double eps = 4 * std::numeric_limits<double>::epsilon() * (std::abs(tau0) + 1) / h;
    for (int it = 0; it < 200 && hi - lo > eps; ++it) {
        double c = (lo * fhi - hi * flo) / (fhi - flo);
        if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
        const double fc = g(c);
        // g = 0 exactly counts as the old side: the point returned must be strictly on the new side, or
        // the restarted piece would begin with g = 0 and find this root once more.
        if (sign_of(fc) != -old_sign) {
            lo = c;
            flo = fc;
            if (side == -1) fhi *= 0.5;
            side = -1;
        } else {
            hi = c;
            fhi = fc;
            if (side == 1) flo *= 0.5;
            side = 1;
        }
    }
    return hi;
}

// First theta in [0, 1] where g leaves the side `old_sign`, or 2 if it does not. g0, g1 are the values and
// dg0, dg1 the slopes d g / d theta at the step ends. Comparing end values alone misses a brief excursion
// inside one step (e.g. the short backward motion of P for zeta just below 1, or a step that grew long
// while the right-hand side was nearly constant): when the slopes say that g heads towards zero at the
// start and away from it at the end, the extremum between is found (golden section on the dense output)
// and checked.
template <class G>
double crossing(const G& g, double g0, double dg0, double g1, double dg1, int old_sign, double h, double tau0,
                double noise) {
    if (old_sign == 0) return 2;
    if (sign_of(g1) == -old_sign) return locate(g, 0.0, 1.0, g0, g1, old_sign, h, tau0);
    if (!(old_sign * dg0 < 0 && old_sign * dg1 > 0)) return 2;
    constexpr double kGold = 0.6180339887498949;
    double a = 0, b = 1;
    double x1 = b - kGold * (b - a), x2 = a + kGold * (b - a);
    double f1 = old_sign * g(x1), f2 = old_sign * g(x2);
    for (int it = 0; it < 60 && b - a > 1e-12; ++it) {
        if (f1 < 0 || f2 < 0) break;
        if (f1 < f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - kGold * (b - a);
            f1 = old_sign * g(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + kGold * (b - a);
            f2 = old_sign * g(x2);
        }
    }
    const double xm = f1 <= f2 ? x1 : x2, fm = std::min(f1, f2);
    // A dip that reaches below zero only by rounding (g grazes zero: v touches 0 and turns back) is no
    // event: firing it would flip the law back and forth at one instant.
    if (!(fm < -noise)) return 2;
    return locate(g, 0.0, xm, g0, old_sign * fm, old_sign, h, tau0);
}

OdePeriod LagOde::period(Vec2 lag0, std::vector<OdeEvent>* events, std::vector<Sample>* samples,
                         int n_samples, const Params& p) {
    OdePeriod out;
    // Admissible start: z <= z_ss (the continuous model never leaves the disc).
    double z0 = lag0.norm();
    if (z0 > zss_) lag0 *= zss_ / z0;
    z0 = lag0.norm();
    // Where the deflection counts as full. For i = 0 z crosses z_ss transversally (dz = v dtau). For
    // 0 < i < 1 it arrives in finite time but with dz/dtau -> 0; for i >= 1 only asymptotically. Pinning it
    // to the circle 1e-12 z_ss early costs a force error of 1e-12 and turns a creeping approach (for i > 1
    // an algebraic one) into the exact pursuit motion that it tends to.
    const double zreach = i_ == 0 ? zss_ : zss_ * (1 - 1e-12);
    bool sat = z0 >= zreach && lag0.dot(dP(0)) >= 0;
    if (sat) lag0 *= zss_ / z0;

    State y;
    y << lag0.x(), lag0.y(), 0, 0;
    double tau = 0;
    int vsign = sign_of(lag0.dot(dP(0))); // sign of v on the current piece (0: not yet known)
    State k1 = f(tau, y, sat, vsign);
    if (vsign < 0) out.v_negative = true;
    const double atol_L = tol_ * zss_, atol_Q = tol_, rtol = tol_;
    const double hmin = 1e-14;
    int next_sample = 1;
    int event_count = 0;
    double last_event_tau = -1;
    int same_instant = 0;
    bool suppress_events = false;
    constexpr double kMaxStep = 0.5;
    constexpr int kMaxEvents = 10000; // a chattering guard: never reached by the model's few events

    auto record = [&](const Dense& dn, double tau_end, bool last) {
        if (!samples) return;
        while (next_sample <= n_samples) {
            const double ts = kTwoPi * next_sample / n_samples;
            if (ts > tau_end && !(last && next_sample == n_samples)) break;
            const double th = std::clamp((ts - dn.tau0) / dn.h, 0.0, 1.0);
            Vec2 L = dn.at(th).head<2>();
            // The interpolant between steps leaves the disc |L| <= z_ss by up to the local tolerance
            // (on the circle the steps themselves are projected); the model never does.
            const double z = L.norm();
            if (z > zss_) L *= zss_ / z;
            Sample s;
            s.tau = ts;
            s.P = body_point(p, ts);
            s.T = s.P - L;
            s.z = L.norm();
            s.F = L * rdisp_;
            samples->push_back(s);
            ++next_sample;
        }
    };

    while (kTwoPi - tau > 1e-13) {
        // At most 1/12 of a period per step, so that each event function has at most one extremum
        // within a step (see crossing()).
        double h = std::min({h_, kMaxStep, kTwoPi - tau});
        if (kTwoPi - tau - h < 1e-10) h = kTwoPi - tau; // no sliver of a step at the end
        // Dormand-Prince stages.
        const State k2 = f(tau + c2 * h, y + h * (a21 * k1), sat, vsign);
        const State k3 = f(tau + c3 * h, y + h * (a31 * k1 + a32 * k2), sat, vsign);
        const State k4 = f(tau + c4 * h, y + h * (a41 * k1 + a42 * k2 + a43 * k3), sat, vsign);
        const State k5 = f(tau + c5 * h, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4), sat, vsign);
        const State k6 =
            f(tau + h, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5), sat, vsign);
        const State y1 = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
        const State k7 = f(tau + h, y1, sat, vsign);
        // Continuous extension of the step (Hairer's DOPRI5 coefficients).
        auto make_dense = [&] {
            Dense d;
            d.tau0 = tau;
            d.h = h;
            d.y0 = y;
            d.r2 = y1 - y;
            d.r3 = h * k1 - d.r2;
            d.r4 = d.r2 - h * k7 - d.r3;
            d.r5 = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
            return d;
        };
        const State err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
        double en = 0;
        for (int c = 0; c < 4; ++c) {
            const double sc = (c < 2 ? atol_L : atol_Q) + rtol * std::max(std::abs(y[c]), std::abs(y1[c]));
            en = std::max(en, std::abs(err[c]) / sc);
        }
        if (!std::isfinite(en)) en = 1e10;
        if (en > 1 && h > hmin) {
            h_ = h * std::max(0.2, 0.9 * std::pow(en, -0.2));
            ++out.rejected;
            // A step that runs into an event sees the other law only at its end; if the rejected
            // candidate already shows the event, the next try ends just past it (the candidate's dense
            // output places it well enough), instead of creeping up on it by repeated rejections.
            const Vec2 L1 = y1.head<2>();
            const bool v_ev = (sat || i_ > 0) && vsign != 0 && sign_of(L1.dot(dP(tau + h))) == -vsign;
            const bool z_ev = !sat && L1.norm() >= zreach && y.head<2>().norm() < zreach;
            if (v_ev || z_ev) {
                const Dense dn = make_dense();
                double th = 1;
                if (v_ev) {
                    auto g = [&](double t) { return dn.at(t).head<2>().dot(dP(tau + t * h)); };
                    th = std::min(th, locate(g, 0.0, 1.0, g(0.0), L1.dot(dP(tau + h)), vsign, h, tau));
                }
                if (z_ev) {
                    auto g = [&](double t) { return dn.at(t).head<2>().norm() - zreach; };
                    th = std::min(th, locate(g, 0.0, 1.0, g(0.0), L1.norm() - zreach, -1, h, tau));
                }
                h_ = std::min(h_, std::max(1e-3 * h, th * h * (1 + 1e-7)));
            }
            continue;
        }
        ++out.steps;
        // Next step size (standard controller; at most 5x growth).
        const double grow = en > 0 ? std::min(5.0, std::max(0.2, 0.9 * std::pow(en, -0.2))) : 5.0;
        const double h_next = std::max(hmin, h * grow);

        const Dense dn = make_dense();

        // Events within this step: the earliest one wins.
        double ev_th = 2;
        OdeEventKind ev_kind = OdeEventKind::velocity_sign;
        const double tau1 = tau + h;
        const Vec2 L0 = y.head<2>(), L1 = y1.head<2>();
        const Vec2 dp0 = dP(tau), dp1 = dP(tau1);
        const double gv1 = L1.dot(dp1);
        const bool v_matters = sat || i_ > 0; // for i = 0 below z_ss the law does not depend on sgn(v)
        if (event_count < kMaxEvents && !suppress_events) {
            if (v_matters && vsign != 0) {
                // g = L . P', g' = L' . P' + L . P''; slopes per unit theta = h d/dtau.
                auto g = [&](double th) { return dn.at(th).head<2>().dot(dP(tau + th * h)); };
                const double dg0 = h * (k1.head<2>().dot(dp0) + L0.dot(ddP(tau)));
                const double dg1 = h * (k7.head<2>().dot(dp1) + L1.dot(ddP(tau1)));
                const double th =
                    crossing(g, L0.dot(dp0), dg0, gv1, dg1, vsign, h, tau, 1e-12 * zss_ * (1 + zeta_));
                if (th <= 1) {
                    ev_th = th;
                    ev_kind = sat ? OdeEventKind::leave_zss : OdeEventKind::velocity_sign;
                }
            }
            if (!sat) {
                // g = |L| - z_ss, g' = e . L'.
                auto g = [&](double th) { return dn.at(th).head<2>().norm() - zreach; };
                const double za = L0.norm(), z1 = L1.norm();
                // A piece that begins on the circle (just after leave_zss, v < 0) counts as inside.
                const double dg0 = za > 0 ? h * L0.dot(k1.head<2>()) / za : 0;
                const double dg1 = z1 > 0 ? h * L1.dot(k7.head<2>()) / z1 : 0;
                const double th = crossing(g, za - zreach, dg0, z1 - zreach, dg1, -1, h, tau, 1e-14 * zss_);
                if (th < ev_th) {
                    ev_th = th;
                    ev_kind = OdeEventKind::reach_zss;
                }
            }
        }

        if (ev_th <= 1) {
            ++event_count;
            const double tau_e = tau + ev_th * h;
            // Chattering guard: events piling up at one instant (a grazing contact resolved below
            // rounding) are switched off for the next step, which then carries the state past it.
            same_instant = tau_e - last_event_tau <= 1e-12 * (1 + tau_e) ? same_instant + 1 : 0;
            last_event_tau = tau_e;
            suppress_events = same_instant >= 3;
            State ye = dn.at(ev_th);
            record(dn, tau_e, false);
            switch (ev_kind) {
            case OdeEventKind::velocity_sign:
                vsign = -vsign;
                break;
            case OdeEventKind::leave_zss:
                sat = false;
                vsign = -1;
                break;
            case OdeEventKind::reach_zss: {
                sat = true;
                vsign = 1;
                const Vec2 L = ye.head<2>();
                const double z = L.norm();
                ye.head<2>() = L * (zss_ / z);
                break;
            }
            }
            if (vsign < 0) out.v_negative = true;
            if (sat) out.saturated = true;
            if (events) events->push_back({tau_e, ev_kind, Vec2(ye.head<2>())});
            tau = tau_e;
            y = ye;
            k1 = f(tau, y, sat, vsign);
            // The old step size was fine up to the event; a smaller one restarts cleanly after a jump.
            h_ = std::max(hmin, std::min(h_next, std::max(h * (1 - ev_th), 1e-3 * h)));
            continue;
        }

        // No event: take the whole step.
        suppress_events = false;
        record(dn, tau1, kTwoPi - tau1 <= 1e-13);
        tau = tau1;
        y = y1;
        if (sat) {
            // Pursuit keeps |L| = z_ss exactly; the integrator only to its tolerance: project back.
            const Vec2 L = y.head<2>();
            y.head<2>() = L * (zss_ / L.norm());
            k1 = f(tau, y, sat, vsign);
            out.saturated = true;
        } else {
            k1 = k7; // first same as last
            if (i_ == 0 || vsign == 0) {
                // No velocity events for i = 0 below z_ss (or v unknown at the start): just track sgn(v).
                const int was = vsign;
                if (gv1 != 0) vsign = sign_of(gv1);
                if (was == 0 && vsign != 0) k1 = f(tau, y, sat, vsign); // the branch is now fixed
            }
            if (vsign < 0) out.v_negative = true;
        }
        h_ = h_next;
    }
    out.lag_end = y.head<2>();
    out.mean_force = Vec2(y[2], y[3]) / kTwoPi;
    return out;
}

double wrap_angle(double a) {
    return std::remainder(a, kTwoPi);
}

} // namespace

Vec2 ode_lag_rate(const Params& p, double tau, Vec2 lag, bool saturated) {
    return LagOde(p, 1e-10).rate(tau, lag, saturated);
}

OdePeriod ode_period(const Params& p, Vec2 lag0, double tolerance, std::vector<OdeEvent>* events,
                     std::vector<Sample>* samples, int n_samples) {
    const std::string msg = validate(p);
    if (!msg.empty()) throw std::invalid_argument(msg);
    LagOde ode(p, tolerance);
    return ode.period(lag0, events, samples, n_samples, p);
}

OdeSolution ode_solve(const Params& p, const OdeOptions& opt) {
    const std::string msg = validate(p);
    if (!msg.empty()) throw std::invalid_argument(msg);
    if (!(opt.tolerance > 0)) throw std::invalid_argument("tolerance must be > 0");
    const double zss = p.zss();
    const double tol = opt.tolerance;
    // The integrator runs 10x tighter than the target: the global error of r over a period is about
    // the local tolerance (bench/ode_accuracy.cpp), and the period map's "noise" (the step sequence, and
    // so the rounding, changes with the start) must stay well below the fixed-point target.
    constexpr double kLocal = 0.1;
    LagOde ode(p, kLocal * tol);
    int periods = 0;
    struct Iter {
        Vec2 L;
        OdePeriod out;
        Vec2 res() const { return out.lag_end - L; }
    };
    auto project = [&](Vec2 L) {
        const double z = L.norm();
        return z > zss ? Vec2(L * (zss / z)) : L;
    };
    auto eval = [&](Vec2 L) {
        ++periods;
        L = project(L);
        return Iter{L, ode.period(L, nullptr, nullptr, 0, p)};
    };

    OdeSolution sol;
    Iter cur = eval(opt.initial_lag);
    bool converged = false;
    double dist = std::numeric_limits<double>::infinity(); // estimated |L - L*| of cur
    bool have_inv = false;
    bool trusted_inv = false; // a Newton step with this Ainv cut the residual at least 5x: use it for dist
    Eigen::Matrix2d Ainv;     // (DPhi - I)^-1 at a recent iterate (chord Newton)
    double rho = std::numeric_limits<double>::quiet_NaN(), rho_prev = rho;
    Vec2 prev_delta(0, 0);
    bool have_prev_delta = false;
    bool tried_circle = false;

    // Jacobian of Phi by finite differences. Near the circle the probes go inwards and along it, so
    // they stay in the disc and on the same side of the reach/leave events as far as possible.
    auto jacobian = [&](const Iter& it) -> bool {
        const double hfd = 1e-5 * zss;
        Vec2 u1(1, 0), u2(0, 1);
        const double z = it.L.norm();
        if (z > 0.5 * zss) {
            u1 = -it.L / z;
            u2 = Vec2(-u1.y(), u1.x());
        }
        const Iter a = eval(it.L + hfd * u1), b = eval(it.L + hfd * u2);
        Eigen::Matrix2d C, U;
        C.col(0) = (a.out.lag_end - it.out.lag_end) / hfd;
        C.col(1) = (b.out.lag_end - it.out.lag_end) / hfd;
        U.col(0) = (a.L - it.L) / hfd; // the probes as actually taken (after projection)
        U.col(1) = (b.L - it.L) / hfd;
        const double du = U.determinant();
        if (!(std::abs(du) > 1e-6)) return false;
        const Eigen::Matrix2d J = C * U.inverse();
        const Eigen::Matrix2d A = J - Eigen::Matrix2d::Identity();
        const double det = A.determinant();
        if (!(std::abs(det) > 1e-10)) return false; // Phi ~ translation (a stuck tip): no Newton
        Ainv = A.inverse();
        return true;
    };

    // The steady period may lie entirely on the circle z = z_ss (pure pursuit with v >= 0 throughout: no
    // relaxation, Figs. 17-18). For i > 1 z approaches z_ss only algebraically and Newton on the 2-D map
    // converges slowly there (the radial direction of Phi is degenerate); but on the circle the problem is
    // a 1-D fixed point in the angle, found by secant steps. Valid only if no period leaves the circle.
    auto try_circle = [&](const Iter& from, Iter& result, double& dist_out) -> bool {
        auto on_circle = [&](double a) { return Vec2(zss * std::cos(a), zss * std::sin(a)); };
        auto residual = [&](const Iter& it, double a) {
            return wrap_angle(std::atan2(it.out.lag_end.y(), it.out.lag_end.x()) - a);
        };
        // A period that already started on the circle (warm start from a pinned neighbour) is the first
        // secant point; otherwise start from where the last period ended.
        const bool on = from.L.norm() >= zss * (1 - 1e-12);
        double phi0 =
            on ? std::atan2(from.L.y(), from.L.x()) : std::atan2(from.out.lag_end.y(), from.out.lag_end.x());
        Iter i0 = on ? from : eval(on_circle(phi0));
        if (i0.out.v_negative || !i0.out.saturated) return false;
        double r0 = residual(i0, phi0);
        double phi1 = phi0 + r0;
        for (int k = 0; k < 30 && periods < opt.max_periods; ++k) {
            Iter i1 = eval(on_circle(phi1));
            if (i1.out.v_negative || !i1.out.saturated) return false;
            const double r1 = residual(i1, phi1);
            double step = r1;
            if (r1 != r0) step = -r1 * (phi1 - phi0) / (r1 - r0);
            if (!std::isfinite(step) || std::abs(step) > 1) step = r1;
            // |dL| = z_ss |d phi|, force error rdisp z_ss |d phi| = |d phi|.
            if (std::abs(step) <= 0.5 * tol || r1 == 0) {
                result = i1;
                dist_out = zss * std::abs(step);
                return true;
            }
            phi0 = phi1;
            r0 = r1;
            phi1 += step;
        }
        return false;
    };

    int stagnant = 0;
    double best_rn = std::numeric_limits<double>::infinity();
    double last_good_rho = std::numeric_limits<double>::quiet_NaN(); // last contraction rate < 1 measured
    auto stuck_now = [&](const Iter& it) { return p.i == 0 && !it.out.saturated; };
    for (;;) {
        const Vec2 res = cur.res();
        const double rn = res.norm();
        Vec2 delta(0, 0);
        if (have_inv) delta = -Ainv * res;
        // Distance to the fixed point: from the (verified) Newton step, else from the contraction rate of
        // plain steps (last one measured < 1: near the noise floor the measured rate is noise).
        if (have_inv && trusted_inv) {
            dist = delta.norm();
            // Newton converges linearly at a degenerate fixed point: the step then undershoots the
            // distance by the factor q of successive steps, dist = |delta| / (1 - q).
            if (have_prev_delta) {
                const double q = delta.norm() / prev_delta.norm();
                if (q > 0.2 && q < 1 && delta.dot(prev_delta) > 0.9 * delta.norm() * prev_delta.norm())
                    dist = delta.norm() / (1 - q);
            }
        } else if (last_good_rho < 1) {
            dist = rn / (1 - last_good_rho);
        } else {
            dist = rn == 0 ? 0 : std::numeric_limits<double>::infinity();
        }
        if (p.rdisp * dist <= tol) {
            converged = true;
            break;
        }
        if (periods >= opt.max_periods) break;
        // Near the noise floor progress is judged on the residual (dist is unreliable once the residual is at
        // the integration's noise: the step sequence, and so the rounding of a period, changes with the
        // start, and the measured "contraction" becomes noise, even > 1).
        if (rn < 0.5 * best_rn) {
            best_rn = rn;
            stagnant = 0;
        } else if (!stuck_now(cur) && p.rdisp * rn <= 1000 * tol && ++stagnant > 3) {
            // Accept the state if that noise is small; the error estimate says how small.
            const double r_good = std::isnan(last_good_rho) ? 0.5 : std::min(last_good_rho, 0.9);
            dist = std::min(dist, rn / (1 - r_good));
            converged = p.rdisp * dist <= 30 * tol;
            break;
        }

        if (!tried_circle && !cur.out.v_negative && cur.out.lag_end.norm() > 0.5 * zss) {
            tried_circle = true;
            Iter c;
            double d = 0;
            if (try_circle(cur, c, d)) {
                cur = c;
                dist = d;
                converged = true;
                sol.newton_steps += 1;
                break;
            }
        }

        // i = 0 without slip: Phi(L) = L + (2 pi zeta, 0) (the tip sticks; P drifts), DPhi = I. Only
        // plain periods bring the tip to its first slip.
        // Newton where plain steps contract slowly. (At the noise floor its finite differences are poor,
        // but the monotonicity test below rejects what does not help.)
        const bool stuck = stuck_now(cur);
        if (!stuck && rho > 0.1) {
            if (!have_inv) {
                have_inv = jacobian(cur);
                trusted_inv = false;
                have_prev_delta = false;
                if (have_inv) delta = -Ainv * res;
            }
            if (have_inv) {
                Vec2 d = delta;
                if (have_prev_delta) {
                    const double q = d.norm() / prev_delta.norm();
                    if (q > 0.2 && q < 0.98 && d.dot(prev_delta) > 0.9 * d.norm() * prev_delta.norm())
                        d /= (1 - q); // Aitken: jump the geometric series of a linearly converging Newton
                }
                const Iter nx = eval(cur.L + d);
                // Natural monotonicity test (Deuflhard): compare the Newton corrections, not the residuals.
                // Phi is very anisotropic (the radial direction is wiped out while the tip slips, the
                // angular one may contract only slowly), so a step that lands much closer to L* can still
                // have a larger residual |Phi(L) - L|.
                const double dn_old = delta.norm(), dn_new = (Ainv * nx.res()).norm();
                if (dn_new < 0.9 * dn_old || nx.res().norm() < 0.5 * rn) {
                    // Keep the Jacobian (chord steps) while it works well; refresh it when it does not.
                    trusted_inv = dn_new < 0.2 * dn_old;
                    if (dn_new > 0.3 * dn_old) have_inv = trusted_inv = false;
                    prev_delta = d;
                    have_prev_delta = true;
                    cur = nx;
                    ++sol.newton_steps;
                    continue;
                }
                have_inv = trusted_inv = false;
                have_prev_delta = false;
            }
        }
        // Plain step L <- Phi(L): always admissible, contracting once the tip slips.
        const Iter nx = eval(cur.out.lag_end);
        ++sol.plain_steps;
        const double rn_new = nx.res().norm();
        const double rho_now = rn > 0 ? rn_new / rn : 0;
        rho = std::isnan(rho_prev) ? rho_now : std::max(rho_now, rho_prev);
        rho_prev = rho_now;
        if (rho < 1) last_good_rho = rho;
        if (stuck) rho = rho_prev = std::numeric_limits<double>::quiet_NaN(); // not a contraction rate yet
        cur = nx;
    }

    // The reported period is the last one integrated, from cur.L.
    SteadyResult& r = sol.result;
    r.rx = cur.out.mean_force.x();
    r.ry = cur.out.mean_force.y();
    r.steady_error = p.rdisp * dist;
    // Integration error: the same period 10x looser. Global error ~ local tolerance, so the loose run's
    // error is ~10x ours and the difference ~9x; divided by 3 (not 9) to stay on the safe side.
    LagOde loose(p, 10 * kLocal * tol);
    const OdePeriod lo = loose.period(cur.L, nullptr, nullptr, 0, p);
    sol.integration_error = (lo.mean_force - cur.out.mean_force).cwiseAbs().maxCoeff() / 3;
    r.status = converged ? SteadyStatus::converged : SteadyStatus::not_converged;
    r.steps_per_period = cur.out.steps;
    r.levels = 1;
    r.scheme = Scheme::ode;
    sol.lag = cur.L;
    r.error_estimate = r.steady_error + sol.integration_error;
    r.periods = r.total_periods = periods;
    if (opt.record_period) {
        // The same period again, now with samples and events (same tolerance, same start: same result).
        LagOde rec(p, kLocal * tol);
        r.period.reserve(static_cast<std::size_t>(std::max(1, opt.record_samples)));
        rec.period(cur.L, &sol.events, &r.period, std::max(1, opt.record_samples), p);
    }
    return sol;
}

SteadyResult ode_steady(const Params& p, const OdeOptions& opt) {
    return ode_solve(p, opt).result;
}

std::vector<SweepPoint> ode_sweep_zeta(const std::vector<double>& zetas, const std::vector<double>& thetas,
                                       const std::vector<double>& rdisps, const std::vector<double>& is,
                                       const OdeOptions& opt, int threads) {
    std::vector<SweepPoint> pts;
    pts.reserve(zetas.size() * thetas.size() * rdisps.size() * is.size());
    for (double i : is)
        for (double th : thetas)
            for (double r : rdisps)
                for (double z : zetas) {
                    SweepPoint sp;
                    sp.model = Model::dahl;
                    sp.params = {z, th, r, i};
                    pts.push_back(sp);
                }
    const int families = static_cast<int>(thetas.size() * rdisps.size() * is.size());
    const std::size_t nz = zetas.size();
    OdeOptions o = opt;
    o.record_period = false;
    parallel_for(
        families,
        [&](int f) {
            OdeOptions of = o;
            for (std::size_t k = 0; k < nz; ++k) {
                SweepPoint& sp = pts[static_cast<std::size_t>(f) * nz + k];
                OdeSolution s = ode_solve(sp.params, of);
                sp.result = std::move(s.result);
                of.initial_lag = s.lag; // the neighbour's steady lag: usually a step or two from the next
            }
        },
        threads);
    return pts;
}

} // namespace fv
