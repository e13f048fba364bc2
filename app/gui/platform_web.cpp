// The web platform (browser build only): the page's canvas as a GLFW window through emscripten's GLFW (WebGL
// 2; the GL context is gfx::WindowContext, as on the desktop) with Dear ImGui's GLFW input backend. The app's
// loop (run_gui) is a plain loop; present() hands control back to the browser once per frame
// (emscripten_sleep under ASYNCIFY), so the page stays responsive and the canvas is shown.
#include "platform_glfw.hpp"

#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

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

// Tells the page a frame was drawn (Module.fvFrame, when the page has one: the benchmark's page).
EM_JS(void, fv_web_frame_shown, (), {
    if (Module["fvFrame"]) Module["fvFrame"]();
});
// clang-format on

// Framebuffer pixels per CSS pixel: as asked, else the screen's (window.devicePixelRatio: 2 on a HiDPI
// screen, also with the browser's zoom).
float canvas_ratio(const PlatformOptions& o) {
    return o.scale > 0 ? o.scale : static_cast<float>(emscripten_get_device_pixel_ratio());
}

// The canvas in framebuffer pixels (its width and height attributes: emscripten's GLFW counts the window in
// them, and the mouse too); index.html's style shows it at 1280 x 800 CSS pixels.
gfx::WindowOptions canvas_options(const PlatformOptions& o) {
    const float r = canvas_ratio(o);
    gfx::WindowOptions w;
    w.title = o.title;
    w.width = o.width > 0 ? o.width : static_cast<int>(std::lround(1280 * r));
    w.height = o.height > 0 ? o.height : static_cast<int>(std::lround(800 * r));
    w.scale_to_monitor = false;
    return w;
}

class WebPlatform final : public GlfwPlatform {
  public:
    explicit WebPlatform(const PlatformOptions& o)
        : GlfwPlatform(canvas_options(o)), ratio_(canvas_ratio(o)) {}

    std::string_view name() const override { return "web"; }
    float pixel_ratio() const override { return ratio_; }
    void imgui_new_frame(gfx::Vec2 logical) override {
        GlfwPlatform::imgui_new_frame(logical);
        // Under Chromium's --virtual-time-budget (the tests) the clock stands still: ImGui needs time to
        // pass.
        ImGuiIO& io = ImGui::GetIO();
        if (!(io.DeltaTime > 0)) io.DeltaTime = 1.0f / 60.0f;
    }
    // Back to the browser, which shows the frame and delivers input, for what is left of 1/60 s since the
    // last frame (at least 1 ms). A timer, not a busy wait: under a virtual time budget (the tests) the
    // page's clock moves only with its timers.
    void present() override {
        ctx_.present();
        fv_web_frame_shown();
        const double now = emscripten_get_now();
        const double wait = last_present_ > 0 ? 1000.0 / 60 - (now - last_present_) : 1000.0 / 60;
        emscripten_sleep(static_cast<unsigned>(wait > 1 ? wait : 1));
        last_present_ = emscripten_get_now();
    }

    void rest_after_frame(double /*frame_ms*/) override {} // present() paced the frame

    bool choose_file(const std::string& accept) override {
        fv_web_choose_file(accept.c_str());
        return true;
    }
    void file_written(const std::string& path) override { fv_web_download(path.c_str()); }

  private:
    float ratio_;
    double last_present_ = 0; // emscripten_get_now() after the last frame, ms
};

} // namespace

std::unique_ptr<Platform> make_web_platform(const PlatformOptions& options) {
    return std::make_unique<WebPlatform>(options);
}

} // namespace fv::app
