#include "setup_run.hpp"

#include "fv/ode_solver.hpp"

#include <algorithm>
#include <cmath>

namespace fv::app {

void SetupRun::retarget_frame(const Setup& s, double trail_periods, double aspect, bool snap) {
    const FrameBox to = steady_frame(s.model, s.params, trail_periods, aspect);
    if (snap) {
        from_ = to_ = to, ease_ = 1;
        return;
    }
    if (to == to_) return;
    from_ = frame(); // from where it is now: no jump
    to_ = to;
    ease_ = 0;
}

void SetupRun::ease(double dt) {
    if (ease_ < 1) ease_ = std::min(1.0, ease_ + dt / kFrameEaseSeconds);
}

void SetupRun::run(double periods) {
    carry_ += periods * sim_.steps_per_period();
    const int n = static_cast<int>(carry_);
    carry_ -= n;
    sim_.step(n);
}

void SetupRun::step_frame(double tau) {
    sim_.step(std::max(1, static_cast<int>(std::lround(tau / sim_.dtau()))));
}

std::string SetupRun::jump_to_steady(const Setup& s) {
    if (s.model == Model::rigid)
        return "the rigid model has no transient: its friction follows the velocity at once";
    OdeOptions opt;
    opt.start = s.start; // the state the chosen start reaches, where two coexist
    const OdeSolution sol = ode_solve(s.params, opt);
    if (!ok(sol.result.status) || !std::isfinite(sol.lag.x()) || !std::isfinite(sol.lag.y()))
        return std::string("no verified steady state to jump to here (") + to_string(sol.result.status) + ")";
    // The solver's L* at a period start, then one period animated at once so that the trails, the force
    // plot and the period mean show the steady motion.
    sim_.start_steady(sol.lag);
    sim_.step(sim_.steps_per_period());
    return "";
}

} // namespace fv::app
