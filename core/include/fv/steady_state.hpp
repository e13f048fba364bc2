// Periodic steady state of the lumped asperity and the friction ratios of one steady period, Eqs. (30)-(33).
#pragma once

#include "fv/paper_scheme.hpp"
#include "fv/params.hpp"
#include "fv/rigid.hpp"

#include <string>
#include <vector>

namespace fv {

// What became of a steady-state computation. Only `converged` is a result the solver vouches for; every
// other value is a numerical failure (command-line exit status 3) and names its reason.
enum class SteadyStatus {
    converged,          // the estimated error of r_x, r_y is below the tolerance
    not_converged,      // the period or iteration budget ran out first; error_estimate says how far it may be
    integration_failed, // the integrator could not continue (step size underflow, stage equations unsolved)
    non_finite,         // a value that is not a finite number came up (never expected; reported, not hidden)
    unsettled, // the only periodic state found is unstable (a Floquet multiplier beyond 1): the motion
               // does not settle, so there is no steady r_x, r_y to give
};
// "ok" for converged, else the reason as one word: "not_converged", "integration_failed", "non_finite",
// "unsettled".
const char* to_string(SteadyStatus s);
inline bool ok(SteadyStatus s) {
    return s == SteadyStatus::converged;
}

// How the Dahl model's steady state is computed.
enum class Scheme {
    ode,   // default: the scheme's dtau -> 0 limit as an ODE with event location, fixed point by Newton
           // (ode_solver.hpp); within 1e-6 of the limit, ~10-500x faster than `paper` at equal accuracy
    paper, // the paper's stepping scheme, Eqs. (17)-(27), as printed (extrapolated unless N is given)
};
const char* to_string(Scheme s);

struct SteadyOptions {
    Scheme scheme = Scheme::ode;
    double ode_tolerance = 1e-8; // Scheme::ode: target for |r - r(dtau -> 0)|

    // 0: choose automatically: runs at n0/2, n0, 2 n0, 4 n0 steps (n0 = default_steps_per_period)
    // extrapolated to dtau -> 0, so the result meets the accuracy contract |r - r(dtau -> 0)| <= 1e-5 on zeta
    // in [0.02, 3], theta in [0, 90 deg], rdisp in [0.2, 100], i in {0, 1}. > 0: run exactly the paper's
    // scheme with this many steps per period, no extrapolation.
    int steps_per_period = 0;
    double tolerance = 1e-9;         // target for the steady-state part of the error (force units)
    int max_periods = 20000;         // hard cap on periods per resolution
    double max_steps = 1e8;          // cap on steps summed over all resolutions: every call ends in seconds
    Vec2 initial_lag = Vec2::Zero(); // P(0) - T(0)
    bool record_period = false;      // keep the samples of the last steady period (trace)
};

struct SteadyResult {
    Scheme scheme = Scheme::paper; // which solver produced it (for reports)
    double rx = 0, ry = 0;         // Eq. (33) and its y-twin (31)
    SteadyStatus status = SteadyStatus::converged;
    int periods = 0;           // periods run until the steady state was accepted (finest resolution)
    int total_periods = 0;     // summed over all resolutions
    double error_estimate = 0; // estimate of |r - exact| (steady-state + discretisation), force units
    double steady_error = 0;   // the steady-state part of it
    int steps_per_period = 0;  // finest resolution used
    int levels = 1;            // resolutions combined by Richardson extrapolation
    // What the continuous-time search did (Scheme::ode only): updates on the circle's angle or in the plane,
    // plain periods, whole stuck periods skipped in closed form, law changes in the steady period, whether
    // the steady period starts on the circle, and in words what stopped it when the status is not converged.
    int newton_steps = 0, plain_steps = 0, events_per_period = 0;
    long periods_skipped = 0;
    bool on_circle = false;
    std::string detail;
    Vec2 lag{0, 0}; // Scheme::ode: L = P(0) - T(0) of the steady period found (a warm start for neighbours)
    std::vector<Sample> period; // last steady period at n0 = default_steps_per_period (or the N asked for),
                                // samples k = 1..n of Eq. (30)
};

// Dahl model in steady state.
SteadyResult dahl_steady(const Params& p, const SteadyOptions& opt = {});

// Default steps per period of the coarsest resolution (see steady_state.cpp for why).
int default_steps_per_period(const Params& p);

// Either model through one door: rigid -> Eq. (9) quadrature (periods = 0, error ~1e-12); Dahl -> the
// continuous-time solver, or the paper's scheme when opt.scheme is Scheme::paper or steps_per_period > 0.
SteadyResult steady_ratio(Model m, const Params& p, const SteadyOptions& opt = {});

// True when these options run the paper's stepping scheme.
inline bool uses_paper_scheme(const SteadyOptions& o) {
    return o.scheme == Scheme::paper || o.steps_per_period > 0;
}

} // namespace fv
