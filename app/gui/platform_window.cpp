// The window platform: a GLFW window (its GL context lives in the render layer, gfx::WindowContext) with
// Dear ImGui's GLFW input backend. The only place in the app that calls GLFW or an ImGui platform backend.
#include "platform.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cfloat>
#include <cmath>

namespace fv::app {
namespace {

gfx::WindowOptions window_options(const PlatformOptions& o) {
    gfx::WindowOptions w;
    w.title = o.title;
    if (o.width > 0 || o.scale > 0) {
        // A size or scale given: the framebuffer in pixels is what was asked for (window units are pixels
        // on X11), so that --size/--scale mean the same picture as headless.
        const float s = o.scale > 0 ? o.scale : 1.0f;
        w.width = o.width > 0 ? o.width : static_cast<int>(std::lround(1280 * s));
        w.height = o.height > 0 ? o.height : static_cast<int>(std::lround(800 * s));
        w.scale_to_monitor = false;
    }
    return w;
}

class WindowPlatform final : public Platform {
  public:
    explicit WindowPlatform(const PlatformOptions& o) : scale_(o.scale), ctx_(window_options(o)) {}
    ~WindowPlatform() override { disconnect_imgui(); }

    std::string_view name() const override { return "window"; }
    gfx::GpuContext& context() override { return ctx_; }
    // Given: as asked. Else the monitor's content scale (2 on a HiDPI screen, also on X11 where the window
    // is counted in pixels).
    float pixel_ratio() const override { return scale_ > 0 ? scale_ : ctx_.content_scale(); }
    bool interactive() const override { return true; }
    void connect_imgui() override {
        if (!connected_) connected_ = ImGui_ImplGlfw_InitForOpenGL(ctx_.native(), true);
    }
    void disconnect_imgui() override {
        if (connected_) ImGui_ImplGlfw_Shutdown();
        connected_ = false;
    }
    PlatformEvents poll() override {
        ctx_.poll_events();
        const bool f1 = glfwGetKey(ctx_.native(), GLFW_KEY_F1) == GLFW_PRESS;
        const bool pressed = f1 && !f1_down_;
        f1_down_ = f1;
        return {ctx_.should_close(), ctx_.take_dropped_paths(), pressed};
    }
    void imgui_new_frame(gfx::Vec2 logical) override {
        ImGui_ImplGlfw_NewFrame(); // mouse, keys, time, all in window units
        // Window units to logical units: 1 where the OS scales the window (Wayland, macOS), 1 / content
        // scale on X11, whose windows are counted in pixels.
        ImGuiIO& io = ImGui::GetIO();
        const gfx::Size win = ctx_.logical_size();
        const float kx = win.width > 0 ? logical.x / static_cast<float>(win.width) : 1.0f;
        const float ky = win.height > 0 ? logical.y / static_cast<float>(win.height) : 1.0f;
        if (io.MousePos.x > -FLT_MAX / 2) io.MousePos = ImVec2(io.MousePos.x * kx, io.MousePos.y * ky);
        io.DisplaySize = ImVec2(logical.x, logical.y);
        const float r = pixel_ratio();
        io.DisplayFramebufferScale = ImVec2(r, r);
    }
    void present() override { ctx_.present(); }

  private:
    float scale_;
    gfx::WindowContext ctx_;
    bool connected_ = false;
    bool f1_down_ = false;
};

} // namespace

std::unique_ptr<Platform> make_window_platform(const PlatformOptions& options) {
    return std::make_unique<WindowPlatform>(options);
}

} // namespace fv::app
