// The r_x(zeta) curves and the steady-state readouts of one parameter set, as the app's ratio panel shows
// them: the steady state at the parameters (every stable state listed), the model's and the rigid curve over
// zeta, and (on request) the (zeta, theta) map. The work is a RatioJob of small steps, so that a caller can
// spread it over time (the app's worker thread, or the browser's frames: gui/ratio_worker.hpp) or run it at
// once (compute_ratio_curves: the animation export).
#pragma once

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace fv {

struct RatioRequest {
    Model model = Model::dahl;
    Params params;
    bool map = false;    // also the (zeta, theta) map for params.rdisp, params.i (Dahl only; ~1-3 s)
    double zeta_max = 3; // the curves reach this far (further when measured points do)
    // The history: which of coexisting steady states the current point, the curve and the map report.
    Start start = Start::rest;
    bool operator==(const RatioRequest& o) const {
        return model == o.model && params.zeta == o.params.zeta && params.theta == o.params.theta &&
               params.rdisp == o.params.rdisp && params.i == o.params.i && map == o.map &&
               zeta_max == o.zeta_max && start == o.start;
    }
};

// The options the current point is computed with: the request's start, and every stable state listed
// (SteadyResult::states; the Dahl model).
SteadyOptions current_point_options(const RatioRequest& req);

// The status a result is shown with: the solver's, or non_finite when it vouches for an r_x or r_y that is
// not a finite number (as the command line reports it). Only SteadyStatus::converged is a verified value.
inline SteadyStatus shown_status(const SteadyResult& r) {
    if (!ok(r.status)) return r.status;
    return std::isfinite(r.rx) && std::isfinite(r.ry) ? SteadyStatus::converged : SteadyStatus::non_finite;
}

struct RatioCurves {
    RatioRequest request;
    std::vector<double> zetas, model_rx, rigid_rx; // model_rx empty for the rigid model; NaN where the
                                                   // point failed (a gap in the drawn curve)
    int model_failed = 0;                          // points of model_rx that failed (shown_status not ok)
    SteadyResult current;         // the steady state at request.params from request.start, with every stable
                                  // state found there in current.states (both starts searched)
    std::optional<PanelData> map; // the map panel when asked for
};

// One request's work in small steps, on whichever thread calls step(): the steady state at the parameters
// and the rigid curve; each point of the model's r_x(zeta) curve (the same steady_ratio calls as sweep());
// then, with the map, each of its cells and the panel (map_points, map_panel_of: as compute_figure).
class RatioJob {
  public:
    // with_map: also the map when req.map asks for it (Dahl only); `reuse` is taken instead when it is the
    // map of the same r_disp and i (the map does not depend on zeta or theta).
    RatioJob(const RatioRequest& req, bool with_map, const std::optional<PanelData>& reuse = std::nullopt);
    // Does the next step; false once there was nothing left to do (the result is complete).
    bool step();
    bool done() const { return stage_ == Stage::done; }
    RatioCurves& result() { return out_; }

  private:
    enum class Stage { start, curve, map_cells, map_panel, done };
    void next_stage();

    RatioCurves out_;
    Stage stage_ = Stage::start;
    std::size_t next_ = 0; // the next point of the curve or cell of the map
    MapFigure map_spec_;
    SteadyOptions map_options_;
    std::vector<SweepPoint> cells_;
};

// The stable steady states at the current point when more than one coexists (by r_x, as the solver lists
// them), else none: the app then shows each and which one the animation is in.
inline const std::vector<SteadyState>& coexisting_states(const RatioCurves& c) {
    static const std::vector<SteadyState> none;
    return c.current.states.size() >= 2 ? c.current.states : none;
}

// The start that reaches a state, in words: "from rest", "from sliding", "from both starts" or "from neither
// start" (a state the search found without evidence that either start's motion arrives there).
inline const char* reached_from(const SteadyState& s) {
    return s.from_rest && s.from_sliding ? "from both starts"
           : s.from_rest                 ? "from rest"
           : s.from_sliding              ? "from sliding"
                                         : "from neither start";
}

// Which of `states` a motion whose last period's mean of F_x is `mean_fx` is in: the index of the nearest
// r_x when it lies within `tolerance` of it and nearer to it than to any other (at most a third of the gap
// to the next state), else -1 (still settling, or no period completed: NaN).
int state_of_motion(const std::vector<SteadyState>& states, double mean_fx, double tolerance);
// The app's tolerance for it: the animation steps the paper's scheme at a fixed step, whose periodic state's
// mean differs from the solver's r_x by a few 1e-3 (docs/app.md).
inline constexpr double kMotionStateTolerance = 1e-2;

// The curves and the steady state at req.params (and the map when req.map asks for it: the animation of a
// lesson step with the map panel), on the calling thread. `outdated` (may be empty) is asked between the
// steps; when it says true the rest is skipped and the result is incomplete.
RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated = {});

} // namespace fv
