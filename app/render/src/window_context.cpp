// Window backend: GLFW 3.3, core forward-compatible 3.3 context, HiDPI aware.
// In the browser build the "window" is the page's canvas through emscripten's GLFW (the 3.2 API) with a WebGL
// 2 (OpenGL ES 3.0) context, and the GL table comes from emscripten's WebGL library (linked_gl_proc).
#include "fv/gfx/context.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace fv::gfx {
namespace {

std::string g_last_glfw_error; // GLFW reports errors through a callback; keep the last one for messages.
int g_glfw_users = 0;          // glfwInit/glfwTerminate are process-wide: count windows.

void on_glfw_error(int /*code*/, const char* description) {
    g_last_glfw_error = description ? description : "?";
}

#if !defined(__EMSCRIPTEN__)
void* glfw_loader(const char* name) {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

bool env_set(const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0';
}
#endif

} // namespace

WindowContext::WindowContext(const WindowOptions& o) {
#if !defined(__EMSCRIPTEN__)
    if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY"))
        throw std::runtime_error("no display (neither DISPLAY nor WAYLAND_DISPLAY is set)");
#endif
    glfwSetErrorCallback(&on_glfw_error);
    if (g_glfw_users == 0 && glfwInit() != GLFW_TRUE)
        throw std::runtime_error("GLFW init failed: " + g_last_glfw_error);
    ++g_glfw_users;
    glfwDefaultWindowHints();
#if defined(__EMSCRIPTEN__)
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API); // WebGL 2 (link flags: web/CMakeLists.txt)
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
#else
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, o.scale_to_monitor ? GLFW_TRUE : GLFW_FALSE);
#endif
    glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0); // Our primitives antialias themselves; MSAA would change pixels.
    window_ = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
    if (!window_) {
        if (--g_glfw_users == 0) glfwTerminate();
#if defined(__EMSCRIPTEN__)
        throw std::runtime_error("could not create a WebGL 2 context: " + g_last_glfw_error);
#else
        throw std::runtime_error("could not open a GL 3.3 core window: " + g_last_glfw_error);
#endif
    }
    // The ImGui GLFW backend (1.86) installs no drop callback and does not use the user pointer.
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        auto* self = static_cast<WindowContext*>(glfwGetWindowUserPointer(w));
        for (int k = 0; k < count; ++k) self->dropped_.emplace_back(paths[k]);
    });
    glfwMakeContextCurrent(window_);
#if defined(__EMSCRIPTEN__)
    gl_.load(&linked_gl_proc); // the browser paces frames itself (requestAnimationFrame)
#else
    glfwSwapInterval(1);
    gl_.load(&glfw_loader);
#endif
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
#if defined(__EMSCRIPTEN__)
    return 1.0f; // emscripten's GLFW (3.2 API) has no content scale; its canvas is in CSS pixels
#else
    float x = 1, y = 1;
    glfwGetWindowContentScale(window_, &x, &y);
    return x > 0 ? x : 1.0f;
#endif
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
