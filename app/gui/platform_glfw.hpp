// What the window and web platforms share (platform_window.cpp, platform_web.cpp): a GLFW window with its GL
// context (gfx::WindowContext, in the render layer; the page's canvas in the browser) and Dear ImGui's GLFW
// input backend. Only these adapters call GLFW or an ImGui platform backend.
#pragma once

#include "platform.hpp"

namespace fv::app {

class GlfwPlatform : public Platform {
  public:
    ~GlfwPlatform() override { disconnect_imgui(); }

    gfx::GpuContext& context() override { return ctx_; }
    bool interactive() const override { return true; }
    void connect_imgui() override;
    void disconnect_imgui() override;
    // Events, the window's close button, drops, and F1 as it goes down.
    PlatformEvents poll() override;
    // ImGui's GLFW backend (mouse, keys, time in window units), the mouse scaled from window units to the
    // logical page, the display size and the framebuffer scale (pixel_ratio()).
    void imgui_new_frame(gfx::Vec2 logical) override;

  protected:
    explicit GlfwPlatform(const gfx::WindowOptions& window) : ctx_(window) {}
    gfx::WindowContext ctx_;

  private:
    bool connected_ = false;
    bool f1_down_ = false;
};

} // namespace fv::app
