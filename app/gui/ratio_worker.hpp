// Recomputes the r_x(zeta) curves and the steady-state readouts on a background thread, so that the
// window never waits for them. Requests supersede each other: a slider drag only ever costs the last one.
// The browser build without pthreads (a plain static site) has no thread: there the same work (RatioJob) is
// done in time slices, a few milliseconds a frame (RatioWorker::run_slice), and published when complete.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace fv::app {

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

// The curves and the steady state at req.params (not the map), on the calling thread. `outdated` (may be
// empty) is asked between the steps; when it says true the rest is skipped and the result is incomplete.
RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated = {});

// The browser build without pthreads (a plain static site) has no thread to start.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kRatioThread = false;
#else
inline constexpr bool kRatioThread = true;
#endif

class RatioWorker {
  public:
    // threaded: a background thread does the work; else run_slice() does it in slices (the browser build,
    // and the tests of it).
    explicit RatioWorker(bool threaded = kRatioThread);
    ~RatioWorker();
    RatioWorker(const RatioWorker&) = delete;
    RatioWorker& operator=(const RatioWorker&) = delete;

    // Asks for curves at these parameters; returns at once. Ignored if equal to the last request.
    void request(const RatioRequest& r);
    // The newest finished result, if any (copy; cheap enough at ~100 points).
    std::optional<RatioCurves> latest() const;
    // True while a request is being worked on or waiting.
    bool busy() const { return busy_; }
    // Blocks until the last request is finished (scripted runs and tests want the final picture). Without
    // threads, does the rest of the work at once.
    void wait_idle();
    // Without a thread (the browser build): works on the current request for about `budget` (at least one
    // step), publishing the result when it completes; the app's loop calls it once a frame. With a thread:
    // nothing (the thread works).
    void run_slice(std::chrono::microseconds budget);

  private:
    void run();
    // Computes one request (generation `gen`) and publishes it unless a newer request came meanwhile.
    void work(const RatioRequest& req, std::uint64_t gen);
    // A job for `req`, with the last result's map when it can be reused.
    RatioJob make_job(const RatioRequest& req) const;
    // Publishes a finished job's result (unless outdated) and clears busy when nothing waits.
    void finish(RatioJob& job, bool aborted);

    mutable std::mutex mutex_;
    mutable std::condition_variable cv_;
    std::optional<RatioRequest> pending_;
    std::optional<RatioRequest> last_requested_;
    std::optional<RatioCurves> result_;
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<bool> busy_{false};
    bool stop_ = false;
    bool threaded_;
    std::optional<RatioJob> sliced_; // without a thread: the request being worked on in slices
    std::thread thread_;
};

} // namespace fv::app
