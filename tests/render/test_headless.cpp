// Renders small scenes with the headless (OSMesa) backend.
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/compare.hpp"
#include "fv/gfx/context.hpp"
#include "fv/gfx/fonts.hpp"
#include "fv/gfx/imgui_renderer.hpp"
#include "fv/gfx/plot.hpp"
#include "fv/gfx/png.hpp"

#include <catch2/catch.hpp>
#include <imgui.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>

using namespace fv::gfx;

namespace {

struct Rig {
    HeadlessContext ctx{320, 240};
    FontSet fonts;
    ImGuiRenderer imgui{ctx.gl()};
    std::unique_ptr<Canvas> canvas;
    Rig() {
        imgui.upload_font_atlas(fonts.atlas());
        canvas = std::make_unique<Canvas>(ctx.gl(), fonts, imgui);
    }
    Image render(const std::function<void(Canvas&)>& draw) {
        canvas->begin({320, 240}, 1, colors::white);
        draw(*canvas);
        canvas->end();
        return ctx.read_pixels();
    }
};

Rig& rig() {
    static Rig r; // One OSMesa context for all tests.
    return r;
}

bool is_white(const Image& img, int x, int y) {
    const std::uint8_t* p = img.pixel(x, y);
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

} // namespace

TEST_CASE("readback is top-down and opaque") {
    const Image img = rig().render([](Canvas& c) { c.fill_rect({0, 0, 320, 10}, Color::hex(0xFF0000)); });
    REQUIRE(img.width == 320);
    CHECK(img.pixel(5, 5)[0] == 255);
    CHECK(img.pixel(5, 5)[1] == 0);
    CHECK(is_white(img, 5, 20));
    CHECK(img.pixel(5, 200)[3] == 255);
}

TEST_CASE("the same drawing twice gives identical pixels") {
    auto scene = [](Canvas& c) {
        Plot p({0, 0, 320, 240});
        p.title = "θ = 90°, r_{disp} = 2";
        p.x_axis.title = "ζ";
        p.add_series("a", {0, 1, 2, 3}, {0, 1, 0.5, 2}, {std::nullopt, 2, LineStyle::Dashed});
        p.draw(c);
    };
    const Image a = rig().render(scene), b = rig().render(scene);
    CHECK(a.rgba == b.rgba);
}

TEST_CASE("a NaN point breaks the line") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    PlotTransform tf;
    const Image img = rig().render([&](Canvas& c) {
        Plot p({0, 0, 320, 240});
        p.legend = LegendPosition::None;
        p.x_axis.grid = p.y_axis.grid = false;
        p.y_axis.set_range(0, 2);
        p.x_axis.set_range(0, 4);
        p.add_series("", {0, 1, 2, 3, 4}, {1, 1, nan, 1, 1});
        tf = p.layout(c);
        p.draw(c);
    });
    const Vec2 on = tf.to_pixel(0.5, 1), gap = tf.to_pixel(2, 1);
    CHECK_FALSE(is_white(img, static_cast<int>(on.x), static_cast<int>(on.y)));
    CHECK(is_white(img, static_cast<int>(gap.x), static_cast<int>(gap.y)));
}

TEST_CASE("degenerate data ranges give a finite layout") {
    rig().render([](Canvas& c) {
        Plot empty({0, 0, 320, 240});
        const PlotTransform t0 = empty.layout(c);
        CHECK(t0.x1 > t0.x0);
        Plot flat({0, 0, 320, 240});
        flat.add_series("", {1, 1, 1}, {5, 5, 5});
        const PlotTransform t1 = flat.layout(c);
        CHECK(t1.x1 > t1.x0);
        CHECK(t1.y1 > t1.y0);
        CHECK(std::isfinite(t1.to_pixel(1, 5).x));
        Plot logp({0, 0, 320, 240});
        logp.x_axis.log = true;
        logp.add_series("", {0, 1, 10, 100}, {1, 2, 3, 4}); // 0 is skipped on a log axis
        const PlotTransform t2 = logp.layout(c);
        CHECK(t2.x0 > 0);
        flat.draw(c);
        logp.draw(c);
    });
}

TEST_CASE("equal aspect gives the same pixels per unit on both axes") {
    rig().render([](Canvas& c) {
        Plot p({0, 0, 320, 240});
        p.equal_aspect = true;
        p.add_series("", {0, 2}, {-1, 1});
        const PlotTransform t = p.layout(c);
        const double sx = t.area.width() / (t.x1 - t.x0), sy = t.area.height() / (t.y1 - t.y0);
        CHECK(sx == Approx(sy).epsilon(1e-6));
    });
}

TEST_CASE("markup subscripts are narrower than the plain text") {
    const FontSet& f = rig().fonts;
    CHECK(measure_text(f, "r_{disp}", 14).x < measure_text(f, "rdisp", 14).x);
    CHECK(measure_text(f, "r_{disp}", 14, false).x > measure_text(f, "rdisp", 14).x);
}

namespace {

// Every kind of primitive: dashed and solid polylines, markers of each shape, a triangle, rectangles, a
// circle, an image, text with sub- and superscripts, a clip.
void every_primitive(Canvas& c) {
    Plot p({0, 0, 320, 240});
    p.title = "θ = 90°, r_{disp} = 2, 10^{−3}";
    p.x_axis.title = "ζ";
    p.add_series("a", {0, 1, 2, 3}, {0, 1, 0.5, 2}, {std::nullopt, 2, LineStyle::Dashed});
    p.add_series("b", {0, 1, 2, 3}, {2, 0.5, 1.5, 0.2}, {std::nullopt, 1.5, LineStyle::Solid});
    p.draw(c);
    const MarkerShape shapes[] = {MarkerShape::Circle,  MarkerShape::Square, MarkerShape::Triangle,
                                  MarkerShape::Diamond, MarkerShape::Cross,  MarkerShape::Plus};
    float x = 60;
    for (MarkerShape s : shapes) {
        c.marker({x, 200}, {s, 9, Color::hex(0xE69F00), colors::black, 1});
        x += 20;
    }
    c.fill_triangle({200, 180}, {240, 220}, {180, 225}, Color::hex(0x56B4E9));
    c.circle({270, 200}, 15, {Color::hex(0x009E73), 2});
    Image img(4, 2);
    for (std::size_t k = 0; k < img.rgba.size(); ++k) img.rgba[k] = static_cast<std::uint8_t>(k * 29);
    c.image({280, 40, 310, 60}, img);
}

// Many lines of text in one batch: more than 65536 vertices in one ImDrawList, so that its later commands
// start at a vertex offset (ImDrawListFlags_AllowVtxOffset with 16-bit indices).
void much_text(Canvas& c) {
    for (int pass = 0; pass < 20; ++pass)
        for (int row = 0; row < 22; ++row)
            c.text({2, 2 + 10.5f * static_cast<float>(row)},
                   "The asperity tip T trails the body point P; ζ θ r_{disp} 0123456789", {10});
}

// Pixel-exact comparison, reported as the largest channel difference and the share of differing pixels
// (the diff image is written to DIFF_PATH for a look).
bool same_pixels(const Image& actual, const Image& expected, const char* diff_path) {
    const ImageComparison cmp = compare_images(actual, expected, 0, 0.0);
    INFO("max channel difference " << cmp.max_channel_diff << ", differing share " << cmp.differing_share);
    if (!cmp.passed && !cmp.diff.empty()) {
        const std::vector<unsigned char> png = encode_png(cmp.diff);
        std::ofstream(diff_path, std::ios::binary)
            .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    }
    CHECK(cmp.passed);
    return cmp.passed;
}

// The rig's drawing with another GL table (a copy of the context's, changed by `change`).
Image render_with(const std::function<void(GlApi&)>& change, const std::function<void(Canvas&)>& draw) {
    static GlApi gl; // outlives the renderers below, which keep a reference
    gl = rig().ctx.gl();
    change(gl);
    ImFontAtlas& atlas = rig().fonts.atlas();
    const ImTextureID rig_texture = atlas.TexID; // the rig's renderer owns it; this one uploads its own
    ImGuiRenderer imgui(gl);
    imgui.upload_font_atlas(atlas);
    Canvas canvas(gl, rig().fonts, imgui);
    canvas.begin({320, 240}, 1, colors::white);
    draw(canvas);
    canvas.end();
    atlas.SetTexID(rig_texture);
    return rig().ctx.read_pixels();
}

} // namespace

TEST_CASE("the GLSL ES 3.00 shaders (browser build) draw the same pixels as 330 core", "[web]") {
    // OSMesa's core context is GL 4.5, which compiles GLSL ES 3.00 (ARB_ES3_compatibility).
    for (auto draw : {&every_primitive, &much_text}) {
        const Image desktop = rig().render(draw);
        const Image es = render_with([](GlApi& gl) { gl.glsl = GlslDialect::es300; }, draw);
        same_pixels(es, desktop, "es300-diff.png");
    }
}

TEST_CASE("without glDrawElementsBaseVertex (WebGL 2) text at vertex offsets draws the same pixels",
          "[web]") {
    const Image with = rig().render(&much_text);
    const Image without = render_with([](GlApi& gl) { gl.DrawElementsBaseVertex = nullptr; }, &much_text);
    same_pixels(without, with, "base-vertex-diff.png");
    // Not a trivial pass: the drawing without offsets differs (later glyphs would come from the wrong
    // vertices).
    const Image wrong = render_with(
        [](GlApi& gl) {
            gl.DrawElementsBaseVertex = [](GLenum mode, GLsizei count, GLenum type, const void* indices,
                                           GLint) {
                rig().ctx.gl().DrawElements(mode, count, type, indices);
            };
        },
        &much_text);
    CHECK(wrong.rgba != with.rgba);
}
