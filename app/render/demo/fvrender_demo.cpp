// fvrender_demo: renders the demo page headless (OSMesa) or in a GLFW window and writes a PNG.
//   fvrender_demo OUT.png [--window] [--imgui] [--page2] [--scale N] [--compare EXPECTED.png [DIFF.png]]
// --window reads back the window's framebuffer, so under xvfb-run the two backends can be compared.
#include "demo_page.hpp"

#include "fv/gfx/canvas.hpp"
#include "fv/gfx/compare.hpp"
#include "fv/gfx/context.hpp"
#include "fv/gfx/fonts.hpp"
#include "fv/gfx/imgui_renderer.hpp"
#include "fv/gfx/png.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using namespace fv::gfx;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

void write_file(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!f) throw std::runtime_error("cannot write " + path);
}

std::vector<unsigned char> read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read " + path);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// A small ImGui panel rendered through our ImGuiRenderer, to exercise it with a real ImGui frame.
void imgui_panel(ImGuiRenderer& r, Vec2 size, float ratio) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(size.x, size.y);
    io.DisplayFramebufferScale = ImVec2(ratio, ratio);
    io.DeltaTime = 1.0f / 60.0f; // Fixed: no clocks, deterministic output.
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(size.x - 300, size.y - 230), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(280, 120), ImGuiCond_Always);
    ImGui::Begin("Parameters (ImGui)");
    static float zeta = 0.15f, theta = 90.0f;
    ImGui::SliderFloat("ζ", &zeta, 0.0f, 3.0f);
    ImGui::SliderFloat("θ [°]", &theta, 0.0f, 90.0f);
    ImGui::Text("r_disp = 2, i = 1");
    ImGui::End();
    ImGui::Render();
    r.render(*ImGui::GetDrawData());
}

int run(int argc, char** argv) {
    std::string out, compare_path, diff_path;
    bool window = false, with_imgui = false, page2 = false;
    int scale = 1; // --scale 2: headless HiDPI check (2x framebuffer, same logical page).
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--window") {
            window = true;
        } else if (a == "--scale" && i + 1 < argc) {
            scale = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--page2") {
            page2 = true;
        } else if (a == "--imgui") {
            with_imgui = true;
        } else if (a == "--compare" && i + 1 < argc) {
            compare_path = argv[++i];
            if (i + 1 < argc && argv[i + 1][0] != '-') diff_path = argv[++i];
        } else if (out.empty() && a[0] != '-') {
            out = a;
        } else {
            std::fprintf(stderr, "unknown argument: %s\n", a.c_str());
            return 2;
        }
    }
    if (out.empty()) {
        std::fprintf(stderr,
                     "usage: fvrender_demo OUT.png [--window] [--imgui] [--page2] [--scale N] [--compare "
                     "EXPECTED.png [DIFF.png]]\n");
        return 2;
    }

    ContextOptions opt;
    opt.backend = window ? Backend::Window : Backend::Headless;
    opt.width = 1280 * (window ? 1 : scale), opt.height = 800 * (window ? 1 : scale),
    opt.title = "fvrender demo";
    auto t0 = Clock::now();
    std::unique_ptr<GpuContext> ctx = create_context(opt);
    // Logical page is always 1280x800; the ratio maps it to framebuffer pixels.
    const float ratio = window ? ctx->pixel_ratio() : static_cast<float>(scale);
    FontSetOptions fo;
    fo.pixel_ratio = ratio;
    FontSet fonts(fo);
    ImGuiRenderer imgui(ctx->gl());
    imgui.upload_font_atlas(fonts.atlas());
    Canvas canvas(ctx->gl(), fonts, imgui);
    std::printf("%s\nsetup (context, fonts, shaders): %.1f ms\n", ctx->describe().c_str(), ms_since(t0));
    const Size fs = ctx->framebuffer_size();
    const Vec2 logical{static_cast<float>(fs.width) / ratio, static_cast<float>(fs.height) / ratio};

    ImGuiContext* imgui_ctx = nullptr;
    if (with_imgui) {
        imgui_ctx = ImGui::CreateContext(&fonts.atlas());
        ImGui::GetIO().IniFilename = nullptr;
        ImGui::GetIO().FontDefault = fonts.font_for(14);
        ImGui::StyleColorsLight();
    }

    // Warm-up frames (ImGui draws some decorations only from frame 2), then timed frames.
    const int warmup = 2, timed = 10;
    Image first, last;
    double render_ms = 0;
    for (int f = 0; f < warmup + timed; ++f) {
        const auto tf = Clock::now();
        canvas.begin(logical, ratio, colors::white);
        if (page2)
            fv::demo::draw_heatmap_page(canvas);
        else
            fv::demo::draw_demo_page(canvas);
        canvas.end();
        if (with_imgui) imgui_panel(imgui, logical, ratio);
        ctx->gl().Finish();
        if (f >= warmup) render_ms += ms_since(tf);
        if (f == warmup - 1) first = ctx->read_pixels();
        if (f == warmup + timed - 1) last = ctx->read_pixels();
        ctx->present();
    }
    std::printf("render one %dx%d frame: %.2f ms (mean of %d)\n", last.width, last.height, render_ms / timed,
                timed);
    std::printf("frame %d vs frame %d byte-identical: %s\n", warmup, warmup + timed,
                first.rgba == last.rgba ? "yes" : "NO");

    t0 = Clock::now();
    const std::vector<unsigned char> png = encode_png(last);
    std::printf("encode PNG: %.1f ms (%zu bytes)\n", ms_since(t0), png.size());
    write_file(out, png);
    std::printf("wrote %s\n", out.c_str());

    int rc = 0;
    if (!compare_path.empty()) {
        const Image expected = decode_png(read_file(compare_path));
        const ImageComparison cmp = compare_images(last, expected, 0, 0.0);
        std::printf("compare with %s: max channel diff %d, differing share %.6f -> %s\n",
                    compare_path.c_str(), cmp.max_channel_diff, cmp.differing_share,
                    cmp.passed ? "identical" : "DIFFERENT");
        if (!diff_path.empty() && !cmp.diff.empty()) write_file(diff_path, encode_png(cmp.diff));
        rc = cmp.passed ? 0 : 1;
    }
    if (imgui_ctx) ImGui::DestroyContext(imgui_ctx);
    return rc;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fvrender_demo: %s\n", e.what());
        return 1;
    }
}
