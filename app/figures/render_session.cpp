#include "render_session.hpp"

#include "column_layout.hpp"
#include "figure_painter.hpp"

#include "fv/atomic_file.hpp"
#include "fv/gfx/png.hpp"

namespace fv::app {
namespace {

gfx::FontSetOptions font_options(float ratio) {
    gfx::FontSetOptions o;
    o.pixel_ratio = ratio;
    return o;
}

} // namespace

RenderSession::RenderSession(const gfx::ContextOptions& options)
    : owned_(gfx::create_context(options)), ctx_(owned_.get()), ratio_(ctx_->pixel_ratio()),
      fonts_(font_options(ratio_)), imgui_(ctx_->gl()),
      canvas_((imgui_.upload_font_atlas(fonts_.atlas()), ctx_->gl()), fonts_, imgui_) {}

RenderSession::RenderSession(gfx::GpuContext& context, float pixel_ratio)
    : ctx_(&context), ratio_(pixel_ratio), fonts_(font_options(ratio_)), imgui_(ctx_->gl()),
      canvas_((imgui_.upload_font_atlas(fonts_.atlas()), ctx_->gl()), fonts_, imgui_) {}

std::vector<unsigned char> RenderSession::encode_png() const {
    return gfx::encode_png(ctx_->read_pixels());
}

std::string RenderSession::save_png(const std::string& path) const {
    const auto png = encode_png();
    return write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

gfx::Vec2 RenderSession::logical_page() const {
    const float ratio = ratio_;
    const gfx::Size fb = ctx_->framebuffer_size();
    return {static_cast<float>(fb.width) / ratio, static_cast<float>(fb.height) / ratio};
}

gfx::DisplayList RenderSession::record_figure(const FigureData& fig) {
    return record_figure(fig, logical_page(), 0);
}

gfx::DisplayList RenderSession::record_figure(const FigureData& fig, gfx::Vec2 logical, float text_factor) {
    canvas_.begin(logical, ratio_, gfx::colors::white);
    paint_figure(canvas_, fig, {0, 0, logical.x, logical.y}, text_factor);
    canvas_.end_recording();
    return canvas_.display_list();
}

gfx::DisplayList RenderSession::record_column_figure(const FigureData& fig, float width) {
    // A page tall enough for the layout's tries (panel_height draws each panel at up to twice the width).
    canvas_.begin({width, 4 * width}, ratio_, gfx::colors::white);
    const ColumnLayout layout = column_layout(canvas_, fig, width);
    canvas_.begin(layout.page, ratio_, gfx::colors::white);
    paint_column_figure(canvas_, fig, layout);
    canvas_.end_recording();
    return canvas_.display_list();
}

gfx::Image RenderSession::render_figure(const FigureData& fig) {
    const float ratio = ratio_;
    const gfx::Vec2 logical = logical_page();
    // One frame: the canvas keeps no state between frames (an ImGui context, which lays some things out
    // only on its second frame, is not involved).
    canvas_.begin(logical, ratio, gfx::colors::white);
    paint_figure(canvas_, fig, {0, 0, logical.x, logical.y});
    canvas_.end();
    gfx::Image img = ctx_->read_pixels();
    ctx_->present();
    return img;
}

} // namespace fv::app
