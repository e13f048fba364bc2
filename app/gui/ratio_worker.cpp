#include "ratio_worker.hpp"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fv::app {

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
    using Us = std::chrono::microseconds;
    const auto start = Clock::now();
    auto step_start = start;
    while (sliced_->step()) {
        if (sliced_->done()) break;
        // Another step only when it is likely to end within the budget: the steps of a stage cost about the
        // same (a curve point, a map cell), so the last one's cost is the guess. At least one step a slice.
        const auto now = Clock::now();
        const Us elapsed = std::chrono::duration_cast<Us>(now - start);
        const Us last = std::chrono::duration_cast<Us>(now - step_start);
        if (elapsed >= budget || last > budget - elapsed) return;
        step_start = now;
    }
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

void RatioWorker::hold(bool on) {
    if (!threaded_) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        held_ = on;
    }
    if (!on) cv_.notify_all();
}

void RatioWorker::work(const RatioRequest& req, std::uint64_t gen) {
    // A newer request makes this one moot: check between steps and give up early.
    RatioJob job = make_job(req);
    bool aborted = false;
    auto unheld = [this] {
        std::unique_lock<std::mutex> lock(mutex_);
        cv_.wait(lock, [this] { return stop_ || !held_; });
        return !stop_;
    };
    while (!aborted) {
        if (!unheld()) { // stopping: the job is left unfinished
            aborted = true;
            break;
        }
        if (!job.step()) break;
        aborted = generation_ != gen;
    }
    finish(job, aborted || generation_ != gen);
}

} // namespace fv::app
