// One setup running in the app: its simulation, the worker that computes its r_x(zeta) curves and its top
// view's frame, eased from one parameter set's to the next. AppState holds two, A always and B in compare
// mode, and drives both through these methods on one time base (the same tau per frame, reset together), so
// that B is a second instance of A's machinery rather than a copy of its code.
#pragma once

#include "ratio_worker.hpp"

#include "fv/live_sim.hpp"
#include "fv/setup.hpp"
#include "fv/top_view_frame.hpp"

#include <string>

namespace fv::app {

class SetupRun {
  public:
    explicit SetupRun(const Setup& s) : sim_(s.model, s.params) {}

    const LiveSim& sim() const { return sim_; }
    RatioWorker& worker() { return worker_; }
    const RatioWorker& worker() const { return worker_; }

    // New parameters at the current instant (the picture stays continuous, LiveSim::apply).
    void apply(const Setup& s) { sim_.apply(s.model, s.params); }
    // Back to tau = 0 from the setup's start.
    void reset(Start start) {
        sim_.reset(start);
        carry_ = 0;
    }
    void set_history_periods(double periods) { sim_.set_history_periods(periods); }

    // The frame for the setup, trail and area in effect: eased to from the frame shown now, or (`snap`) shown
    // at once. Nothing happens when it is the frame already aimed at.
    void retarget_frame(const Setup& s, double trail_periods, double aspect, bool snap);
    // The frame shown now (relative to the vibration centre).
    FrameBox frame() const { return eased_frame(from_, to_, ease_); }

    // dt seconds of wall time: the frame's easing.
    void ease(double dt_seconds);
    // Simulation time: `periods` vibration periods more of it, in whole steps (the remainder carried to the
    // next call).
    void run(double periods);
    // One displayed frame forward: `tau` in at least one step.
    void step_frame(double tau);
    // Onto the periodic steady state the setup's start reaches (the solver's fixed point), one period of it
    // animated; "" or why there is none to jump to.
    std::string jump_to_steady(const Setup& s);

  private:
    LiveSim sim_;
    RatioWorker worker_;
    double carry_ = 0; // steps owed to the simulation (a fraction of one)
    FrameBox from_, to_;
    double ease_ = 1; // of the way from from_ to to_ (0..1, in kFrameEaseSeconds)
};

} // namespace fv::app
