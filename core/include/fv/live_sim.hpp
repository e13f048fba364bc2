// The animated simulation behind the app: the paper's scheme stepped at a fixed dtau, with parameter edits
// applied at one point (between steps) and short histories for trails and the live force plot.
// No drawing, no clock: the caller says how many steps to take.
#pragma once

#include "fv/paper_scheme.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp" // Start

#include <cstdint>
#include <deque>

namespace fv {

struct LiveSample {
    double tau = 0;
    Vec2 P{0, 0}, T{0, 0}; // display coordinates (continuous across parameter changes)
    Vec2 F{0, 0};          // F / F_c
    bool slip = false;     // the tip slips (LiveSim::slipping) at this instant
    // F_x summed over the history's samples up to this one (from its last restart): the mean of F_x over the
    // n samples before an instant is a difference of two, (fx_sum[k] - fx_sum[k - n]) / n.
    double fx_sum = 0;
};

class LiveSim {
  public:
    LiveSim(Model model, const Params& p);

    // Applies new parameters at the current instant. The lag P - T is kept (shortened to the new z_ss if
    // needed) and P's drawn position stays continuous, so a slider move never makes the picture jump.
    void apply(Model model, const Params& p);
    // Back to tau = 0 with empty histories, from `start` (docs/model.md, "Which steady state"): rest puts
    // T(0) = P(0) (the asperity unstretched, the paper's start); sliding puts P(0) - T(0) = z_ss e_x (the
    // asperity fully deflected against v_b, the force F_c along it: the vibration switched on during steady
    // sliding). The rigid model has no lag: both starts are the same.
    void reset(Start start = Start::rest);
    // Onto the periodic steady state: at the next period start (tau a multiple of 2 pi) with the lag
    // P - T = lag_at_period_start (the solver's L*), P's drawn position kept; the histories restart there.
    void start_steady(Vec2 lag_at_period_start);

    void step(int count = 1);

    Model model() const { return model_; }
    const Params& params() const { return p_; }
    int steps_per_period() const { return n_; }
    double dtau() const { return 2 * kPi / n_; }
    double tau() const { return tau_; }
    std::int64_t periods() const { return period_; } // completed periods since reset
    Vec2 P() const;
    Vec2 T() const { return P() - lag_; }
    // Where P would be without the vibration (display coordinates): P moves on the line through it at
    // theta, +-x_v (Eqs. (28)-(29): P = (zeta tau, 0) + sin(tau) (cos theta, sin theta)).
    Vec2 vibration_centre() const;
    Vec2 velocity() const; // dP/dtau, Eq. (1)
    Vec2 force() const;    // F/F_c: (P - T)/z_ss (Dahl), or minus the unit velocity reversed (rigid, Eq. (2))
    double z() const { return lag_.norm(); }
    // The tip slips when the deflection sits at z_ss (Eq. (27)); for i > 0 the Dahl law has no true stick,
    // so "slipping" means within 0.5 % of z_ss.
    bool slipping() const;

    // Mean of F over the last completed period (Eq. (30)); NaN before the first period ends.
    Vec2 last_period_mean() const { return last_mean_; }

    // Bounded histories (oldest first): trail of P and T, force samples. Older samples drop off.
    const std::deque<LiveSample>& history() const { return history_; }
    void set_history_periods(double periods) { history_periods_ = periods; }

    // Steps per period for the animation: fine enough that P moves at most z_ss/8 per step, at least 360.
    static int animation_steps(const Params& p);

  private:
    void record();

    Model model_;
    Params p_;
    int n_ = 360;
    double tau_ = 0; // absolute dimensionless time
    int k_ = 0;      // step within the current period
    std::int64_t period_ = 0;
    double phase_ = 0; // tau of the current period's start, to evaluate P from the phase alone
    Vec2 lag_{0, 0};
    Vec2 offset_{0, 0}; // added to P(tau) so that parameter changes do not move P on screen
    Vec2 sum_{0, 0};
    Vec2 last_mean_;
    double history_periods_ = 2;
    std::deque<LiveSample> history_;
};

} // namespace fv
