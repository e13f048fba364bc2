// Continuous-time steady state of the lumped asperity: the paper's tracking scheme (Eqs. (17)-(27)) in the
// limit dtau -> 0 is a law for the lag L = P - T (docs/model.md). The solver works on the law's phases:
//   stick (i = 0) in closed form, its end a scalar root found rigorously, whole stuck periods skipped;
//   slip on the circle |L| = z_ss (any i) as a scalar equation for the angle of L;
//   relaxation inside the circle (i > 0) in the plane;
// the last two with the L-stable Radau IIA method (order 5), so the cost does not grow with the stiffness
// rdisp. The periodic steady state is the fixed point of the period map L(0) -> L(2 pi), found by Newton's
// method with the map's derivative from the discrete variational equations, on the circle's angle alone
// when the steady period starts there (for i > 1 the only place the state ever gets to). The friction
// ratios r_x, r_y are the period means of F (Eq. (33) with dtau -> 0).
// Pieces: core/src/solver/radau_iia.hpp (integrator), lag_phases.* (the model's phases and events),
// period_map.* (one period through the phases), steady_search.cpp (this header's functions).
#pragma once

#include "fv/paper_scheme.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"
#include "fv/vec2.hpp"

#include <vector>

namespace fv {

// The ode scheme's default tolerance: an answer verified at it is also given at any looser tolerance.
inline constexpr double kDefaultOdeTolerance = 1e-8;

struct OdeOptions {
    // Target for |r - r(dtau -> 0)| in force units; the result's status is `converged` only when its error
    // estimate (steady-state distance + integration error, estimated separately) is within this.
    double tolerance = kDefaultOdeTolerance;
    int max_periods = 400; // cap on Newton's periods from one start (plain periods of the motion, and
                           // stuck periods skipped analytically, are counted apart)
    Vec2 initial_lag = Vec2::Zero(); // P(0) - T(0): a first guess for Newton's method (warm start; zero:
                                     // none); |lag| > z_ss is pulled back. The start decides the state.
    bool record_period = false;      // fill SteadyResult::period with samples of the steady period
    int record_samples = 1024;       // samples at tau = 2 pi k / n, k = 1..n (like Eq. (30))
    Start start = Start::rest;       // the history whose steady state is reported
    bool list_states = false;        // search from the other start too and list every stable state found
    bool list_states_after_failure = true; // also where this start's search failed (the map, which marks such
                                           // a cell as failed anyway, saves the second search there)
    bool list_only_reached = false; // list only states a start reaches: the other start is not searched where
                                    // its motion is shown to settle into a state found (the map's marks)
};

// Instants where the lag's law changes.
enum class OdeEventKind {
    velocity_sign, // v = e . dP/dtau changes sign while z < z_ss (i > 0): sgn(v) in Eq. (16) switches
    reach_zss,     // z reaches z_ss with v > 0: the tip slips at full deflection (i = 0: stick ends)
    leave_zss,     // v turns negative at z = z_ss: the deflection starts to shrink (i = 0: stick begins)
};
const char* to_string(OdeEventKind k);

struct OdeEvent {
    double tau = 0; // within [0, 2 pi] of the period
    OdeEventKind kind = OdeEventKind::velocity_sign;
    Vec2 lag{0, 0}; // P - T at the event
};

// The right-hand side dL/dtau of the lag law at (tau, L): inside the disc (`on_circle` false; i = 0: stick)
// or on z = z_ss with v >= 0 (`on_circle` true: pursuit). Exposed for tests of the derivation.
Vec2 ode_lag_rate(const Params& p, double tau, Vec2 lag, bool on_circle);

struct OdeSolution {
    SteadyResult result;          // rx, ry, status, periods, error_estimate, steady_error, period samples
    Vec2 lag{0, 0};               // L* = P(0) - T(0) of the periodic steady state (warm start for neighbours)
    std::vector<OdeEvent> events; // events of the steady period (only when record_period is set)
    int newton_steps = 0;         // Newton updates (on the circle's angle or in the plane)
    int plain_steps = 0;          // plain updates L <- Phi(L) (leaving the circle, singular derivative)
    long periods_skipped = 0;     // whole stuck periods (i = 0) skipped in closed form
    int events_per_period = 0;    // law changes in the steady period
    bool on_circle = false;       // the steady period starts on the circle z = z_ss (angle-only search)
    double integration_error = 0; // estimated |r error| from integrating one period (force units)
    const char* failure = "";     // what went wrong when the status is not converged
};

// The periodic steady state. Throws std::invalid_argument for inadmissible parameters (fv::validate).
// SteadyResult fields: rx, ry from the last period integrated (it starts at OdeSolution::lag);
// periods = total_periods = periods integrated (Newton's and the error estimate's, not the skipped ones);
// steps_per_period = accepted steps of the last period; levels = 1; steady_error = estimated effect on r of
// the distance to L*; error_estimate = steady_error + integration error (+ the 1e-12 pinning allowance).
// rdisp < 1e-9 (a period's motion lost in the rounding of the force): the small-amplitude limit corrected
// to first order from two verified solves at rdisp = 1e-9 and 1e-8 (docs/model.md, "r_disp below 1e-9");
// steady_error is then the anchors' disagreement with that linear model, and `lag` may be infinite.
// zeta = 0 with i = 0 and rdisp <= 1: the steady state is not unique (the tip never slips); the result is the
// limit zeta -> 0+ in closed form (docs/model.md).
OdeSolution ode_solve(const Params& p, const OdeOptions& opt = {});
SteadyResult ode_steady(const Params& p, const OdeOptions& opt = {});

// The ODE options that carry out SteadyOptions (tolerance, warm start, recording).
OdeOptions ode_options(const SteadyOptions& opt);

// Sweep over zeta for every theta x rdisp x i (zeta fastest, like fv::sweep), all points in parallel, each
// from its own cold start: every row equals ode_steady at its parameters, whatever the grid.
std::vector<SweepPoint> ode_sweep_zeta(const std::vector<double>& zetas, const std::vector<double>& thetas,
                                       const std::vector<double>& rdisps, const std::vector<double>& is,
                                       const OdeOptions& opt = {}, int threads = 0);

// One cell of a (zeta, theta) map whose theta rows are solved along zeta (core/src/solver/map_grid.cpp):
// `prev1`, `prev2` are the results of the one and two cells before it in its row (null at the row's start).
// The cell starts from the straight line through their periodic states where the cold start was slow for
// `prev1`; else, or when that start fails, it is ode_steady at p. Every cell is verified on its own to the
// tolerance, so it agrees with ode_steady at its parameters within the tolerance (not to the bit).
SteadyResult ode_map_cell(const Params& p, const SteadyResult* prev1, const SteadyResult* prev2,
                          const OdeOptions& opt = {});

} // namespace fv
