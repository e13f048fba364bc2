// Recomputes the r_x(zeta) curves and the steady-state readouts on a background thread, so that the
// window never waits for them. Requests supersede each other: a slider drag only ever costs the last one.
// The browser build without pthreads (a plain static site) has no thread: there the same work (RatioJob) is
// done in time slices, a few milliseconds a frame (RatioWorker::run_slice), and published when complete.
#pragma once

#include "fv/ratio_curves.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>

namespace fv::app {

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
    // Without a thread (the browser build): works on the current request within `budget` (one step at
    // least; another only while the last step's cost still fits), publishing the result when it completes;
    // the app's loop calls it once a frame. With a thread: nothing (the thread works).
    void run_slice(std::chrono::microseconds budget);
    // While on, the thread waits before its next step (the app holds it while a frame is drawn: llvmpipe
    // rasterises on every core, and a step run beside it held one of them up, frames at 1920x1080 x1.5 with
    // compare on taking 18-23 ms in runs of several instead of 12). A step under way is finished.
    void hold(bool on);

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
    bool held_ = false; // guarded by mutex_
    bool threaded_;
    std::optional<RatioJob> sliced_; // without a thread: the request being worked on in slices
    std::thread thread_;
};

} // namespace fv::app
