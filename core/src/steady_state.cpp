#include "fv/steady_state.hpp"

#include "fv/ode_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv {

const char* to_string(Scheme s) {
    return s == Scheme::ode ? "ode" : "paper";
}

const char* to_string(SteadyStatus s) {
    switch (s) {
    case SteadyStatus::converged:
        return "ok";
    case SteadyStatus::not_converged:
        return "not_converged";
    case SteadyStatus::integration_failed:
        return "integration_failed";
    case SteadyStatus::non_finite:
        return "non_finite";
    case SteadyStatus::unsettled:
        return "unsettled";
    case SteadyStatus::periodic:
        return "period_k";
    case SteadyStatus::not_periodic:
        return "not_periodic";
    }
    return "?";
}

std::string status_word(const SteadyResult& r) {
    if (r.status == SteadyStatus::periodic) return "period_" + std::to_string(r.period_k);
    return to_string(r.status);
}

SteadyStatus reported_status(const SteadyResult& r) {
    if (ok(r.status) && (!std::isfinite(r.rx) || !std::isfinite(r.ry))) return SteadyStatus::non_finite;
    return r.status;
}

std::string reported_word(const SteadyResult& r) {
    const SteadyStatus st = reported_status(r);
    return st == r.status ? status_word(r) : to_string(st);
}

const char* to_string(Start s) {
    return s == Start::rest ? "rest" : "sliding";
}

bool parse_start(const std::string& text, Start& out) {
    if (text == "rest")
        out = Start::rest;
    else if (text == "sliding")
        out = Start::sliding;
    else
        return false;
    return true;
}

int default_steps_per_period(const Params& p) {
    // The explicit update (17)-(22) is in its first-order regime once P moves only a small fraction of
    // z_ss per step. |dP/dtau| <= 1 + zeta (Eq. (1)), so a step moves P by at most (1 + zeta) dtau; we ask
    // for at most z_ss / kResolution. Powers of two keep the halvings of the extrapolation exact.
    constexpr double kResolution = 32;
    const double needed = 2 * kPi * (1 + p.zeta) * p.rdisp * kResolution;
    int n = 1024;
    while (n < needed && n < (1 << 22)) n *= 2;
    return n;
}

namespace {

struct LevelResult {
    Ratio r;
    SteadyStatus status = SteadyStatus::converged;
    int periods = 0;
    double steady_error = 0; // estimated |r - r(steady)| at this resolution
    Vec2 final_lag{0, 0};
    std::vector<Sample> period;
};

// Runs the scheme at n steps per period from `lag0` until the lag at the start of a period stops moving.
// The period map of a dissipative system contracts: successive changes delta_m of the lag shrink by a
// factor rho per period (exponentially for i <= 1, ever more slowly for i > 1). With rho estimated from the
// last changes, the distance still to go is about delta_m / (1 - rho). For i > 1 the changes decay only
// algebraically, delta_m ~ C m^-q, and that formula undershoots the tail sum delta_m m / (q - 1) by a factor
// q/(q - 1): so q is also estimated (from delta at m/2 and m) and the larger estimate is used. A stuck
// asperity (i = 0 before its first slip) gives rho = 1, q = 0: no estimate, keep going. The changes of the
// period means r_m are watched alongside the lag.
LevelResult run_level(const Params& p, int n, Vec2 lag0, const SteadyOptions& opt, double steps_left,
                      bool record) {
    PaperStepper st(p, n, lag0);
    LevelResult out;
    const int budget =
        std::max(2, static_cast<int>(std::min<double>(opt.max_periods, steps_left / static_cast<double>(n))));
    Ratio prev_r{std::numeric_limits<double>::quiet_NaN(), 0};
    double prev_delta = std::numeric_limits<double>::quiet_NaN();
    double prev_rho = std::numeric_limits<double>::quiet_NaN();
    // Below this the changes are rounding noise of a period's worth of steps: the lag has stopped moving.
    const double noise = 1e-13 * std::sqrt(static_cast<double>(n));
    std::vector<double> changes; // max(delta_m, |r_m - r_m-1|) for m = 1, 2, ...
    out.status = SteadyStatus::not_converged;
    out.steady_error = std::numeric_limits<double>::infinity();
    for (int m = 1; m <= budget; ++m) {
        const bool last_chance = m == budget;
        const Vec2 lag_start = st.lag();
        Vec2 sum{0, 0};
        if (record) out.period.clear();
        // Eqs. (30)-(31): the mean of F(t + k dt), k = 1..n, over one period.
        for (int k = 0; k < n; ++k) {
            st.step();
            sum += st.force();
            if (record) out.period.push_back(st.sample());
        }
        const Ratio r{sum.x() / n, sum.y() / n};
        const double delta = p.rdisp * (st.lag() - lag_start).norm(); // in force units
        const double dr = std::isnan(prev_r.rx)
                              ? std::numeric_limits<double>::infinity()
                              : std::max(std::abs(r.rx - prev_r.rx), std::abs(r.ry - prev_r.ry));
        const double rho_now = delta / prev_delta;
        // The larger of the last two ratios: one lucky small ratio must not end the run early.
        const double rho = std::isnan(prev_rho) ? rho_now : std::max(rho_now, prev_rho);
        out.r = r;
        out.periods = m;
        out.final_lag = st.lag();
        const double change = std::max(delta, dr);
        changes.push_back(change);
        double estimate = std::numeric_limits<double>::infinity();
        if (delta <= noise && dr <= noise) {
            estimate = change;
        } else if (rho < 1 && m >= 4) {
            const double geometric = change / (1 - rho);
            const double q = std::log(changes[static_cast<std::size_t>(m / 2 - 1)] / change) /
                             std::log(static_cast<double>(m) / (m / 2));
            const double algebraic = q > 1 ? change * m / (q - 1) : std::numeric_limits<double>::infinity();
            estimate = std::max(geometric, algebraic);
        }
        out.steady_error = estimate;
        if (estimate <= opt.tolerance) {
            out.status = SteadyStatus::converged;
            break;
        }
        if (last_chance) break;
        prev_r = r;
        prev_rho = rho_now;
        prev_delta = delta;
    }
    return out;
}

} // namespace

SteadyResult dahl_steady(const Params& p, const SteadyOptions& opt) {
    SteadyResult res;
    const bool auto_n = opt.steps_per_period <= 0;
    const int n0 = auto_n ? default_steps_per_period(p) : opt.steps_per_period;
    // Automatic mode runs n0/2, n0, 2 n0 and 4 n0 steps per period (see below); an explicit N runs only N.
    const int first_n = auto_n ? n0 / 2 : n0;
    const int levels = auto_n ? 4 : 1;

    std::vector<LevelResult> lv;
    // The history: from rest (T = P, or the lag asked for) or sliding (P - T = z_ss e_x).
    Vec2 lag = opt.start == Start::sliding ? Vec2(1 / p.rdisp, 0) : opt.initial_lag;
    res.start = opt.start;
    double steps_left = opt.max_steps;
    for (int l = 0; l < levels; ++l) {
        const int n = first_n << l;
        // Finer resolutions start from the coarser steady state (the steady state does not depend on the
        // start, so this only saves periods). The run at n0 is the one recorded: the paper's scheme as is
        // (the one at n0/2 too, in case it is the only one that runs).
        lv.push_back(run_level(p, n, lag, opt, steps_left, opt.record_period && n <= n0));
        const LevelResult& last = lv.back();
        lag = last.final_lag;
        res.total_periods += last.periods;
        steps_left -= static_cast<double>(last.periods) * n;
        if (n <= n0) res.period = last.period;
        // A resolution that did not settle makes finer ones pointless (they settle no faster): stop here.
        if (last.status != SteadyStatus::converged) break;
    }
    res.periods = lv.front().periods;
    res.steps_per_period = first_n << (lv.size() - 1);
    res.levels = static_cast<int>(lv.size());
    res.status = lv.back().status;

    if (lv.size() < 4) {
        // One run (an explicit N, or the first resolution already failed to settle) or a run cut short:
        // report the finest run as it is. Its discretisation error is unknown unless a coarser run exists.
        const LevelResult& f = lv.back();
        res.rx = f.r.rx;
        res.ry = f.r.ry;
        res.steady_error = f.steady_error;
        double disc = 0;
        if (lv.size() >= 2) {
            const LevelResult& c = lv[lv.size() - 2];
            disc = std::max(std::abs(f.r.rx - c.r.rx), std::abs(f.r.ry - c.r.ry));
        }
        res.error_estimate = std::max(f.steady_error + disc, opt.tolerance);
        if (levels == 1) res.error_estimate = f.steady_error; // the scheme as asked for: steady part only
        return res;
    }
    // The scheme is first order: r(n) = r0 + c/n + e(n). Richardson extrapolation R = 2 r(2n) - r(n) of
    // successive halvings removes c/n. What is left, e(n), is not a clean c2/n^2: the stick/slip and
    // turning events fall at different fractions of a step at each resolution, so e(n) wobbles. The spread
    // of three successive extrapolations bounds it honestly where the difference of the last two alone
    // (the classic estimate) can vanish by accident (measured with bench/accuracy_contract.cpp).
    Ratio R[3];
    for (int l = 0; l < 3; ++l) {
        R[l].rx = 2 * lv[static_cast<std::size_t>(l + 1)].r.rx - lv[static_cast<std::size_t>(l)].r.rx;
        R[l].ry = 2 * lv[static_cast<std::size_t>(l + 1)].r.ry - lv[static_cast<std::size_t>(l)].r.ry;
    }
    res.rx = R[2].rx;
    res.ry = R[2].ry;
    // Steady-state errors enter R = 2 r3 - r2 with those weights.
    res.steady_error = 2 * lv[3].steady_error + lv[2].steady_error;
    double spread = 0;
    for (int l = 0; l < 2; ++l)
        spread = std::max({spread, std::abs(R[2].rx - R[l].rx), std::abs(R[2].ry - R[l].ry)});
    // No claim finer than the steady-state tolerance that was aimed at (rounding over ~1e5-step periods
    // alone is ~1e-12..1e-10).
    res.error_estimate = std::max(spread + res.steady_error, opt.tolerance);
    return res;
}

SteadyResult steady_ratio(Model m, const Params& p, const SteadyOptions& opt) {
    if (m == Model::dahl)
        return uses_paper_scheme(opt) ? dahl_steady(p, opt) : ode_steady(p, ode_options(opt));
    SteadyResult res;
    const Ratio r = rigid_ratio(p.zeta, p.theta);
    res.rx = r.rx;
    res.ry = r.ry;
    res.periods = 0;
    res.error_estimate = 1e-12; // the quadrature's tolerance
    res.steps_per_period = 0;
    res.levels = 0;
    return res;
}

} // namespace fv
