#include "figures/render_figures.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_registry.hpp"
#include "fv/gfx/png.hpp"
#include "fv/gfx/vector_output.hpp"

#include <algorithm>
#include <atomic>
#include <deque>
#include <future>
#include <memory>
#include <optional>

namespace fv::app {

std::vector<std::string> PictureFormats::extensions() const {
    std::vector<std::string> e;
    if (png) e.push_back("png");
    if (svg) e.push_back("svg");
    if (pdf) e.push_back("pdf");
    return e;
}

const char* to_string(PaperPage p) {
    switch (p) {
    case PaperPage::a4:
        return "a4";
    case PaperPage::letter:
        return "letter";
    case PaperPage::column:
        return "column";
    case PaperPage::none:
        break;
    }
    return "";
}

PaperPage paper_page(const std::string& name, bool& ok) {
    ok = true;
    for (const PaperPage p : {PaperPage::a4, PaperPage::letter, PaperPage::column})
        if (name == to_string(p)) return p;
    ok = false;
    return PaperPage::none;
}

namespace {

// DejaVu Sans's em is this share of its line box (units_per_EM / (ascender - descender) = 2048 / 2384): a
// text size of 13 units (a tick label's line box) sets 11.2-unit type.
constexpr float kEmPerLine = 2048.f / 2384.f;
constexpr float kTickLine = 13;                          // tick labels and legends, logical units
constexpr float kA4W = 595.276f, kA4H = 841.89f;         // ISO 216, points
constexpr float kLetterW = 612, kLetterH = 792;          // 8.5 x 11 in
constexpr float kColumnW = 3.3f * 72, kPaperMargin = 48; // a journal column; 2/3 in margins
constexpr float kPaperType = 9, kColumnType = 8, kCaptionGap = 1.05f; // points; caption type / tick type

} // namespace

PrintLayout print_layout(PaperPage paper, float width, float height, bool caption) {
    PrintLayout l;
    if (paper == PaperPage::none) {
        // The page is the logical page, one unit a point; a caption gets a margin beside it.
        if (caption) l.vector.origin = {12, 0};
        l.vector.caption_size = 14;
        return l;
    }
    const bool column = paper == PaperPage::column;
    const float type = column ? kColumnType : kPaperType;
    const float scale = type / (kTickLine * kEmPerLine); // points a logical unit
    const float page_w = column ? kColumnW : (paper == PaperPage::a4 ? kA4W : kLetterW);
    const float margin = column ? 0 : kPaperMargin;
    l.logical.x = (page_w - 2 * margin) / scale;
    // A portrait sheet has height to spare: the figure gets at least 3/4 of its width, so that a figure of
    // two panels (fig4's rows of arrows up a time axis) is not squeezed to a wide screen's aspect.
    l.logical.y = column ? 0 : l.logical.x * std::max(0.75f, height / width);
    l.column = column;
    l.text_factor = 1; // full-size text on a page smaller than 640 units: it prints at `type`
    l.vector.scale = scale;
    l.vector.origin = {margin, column ? 0 : margin};
    if (!column) l.vector.size = {page_w, paper == PaperPage::a4 ? kA4H : kLetterH};
    l.vector.caption_size = type * kCaptionGap / kEmPerLine;
    return l;
}

std::vector<NamedFile> encode_pictures(const std::string& id, const PictureFormats& formats,
                                       const gfx::Image& image, const gfx::DisplayList& list,
                                       const gfx::VectorPage& page) {
    std::vector<NamedFile> files;
    if (formats.png) {
        const std::vector<unsigned char> png = gfx::encode_png(image);
        files.emplace_back(id + ".png", std::string(reinterpret_cast<const char*>(png.data()), png.size()));
    }
    if (formats.svg) files.emplace_back(id + ".svg", gfx::render_vector(list, gfx::VectorFormat::Svg, page));
    if (formats.pdf) files.emplace_back(id + ".pdf", gfx::render_vector(list, gfx::VectorFormat::Pdf, page));
    return files;
}

void draw_pictures(RenderSession& session, const FigureData& data, const PictureFormats& formats,
                   const PrintLayout& layout, const std::string& caption, gfx::Image& image,
                   gfx::DisplayList& list, gfx::VectorPage& page) {
    page = layout.vector;
    page.caption = caption;
    const bool vectors = formats.svg || formats.pdf, printed = layout.logical.x > 0;
    if (formats.png) {
        image = session.render_figure(data);
        if (vectors && !printed) list = session.canvas().display_list();
        if (!caption.empty())
            image = gfx::stack_images(image, gfx::render_caption_image(caption, session.logical_page().x,
                                                                       layout.png_caption, 12,
                                                                       session.pixel_ratio()));
    }
    if (vectors && (!formats.png || printed))
        list = layout.column ? session.record_column_figure(data, layout.logical.x)
               : printed     ? session.record_figure(data, layout.logical, layout.text_factor)
                             : session.record_figure(data);
}

namespace {

// A drawn figure on its way to the disk: its frame and display list (freed once encoded) and the files
// beside its pictures.
struct Drawn {
    std::string id;
    gfx::Image image;
    gfx::DisplayList list;
    std::vector<NamedFile> files;
    gfx::VectorPage page; // the SVG and PDF page and caption
};

// nullopt: not written (an earlier write failed); "": written; else the failure.
using WriteResult = std::shared_future<std::optional<std::string>>;

// Encodes one figure (in parallel with the others) and writes its files once the figure before it is written
// (`before`), unless a write failed meanwhile (`stop`, set by the first failure): nothing after a failed
// write is written.
std::optional<std::string> encode_and_write(const RenderJob& job, Drawn d, WriteResult before,
                                            std::atomic<bool>& stop) {
    std::vector<NamedFile> files;
    std::string err;
    try {
        files = encode_pictures(d.id, job.formats, d.image, d.list, d.page);
    } catch (const std::exception& e) {
        err = d.id + ": " + e.what();
    }
    std::vector<std::uint8_t>().swap(d.image.rgba);
    d.list = {};
    if (before.valid()) before.wait();
    if (stop) return std::nullopt;
    files.insert(files.end(), d.files.begin(), d.files.end());
    for (const auto& [file, content] : files)
        if (err.empty()) err = write_file_atomic(job.dir + "/" + file, content);
    if (!err.empty()) stop = true;
    return err;
}

} // namespace

RenderOutcome render_figures(RenderSession& session, std::vector<FigureSpec>& specs, const RenderJob& job) {
    RenderOutcome out;
    auto stop = std::make_shared<std::atomic<bool>>(false);
    std::deque<std::pair<WriteResult, std::string>> pending; // jobs in flight, oldest first, with their ids
    // The oldest job's end, in figure order (so that `wrote` comes in order too).
    auto finish_oldest = [&] {
        const std::optional<std::string> err = pending.front().first.get();
        const std::string id = std::move(pending.front().second);
        pending.pop_front();
        if (err && err->empty() && job.wrote) job.wrote(id);
        if (err && !err->empty() && out.write_error.empty()) out.write_error = *err;
    };
    const gfx::Vec2 logical = session.logical_page();
    const PrintLayout layout = print_layout(job.paper, logical.x, logical.y, job.caption);
    for (FigureSpec& spec : specs) {
        if (*stop) break; // after the first failed write nothing else is computed
        FigureData data = compute_figure(spec);
        FigureExtras extras = job.extras ? job.extras(spec, data) : FigureExtras{};
        if (!extras.failed.empty()) {
            ++out.failed_figures;
            out.failed += (out.failed.empty() ? "" : "; ") + extras.failed;
        }
        Drawn d{data.id, {}, {}, std::move(extras.files), {}};
        // GL is single-threaded: the drawing happens here, the encoding on the job's thread.
        const std::string caption =
            job.caption ? spec.caption + " " + figure_parameters(spec) : ""; // ID.json's
        draw_pictures(session, data, job.formats, layout, caption, d.image, d.list, d.page);
        spec = FigureSpec{}; // its data (fig19's figure) are not needed any more
        while (pending.size() >= std::max<std::size_t>(job.encoders, 1)) finish_oldest();
        const std::string id = d.id;
        WriteResult before = pending.empty() ? WriteResult() : pending.back().first;
        pending.emplace_back(std::async(std::launch::async, encode_and_write, std::cref(job), std::move(d),
                                        std::move(before), std::ref(*stop))
                                 .share(),
                             id);
    }
    while (!pending.empty()) finish_oldest();
    return out;
}

} // namespace fv::app
