// Periodic steady state of the lumped asperity and the friction ratios of one steady period, Eqs. (30)-(33).
#pragma once

#include "fv/paper_scheme.hpp"
#include "fv/params.hpp"
#include "fv/rigid.hpp"

#include <complex>
#include <string>
#include <vector>

namespace fv {

// What became of a steady-state computation. `converged` and `periodic` are results the solver vouches
// for; every other value is a numerical failure (command-line exit status 3) and names its reason.
enum class SteadyStatus {
    converged,          // the estimated error of r_x, r_y is below the tolerance
    periodic,           // the motion repeats every k > 1 periods (period_k); r_x, r_y are its means over
                        // the k periods, with the error estimate below the tolerance (a valid answer)
    not_converged,      // the period or iteration budget ran out first; error_estimate says how far it may be
    integration_failed, // the integrator could not continue (step size underflow, stage equations unsolved)
    non_finite,         // a value that is not a finite number came up (never expected; reported, not hidden)
    unsettled,    // the only periodic state found is unstable (a Floquet multiplier beyond 1): the motion
                  // does not settle, so there is no steady r_x, r_y to give
    not_periodic, // the motion from the start settles into no periodic state with k <= kMaxPeriodK: r_x,
                  // r_y are long-time means over a window, with their standard error (not a steady state)
};
// "ok" for converged, "period_k" for periodic, else the reason as one word: "not_converged",
// "integration_failed", "non_finite", "unsettled", "not_periodic". status_word(result) names k.
const char* to_string(SteadyStatus s);
inline bool ok(SteadyStatus s) {
    return s == SteadyStatus::converged || s == SteadyStatus::periodic;
}

// Where the motion starts: the history that decides which steady state is reached where two coexist
// (docs/model.md, "Which steady state").
enum class Start {
    rest,    // the paper's start (Eqs. (17)-(27)): the asperity unstretched, T = P, when sliding and
             // vibration begin together
    sliding, // vibration switched on during steady sliding: the asperity fully deflected against v_b,
             // P - T = z_ss e_x (the force F_c along v_b)
};
const char* to_string(Start s); // "rest", "sliding"
bool parse_start(const std::string& text, Start& out);
inline constexpr const char* kStartNames = "rest, sliding";

// The longest period (in periods of the vibration) searched for where the 1-period state is unstable
// through a multiplier below -1: k = 2, 4, ..., kMaxPeriodK.
inline constexpr int kMaxPeriodK = 16;
// A Floquet multiplier with |mu| >= kSlowMultiplier is a slow direction: a disturbance along it shrinks by
// less than 1 % a period (halves in more than 69 periods), so where the motion ends depends on its history.
inline constexpr double kSlowMultiplier = 0.99;

// The error estimate's safety factor: |r - r(dtau -> 0)| <= kErrorSafety * error_estimate held at every
// point of the reference sets (tests/test_steady_reference.cpp: brute-force RK4 integrations of the issue's
// hard points and 60 random points, both starts). The estimate itself is the measured difference of two runs
// (docs/model.md, "Error estimate"); where it is optimistic it was so by at most 3.5x.
inline constexpr double kErrorSafety = 4;

// One stable periodic state of the period map (Scheme::ode).
struct SteadyState {
    double rx = 0, ry = 0;               // period means over its k periods
    int period = 1;                      // k: the motion repeats every k periods of the vibration
    std::complex<double> multipliers[2]; // Floquet multipliers of the k-period map, |mu| descending
    double error_estimate = 0;           // of rx, ry
    Vec2 lag{0, 0};                      // P(0) - T(0) at the start of a period of this state
    bool on_circle = false; // the period starts on the circle z = z_ss (the tip slips at full deflection)
    bool from_rest = false, from_sliding = false; // which start's motion reaches it
    // Largest |mu|; where it is 1 for a state on the circle with i > 1 the approach from inside is algebraic.
    double largest_multiplier() const { return std::abs(multipliers[0]); }
    bool slow() const { return largest_multiplier() >= kSlowMultiplier; }
};

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
    Vec2 initial_lag = Vec2::Zero(); // P(0) - T(0) (the paper's scheme from rest; the ode scheme: a
                                     // first guess for the search, the start decides the state)
    bool record_period = false;      // keep the samples of the last steady period (trace)
    Start start = Start::rest;       // the history: which coexisting steady state is reported
    bool list_states = false;        // ode: also search from the other start and list every state found
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
    // Periods of a slow creep towards the circle (i > 1) projected over on the way from the start, not
    // integrated: about as many as the motion takes to get where the search went on (docs/model.md, "Slow
    // creeps").
    double creep_periods_skipped = 0;
    bool on_circle = false;
    std::string detail;
    Vec2 lag{0, 0}; // Scheme::ode: L = P(0) - T(0) of the steady period found (a warm start for neighbours)
    // Which steady state this is (Scheme::ode): the start it was reached from, its period k, the Floquet
    // multipliers of its k-period map, and every stable state found (this one included, ordered by r_x);
    // not_periodic: the standard error of the long-time means over `window` periods.
    Start start = Start::rest;
    bool start_reaches = false; // evidence that the motion from `start` reaches this state (ode scheme)
    int period_k = 1;
    std::complex<double> multipliers[2];
    bool have_multipliers = false;
    std::vector<SteadyState> states;
    double mean_standard_error = 0;
    int window = 0;
    double largest_multiplier() const { return std::abs(multipliers[0]); }
    bool slow() const { return have_multipliers && largest_multiplier() >= kSlowMultiplier; }
    std::vector<Sample> period; // last steady period at n0 = default_steps_per_period (or the N asked for),
                                // samples k = 1..n of Eq. (30)
};

// to_string(status), with k for period_k (e.g. "period_2").
std::string status_word(const SteadyResult& r);

// The status every output reports (command line, Python): r.status, except non_finite for a result the
// solver vouches for whose r_x or r_y is not a finite number (never expected; reported, not hidden).
SteadyStatus reported_status(const SteadyResult& r);
// status_word of the reported status: "ok"-class words with k for period_k, or the failure's word.
std::string reported_word(const SteadyResult& r);

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
