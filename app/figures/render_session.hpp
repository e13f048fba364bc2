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
#include <string>

namespace fv::app {

class RenderSession {
  public:
    // Throws std::runtime_error with a one-line reason if no context can be made.
    explicit RenderSession(const gfx::ContextOptions& options);
    // Draws into a context someone else owns (the app's platform), at pixel_ratio framebuffer pixels per
    // logical unit; the context outlives the session.
    RenderSession(gfx::GpuContext& context, float pixel_ratio);

    gfx::GpuContext& context() { return *ctx_; }
    float pixel_ratio() const { return ratio_; }
    gfx::Canvas& canvas() { return canvas_; }
    gfx::FontSet& fonts() { return fonts_; }
    gfx::ImGuiRenderer& imgui() { return imgui_; }

    // Draws a figure over the whole logical page and reads it back (one frame: the canvas keeps no state
    // between frames; its display list is canvas().display_list() afterwards).
    gfx::Image render_figure(const FigureData& fig);
    // The figure's display list over the logical page, recorded without drawing (for SVG and PDF). After
    // render_figure(), canvas().display_list() holds the same list.
    gfx::DisplayList record_figure(const FigureData& fig);
    // The same on a logical page of its own (a printed page's, render --page), text at `text_factor`.
    gfx::DisplayList record_figure(const FigureData& fig, gfx::Vec2 logical, float text_factor);
    // The same laid out for a journal column `width` units wide (column_layout.hpp): its page as tall as the
    // figure takes there.
    gfx::DisplayList record_column_figure(const FigureData& fig, float width);
    // The logical page: framebuffer / pixel ratio.
    gfx::Vec2 logical_page() const;
    // The screenshot: the frame drawn so far (before present) as a PNG at path, written atomically
    // (fv/atomic_file.hpp). Returns "" or a one-line error.
    std::string save_png(const std::string& path) const;
    // The framebuffer as PNG bytes.
    std::vector<unsigned char> encode_png() const;

  private:
    std::unique_ptr<gfx::GpuContext> owned_;
    gfx::GpuContext* ctx_;
    float ratio_;
    gfx::FontSet fonts_;
    gfx::ImGuiRenderer imgui_;
    gfx::Canvas canvas_;
};

} // namespace fv::app
