// The browser side of port.hpp: the page's canvas through emscripten's GLFW (the 3.2 API) with a WebGL 2
// (OpenGL ES 3.0) context, the GL table from emscripten's WebGL 2 library; no headless context.
#include "port.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstring>
#include <stdexcept>

namespace fv::gfx::port {
namespace {

// The entry points of FV_GL_FUNCTIONS as linked from emscripten's WebGL 2 library, by name (null for any
// other name, e.g. glDrawElementsBaseVertex, which WebGL 2 lacks).
void* linked_gl_proc(const char* name) {
    struct Entry {
        const char* name;
        void* proc;
    };
#define FV_GL_ENTRY(type, member, symbol) {#symbol, reinterpret_cast<void*>(&::symbol)},
    static const Entry table[] = {FV_GL_FUNCTIONS(FV_GL_ENTRY)};
#undef FV_GL_ENTRY
    for (const Entry& e : table)
        if (std::strcmp(e.name, name) == 0) return e.proc;
    return nullptr;
}

} // namespace

void check_window_possible() {} // the page's canvas is always there

void set_window_hints(const WindowOptions& /*o*/) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API); // WebGL 2 (link flags: app/render/CMakeLists.txt)
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    // The canvas's WebGL context attributes (emscripten's GLFW reads them from these hints): no depth or
    // stencil buffer (nothing tests depth or stencil), and an opaque canvas (alpha: false; every frame starts
    // with an opaque clear and blending keeps alpha at 1, so no pixel changes). Emscripten's defaults ask for
    // both buffers and an alpha channel: the browser then clears the depth and stencil buffers for every
    // frame (the app clears colour only) and composites the canvas as translucent over the page. With
    // SwiftShader (software WebGL) that cost the GPU process up to about 1.5 ms of CPU per frame
    // (docs/web.md, Measured).
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    glfwWindowHint(GLFW_ALPHA_BITS, 0);
}

const char* window_kind() {
    return "create a WebGL 2 context";
}

void load_window_gl(GlApi& gl) {
    gl.load(&linked_gl_proc); // the browser paces frames itself (requestAnimationFrame)
}

float content_scale(GLFWwindow* /*window*/) {
    return 1.0f; // emscripten's GLFW (3.2 API) has no content scale; its canvas is in CSS pixels
}

std::unique_ptr<GpuContext> make_headless(const ContextOptions& /*options*/) {
    throw std::runtime_error("no headless (OSMesa) backend in the browser build");
}

} // namespace fv::gfx::port
