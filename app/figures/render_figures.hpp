// The render command's pipeline: every figure in turn computed (core), drawn (GL, or recorded as a display
// list for SVG and PDF), then encoded and written on other threads, in figure order, through the output-path
// policy. Memory does not grow with the number of figures: alive at any time are the context's framebuffer,
// the frame being drawn, the frames being encoded and the data of one figure.
#pragma once

#include "figures/figure_renderer.hpp"
#include "figures/render_session.hpp"

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/gfx/vector_output.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fv::app {

// Which pictures of a figure are made: ID.png, ID.svg, ID.pdf.
struct PictureFormats {
    bool png = true, svg = false, pdf = false;
    // "png", "svg", "pdf" as asked, in that order.
    std::vector<std::string> extensions() const;
};

using NamedFile = std::pair<std::string, std::string>; // file name, content

struct PrintLayout {
    gfx::Vec2 logical{0, 0}; // the page the figure is laid out on ({0, 0}: the session's)
    float text_factor = 0;   // its text factor (paint_figure), 0: the page's own
    bool column = false;     // a journal column: laid out by column_layout.hpp, logical.x wide, as tall as
                             // the figure takes there (logical.y unused)
    gfx::VectorPage vector;  // where it goes on the printed page, the caption's size
    float png_caption = 14;  // a PNG's caption text size, logical units
};
// The layout of `paper` for a figure drawn at `width` x `height` logical units (its aspect is kept for a4
// and letter; a column is as tall as each figure takes: column_layout.hpp), with a caption or not.
PrintLayout print_layout(PaperPage paper, float width, float height, bool caption);

// ID.png (from `image`), ID.svg and ID.pdf (from `list`) as asked. Thread-safe; throws what the encoders
// throw.
std::vector<NamedFile> encode_pictures(const std::string& id, const PictureFormats& formats,
                                       const gfx::Image& image, const gfx::DisplayList& list,
                                       const gfx::VectorPage& page = {});

// Draws `data` for `formats` through `session`: the PNG's frame (with the caption's band under it), the
// display list of the SVG and PDF (on the layout's logical page where it is a printed one) and their page
// with the caption. An empty caption: none.
void draw_pictures(RenderSession& session, const FigureData& data, const PictureFormats& formats,
                   const PrintLayout& layout, const std::string& caption, gfx::Image& image,
                   gfx::DisplayList& list, gfx::VectorPage& page);

// What the caller writes beside a figure's pictures (its tables as CSV, its caption), and "" or a one-line
// note of its failed points; made once the figure is computed.
struct FigureExtras {
    std::vector<NamedFile> files;
    std::string failed;
};

struct RenderJob {
    std::string dir; // an existing directory, without a trailing '/'
    PictureFormats formats;
    std::size_t encoders = 1; // pictures encoded at once (each holds about two frames)
    std::function<FigureExtras(const FigureSpec&, FigureData&)> extras;
    std::function<void(const std::string& id)> wrote; // each figure whose files are all written, in order
    PaperPage paper = PaperPage::none; // the SVG and PDF pages (render --page); PNGs stay the session's size
    bool caption = false; // each figure's caption (as in its ID.json) under it in every format (--caption)
};

struct RenderOutcome {
    // The first failed write ("": everything written). Nothing is written after it, nothing computed.
    std::string write_error;
    int failed_figures = 0; // figures with failed points (written all the same)
    std::string failed;     // their notes, "; " between
};

// Renders `specs` in order into job.dir through `session`; each spec is released once its figure is computed
// (fig19's holds its computed figure). Throws std::runtime_error only for a GL failure.
RenderOutcome render_figures(RenderSession& session, std::vector<FigureSpec>& specs, const RenderJob& job);

} // namespace fv::app
