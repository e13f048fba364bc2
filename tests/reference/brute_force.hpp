// Brute-force time integration of the steady state of the lumped Dahl asperity, for ANY parameters
// (zeta, theta, rdisp, i). Independent reference for the solver tests: it uses only the C++ standard library,
// no fv:: code and no other reference. It does not solve for a periodic orbit; it starts from a given force
// and integrates period after period until the section state repeats (or gives up and averages).
//
// ---------------------------------------------------------------------------------------------------------
// Model (dimensionless as in docs/model.md, "Parameters" and "The lag law"). P(tau) = (zeta tau +
// sin tau cos theta, sin tau sin theta), P' = (zeta + cos tau cos theta, cos tau sin theta). The state is the
// force l = F/F_c = rdisp L, L = P - T; rho = |l| <= 1, e = l/rho, v = e . P', s = sgn v. The dtau -> 0 limit
// of the scheme, dL/dtau = P' - (v - dz/dtau) e with dz/dtau = v (1 - s rho)^i (Eq. (16)), in force units
// (r := rdisp):
//     i > 0, rho < 1:            l' = r (P' - v g e),   g = 1 - (1 - s rho)^i      ("interior")
//     i = 0, rho < 1:            l' = r P'                                         ("stick")
//     rho = 1, v >= 0, every i:  l' = r (P' - v e)   (|l| stays 1, only e turns)   ("circle")
//     rho = 1, v <  0:           the interior law with s = -1 (stick for i = 0); the tip leaves the circle.
// The interior law written with q = g/rho (q -> s i as rho -> 0) is l' = r (P' - v q l): continuous at l = 0
// (the correction is O(rho)), so the start from rest (l = 0) needs no special case. Taking the radial part,
// rho' = r v (1 - s rho)^i (Eq. (16)); across e, e' = r (P' - v e)/rho.
// Friction ratios: r_x + i r_y = the mean of l over a steady period (2 pi; k 2 pi for a period-k orbit).
//
// Where the law is not smooth, and how each place is treated (so that the fourth order of RK4 is kept):
//  * v = 0 inside (i > 0): s flips, the right-hand side has a kink. Located as an event (the sign of l . P'),
//    the step is cut there and continued with the other s. (In 1-D, theta = 0 or 180, l . P' also changes
//    sign when l passes 0; there the two laws are one smooth law, and the cut is harmless.)
//  * i = 0, stick -> circle when rho reaches 1 (event, the state is projected to rho = 1, a <= 1e-14 move);
//    circle -> stick/interior when v turns negative (event). For i > 0 the same "leave" event.
//  * 0 < i < 1, loading (s = +1): the approach to the circle is finite-time and not Lipschitz,
//    w' = -r v w^i for w = 1 - rho. With u = w^(1-i) it is smooth, u' = -(1 - i) r v, and reaches u = 0 at a
//    regular crossing. So for s = +1 and rho >= 1/2 the state is carried as (u, phi), e = (cos phi, sin phi)
//    ("radial" representation; rho >= 1/2 keeps phi' = r e_perp . P'/rho regular), u = 0 is an event that
//    puts the tip on the circle. Nothing is ever pinned to the circle from inside.
//  * i >= 1, loading: the law is Lipschitz at rho = 1; the state approaches the circle exponentially (i = 1)
//    or algebraically (i > 1) and is left to do so (rounding past rho = 1 is projected back, 1e-16).
//    Consequence for i > 1 (seen at i = 10): where the loading lasts the whole period (v > 0 throughout,
//    the direction turning faster inside than on the circle), the deficit w = 1 - rho creeps down like
//    n^(-1/(i-1)) in the number of periods n (section differences like n^(-i/(i-1)), contraction ratio
//    ~ 1 - (i/(i-1))/n) until the orbit comes close enough to the circle that v dips below 0 somewhere; the
//    brief unloadings (2^i times faster than loading) then hold w and the run settles geometrically. That
//    takes thousands to tens of thousands of periods (zeta = 0.285, theta = 90, rdisp = 2: ~14100;
//    0.27, 30, 10: ~31900), or more than can be run when the circle orbit itself only just dips below v = 0
//    (0.18, 124, 10: v_min = -2e-5 on the circle, the threshold is near w ~ 1e-4, and w ~ n^(-1/9)):
//    such runs end "unsettled".
//  * A dip of v (or of any event function) below 0 that begins and ends inside one step would be missed by
//    a sign test at the step ends (it was, at the coarse resolution, for the brief unloadings just
//    described, and produced a spurious period-2 orbit). So the event functions' rates along the flow are
//    tracked too: where a rate changes from < 0 to > 0 inside a step, the minimum is located and, if it is
//    below 0, the first crossing before it is the event.
//  * The circle itself is carried as the angle phi: phi' = r (-P'_x sin phi + P'_y cos phi).
//
// Numerics. Classical RK4 (the mean integral M' = l is integrated as extra components and summed with
// Kahan's compensation). The period is cut into a fixed grid of N steps, N a power of two with
// N >= 2048 and rdisp (1 + zeta) (2 pi / N) <= sigma (sigma = 0.1 at the coarse resolution). A grid step is
// split into sub-steps no longer than sigma/lambda, lambda a bound of the local stiffness taken at the
// sub-step's start: r (|P'| + h) (1 + max(|q|, |dg/drho|)) inside (for i = 10 unloading from rho ~ 1,
// dg/drho = 10 2^9: the Dahl loop's steep reversal), r (|P'| + h) (1 + 1/rho) in the radial representation,
// r (|P'| + h) on the circle, 0 in stick. Events are located by the Illinois method on the length of the RK4
// sub-step to 1e-15 in tau, and the step is taken to the far end of the final bracket (past the switch), so
// the new law starts on its own side. Time is the phase t in [0, 2 pi) of the current period, so every period
// repeats the same floating-point operations: the period map is a fixed function (no drift of tau's rounding)
// and its fixed point can be detected to ~1e-14.
// Error estimate: the whole run is repeated with N -> 2N and sigma -> sigma/2 (every step halved) and the
// difference of the two results is reported, plus the tail estimate below (fourth order: the error of the
// finer result is usually ~1/16 of the difference; the approach to the order is slower where i = 10 orbits
// have brief stiff unloadings, e.g. 0.27, 30, 10, 10: differences 5.9e-10, 3.7e-11 for N = 2048/4096/8192).
//
// Periodicity. At every section t = 0 (tau = 2 pi n) the state l_n is compared with l_{n-k}, k = 1..16:
// d_k(n) = |l_n - l_{n-k}|. The run is period_k at the first n where, for the smallest such k, d_k(n) < tol
// and the geometric tail max(d_k(n), |change of the k-period mean|) c/(1 - c) < tol, c the contraction per
// k periods measured over baselines k, 2k, 4k, ... (the slowest of those over which d changed by >= 5%,
// so that a slow contraction is not hidden by rounding noise in d); then k is reduced to the least divisor
// along which the state also repeats to 10 tol. The result is the mean over the last k periods.
// At max_periods without that: "unsettled" if some d_k stayed < 1e-4 over the last quarter of the run and is
// below its value at every baseline (a slow, monotone approach: the creep above, the algebraic approach of
// i > 1 to a circle state, or a circle state contracting at a rate ~ rdisp zeta): mean of the last k periods,
// error = the larger of the geometric tail and the sum of a power law d ~ n^-p fitted over the last half
// (+inf if p <= 1 and no contraction is measurable); otherwise
// "not_periodic": the mean over the last half of the periods with its standard error by 20 batch means.
// "capped": the step budget ran out first; reported like not_periodic over what was run.
// ---------------------------------------------------------------------------------------------------------
#pragma once

#include <string>

namespace fv::ref {

enum class BruteStart {
    rest,   // l0 = (0, 0): T = P at tau = 0
    sliding // l0 = (1, 0): fully deflected along the sliding direction
};

struct BruteForceOptions {
    int max_periods = 20000;
    int steps_per_period = 0; // N at the coarse resolution (rounded up to a power of two); 0: automatic
    double sigma = 0.1;       // max lambda * step at the coarse resolution
    double tol = 1e-11;       // on |l_n - l_{n-k}| and on the tail estimate
    double max_steps = 0;     // RK4 steps per run (both resolutions count separately); 0: no limit
    bool refine = true;       // run at N and 2N (false: N only, no error estimate)
};

// One run at one resolution.
struct BruteForceRun {
    std::string status;        // "period_<k>", "unsettled", "not_periodic", "capped"
    int k = 0;                 // period (in periods of 2 pi) for period_k and unsettled; 0 otherwise
    int periods = 0;           // periods integrated (for period_k: periods to settle)
    double rx = 0, ry = 0;     // mean over the last k periods, or the long-time mean (see above)
    double se_x = 0, se_y = 0; // batch-means standard errors (not_periodic, capped), else 0
    double tail = 0;           // estimated distance of the last section state from the limit cycle
    double contraction = 0;    // per-period contraction factor near the end (0: not measurable, e.g. exact)
    double last_diff = 0;      // d_k at the end (k as reported, or k = 1 for not_periodic)
    double lx = 0, ly = 0;     // state at the last section
    int steps_per_period = 0;  // grid N of this run
    double steps = 0;          // RK4 steps taken, sub-steps and event location included
    long long events = 0;      // law switches
};

// Both resolutions and the combined result (the finer run's values).
struct BruteForceResult {
    BruteForceRun coarse, fine; // fine == coarse when options.refine is false
    std::string status;
    int k = 0;
    int periods = 0;
    double rx = 0, ry = 0;
    double rx_err = 0, ry_err = 0; // |fine - coarse| + tail (period_k, unsettled); the standard error for
                                   // not_periodic/capped (the coarse-fine difference is then in note)
    double lx = 0, ly = 0;
    std::string note; // disagreements between the resolutions, etc.
};

// One run from l0 (|l0| <= 1) with N steps per period and stiffness budget sigma. theta in DEGREES.
// Throws std::invalid_argument for parameters outside zeta >= 0, 0 <= theta <= 180, rdisp > 0, 0 <= i <= 50.
BruteForceRun brute_force_run(double zeta, double theta_deg, double rdisp, double i, double l0x, double l0y,
                              int steps_per_period, double sigma, const BruteForceOptions& options);

// The coarse N used by brute_force for these parameters.
int brute_force_steps(double zeta, double rdisp, const BruteForceOptions& options);

// Runs at N and 2N (sigma and sigma/2) from the named start and combines them.
BruteForceResult brute_force(double zeta, double theta_deg, double rdisp, double i, BruteStart start,
                             const BruteForceOptions& options = {});

} // namespace fv::ref
