// Where the app's frames go and where its input comes from (MuJoCo's PlatformUIAdapter, polyscope's backends
// by name). The loop in gui_app.cpp sees only this interface; the window and web adapters
// (platform_window.cpp, platform_web.cpp, with what they share in platform_glfw.*, the GLFW context in the
// render layer) are the only code that calls GLFW or an ImGui platform backend.
#pragma once

#include "fv/gfx/context.hpp"
#include "fv/gfx/types.hpp"

#include <chrono>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace fv::app {

struct PlatformOptions {
    // Framebuffer pixels. 0: the platform's default (1280 x 800 logical units at the pixel ratio).
    int width = 0, height = 0;
    // Framebuffer pixels per logical unit (UI and drawing scale). 0: the platform's own (the monitor's
    // content scale in a window, 1 headless).
    float scale = 0;
    std::string title = "frictionviz";
};

// The work of one frame on the app's thread, by phase, in ms of wall time: the events and the panel (without
// the curves' slice), the curves' slice (without threads), the sync, the simulation, the dashboard's layout
// and the GL drawing (up to glFinish). The web platform hands it to the page (the benchmark's,
// bench/web/bench.html).
struct FrameWork {
    double ui_ms = 0, slice_ms = 0, sync_ms = 0, sim_ms = 0, paint_ms = 0, gl_ms = 0;
};

// What happened since the last frame.
struct PlatformEvents {
    bool close = false;               // the user closed the window
    std::vector<std::string> dropped; // files dropped onto the window, oldest first
    bool help_key = false;            // F1 went down
};

class Platform {
  public:
    virtual ~Platform() = default;
    Platform(const Platform&) = delete;
    Platform& operator=(const Platform&) = delete;

    // "window" or "headless": what make_platform() resolved the name to.
    virtual std::string_view name() const = 0;
    virtual gfx::GpuContext& context() = 0;
    // Framebuffer pixels per logical unit this frame (fonts, lines, the ImGui scale).
    virtual float pixel_ratio() const = 0;
    // Live input and wall-clock time. A platform that is not interactive runs on a fixed 1/60 s per frame
    // with no mouse, so its frames are reproducible.
    virtual bool interactive() const = 0;

    // Connects the current ImGui context to the platform's input; disconnect() before it is destroyed.
    virtual void connect_imgui() = 0;
    virtual void disconnect_imgui() = 0;
    // Pumps the event queue.
    virtual PlatformEvents poll() = 0;
    // Feeds ImGui's IO for the next frame: display size (the logical page), framebuffer scale, and the
    // mouse (in logical units), keys and time where there is input.
    virtual void imgui_new_frame(gfx::Vec2 logical) = 0;
    // Shows the frame (swap buffers; nothing headless).
    virtual void present() = 0;
    // What the frame about to be shown cost (called before present()); only the web platform keeps it.
    virtual void frame_work(const FrameWork& work) { (void)work; }
    // Whether the app has work of its own for the next frame (called before present()): true while the
    // curves are computed in slices, one a frame. Without it and without input only the animation moves,
    // and the web platform draws fewer frames (platform_web.cpp); the others draw every frame anyway.
    virtual void work_pending(bool pending) { (void)pending; }
    // After a real-time frame that took frame_ms: without vsync (e.g. Xvfb) do not spin, about 60 frames per
    // second are plenty. The web platform paces its frames in present(), where it hands control back to the
    // browser, and does nothing here.
    virtual void rest_after_frame(double frame_ms) {
        if (frame_ms < 15)
            std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(15 - frame_ms));
    }

    // The platform's own file chooser for a file of the kind `accept` (".csv"), where it has one (the web
    // page's file input): true when it opened; the file chosen arrives later among PlatformEvents::dropped,
    // as if dropped. False: the app shows its own path dialog.
    virtual bool choose_file(const std::string& accept) {
        (void)accept;
        return false;
    }
    // A file the user asked for (a screenshot, an export, a session) was written at `path`: the web platform
    // hands a copy to the browser as a download; elsewhere the file is where it belongs already.
    virtual void file_written(const std::string& path) { (void)path; }

  protected:
    Platform() = default;
};

// The names make_platform() takes: window, headless, auto (a window when a display is there, else headless);
// in the browser build web and auto (= web).
const std::vector<std::string_view>& platform_names();
// The one place a platform is chosen. Throws std::invalid_argument for an unknown name (the message lists
// the names) and std::runtime_error (one line) when the platform cannot start (no display, no GL).
std::unique_ptr<Platform> make_platform(std::string_view name, const PlatformOptions& options);
// What "auto" picks here: "window" when DISPLAY or WAYLAND_DISPLAY is set, else "headless".
std::string_view resolve_platform_name(std::string_view name);

// The adapters (platform_window.cpp, platform_headless.cpp; platform_web.cpp in the browser build, where it
// is the only one); use make_platform().
std::unique_ptr<Platform> make_window_platform(const PlatformOptions& options);
std::unique_ptr<Platform> make_headless_platform(const PlatformOptions& options);
std::unique_ptr<Platform> make_web_platform(const PlatformOptions& options);

} // namespace fv::app
