// The web platform (browser build only): the page's canvas as a GLFW window through emscripten's GLFW (WebGL
// 2; the GL context is gfx::WindowContext, as on the desktop) with Dear ImGui's GLFW input backend. The app's
// loop (run_gui) is a plain loop; present() hands control back to the browser once per frame
// (until the browser's next animation frame, an await under ASYNCIFY), so the page stays responsive and the
// canvas is shown.
#include "platform_glfw.hpp"

#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace fv::app {
namespace {

// The browser's file input for a file of the kind `accept`; the file chosen goes the way of a file dropped
// onto the canvas (emscripten's GLFW: read into the in-memory file system, /.glfw_dropped_files/NAME, then
// the drop callback). Browsers open the chooser only shortly after a user's click, which this follows.
// clang-format off
EM_JS(void, fv_web_choose_file, (const char* accept), {
    var input = document.createElement("input");
    input.type = "file";
    input.accept = UTF8ToString(accept);
    input.onchange = function() {
        if (input.files && input.files.length > 0)
            GLFW.onDrop({dataTransfer: {files: input.files}, preventDefault: function() {}});
    };
    input.click();
});

// A file of the in-memory file system to the browser as a download (a Blob behind a link clicked once).
EM_JS(void, fv_web_download, (const char* path), {
    var p = UTF8ToString(path);
    var data = FS.readFile(p);
    var name = p.substring(p.lastIndexOf("/") + 1);
    var types = {png: "image/png", csv: "text/csv", json: "application/json"};
    var ext = name.substring(name.lastIndexOf(".") + 1).toLowerCase();
    var url = URL.createObjectURL(new Blob([data], {type: types[ext] || "application/octet-stream"}));
    var a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(function() { URL.revokeObjectURL(url); }, 60000);
    console.log("frictionviz: download " + name + " (" + data.length + " bytes)");
});

// The canvas's size on the page in CSS pixels (the page's style sets it: index.html makes it the window).
EM_JS(double, fv_web_canvas_css_width, (), { return Module["canvas"].getBoundingClientRect().width; });
EM_JS(double, fv_web_canvas_css_height, (), { return Module["canvas"].getBoundingClientRect().height; });

// The canvas's own size (its backing store, device pixels): through emscripten's Browser.setCanvasSize,
// whose resize listener updates GLFW's window (glfwSetWindowSize would ask for full screen when the size
// equals the screen's).
EM_JS(void, fv_web_set_canvas_size, (int width, int height), { Browser.setCanvasSize(width, height); });

// Text to the system clipboard (ImGui's clipboard in the page: Copy link, Ctrl+C in a field). Browsers may
// refuse (no permission, no recent click, an insecure http:// address that is not localhost): then a box
// over the page holds the text, selected, for Ctrl+C, with a button to close it. The box is #fv-copy, its
// field #fv-copy-text (the tests read them).
EM_JS(void, fv_web_copy_text, (const char* text), {
    var t = UTF8ToString(text);
    function fallback() {
        var box = document.getElementById("fv-copy");
        if (!box) {
            box = document.createElement("div");
            box.id = "fv-copy";
            box.style.cssText = "position:fixed;left:8px;right:8px;bottom:8px;background:#fff;border:1px solid #888;" +
                                "padding:8px;font:14px sans-serif;z-index:10;box-shadow:0 2px 8px rgba(0,0,0,.3)";
            box.innerHTML = "<div>The browser did not let the page copy: press Ctrl+C (Cmd+C on a Mac) to copy " +
                            "the selected address.</div><input id='fv-copy-text' readonly " +
                            "style='width:100%;box-sizing:border-box;margin:6px 0;font:13px monospace'>" +
                            "<button id='fv-copy-close'>Close</button>";
            document.body.appendChild(box);
            document.getElementById("fv-copy-close").onclick = function() { box.style.display = "none"; };
        }
        var field = document.getElementById("fv-copy-text");
        field.value = t;
        box.style.display = "block";
        field.focus();
        field.select();
        try {
            if (document.execCommand("copy")) console.log("frictionviz: copied (execCommand) " + t);
        } catch (e) {
        }
    }
    if (navigator.clipboard && navigator.clipboard.writeText)
        navigator.clipboard.writeText(t).then(function() { console.log("frictionviz: copied " + t); }, fallback);
    else
        fallback();
});

void web_set_clipboard(void* /*user*/, const char* text) {
    fv_web_copy_text(text);
}

// Tells the page a frame was drawn (Module.fvFrame, when the page has one: the benchmark's and the tests'
// pages), with the work it took on the page's thread by phase (FrameWork, ms), why it was drawn when it was
// (fv_web_next_animation_frame: "start", "input", "work", "idle" or "timeout"), how many animation frames
// were passed over before it, and when it began (performance.now()).
EM_JS(void, fv_web_frame_shown, (double ui, double slice, double sync, double sim, double paint, double gl), {
    if (Module["fvFrame"])
        Module["fvFrame"]({ui: ui, slice: slice, sync: sync, sim: sim, paint: paint, gl: gl,
                           cause: Module["fvCause"] || "start", skipped: Module["fvSkipped"] || 0,
                           begun: Module["fvFrameBegun"] || 0});
});
// Marks Module.fvInput on any input the page gets (capturing, before emscripten's GLFW sees it): the next
// frame is then drawn at the browser's next animation frame, whatever the pace of the animation.
EM_JS(void, fv_web_watch_input, (), {
    Module["fvInput"] = true;
    var mark = function() { Module["fvInput"] = true; };
    ["mousemove", "mousedown", "mouseup", "wheel", "keydown", "keyup", "touchstart", "touchmove", "touchend",
     "touchcancel", "resize", "focus", "blur", "drop"].forEach(function(type) {
        window.addEventListener(type, mark, true);
    });
});
// Back to the browser until its next animation frame (requestAnimationFrame), at most timeout_ms: the
// browser shows the frame drawn and delivers input meanwhile. A browser calls its animation frames no faster
// than it can show them (the screen's rate, or slower when its GPU side lags behind), so a page drawing on
// them never queues more frames than the browser can draw. Unless `at_once` or input came, the first
// animation frame at least idle_ms after the last frame began.
EM_ASYNC_JS(void, fv_web_next_animation_frame, (double timeout_ms, double idle_ms, bool at_once), {
    var begun = Module["fvFrameBegun"] || 0;
    await new Promise(function(resolve) {
        var done = false;
        var skipped = 0;
        function begin(cause) {
            if (!done) {
                done = true;
                Module["fvCause"] = cause;
                Module["fvSkipped"] = skipped;
                resolve();
            }
        }
        function tick() {
            if (done) return;
            if (Module["fvInput"])
                begin("input");
            else if (at_once)
                begin("work");
            else if (performance.now() - begun >= idle_ms)
                begin("idle");
            else {
                ++skipped;
                requestAnimationFrame(tick);
            }
        }
        requestAnimationFrame(tick);
        setTimeout(function() { begin("timeout"); }, timeout_ms);
    });
    Module["fvInput"] = false;
    Module["fvFrameBegun"] = performance.now();
});
// clang-format on

// Beyond 3 device pixels per CSS pixel nobody sees a difference, while the pixels to fill grow with its
// square (a phone at 3: 1170 x 2532 for 390 x 844 CSS pixels).
constexpr double kMaxRatio = 3;

// present() waits at most this long for the browser's next animation frame: a hidden tab gets none, and under
// Chromium's virtual time (the tests) the page's timers move the clock. 0.1 s is the longest step the app's
// simulation takes (GuiLoop::advance), so pictures after some seconds are the same either way.
constexpr double kMaxFrameWaitMs = 100;

// A frame where only the animation moves (no input, no work of the app's pending) begins at least this long
// after the last one: every second animation frame at 60 Hz, every fourth at 120 Hz, 30 frames a second
// (1000/30 ms less a few for the animation frames' jitter). The animation runs on the clock, so it keeps its
// speed; 30 frames a second are smooth at its slow motion. What this buys is room on the browser's GPU side,
// which in software (SwiftShader) needs 25-40 ms of CPU per frame: drawing every animation frame kept it
// busy, and a slider's move then waited for the frames queued before it (docs/web.md, "Idle frames").
constexpr double kIdleFrameMs = 29;

// Framebuffer pixels per CSS pixel: as asked, else the screen's (window.devicePixelRatio: 2 on a HiDPI
// screen, also with the browser's zoom), at most kMaxRatio. Fixed at start (the fonts are rasterised at it):
// a page dragged to another screen keeps its first ratio, at the new size.
float canvas_ratio(const PlatformOptions& o) {
    return o.scale > 0 ? o.scale
                       : static_cast<float>(std::min(kMaxRatio, emscripten_get_device_pixel_ratio()));
}

// The canvas's CSS size times the ratio, in framebuffer pixels (emscripten's GLFW counts the window in them,
// and the mouse too); at least 1 x 1.
gfx::Size backing_size(float ratio) {
    return {std::max(1, static_cast<int>(std::lround(fv_web_canvas_css_width() * ratio))),
            std::max(1, static_cast<int>(std::lround(fv_web_canvas_css_height() * ratio)))};
}

gfx::WindowOptions canvas_options(const PlatformOptions& o) {
    const float r = canvas_ratio(o);
    const gfx::Size follow = backing_size(r);
    gfx::WindowOptions w;
    w.title = o.title;
    w.width = o.width > 0 ? o.width : follow.width;
    w.height = o.height > 0 ? o.height : follow.height;
    w.scale_to_monitor = false;
    return w;
}

class WebPlatform final : public GlfwPlatform {
  public:
    explicit WebPlatform(const PlatformOptions& o)
        : GlfwPlatform(canvas_options(o)), ratio_(canvas_ratio(o)), follow_(o.width <= 0 && o.height <= 0) {
        fv_web_watch_input();
    }

    std::string_view name() const override { return "web"; }
    // The canvas follows its size on the page (the window's, with index.html's style): checked every frame,
    // which also catches what a resize event would (a rotated phone, a window dragged larger, the browser's
    // zoom), at the cost of reading one rectangle.
    PlatformEvents poll() override {
        if (follow_) {
            const gfx::Size want = backing_size(ratio_), have = ctx_.framebuffer_size();
            if (want.width != have.width || want.height != have.height)
                fv_web_set_canvas_size(want.width, want.height);
        }
        return GlfwPlatform::poll();
    }
    void connect_imgui() override {
        GlfwPlatform::connect_imgui();
        ImGui::GetIO().SetClipboardTextFn = web_set_clipboard; // GLFW's clipboard in the page is its own
    }
    float pixel_ratio() const override { return ratio_; }
    void imgui_new_frame(gfx::Vec2 logical) override {
        GlfwPlatform::imgui_new_frame(logical);
        // Under Chromium's --virtual-time-budget (the tests) the clock stands still: ImGui needs time to
        // pass.
        ImGuiIO& io = ImGui::GetIO();
        if (!(io.DeltaTime > 0)) io.DeltaTime = 1.0f / 60.0f;
    }
    // Back to the browser until its next animation frame (at most kMaxFrameWaitMs), which shows the frame
    // and delivers input meanwhile. Not a timer of 1/60 s: a page's WebGL calls only queue commands for
    // the browser's GPU side, and where it draws more slowly than the page makes frames (software
    // rendering, SwiftShader, on a loaded machine) the queue grew until a call blocked the page for as long
    // as the backlog took: a slider edit then waited 0.1 s to seconds inside a frame's drawing.
    void present() override {
        ctx_.present();
        fv_web_frame_shown(work_.ui_ms, work_.slice_ms, work_.sync_ms, work_.sim_ms, work_.paint_ms,
                           work_.gl_ms);
        fv_web_next_animation_frame(kMaxFrameWaitMs, kIdleFrameMs, work_pending_);
    }
    void work_pending(bool pending) override { work_pending_ = pending; }

    void frame_work(const FrameWork& work) override { work_ = work; }
    void rest_after_frame(double /*frame_ms*/) override {} // present() paced the frame

    bool choose_file(const std::string& accept) override {
        fv_web_choose_file(accept.c_str());
        return true;
    }
    void file_written(const std::string& path) override { fv_web_download(path.c_str()); }

  private:
    float ratio_;
    bool follow_;               // the canvas follows its CSS size (no fixed size asked for)
    FrameWork work_;            // the frame's, for the page
    bool work_pending_ = false; // the app has work for the next frame: no idle pacing
};

} // namespace

std::unique_ptr<Platform> make_web_platform(const PlatformOptions& options) {
    return std::make_unique<WebPlatform>(options);
}

} // namespace fv::app
