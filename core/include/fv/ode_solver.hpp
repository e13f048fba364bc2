// Continuous-time steady state of the lumped asperity: the paper's tracking scheme (Eqs. (17)-(27)) in the
// limit dtau -> 0 is an ODE for the lag L = P - T (derivation in ode_solver.cpp). One period of it is
// integrated with an adaptive Dormand-Prince 5(4) method that stops at every instant where the right-hand
// side is not smooth (events) and restarts there. The periodic steady state is the fixed point of the
// period map L(0) -> L(2 pi), found by Newton's method (finite-difference Jacobian, natural monotonicity
// test) where plain periods contract slowly, by plain iteration L <- Phi(L) where they contract fast or the
// tip still sticks (i = 0), and directly on the circle z = z_ss when the steady period never leaves it
// (pure pursuit; for i > 1 the paper's scheme only creeps there algebraically). The friction ratios r_x,
// r_y are the period means of F (Eq. (33) with dtau -> 0), integrated as extra ODE components.
// Assumes, like the rest of the project, that the periodic steady state is unique (zeta > 0).
#pragma once

#include "fv/paper_scheme.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"
#include "fv/vec2.hpp"

#include <vector>

namespace fv {

struct OdeOptions {
    // Target for |r - r(dtau -> 0)| in force units. The integrator's local tolerance is 0.1x this; the
    // fixed-point iteration stops when the estimated distance to L* is below it (or at the integration's
    // noise floor, then with the achieved figure in error_estimate). Measured: 1e-8 gives |error| ~1e-9.
    double tolerance = 1e-8;
    int max_periods = 4000;          // cap on integrated periods (all of them: Newton's probes included)
    Vec2 initial_lag = Vec2::Zero(); // P(0) - T(0) to start from (warm start); |lag| > z_ss is pulled back
    bool record_period = false;      // fill SteadyResult::period with samples of the steady period
    int record_samples = 1024;       // samples at tau = 2 pi k / n, k = 1..n (like Eq. (30))
};

// Instants where the right-hand side of the lag ODE is not smooth.
enum class OdeEventKind {
    velocity_sign, // v = e . dP/dtau changes sign while z < z_ss (i > 0): sgn(v) in Eq. (16) switches
    reach_zss, // z reaches z_ss with v > 0: the tip starts slipping at full deflection (i = 0: stick ends)
    leave_zss, // v turns negative at z = z_ss: the deflection starts to shrink (i = 0: stick begins)
};
const char* to_string(OdeEventKind k);

struct OdeEvent {
    double tau = 0; // within [0, 2 pi] of the period
    OdeEventKind kind = OdeEventKind::velocity_sign;
    Vec2 lag{0, 0}; // P - T at the event
};

// One period of the lag ODE from lag0 at tau = 0 (the ODE is 2 pi-periodic in tau).
struct OdePeriod {
    Vec2 lag_end{0, 0};      // P - T at tau = 2 pi: the period map Phi(lag0)
    Vec2 mean_force{0, 0};   // (1/2 pi) int_0^{2 pi} F dtau: r_x, r_y of this period
    int steps = 0;           // accepted steps
    int rejected = 0;        // rejected steps
    bool saturated = false;  // z = z_ss for a while (i = 0: the tip slipped in this period)
    bool v_negative = false; // the deflection shrank at some time (v < 0)
};

// Integrates one period. `tolerance` as in OdeOptions. Events and samples (tau = 2 pi k/n, k = 1..n, P in
// absolute coordinates of the first period) are appended when the pointers are given.
OdePeriod ode_period(const Params& p, Vec2 lag0, double tolerance, std::vector<OdeEvent>* events = nullptr,
                     std::vector<Sample>* samples = nullptr, int n_samples = 1024);

// The right-hand side dL/dtau of the lag ODE at (tau, L), for z < z_ss or v < 0 (`saturated` = false) or
// on z = z_ss with v >= 0 (`saturated` = true). Exposed for tests.
Vec2 ode_lag_rate(const Params& p, double tau, Vec2 lag, bool saturated);

struct OdeSolution {
    SteadyResult result;          // rx, ry, status, periods, error_estimate, steady_error, period samples
    Vec2 lag{0, 0};               // L* = P(0) - T(0) of the periodic steady state (warm start for neighbours)
    std::vector<OdeEvent> events; // events of the steady period (only when record_period is set)
    int newton_steps = 0;         // accepted Newton (or secant) updates
    int plain_steps = 0;          // plain updates L <- Phi(L)
    double integration_error = 0; // estimated |r error| from integrating one period (force units)
};

// The periodic steady state. Throws std::invalid_argument for inadmissible parameters (fv::validate).
// SteadyResult fields: rx, ry from the last period integrated (it starts at OdeSolution::lag);
// periods = total_periods = periods integrated by the fixed-point search, Newton's probes included (not
// the re-run at 10x looser tolerance that estimates the integration error, nor the recording run);
// steps_per_period = accepted steps of the last period; levels = 1; steady_error = rdisp x estimated
// |lag - L*|; error_estimate = steady_error + integration error; period = record_samples samples of the
// steady period when record_period is set.
OdeSolution ode_solve(const Params& p, const OdeOptions& opt = {});
SteadyResult ode_steady(const Params& p, const OdeOptions& opt = {});

// The ODE options that carry out SteadyOptions (tolerance, warm start, recording).
OdeOptions ode_options(const SteadyOptions& opt);

// Sweep over zeta for every theta x rdisp x i (zeta fastest, like fv::sweep): each family (theta, rdisp, i)
// runs on one thread, its zeta values in the given order, each warm-started from its neighbour's L*.
std::vector<SweepPoint> ode_sweep_zeta(const std::vector<double>& zetas, const std::vector<double>& thetas,
                                       const std::vector<double>& rdisps, const std::vector<double>& is,
                                       const OdeOptions& opt = {}, int threads = 0);

} // namespace fv
