#include "ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/rigid.hpp"
#include "fv/sweep.hpp"

#include <cmath>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fv::app {

RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated) {
    RatioCurves out;
    out.request = req;
    out.current = steady_ratio(req.model, req.params);
    out.zetas = ratio_zeta_grid(req.zeta_max);
    if (outdated && outdated()) return out;
    for (double z : out.zetas) out.rigid_rx.push_back(rigid_ratio(z, req.params.theta).rx);
    // One warm-started sweep along zeta with the continuous-time solver: a whole curve in a few tens of
    // milliseconds, so a dragged slider redraws it within a frame or two.
    if (req.model == Model::dahl) {
        const auto rows =
            sweep(Model::dahl, out.zetas, {req.params.theta}, {req.params.rdisp}, {req.params.i}, {}, 1);
        // A failed point is not drawn as if it were valid: NaN leaves a gap in the curve.
        for (const auto& r : rows) {
            const bool good = ok(shown_status(r.result));
            out.model_rx.push_back(good ? r.result.rx : std::nan(""));
            out.model_failed += !good;
        }
    }
    return out;
}

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
// The browser build without pthreads: no thread; request() computes at once (see ratio_worker.hpp).
RatioWorker::RatioWorker() = default;
#else
RatioWorker::RatioWorker() : thread_([this] { run(); }) {}
#endif

RatioWorker::~RatioWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void RatioWorker::request(const RatioRequest& r) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (last_requested_ && *last_requested_ == r) return;
        last_requested_ = r;
        pending_ = r;
        busy_ = true;
        ++generation_;
    }
    cv_.notify_all();
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    pending_.reset();
    work(r, generation_);
#endif
}

std::optional<RatioCurves> RatioWorker::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return result_;
}

void RatioWorker::wait_idle() const {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait(lock, [this] { return !busy_; });
}

void RatioWorker::run() {
    // Lowest CPU priority: on two cores the renderer (llvmpipe's threads) must win, the curves can wait a
    // frame. (On Linux, setpriority on a thread id applies to that thread alone; elsewhere, e.g. the browser
    // build, there is no thread id to name and the worker keeps the default priority.)
#if defined(__linux__)
    ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
#endif
    for (;;) {
        RatioRequest req;
        std::uint64_t gen = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            cv_.wait(lock, [this] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            req = *pending_;
            pending_.reset();
            gen = generation_;
        }
        work(req, gen);
    }
}

void RatioWorker::work(const RatioRequest& req, std::uint64_t gen) {
    // A newer request makes this one moot: check between points and give up early.
    auto outdated = [&] { return generation_ != gen; };
    RatioCurves out = compute_ratio_curves(req, outdated);
    bool aborted = outdated();
    // The map only changes with r_disp and i: keep the previous one when those did not move.
    if (!aborted && req.map && req.model == Model::dahl) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (result_ && result_->map && result_->request.params.rdisp == req.params.rdisp &&
                result_->request.params.i == req.params.i)
                out.map = result_->map;
        }
        if (!out.map) {
            FigureData f = compute_figure(map_figure(req.params.rdisp, req.params.i), 1);
            out.map = std::move(f.panels.front());
        }
        aborted = outdated();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (!aborted) result_ = std::move(out);
    if (!pending_) busy_ = false;
    cv_.notify_all();
}

} // namespace fv::app
