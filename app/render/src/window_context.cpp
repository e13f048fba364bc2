// Window backend: a GLFW window (desktop: GLFW 3.3, core forward-compatible 3.3 context, HiDPI aware; the
// browser: the page's canvas with a WebGL 2 context). What differs is in port.hpp.
#include "port.hpp"

#include "fv/gfx/context.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <utility>

namespace fv::gfx {
namespace {

std::string g_last_glfw_error; // GLFW reports errors through a callback; keep the last one for messages.
int g_glfw_users = 0;          // glfwInit/glfwTerminate are process-wide: count windows.

void on_glfw_error(int /*code*/, const char* description) {
    g_last_glfw_error = description ? description : "?";
}

} // namespace

WindowContext::WindowContext(const WindowOptions& o) {
    port::check_window_possible();
    glfwSetErrorCallback(&on_glfw_error);
    if (g_glfw_users == 0 && glfwInit() != GLFW_TRUE)
        throw std::runtime_error("GLFW init failed: " + g_last_glfw_error);
    ++g_glfw_users;
    glfwDefaultWindowHints();
    port::set_window_hints(o);
    glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0); // Our primitives antialias themselves; MSAA would change pixels.
    window_ = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
    if (!window_) {
        if (--g_glfw_users == 0) glfwTerminate();
        throw std::runtime_error(std::string("could not ") + port::window_kind() + ": " + g_last_glfw_error);
    }
    // The ImGui GLFW backend (1.86) installs no drop callback and does not use the user pointer.
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        auto* self = static_cast<WindowContext*>(glfwGetWindowUserPointer(w));
        for (int k = 0; k < count; ++k) self->dropped_.emplace_back(paths[k]);
    });
    glfwMakeContextCurrent(window_);
    port::load_window_gl(gl_);
}

WindowContext::~WindowContext() {
    glfwDestroyWindow(window_);
    if (--g_glfw_users == 0) glfwTerminate();
}

std::vector<std::string> WindowContext::take_dropped_paths() {
    return std::exchange(dropped_, {});
}

Size WindowContext::framebuffer_size() const {
    Size s;
    glfwGetFramebufferSize(window_, &s.width, &s.height);
    return s;
}

Size WindowContext::logical_size() const {
    Size s;
    glfwGetWindowSize(window_, &s.width, &s.height);
    return s;
}

void WindowContext::make_current() {
    glfwMakeContextCurrent(window_);
}
void WindowContext::present() {
    glfwSwapBuffers(window_);
}
float WindowContext::content_scale() const {
    return port::content_scale(window_);
}
bool WindowContext::should_close() const {
    return glfwWindowShouldClose(window_) != 0;
}
void WindowContext::poll_events() {
    glfwPollEvents();
}

std::string WindowContext::describe() const {
    return "GLFW window, " + gl_.describe();
}

} // namespace fv::gfx
