// The periodic steady state: Newton's method on the period map (see ode_solver.hpp, docs/model.md).
#include "closed_forms.hpp"
#include "period_map.hpp"
#include "reach.hpp"
#include "search_starts.hpp"

#include "fv/detail/parallel_for.hpp"
#include "fv/ode_solver.hpp"
#include "fv/param_ranges.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
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

Vec2 ode_lag_rate(const Params& p, double tau, Vec2 lag, bool on_circle) {
    const solver::LagModel m(p);
    const Vec2 dp = m.dP(tau);
    const double z = lag.norm();
    if (on_circle) {
        const Vec2 e = lag / z;
        return dp - e.dot(dp) * e; // pursuit: T follows along e, |L| stays z_ss
    }
    if (p.i == 0) return dp; // stick
    const Vec2 l = p.rdisp * lag;
    const double v = l.dot(dp);
    const solver::InteriorProblem pb(m, l, v < 0 ? -1.0 : 1.0);
    return pb.eval(tau, Eigen::Vector2d::Zero()).f;
}

namespace {

using solver::kTinyR;
using solver::kTwoPi;
using solver::LagModel;
using solver::Orbit;
using solver::PeriodRequest;
using solver::Reach;
using solver::ReachSetup;

// A stable state of the listing from an orbit found from a start.
SteadyState listed(const Orbit& o, double r) {
    SteadyState st;
    st.rx = o.rx;
    st.ry = o.ry;
    st.period = o.k;
    st.multipliers[0] = o.mu[0];
    st.multipliers[1] = o.mu[1];
    st.error_estimate = o.error_estimate;
    st.lag = o.l0 / r;
    st.on_circle = o.on_circle;
    return st;
}

// Adds a state to the listing, or marks the start on the one already there (the same orbit: the same
// period and means within their error estimates and 1e-6).
void add_state(std::vector<SteadyState>& list, SteadyState s, Start from, bool reached) {
    for (SteadyState& x : list) {
        const double slack = 1e-6 + x.error_estimate + s.error_estimate;
        if (x.period == s.period && std::abs(x.rx - s.rx) <= slack && std::abs(x.ry - s.ry) <= slack) {
            if (reached) (from == Start::rest ? x.from_rest : x.from_sliding) = true;
            return;
        }
    }
    s.from_rest = s.from_rest || (reached && from == Start::rest);
    s.from_sliding = s.from_sliding || (reached && from == Start::sliding);
    list.push_back(s);
}

// Where Newton's method is tried first for a start, before the motion from it is followed: a warm start,
// a settled circle start, the nearby limit (before the start itself: from sliding the start on the circle
// is far from a state near the limit, and Newton's method from it mostly gives up; over 3000 random points
// from sliding 21 % fewer periods, answers above 2 ms 38 -> 6), the start itself, then the other starts
// (along P'(0), along e_x, zero) as ode_solve always did (search_starts.hpp).
std::vector<Vec2> guesses_for(const LagModel& m, const OdeOptions& opt, const Vec2& start,
                              const PeriodRequest& rq) {
    std::vector<Vec2> g;
    auto add = [&](Vec2 l) {
        if (!l.allFinite()) return;
        if (l.norm() > 1) l /= l.norm();
        if (!solver::near_any(g, l, 1e-9)) g.push_back(l);
    };
    if (opt.initial_lag.squaredNorm() > 0 && opt.initial_lag.allFinite()) add(m.r * opt.initial_lag);
    // A settled circle start is within a hair of the state where the tip slips all along (rdisp >~ 5),
    // which most starts reach within a period there.
    if (const auto pre = solver::prerolled_start(m, rq)) add(*pre);
    const std::vector<Vec2> others = solver::other_starts(m);
    if (!others.empty()) add(others.front());
    add(start);
    // The other limits and the circle (search_starts.hpp): from sliding too, where at small r_disp the motion
    // drifts from the circle to its state over ~1/r_disp^2 periods and Newton's method from the start itself
    // gives up (zeta 0.316, theta 60 deg, rdisp 1e-8, i 10: 57 -> 37 periods with the first of them); all of
    // them before the motion is followed, which otherwise goes on for a hundred periods and more before its
    // own Newton's method gives up and sends the search to them (zeta 0.0042, theta 90 deg, rdisp 0.01, i 2
    // from sliding: 179 -> 40 periods, the state found from along P'(0)). The evidence decides whether the
    // start reaches what they find.
    for (const Vec2& o : others) add(o);
    return g;
}

// The search as it has always run from rest: Newton's method from the warm start, a settled circle start,
// the nearby limit and the other starts in turn (search_starts.hpp), each given up when it makes no
// progress (the last only when the budget runs out); the first that converges, verified.
Orbit default_search(const ReachSetup& s, const OdeOptions& opt, int& periods, Vec2& found_from,
                     std::vector<Vec2>& fruitless) {
    const Params& p = *s.p;
    const LagModel& m = *s.m;
    const double r = p.rdisp;
    std::vector<Vec2> starts;
    if (opt.initial_lag.squaredNorm() > 0 && opt.initial_lag.allFinite()) {
        Vec2 l = r * opt.initial_lag;
        if (l.norm() > 1) l /= l.norm();
        if (l.allFinite()) starts.push_back(l);
    }
    if (const auto pre = solver::prerolled_start(m, s.rq)) starts.push_back(*pre);
    for (const Vec2& l : solver::other_starts(m))
        if (!solver::near_any(starts, l, 1e-9)) starts.push_back(l);
    solver::Search best;
    for (std::size_t k = 0; k < starts.size(); ++k) {
        const bool final_try = k + 1 == starts.size();
        const solver::Search sr = solver::search_from(p, m, starts[k], s.rq, s.aim, opt.max_periods - periods,
                                                      final_try ? 0 : solver::kGiveUp);
        periods += sr.periods;
        if (sr.gave_up) fruitless.push_back(starts[k]);
        const bool better = !best.have_last || (sr.have_last && (sr.converged || sr.dist < best.dist));
        if (k == 0 || better) {
            best = sr;
            found_from = starts[k];
        }
        if (sr.converged || sr.status != SteadyStatus::converged || periods >= opt.max_periods) break;
    }
    Orbit o;
    if (!best.have_last) {
        o.status = SteadyStatus::integration_failed;
        o.rx = o.ry = std::numeric_limits<double>::quiet_NaN();
        o.failure = best.failure;
        return o;
    }
    const solver::Verified v = solver::verify_fixed_point(p, m, best, s.rq, s.aim, s.tol, s.record,
                                                          s.record_samples, opt.max_periods - periods);
    periods += v.periods;
    o = solver::orbit_of(s, v);
    if (v.converged && v.unstable && best.status == SteadyStatus::converged) {
        o.status = SteadyStatus::unsettled;
        o.failure = "the periodic state found is unstable: the motion does not settle";
    }
    if (v.converged) {
        solver::period1_multipliers(s, v.last, v.l0, o.mu);
        o.have_mu = true;
    }
    return o;
}

Vec2 start_force(Start s) {
    return s == Start::sliding ? Vec2(1, 0) : Vec2(0, 0);
}

void fill_result(OdeSolution& sol, const Orbit& o, const Params& p, int periods) {
    SteadyResult& res = sol.result;
    res.scheme = Scheme::ode;
    res.levels = 1;
    res.status = o.status;
    res.rx = o.rx;
    res.ry = o.ry;
    res.error_estimate = o.error_estimate;
    res.steady_error = o.steady_error;
    res.periods = res.total_periods = periods;
    res.steps_per_period = o.steps_per_period;
    res.period_k = o.k;
    res.multipliers[0] = o.mu[0];
    res.multipliers[1] = o.mu[1];
    res.have_multipliers = o.have_mu;
    res.mean_standard_error = o.standard_error;
    res.window = o.window;
    res.period = o.samples;
    sol.events = o.events;
    sol.newton_steps = res.newton_steps = o.newton_steps;
    sol.plain_steps = res.plain_steps = o.plain_steps;
    sol.periods_skipped = res.periods_skipped = o.periods_skipped;
    sol.events_per_period = res.events_per_period = o.events_per_period;
    sol.on_circle = res.on_circle = o.on_circle;
    sol.integration_error = o.integration_error;
    sol.lag = o.l0 / p.rdisp;
    res.lag = sol.lag;
    sol.failure = o.failure;
    res.detail = o.failure;
}

// Whether the motion from the other start is shown to settle into one of the stable states found (the
// start's state, then the others); that state is marked reached from the other start in the listing.
bool other_reaches_known(const ReachSetup& setup, Start other, const Orbit& state,
                         const std::vector<Orbit>& others, int& periods, std::vector<SteadyState>& list) {
    const Vec2 from = start_force(other);
    auto try_orbit = [&](const Orbit& o) {
        if (!ok(o.status) || !o.have_mu || !solver::stable(o.mu)) return false;
        if (!solver::reaches(setup, from, o.l0, o.M, o.k, o.circle_state, periods)) return false;
        add_state(list, listed(o, setup.p->rdisp), other, true);
        return true;
    };
    if (try_orbit(state)) return true;
    return std::any_of(others.begin(), others.end(), try_orbit);
}

OdeSolution solve_start(const Params& p, const OdeOptions& opt) {
    const LagModel m(p);
    const double r = p.rdisp;
    if (p.zeta == 0 && p.i == 0 && r <= 1) return solver::lens_solution(p, m, opt);
    if (r < kTinyR) return solver::small_amplitude_solution(p, m, opt);

    // The solver aims at 0.3 tol and accepts its result when the error estimate is within tol.
    const double tol = opt.tolerance;
    const double aim = 0.3 * tol;
    // Local tolerance of the displacements (x_v): force errors are r times larger for r > 1; for r < 1 the
    // fixed-point equation L(2 pi) - L(0) = 0 needs the displacements themselves. Radau IIA's error estimate
    // is of lower order than the method: measured over whole periods, a local tolerance a gives mean-force
    // errors ~1e-3 a and end-state errors ~1e-2 a, so (like RADAU5, which uses 0.1 tol^(2/3)) the local
    // tolerance is looser than the target; the separate estimate in verify_state.cpp checks the outcome.
    PeriodRequest rq;
    rq.atol = 0.1 * std::pow(aim, 2.0 / 3.0) / std::max(1.0, r);
    // The quadrature's local tolerance per unit time (it sets the step size): the period mean's error is
    // measured at 0.1-0.4 of it. Not looser: at 2 aim (1/7 fewer steps) the integration error of a period
    // whose fixed point lies next to a grazing of the circle (zeta 0.4243, theta 132 deg, rdisp 2, i = 1)
    // reached 1.1e-8, and the refinement at 4x tighter tolerance cycled between the laws at the section.
    rq.atol_force = aim;
    rq.sensitivity = true;

    ReachSetup setup;
    setup.p = &p;
    setup.m = &m;
    setup.rq = rq;
    setup.aim = aim;
    setup.tol = tol;
    setup.record = opt.record_period;
    setup.record_samples = opt.record_samples;
    setup.max_search_periods = opt.max_periods;

    // From rest (the default): Newton's method from the starts that lead to the steady state fastest
    // (search_starts.hpp), then the evidence that the motion from rest reaches the state found. Where there
    // is none (another state is reached, or the state found is unstable, or Newton's method creeps), the
    // state the motion from the start reaches is searched for as for any start (reach.hpp): Newton's method
    // from the start, then the motion followed (period-k states, motion that does not repeat).
    OdeSolution sol;
    SteadyResult& res = sol.result;
    int periods = 0;
    Orbit state;
    std::vector<Orbit> others;
    double creep_skipped = 0;
    const Vec2 l_start = start_force(opt.start);
    Vec2 found_from{2, 2}; // where the default search's Newton's method started (none: outside the disc)
    solver::Prior prior;
    if (opt.start == Start::rest) {
        state = default_search(setup, opt, periods, found_from, prior.fruitless);
#ifdef FV_SOLVER_TRACE
        std::fprintf(stderr, "default search: %d periods\n", periods);
#endif
        if (ok(state.status))
            state.reached =
                solver::reaches(setup, l_start, state.l0, state.M, 1, state.circle_state, periods);
#ifdef FV_SOLVER_TRACE
        std::fprintf(stderr, "default search: state (%.6g,%.6g) %s, reached from rest %d, %d periods\n",
                     state.l0.x(), state.l0.y(), to_string(state.status), state.reached, periods);
#endif
    }
    if (!state.reached && state.status != SteadyStatus::integration_failed) {
        // The default search's state, found but not shown to be reached (or unstable): its own start is not
        // searched again, and a guess that leads to it again is only followed up (reach.hpp); nor are the
        // starts it gave up.
        const bool rejected = ok(state.status) && state.have_mu && solver::stable(state.mu);
        const bool unstable = state.status == SteadyStatus::unsettled && state.have_mu;
        if (rejected) prior.rejected = &state;
        if (unstable) {
            prior.unstable = &state;
            prior.fruitless.push_back(found_from);
        }
        std::vector<Vec2> guesses = guesses_for(m, opt, l_start, rq);
        if (rejected || unstable)
            guesses.erase(std::remove_if(guesses.begin(), guesses.end(),
                                         [&](const Vec2& g) { return (g - found_from).norm() < 1e-12; }),
                          guesses.end());
        Reach reach = solver::reach_from(setup, l_start, guesses, prior);
        periods += reach.periods;
        creep_skipped = reach.skipped;
        const bool better = ok(reach.state.status) || reach.state.status == SteadyStatus::not_periodic ||
                            opt.start != Start::rest;
        if (better) {
            if (ok(state.status)) others.push_back(std::move(state)); // found, but not shown to be reached
            state = std::move(reach.state);
        }
        for (Orbit& o : reach.others) others.push_back(std::move(o));
    }
    fill_result(sol, state, p, periods);
    res.creep_periods_skipped = creep_skipped;
    res.start = opt.start;
    res.start_reaches = state.reached;
    std::vector<SteadyState>& list = res.states;
    if (ok(state.status)) add_state(list, listed(state, r), opt.start, state.reached);
    for (const Orbit& o : others)
        if (ok(o.status)) add_state(list, listed(o, r), opt.start, false);
    const Start other = opt.start == Start::rest ? Start::sliding : Start::rest;
    // Where only reached states matter (the map), the other start needs no search of its own when its motion
    // is shown to settle into a state already found: the search would find that state, and the states it
    // passes on the way are not listed.
    const bool other_known = opt.list_states && opt.list_only_reached &&
                             other_reaches_known(setup, other, state, others, periods, list);
    if (opt.list_states && !other_known && (opt.list_states_after_failure || ok(state.status))) {
        // The other start's state: only to list it (its period is not recorded).
        OdeOptions o2 = opt;
        o2.start = other;
        o2.list_states = false;
        o2.record_period = false;
        const OdeSolution second = solve_start(p, o2);
        periods += second.result.periods;
        for (const SteadyState& x : second.result.states)
            add_state(list, x, other, other == Start::rest ? x.from_rest : x.from_sliding);
    }
    std::sort(list.begin(), list.end(),
              [](const SteadyState& a, const SteadyState& b) { return a.rx < b.rx; });
    res.periods = res.total_periods = periods;
    return sol;
}

} // namespace

OdeSolution ode_solve(const Params& p, const OdeOptions& opt) {
    const std::string msg = validate(p);
    if (!msg.empty()) throw std::invalid_argument(msg);
    if (!(opt.tolerance > 0)) throw std::invalid_argument("tolerance must be > 0");
    OdeSolution sol = solve_start(p, opt);
    // Another tolerance's answer in place of a failure, where it is verified within the one asked for (and,
    // `same`, is the state the failure had found, within both estimates).
    auto retry_at = [&](double tolerance, bool same) {
        OdeOptions o = opt;
        o.tolerance = tolerance;
        OdeSolution again = solve_start(p, o);
        again.result.periods += sol.result.periods;
        again.result.total_periods = again.result.periods;
        const double both = sol.result.error_estimate + again.result.error_estimate;
        const bool agrees = std::abs(again.result.rx - sol.result.rx) <= both &&
                            std::abs(again.result.ry - sol.result.ry) <= both;
        if (ok(again.result.status) && again.result.error_estimate <= std::max(opt.tolerance, tolerance) &&
            (!same || agrees))
            sol = std::move(again);
        else
            sol.result.periods = sol.result.total_periods = again.result.periods;
    };
    // A near miss (the state found, its error estimate within 100 times the tolerance but above it: the
    // integration's own error, which the verification's refinement does not shrink) once more at a 4x
    // tighter tolerance, taken if it is the same state: over 9000 random points of the domain 3 had ended so
    // (zeta 0.0274, theta 1.4 deg, rdisp 0.23, i 0.5: 1.6e-8 at 1e-8; at 2.5e-9 it is 9.4e-10). Not another
    // state the tighter search comes to (zeta 0, theta 90 deg, rdisp 1e-7, i 10 from sliding: the circle's
    // 1 at 4e-8, then the centre's 0).
    const double est = sol.result.error_estimate;
    if (sol.result.status == SteadyStatus::not_converged && std::isfinite(est) &&
        est <= 100 * opt.tolerance && opt.tolerance / 4 >= kToleranceRange.lo)
        retry_at(opt.tolerance / 4, true);
    // A looser tolerance never turns a verified answer into a failure: where the search at the looser
    // settings does not settle, the default tolerance's answer (its error estimate within it) is given.
    if (!ok(sol.result.status) && opt.tolerance > kDefaultOdeTolerance) retry_at(kDefaultOdeTolerance, false);
    return sol;
}

OdeOptions ode_options(const SteadyOptions& opt) {
    OdeOptions o;
    o.tolerance = opt.ode_tolerance;
    o.initial_lag = opt.initial_lag;
    o.record_period = opt.record_period;
    o.start = opt.start;
    o.list_states = opt.list_states;
    return o;
}

SteadyResult ode_steady(const Params& p, const OdeOptions& opt) {
    return ode_solve(p, opt).result;
}

std::vector<SweepPoint> ode_sweep_zeta(const std::vector<double>& zetas, const std::vector<double>& thetas,
                                       const std::vector<double>& rdisps, const std::vector<double>& is,
                                       const OdeOptions& opt, int threads) {
    std::vector<SweepPoint> pts = sweep_grid(Model::dahl, zetas, thetas, rdisps, is);
    // Every point from its own cold start: a row never depends on its neighbours or on the grid it is in
    // (a warm start can sit next to a degenerate fixed point of another law), and cold starts from the
    // nearby limits cost about what warm starts did.
    OdeOptions o = opt;
    o.record_period = false;
    parallel_for(
        static_cast<int>(pts.size()),
        [&](int k) {
            SweepPoint& sp = pts[static_cast<std::size_t>(k)];
            sp.result = ode_solve(sp.params, o).result;
        },
        threads);
    return pts;
}

} // namespace fv
