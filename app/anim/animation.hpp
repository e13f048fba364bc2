// Animation export: the periodic steady state as a seamless loop, rendered headless
// through OSMesa (RenderSession) and encoded as an animated GIF (giflib) or an H.264 MP4 (FFmpeg), written
// atomically. The same code serves `frictionviz animate` and the app's File > Export animation (which runs
// it on a worker thread with its own headless context: GL contexts are per thread).
#pragma once

#include "figures/animation_spec.hpp"

#include "fv/gfx/canvas.hpp"
#include "fv/live_panels.hpp"
#include "fv/live_sim.hpp"
#include "fv/ratio_curves.hpp"
#include "fv/setup.hpp"

#include <atomic>
#include <functional>
#include <optional>
#include <string>

namespace fv::anim {

using Format = AnimationFormat;
using View = AnimationView;
using Spec = AnimationSpec;

inline constexpr int kMinPeriods = 1, kMaxPeriods = 20;
inline constexpr double kMinFps = 1, kMaxFps = 60;
inline constexpr double kMaxGifFps = 50; // a GIF frame lasts a whole number of 1/100 s, at least 2
inline constexpr double kMinSpeed = 0.05, kMaxSpeed = 10; // vibration periods per second (the app's range)
inline constexpr int kMaxFrames = 3600;

// The format a file name asks for by its extension (.gif, .mp4; any case), if any.
std::optional<Format> format_for_path(const std::string& path);
// "FILE.gif, FILE.mp4": what format_for_path() accepts, for messages.
const char* allowed_extensions();
// The size rounded up to even numbers for MP4 (4:2:0 chroma needs them); unchanged for GIF.
void even_size(Spec& spec);

// Frames in the loop: periods x fps / speed, rounded.
int frame_count(const Spec& spec);
// "" or a one-line reason the spec cannot be exported, naming what is allowed (ranges, frame count, the GIF
// frame rate, MP4's even size, libx264 missing).
std::string check_spec(const Spec& spec);

// One setup's part of a loop: the live simulation settled on its steady state (the continuous-time solver's
// fixed point, then the animation's own stepping), the simulation at the frame drawn, its steady r_x, its
// r_x(zeta) curves (for the dashboard views) and the top view's frame held over the loop.
struct SetupLoop {
    // with_map: the curves with the (zeta, theta) map too (the map panel; Dahl only).
    SetupLoop(const Spec& spec, const Setup& setup, bool with_curves, bool with_map = false);
    // The simulation at frame k of `count` in a loop of `periods` periods: floor(k N / count) steps into it
    // (N = periods x steps per period), so that frame `count` is the loop's start again.
    const LiveSim& at_frame(int k, int count, int periods);

    Setup setup;
    double rx = 0;
    std::optional<RatioCurves> curves;
    LiveSim start, sim;
    int at = 0; // the frame sim is at
    FrameBox box;
};

// The loop's frames: each setup's steady state (A's; in the compare view B's too, on the same time base: the
// setups share the vibration and so its period 2 pi, and each is sampled at periods x its steps per period /
// frames steps apart), so that the frame after the last is the first for both.
class Frames {
  public:
    explicit Frames(const Spec& spec);
    int count() const { return count_; }
    // Draws frame k over the logical page (the canvas between begin() and end()). Frames are cheapest in
    // increasing order; any order works.
    void paint(gfx::Canvas& canvas, gfx::Vec2 page, int k);
    // Measures the top view's data area on this page (drawing frame 0 into a recording that is thrown
    // away), so that its frame fits the area exactly: the ground frame's wrap-around then falls on the
    // axes' edges. Without it the frame is the parameters' own, widened by the painter.
    void fit(gfx::Canvas& canvas, gfx::Vec2 page, float pixel_ratio);
    // The frame the top view shows in every frame of the loop (relative to the vibration centre); B's in the
    // compare view.
    const FrameBox& frame_box() const { return a_.box; }
    const FrameBox* frame_box_b() const { return b_ ? &b_->box : nullptr; }
    // The steady r_x the caption shows (A's).
    double rx() const { return a_.rx; }
    // The frame a still picture shows: 0, or in the ground frame the one with the body nearest the middle of
    // the frame (in frame 0 it may stand on the edge, drawn half at each side).
    int still_frame();

  private:
    PanelData top_view(SetupLoop& loop, int k, const char* name);

    Spec spec_;
    int count_ = 0;
    SetupLoop a_;
    std::optional<SetupLoop> b_; // the compare view's setup B
    MechanismBase mechanism_;    // the why panel's base (for A's zeta and theta: computed once, kept)
    float top_ = 24;             // the panels' top: below the caption, and the title where there is one
    double aspect_ = 0;
    gfx::Rect top_view_area(gfx::Vec2 page) const;
};

struct Progress {
    std::function<void(int done, int total)> report; // after each frame (from the exporting thread)
    const std::atomic<bool>* cancel = nullptr;       // set: stop, write nothing, return "cancelled"
};

// The still frame of the loop (Frames::still_frame) as one picture: its pixels (for a PNG) and its display
// list (for SVG and PDF), at the spec's size and scale; `render --lesson` draws a lesson step's picture with
// it. `vector_page` > 0: the display list laid out on that logical page instead (render --lesson --page: a
// printed page's, whose full-size text prints at 8-9 pt). Throws std::runtime_error when no headless GL
// context can be made.
struct Still {
    gfx::Image image;
    gfx::DisplayList list;
};
Still render_still(const Spec& spec, gfx::Vec2 vector_page = {0, 0});

// Renders the frames and writes `path` through fv::write_file_atomic. The spec must have passed check_spec()
// and its format match the path. Returns "" or a one-line error (nothing written then). Throws
// std::runtime_error when no headless GL context can be made.
std::string export_animation(const Spec& spec, const std::string& path, const Progress& progress = {});

} // namespace fv::anim
