// render's output formats and resolution: --format png,svg,pdf and --scale, checked before anything is
// drawn; each figure's files written through the output-path policy (fv::write_file_atomic).
#pragma once

#include "figures/figure_renderer.hpp"
#include "figures/render_figures.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace fv::cli {

// --scale, the logical page (--size / --scale) and --size WxH (render and gui) take the figures layer's
// limits, which the installed library checks too.
using app::kMaxPageH, app::kMaxPageW, app::kMaxScale, app::kMaxSizeH, app::kMaxSizeW, app::kMinPageH,
    app::kMinPageW, app::kMinScale, app::kMinSizeH, app::kMinSizeW;

// An image size in pixels.
struct PixelSize {
    int w = 1280, h = 800;
};
// Checks "WxH" with W in [kMinSizeW, kMaxSizeW] and H in [kMinSizeH, kMaxSizeH].
CLI::Validator size_spec();
// A size that passed size_spec().
PixelSize parse_size(const std::string& s);

// "[0.25, 8]": the allowed --scale, for help texts.
std::string scale_range_text();

struct OutputArgs {
    std::string format = "png";
    double scale = 1;
    // Parsed from `format`, in the order png, svg, pdf.
    bool png = false, svg = false, pdf = false;
    // The pictures asked for, and their file extensions ("png", "svg", "pdf").
    app::PictureFormats pictures() const { return {png, svg, pdf}; }
    std::vector<std::string> extensions() const { return pictures().extensions(); }
};

// Adds --format and --scale to `cmd`.
void add_output_options(CLI::App& cmd, OutputArgs& args);

// Parses the format list and checks the page of `width` x `height` pixels at the scale (UsageError, one
// line naming the allowed values).
void check_output_args(OutputArgs& args, int width, int height);

// The GL path's limits for the session's framebuffer and font atlas (GL_MAX_RENDERBUFFER_SIZE,
// GL_MAX_VIEWPORT_DIMS, GL_MAX_TEXTURE_SIZE): UsageError when --size at --scale passes them.
void check_gl_limits(app::RenderSession& session, const OutputArgs& args);

} // namespace fv::cli
