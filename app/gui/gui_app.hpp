// The interactive app: one loop for every platform (platform.hpp): the window, headless runs (scripted tests,
// screenshots, benchmarks).
#pragma once

#include "animation_export.hpp"
#include "screen_layout.hpp"
#include "session.hpp"
#include "session_link.hpp"

#include "figures/dashboard_painter.hpp"

#include "fv/gfx/context.hpp" // Size

#include "fv/measurements.hpp"
#include "fv/params.hpp"

#include <functional>
#include <optional>
#include <string>

namespace fv::app {

// Where a frame put the panel and the pictures, in logical pixels (CSS pixels in the browser).
struct ShownLayout {
    gfx::Vec2 page;
    float pixel_ratio = 1;
    gfx::Size framebuffer;
    ScreenLayout screen;
    DashboardLayout panels;
    float controls_scroll_max = 0; // how far the panel's rows scroll (0: all in view)
};

struct GuiOptions {
    std::string platform = "auto"; // make_platform(): window, headless or auto
    int width = 0, height = 0;     // framebuffer pixels; 0: the platform's default (1280 x 800 logical)
    float scale = 0;               // pixels per logical unit; 0: the platform's (monitor content scale)
    // The state to start from: the command line's flags, a --link or a --session file, checked (the
    // vibration: both finite and > 0, v_v = 2 pi f A too). Default: Fig. 14a's parameters, the paper's
    // Littmann experiment (Sec. 4: 0.7 um at 60 kHz).
    Session start;
    std::string session_file; // the --session file start came from (named in the status line), or ""
    int lesson = 0;           // > 0: open on this lesson step (lessons.hpp), set up as the Lessons menu does
    int frames = 0;           // > 0: stop after this many frames (scripted runs)
    std::string script;       // scripted slider changes, see script.hpp
    std::string screenshot;   // write the last frame here (PNG)
    int bench_frames = 0;     // > 0: change the sliders every frame and print frame-time percentiles
    std::optional<MeasurementSet> data; // measured r_x(zeta) to show from the start, read with start's A, f
    // File > Export animation… and the script's `animate`: what writes the file (the command line passes
    // app/anim's exporter); empty: the menu item says it is not available.
    AnimationExporter animation_exporter;
    // Called once a frame after that frame's edits took effect (the browser page writes the state into its
    // address as a share link); may be empty.
    std::function<void(const UiState&)> on_state;
    // Where Copy link points (the page's address in the browser; --link-base on the desktop).
    ShareAddress share;
    // A first line for the status line (a link's view values that were ignored), or "".
    std::string start_notice;
    // Called once a frame after drawing with where everything went (the browser page hands it to its tests);
    // may be empty.
    std::function<void(const ShownLayout&)> on_layout;
};

// Returns the process exit code. Throws std::invalid_argument for an unknown platform and
// std::runtime_error (one line) when no context can be made.
int run_gui(const GuiOptions& options);

} // namespace fv::app
