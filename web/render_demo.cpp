// The render layer's demo page (app/render/demo) in the browser: WebGL 2 through emscripten's GLFW, the same
// canvas, plots, text and shaders (as GLSL ES 3.00) as the desktop. The web test screenshots it in headless
// Chromium and compares it with fvrender_demo's headless (OSMesa) PNG.
#include "demo_page.hpp"

#include "fv/gfx/canvas.hpp"
#include "fv/gfx/context.hpp"
#include "fv/gfx/fonts.hpp"
#include "fv/gfx/imgui_renderer.hpp"

#include <emscripten.h>

#include <cstdio>
#include <exception>
#include <memory>

namespace {

using namespace fv::gfx;

struct Demo {
    std::unique_ptr<GpuContext> ctx;
    std::unique_ptr<FontSet> fonts;
    std::unique_ptr<ImGuiRenderer> imgui;
    std::unique_ptr<Canvas> canvas;
    int frames = 0;
};

void frame(void* arg) {
    auto& d = *static_cast<Demo*>(arg);
    d.canvas->begin({1280, 800}, 1.0f, colors::white);
    fv::demo::draw_demo_page(*d.canvas);
    d.canvas->end();
    d.ctx->present();
    // The page's title says when a frame is complete (the test waits for frame 2, as the desktop captures).
    if (++d.frames == 2) emscripten_run_script("document.title = 'fvrender demo: drawn'");
}

} // namespace

int main() {
    static Demo d;
    try {
        ContextOptions opt;
        opt.backend = Backend::Window;
        opt.width = 1280, opt.height = 800, opt.title = "fvrender demo";
        d.ctx = create_context(opt);
        d.fonts = std::make_unique<FontSet>();
        d.imgui = std::make_unique<ImGuiRenderer>(d.ctx->gl());
        d.imgui->upload_font_atlas(d.fonts->atlas());
        d.canvas = std::make_unique<Canvas>(d.ctx->gl(), *d.fonts, *d.imgui);
        std::printf("%s\n", d.ctx->describe().c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fvrender demo: %s\n", e.what());
        return 1;
    }
    emscripten_set_main_loop_arg(&frame, &d, 0, 0);
    return 0;
}
