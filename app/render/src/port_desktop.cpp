// The desktop side of port.hpp: GLFW 3.3 windows with an OpenGL 3.3 core context, headless through OSMesa.
#include "port.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <stdexcept>

namespace fv::gfx::port {
namespace {

bool env_set(const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0';
}

void* glfw_loader(const char* name) {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

} // namespace

void check_window_possible() {
    if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY"))
        throw std::runtime_error("no display (neither DISPLAY nor WAYLAND_DISPLAY is set)");
}

void set_window_hints(const WindowOptions& o) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, o.scale_to_monitor ? GLFW_TRUE : GLFW_FALSE);
}

const char* window_kind() {
    return "open a GL 3.3 core window";
}

void load_window_gl(GlApi& gl) {
    glfwSwapInterval(1);
    gl.load(&glfw_loader);
}

float content_scale(GLFWwindow* window) {
    float x = 1, y = 1;
    glfwGetWindowContentScale(window, &x, &y);
    return x > 0 ? x : 1.0f;
}

std::unique_ptr<GpuContext> make_headless(const ContextOptions& options) {
    return std::make_unique<HeadlessContext>(options.width, options.height, options.scale);
}

} // namespace fv::gfx::port
