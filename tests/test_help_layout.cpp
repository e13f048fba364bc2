// The help overlay laid out by Dear ImGui itself (the app's fonts, no GL: the atlas is built on the CPU) at
// the sizes a lecture meets: no term runs into its meaning, the window stays inside the area beside the
// panel, and rows that do not fit are reached by scrolling, in normal (15 px) and presentation (22 px) type.
#include "gui/help_overlay.hpp"

#include "fv/gfx/fonts.hpp"

#include <catch2/catch.hpp>
#include <imgui.h>

namespace {

fv::app::HelpLayout lay_out(float width, float height, float font_px, float panel_w) {
    fv::gfx::FontSet fonts;
    ImGuiContext* ctx = ImGui::CreateContext(&fonts.atlas());
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(width, height);
    io.DeltaTime = 1.0f / 60;
    io.FontDefault = fonts.font_for(font_px);
    fv::app::HelpLayout layout;
    // A few frames: ImGui sizes an auto-fitting window from the frame before.
    for (int frame = 0; frame < 4; ++frame) {
        ImGui::NewFrame();
        fv::app::draw_help_overlay(true, {panel_w, 0, width, height}, &layout);
        ImGui::Render();
    }
    ImGui::DestroyContext(ctx);
    return layout;
}

} // namespace

TEST_CASE("help overlay: columns from the widest term, inside the area, scrolling when too tall",
          "[gui][help][layout]") {
    struct Case {
        float w, h, font, panel;
    };
    // The app's panel is 340 wide, 450 in presentation mode (gui_app.cpp).
    const Case cases[] = {{1280, 800, 15, 340},
                          {1280, 800, 22, 450},
                          {1920, 1080, 15, 340},
                          {1920, 1080, 22, 450},
                          {1024, 640, 22, 450}};
    for (const Case& c : cases) {
        INFO(c.w << "x" << c.h << " at " << c.font << " px");
        const fv::app::HelpLayout l = lay_out(c.w, c.h, c.font, c.panel);
        CHECK(l.term_right > c.panel);
        CHECK(l.term_right < l.meaning_left); // no term overlaps the meanings' column
        CHECK(l.window.x0 >= c.panel);
        CHECK(l.window.x1 <= c.w);
        CHECK(l.window.y0 >= 0);
        CHECK(l.window.y1 <= c.h);               // nothing below the screen's edge ...
        if (c.h == 640) CHECK(l.scroll_max > 0); // ... the rows that do not fit scroll into view
    }
}
