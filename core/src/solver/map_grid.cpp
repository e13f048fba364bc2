// One cell of a (zeta, theta) map solved row by row along zeta (see ode_solver.hpp, docs/model.md).
#include "fv/ode_solver.hpp"

namespace fv {

namespace {

bool usable(const SteadyResult* r) {
    return r && ok(r->status) && r->lag.allFinite();
}

} // namespace

SteadyResult ode_map_cell(const Params& p, const SteadyResult* prev1, const SteadyResult* prev2,
                          const OdeOptions& opt) {
    OdeOptions cold = opt;
    cold.record_period = false;
    cold.initial_lag = Vec2::Zero();
    // Where to start: the cell's own cold start (ode_solve's) unless that was slow for the previous cell
    // (more than the minimum of two periods: one search period and the verification); then the straight
    // line through the periodic states of the last two cells. Not where the previous cell converged on the
    // circle and rdisp > 2: there the cold start on the circle along P'(0) is within O(1/rdisp^2) of the
    // fixed point (the tip tracks P', and P'' = 0 at tau = 0) and beats the extrapolation (measured on the
    // map, i = 1: at rdisp = 100 the extrapolation took 2.37 periods per cell against 2.08 cold; at
    // rdisp = 0.1, 1, 2 it saves 45%, 20%, 12% of the time).
    const bool warm = usable(prev1) && prev1->periods > 2 && (!prev1->on_circle || p.rdisp <= 2);
    if (warm) {
        OdeOptions o = cold;
        o.initial_lag = usable(prev2) ? Vec2(2 * prev1->lag - prev2->lag) : prev1->lag;
        SteadyResult r = ode_solve(p, o).result;
        if (ok(r.status)) return r;
        // A warm-started cell that fails is solved cold: a cell fails only where its single point does.
    }
    return ode_solve(p, cold).result;
}

} // namespace fv
