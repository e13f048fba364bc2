// What differs between the desktop and the browser build of the render layer, in one place: the build
// compiles port_desktop.cpp or port_web.cpp (app/render/CMakeLists.txt), and no other source of the layer
// asks which one it is in. (Header-level differences - which GL header declares the entry points, the
// GLSL dialect's default - stay in gl_api.hpp.)
#pragma once

#include "fv/gfx/context.hpp"

#include <memory>

struct GLFWwindow;

namespace fv::gfx::port {

// Throws std::runtime_error with the reason where no window can open at all (the desktop without a display).
void check_window_possible();
// The GLFW hints for the window's context: OpenGL 3.3 core (desktop) or WebGL 2, i.e. OpenGL ES 3.0.
void set_window_hints(const WindowOptions& o);
// What could not be created when glfwCreateWindow fails ("a GL 3.3 core window", "a WebGL 2 context").
const char* window_kind();
// With the window's context current: the GL table filled (and the desktop's swap interval set to 1; the
// browser paces frames itself).
void load_window_gl(GlApi& gl);
// The window's content scale (the browser's canvas is in CSS pixels: 1).
float content_scale(GLFWwindow* window);
// The headless (OSMesa) context, or std::runtime_error where there is none (the browser).
std::unique_ptr<GpuContext> make_headless(const ContextOptions& options);

} // namespace fv::gfx::port
