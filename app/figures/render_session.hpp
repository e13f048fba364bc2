// Everything needed to draw: a GL context (headless or window, chosen by the caller through one option),
// the fonts, the ImGui draw-data renderer and the canvas. The figure code only ever sees the canvas.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/context.hpp"
#include "fv/gfx/fonts.hpp"
#include "fv/gfx/image.hpp"
#include "fv/gfx/imgui_renderer.hpp"

#include <memory>

namespace fv::app {

class RenderSession {
  public:
    // Throws std::runtime_error with a one-line reason if no context can be made.
    explicit RenderSession(const gfx::ContextOptions& options);

    gfx::GpuContext& context() { return *ctx_; }
    gfx::Canvas& canvas() { return canvas_; }
    gfx::FontSet& fonts() { return fonts_; }
    gfx::ImGuiRenderer& imgui() { return imgui_; }

    // Draws a figure over the whole logical page and reads it back (one frame: the canvas keeps no state
    // between frames; its display list is canvas().display_list() afterwards).
    gfx::Image render_figure(const FigureData& fig);
    // The figure's display list over the logical page, recorded without drawing (for SVG and PDF). After
    // render_figure(), canvas().display_list() holds the same list.
    gfx::DisplayList record_figure(const FigureData& fig);
    // The logical page: framebuffer / pixel ratio.
    gfx::Vec2 logical_page() const;

  private:
    std::unique_ptr<gfx::GpuContext> ctx_;
    gfx::FontSet fonts_;
    gfx::ImGuiRenderer imgui_;
    gfx::Canvas canvas_;
};

} // namespace fv::app
