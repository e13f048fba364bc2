// Steady states known in closed form or from a limit (see closed_forms.hpp).
#include "closed_forms.hpp"

#include "fv/paper_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace fv::solver {

namespace {

constexpr double kAnchorR1 = 1e-9, kAnchorR2 = 1e-8;

// The steady period's samples where the force is known in closed form, F(tau).
template <class Force>
void record_closed_form(const Params& p, const OdeOptions& opt, SteadyResult& res, Force F) {
    const int n = std::max(1, opt.record_samples);
    for (int k = 1; k <= n; ++k) {
        Sample s;
        s.tau = kTwoPi * k / n;
        s.P = body_point(p, s.tau);
        s.F = F(s.tau);
        s.T = s.P - s.F / p.rdisp;
        s.z = s.F.norm() / p.rdisp;
        res.period.push_back(s);
    }
}

// The small-amplitude limit of the period means (rdisp -> 0 at fixed zeta > 0): i = 0: (1, 0) (the tip
// slips at full deflection along e_x); i > 0: (rho, 0) with rho from small_amplitude_rho; zeta = 0, i > 0:
// (0, 0) (the steady state is symmetric under tau -> tau + pi). `err` bounds the closed form's own error
// (rounding of the balance k+ I+ + k- I- = 2 pi zeta through its slope at the root).
Vec2 small_amplitude_limit(const LagModel& m, double& err) {

    err = 0;
    if (m.i == 0) return {1, 0};
    if (!(m.zeta > 0)) return {0, 0};
    const double rho = small_amplitude_rho(m);
    if (rho < 1) {
        // The balance H(rho) = k+ I+ + k- I- - 2 pi zeta is computed to ~eps (|I+| + |I-| + 2 pi zeta); its
        // root moves by that over H'(rho) = i ((1 - rho)^(i-1) I+ - (1 + rho)^(i-1) I-) (I- <= 0).
        const double a = m.zeta, b = std::abs(m.cth);
        double ip = kTwoPi * a, in = 0;
        if (b > a) {
            const double al = std::acos(-a / b);
            ip = 2 * (a * al + b * std::sin(al));
            in = kTwoPi * a - ip;
        }
        const double slope = m.i * (std::pow(1 - rho, m.i - 1) * ip - std::pow(1 + rho, m.i - 1) * in);
        const double noise = 16 * std::numeric_limits<double>::epsilon() * (ip - in + kTwoPi * a);
        err = slope > 0 ? std::min(1.0, noise / slope + 1e-16) : 1.0;
    }
    return {rho, 0};
}

} // namespace

// zeta = 0, i = 0, rdisp <= 1: L(tau) = c/r + sin(tau) u never slips once |c +- r u| <= 1. As zeta -> 0+ the
// slow drift sweeps c to the point of that lens (two unit discs centred at -+ r u) farthest along +x
// (docs/model.md, "zeta = 0").
Vec2 lens_center(const LagModel& m) {
    const double r = m.r;
    const Vec2 u = m.u();
    if (u.x() >= r) return Vec2(1, 0) - r * u;
    if (u.x() <= -r) return Vec2(1, 0) + r * u;
    return std::sqrt(std::max(0.0, 1 - r * r)) * Vec2(m.sth, -m.cth);
}

OdeSolution lens_solution(const Params& p, const LagModel& m, const OdeOptions& opt) {
    OdeSolution sol;
    const Vec2 c = lens_center(m);
    SteadyResult& r = sol.result;
    r.scheme = Scheme::ode;
    r.rx = c.x();
    r.ry = c.y();
    r.status = SteadyStatus::converged;
    r.error_estimate = 1e-15;
    r.levels = 1;
    sol.lag = (c + m.r * std::sin(0.0) * m.u()) / m.r;
    if (opt.record_period)
        record_closed_form(p, opt, r, [&](double tau) { return Vec2(c + m.r * std::sin(tau) * m.u()); });
    return sol;
}

// The small-amplitude limit (rdisp -> 0, i > 0): the force l hardly moves in a period, so its drift is the
// period mean of the law at fixed l, G(l) = mean(P') - mean(v k(v) e) with v = e . P' = a + b cos tau
// (a = zeta e_x, b = e . u), k = 1 - (1 - sgn(v) rho)^i. T moves only along e, and on average it must move
// along e_x: so e = e_x, and rho solves k+(rho) I+ + k-(rho) I- = 2 pi zeta with I+- = int of the positive
// and negative parts of v (closed form), k+- = 1 - (1 -+ rho)^i. The left side grows with rho; no root
// below 1 means the tip stays on the circle. (docs/model.md, "Small amplitude".)
double small_amplitude_rho(const LagModel& m) {
    const double a = m.zeta, b = std::abs(m.cth);
    double ip = 0, in = 0; // int v+ and int v- over a period
    if (b <= a) {
        ip = kTwoPi * a;
    } else {
        const double al = std::acos(-a / b); // v > 0 for |tau| < al (b > 0 after the flip tau -> tau + pi)
        ip = 2 * (a * al + b * std::sin(al));
        in = kTwoPi * a - ip;
    }
    auto H = [&](double rho) {
        return (1 - std::pow(1 - rho, m.i)) * ip + (1 - std::pow(1 + rho, m.i)) * in - kTwoPi * m.zeta;
    };
    if (!(H(1) > 0)) return 1;
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (H(mid) > 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

// rdisp < kTinyR: the limit l0 (above) plus its first-order correction, from the solver at the anchors
// r1 = 1e-9 and r2 = 1e-8 (4x tighter tolerance): with R(r) = l0 + s r + c r^2 + O(r^3), the slope
// s1 = (R1 - l0)/r1, and the result l0 + s1 r differs from R(r) by at most
//   delta (1 - r/r1) + e1 r/r1 + |c| r r1   (delta: the limit's error, e1: the anchor's)
// for r <= r1. |s2 - s1| r1 = |9 c r1^2 + 0.9 delta + e2/10 - e1| bounds the first and last terms (with
// the anchors' own errors), so the error estimate is |s2 - s1| r1 + (r/r1) est1 + err(l0). A failed
// anchor is the result's failure.
OdeSolution small_amplitude_solution(const Params& p, const LagModel& m, const OdeOptions& opt) {
    double lim_err = 0;
    const Vec2 l0 = small_amplitude_limit(m, lim_err);
    OdeOptions oa = opt;
    oa.record_period = false;
    oa.initial_lag = Vec2::Zero();
    oa.tolerance = 0.25 * opt.tolerance;
    Params p1 = p, p2 = p;
    p1.rdisp = kAnchorR1;
    p2.rdisp = kAnchorR2;
    const OdeSolution a1 = ode_solve(p1, oa);
    OdeSolution sol;
    SteadyResult& res = sol.result;
    auto fail = [&](const OdeSolution& a, const char* which) {
        sol = a;
        sol.lag = Vec2(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
        sol.failure = "small-amplitude limit: an anchor of the solver (rdisp 1e-9, 1e-8) failed";
        res.detail = std::string("small-amplitude limit: the anchor at rdisp = ") + which + " failed (" +
                     (a.failure && *a.failure ? a.failure : to_string(a.result.status)) + ")";
        res.rx = res.ry = std::numeric_limits<double>::quiet_NaN();
        res.status = SteadyStatus::not_converged;
        return sol;
    };
    if (a1.result.status != SteadyStatus::converged) return fail(a1, "1e-9");
    const OdeSolution a2 = ode_solve(p2, oa);
    if (a2.result.status != SteadyStatus::converged) return fail(a2, "1e-8");
    const double r = p.rdisp;
    const Vec2 R1(a1.result.rx, a1.result.ry), R2(a2.result.rx, a2.result.ry);
    const Vec2 s1 = (R1 - l0) / kAnchorR1, s2 = (R2 - l0) / kAnchorR2;
    const Vec2 l = l0 + s1 * r;
    res.scheme = Scheme::ode;
    res.levels = 1;
    res.rx = l.x();
    res.ry = l.y();
    res.steady_error = (s2 - s1).norm() * kAnchorR1;
    res.error_estimate = res.steady_error + (r / kAnchorR1) * a1.result.error_estimate + lim_err + 1e-15;
    res.periods = res.total_periods = a1.result.periods + a2.result.periods;
    res.steps_per_period = 0;
    res.status = res.error_estimate <= opt.tolerance ? SteadyStatus::converged : SteadyStatus::not_converged;
    sol.failure =
        res.status == SteadyStatus::converged
            ? ""
            : "small-amplitude limit: the anchors rdisp = 1e-9, 1e-8 do not confirm it to the tolerance";
    res.detail = sol.failure;
    sol.lag = l / r; // |L| ~ 1/rdisp: infinite below rdisp ~ 5.6e-309
    // The force moves by O(rdisp) within the period: its mean stands for it.
    if (opt.record_period) record_closed_form(p, opt, res, [&](double) { return l; });
    return sol;
}

} // namespace fv::solver
