// File > Export animation…: a GIF or MP4 loop of the current parameters, made in the
// background. The app only knows the request and a function that fulfils it (GuiOptions::animation_exporter,
// given by the command line: the encoders live in app/anim/, outside the app library); the job runs it on a
// worker thread, which makes its own headless GL context (GL contexts are current on one thread), at low CPU
// priority so that the window keeps its frame rate; progress and the result go to the status line.
#pragma once

#include "figures/animation_spec.hpp"

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace fv::app {

// An export asked for: the file (its extension picks the format) and what to animate (the export dialog sets
// the view, periods and speed; AppState::sync fills in the parameters in effect).
struct AnimationRequest {
    std::string path;
    AnimationSpec spec;
};

// Renders and writes the animation on the calling thread; progress(done, total) after each frame; stops when
// cancel is set. Returns "" or a one-line error.
using AnimationExporter = std::function<std::string(
    const AnimationRequest&, const std::function<void(int, int)>& progress, const std::atomic<bool>& cancel)>;

class AnimationExportJob {
  public:
    explicit AnimationExportJob(AnimationExporter exporter);
    ~AnimationExportJob(); // cancels a running export (nothing is written) and waits for it
    AnimationExportJob(const AnimationExportJob&) = delete;
    AnimationExportJob& operator=(const AnimationExportJob&) = delete;

    bool available() const { return static_cast<bool>(exporter_); }
    bool running() const { return running_; }
    // Starts an export; returns the status line to show ("exporting …", or why not).
    std::string start(const AnimationRequest& r);
    // The status line when it changed since the last call (progress, then the result).
    std::optional<std::string> poll();
    // Whether an export failed or was refused since the last call (its reason is in the status line poll() or
    // start() gave): a scripted run exits 1 for it.
    bool take_failure() { return failed_.exchange(false); }
    // Blocks until the export is done (scripted runs want the file before the next frame).
    void wait();

  private:
    AnimationExporter exporter_;
    std::thread thread_;
    std::atomic<bool> running_{false}, cancel_{false}, failed_{false};
    std::atomic<int> done_{0}, total_{0};
    std::mutex mutex_;
    std::string path_, result_;
    bool finished_ = false;
    int shown_ = -1;
};

// The export dialog's state between frames.
struct ExportDialog {
    bool open_requested = false;
    std::string path = "frictionviz-animation.gif";
    int view = 0; // 0 dashboard, 1 scene
    int periods = 2;
    std::string error; // why the path was not accepted
};

// The modal dialog (file name, GIF or MP4, view, periods); call once per frame at window level. Returns the
// request when the user exports (the parameters are filled in by AppState::sync).
std::optional<AnimationRequest> draw_export_dialog(ExportDialog& d, double speed, bool busy);

} // namespace fv::app
