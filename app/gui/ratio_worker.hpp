// Recomputes the r_x(zeta) curves and the steady-state readouts on a background thread, so that the
// window never waits for them. Requests supersede each other: a slider drag only ever costs the last one.
// The browser build without pthreads (a plain static site) has no thread: request() computes at once.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/params.hpp"
#include "fv/steady_state.hpp"

#include <atomic>
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
    bool operator==(const RatioRequest& o) const {
        return model == o.model && params.zeta == o.params.zeta && params.theta == o.params.theta &&
               params.rdisp == o.params.rdisp && params.i == o.params.i && map == o.map &&
               zeta_max == o.zeta_max;
    }
};

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
    SteadyResult current;                          // the steady state at request.params
    std::optional<PanelData> map;                  // the map panel when asked for
};

// The curves and the steady state at req.params (not the map), on the calling thread. `outdated` (may be
// empty) is asked between the steps; when it says true the rest is skipped and the result is incomplete.
RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated = {});

class RatioWorker {
  public:
    RatioWorker();
    ~RatioWorker();
    RatioWorker(const RatioWorker&) = delete;
    RatioWorker& operator=(const RatioWorker&) = delete;

    // Asks for curves at these parameters; returns at once. Ignored if equal to the last request.
    void request(const RatioRequest& r);
    // The newest finished result, if any (copy; cheap enough at ~100 points).
    std::optional<RatioCurves> latest() const;
    // True while a request is being worked on or waiting.
    bool busy() const { return busy_; }
    // Blocks until the last request is finished (scripted runs and tests want the final picture).
    void wait_idle() const;

  private:
    void run();
    // Computes one request (generation `gen`) and publishes it unless a newer request came meanwhile.
    void work(const RatioRequest& req, std::uint64_t gen);

    mutable std::mutex mutex_;
    mutable std::condition_variable cv_;
    std::optional<RatioRequest> pending_;
    std::optional<RatioRequest> last_requested_;
    std::optional<RatioCurves> result_;
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<bool> busy_{false};
    bool stop_ = false;
    std::thread thread_;
};

} // namespace fv::app
