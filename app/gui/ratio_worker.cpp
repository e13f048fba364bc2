#include "ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/rigid.hpp"
#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fv::app {

SteadyOptions current_point_options(const RatioRequest& req) {
    SteadyOptions opt;
    opt.start = req.start;
    opt.list_states = req.model == Model::dahl;
    return opt;
}

int state_of_motion(const std::vector<SteadyState>& states, double mean_fx, double tolerance) {
    if (!std::isfinite(mean_fx)) return -1;
    int best = -1;
    double best_d = HUGE_VAL, gap = HUGE_VAL;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const double d = std::abs(states[k].rx - mean_fx);
        if (d < best_d) best_d = d, best = static_cast<int>(k);
        for (std::size_t m = k + 1; m < states.size(); ++m)
            gap = std::min(gap, std::abs(states[k].rx - states[m].rx));
    }
    return best >= 0 && best_d <= std::min(tolerance, gap / 3) ? best : -1;
}

RatioJob::RatioJob(const RatioRequest& req, bool with_map, const std::optional<PanelData>& reuse) {
    out_.request = req;
    if (with_map && req.map && req.model == Model::dahl) {
        if (reuse) {
            out_.map = reuse;
        } else {
            map_spec_ = std::get<MapFigure>(map_figure(req.params.rdisp, req.params.i, req.start).content);
            map_options_ = map_options(map_spec_);
            cells_ = map_points(map_spec_);
        }
    }
}

void RatioJob::next_stage() {
    next_ = 0;
    if (stage_ == Stage::start && out_.request.model == Model::dahl)
        stage_ = Stage::curve;
    else if ((stage_ == Stage::start || stage_ == Stage::curve) && !cells_.empty())
        stage_ = Stage::map_cells;
    else if (stage_ == Stage::map_cells)
        stage_ = Stage::map_panel;
    else
        stage_ = Stage::done;
}

bool RatioJob::step() {
    const RatioRequest& req = out_.request;
    switch (stage_) {
    case Stage::start:
        out_.current = steady_ratio(req.model, req.params, current_point_options(req));
        out_.zetas = ratio_zeta_grid(req.zeta_max);
        for (double z : out_.zetas) out_.rigid_rx.push_back(rigid_ratio(z, req.params.theta).rx);
        next_stage();
        return true;
    case Stage::curve: {
        // Every point on its own, as sweep() computes it. A failed point is not drawn as if it were valid:
        // NaN leaves a gap in the curve.
        SteadyOptions opt;
        opt.record_period = false;
        opt.start = req.start;
        const Params p{out_.zetas[next_], req.params.theta, req.params.rdisp, req.params.i};
        const SteadyResult r = steady_ratio(Model::dahl, p, opt);
        const bool good = ok(shown_status(r));
        out_.model_rx.push_back(good ? r.rx : std::nan(""));
        out_.model_failed += !good;
        if (++next_ == out_.zetas.size()) next_stage();
        return true;
    }
    case Stage::map_cells: {
        SweepPoint& c = cells_[next_];
        c.result = map_cell(map_spec_, cells_, next_);
        if (++next_ == cells_.size()) next_stage();
        return true;
    }
    case Stage::map_panel:
        out_.map = map_panel_of(map_spec_, cells_, nullptr, 1);
        cells_.clear();
        next_stage();
        return true;
    case Stage::done:
        return false;
    }
    return false;
}

RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated) {
    RatioJob job(req, false);
    while (job.step())
        if (outdated && outdated()) break;
    return std::move(job.result());
}

RatioWorker::RatioWorker(bool threaded) : threaded_(threaded) {
    if (threaded_) thread_ = std::thread([this] { run(); });
}

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
    if (!threaded_) {
        pending_.reset();
        sliced_.emplace(make_job(r)); // supersedes the one in progress
    }
}

std::optional<RatioCurves> RatioWorker::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return result_;
}

void RatioWorker::wait_idle() {
    if (!threaded_) {
        run_slice(std::chrono::microseconds::max());
        return;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait(lock, [this] { return !busy_; });
}

void RatioWorker::run_slice(std::chrono::microseconds budget) {
    if (threaded_ || !sliced_) return;
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    while (sliced_->step())
        if (!sliced_->done() &&
            std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start) >= budget)
            return;
    finish(*sliced_, false);
    sliced_.reset();
}

RatioJob RatioWorker::make_job(const RatioRequest& req) const {
    // The map only changes with r_disp, i and the start: keep the previous one when those did not move.
    std::lock_guard<std::mutex> lock(mutex_);
    const bool reuse = result_ && result_->map && result_->request.params.rdisp == req.params.rdisp &&
                       result_->request.params.i == req.params.i && result_->request.start == req.start;
    return RatioJob(req, true, reuse ? result_->map : std::nullopt);
}

void RatioWorker::finish(RatioJob& job, bool aborted) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!aborted) result_ = std::move(job.result());
    if (!pending_) busy_ = false;
    cv_.notify_all();
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
    // A newer request makes this one moot: check between steps and give up early.
    RatioJob job = make_job(req);
    bool aborted = false;
    while (!aborted && job.step()) aborted = generation_ != gen;
    finish(job, aborted || generation_ != gen);
}

} // namespace fv::app
