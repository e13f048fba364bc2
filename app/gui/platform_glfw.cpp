#include "platform_glfw.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cfloat>

namespace fv::app {

void GlfwPlatform::connect_imgui() {
    if (!connected_) connected_ = ImGui_ImplGlfw_InitForOpenGL(ctx_.native(), true);
}

void GlfwPlatform::disconnect_imgui() {
    if (connected_) ImGui_ImplGlfw_Shutdown();
    connected_ = false;
}

PlatformEvents GlfwPlatform::poll() {
    ctx_.poll_events();
    const bool f1 = glfwGetKey(ctx_.native(), GLFW_KEY_F1) == GLFW_PRESS;
    const bool pressed = f1 && !f1_down_;
    f1_down_ = f1;
    return {ctx_.should_close(), ctx_.take_dropped_paths(), pressed};
}

void GlfwPlatform::imgui_new_frame(gfx::Vec2 logical) {
    ImGui_ImplGlfw_NewFrame(); // mouse, keys, time, all in window units
    // Window units to logical units: 1 where the OS scales the window (Wayland, macOS) and in the browser
    // (CSS pixels), 1 / content scale on X11, whose windows are counted in pixels.
    ImGuiIO& io = ImGui::GetIO();
    const gfx::Size win = ctx_.logical_size();
    const float kx = win.width > 0 ? logical.x / static_cast<float>(win.width) : 1.0f;
    const float ky = win.height > 0 ? logical.y / static_cast<float>(win.height) : 1.0f;
    if (io.MousePos.x > -FLT_MAX / 2) io.MousePos = ImVec2(io.MousePos.x * kx, io.MousePos.y * ky);
    io.DisplaySize = ImVec2(logical.x, logical.y);
    const float r = pixel_ratio();
    io.DisplayFramebufferScale = ImVec2(r, r);
}

} // namespace fv::app
