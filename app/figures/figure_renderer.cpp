#include "figures/figure_renderer.hpp"

#include "figures/render_figures.hpp"
#include "figures/render_session.hpp"

#include <sstream>
#include <stdexcept>

namespace fv::app {

const char* to_string(PictureFormat f) {
    switch (f) {
    case PictureFormat::png:
        return "png";
    case PictureFormat::svg:
        return "svg";
    case PictureFormat::pdf:
        return "pdf";
    }
    return "";
}

std::string picture_size_error(const PictureSize& size) {
    std::ostringstream m;
    if (size.width < kMinSizeW || size.width > kMaxSizeW || size.height < kMinSizeH ||
        size.height > kMaxSizeH) {
        m << "picture size " << size.width << "x" << size.height << " is out of range; allowed: width in ["
          << kMinSizeW << ", " << kMaxSizeW << "], height in [" << kMinSizeH << ", " << kMaxSizeH << "]";
        return m.str();
    }
    if (!(size.scale >= kMinScale && size.scale <= kMaxScale)) {
        m << "picture scale " << size.scale << " is out of range; allowed: [" << kMinScale << ", "
          << kMaxScale << "]";
        return m.str();
    }
    const double pw = size.width / size.scale, ph = size.height / size.scale;
    if (pw < kMinPageW - 1e-9 || ph < kMinPageH - 1e-9 || pw > kMaxPageW + 1e-9 || ph > kMaxPageH + 1e-9) {
        m << "picture size " << size.width << "x" << size.height << " at scale " << size.scale
          << " is a page of " << pw << "x" << ph << " logical units; allowed: size / scale between "
          << kMinPageW << "x" << kMinPageH << " and " << kMaxPageW << "x" << kMaxPageH;
        return m.str();
    }
    return {};
}

namespace {

// The FigureInputs member that gives `p`.
const char* input_name(FigureParam p) {
    switch (p) {
    case FigureParam::zeta:
        return "zeta";
    case FigureParam::zeta_range:
        return "zeta_span";
    case FigureParam::model:
        return "models";
    case FigureParam::theta:
        return "theta_deg";
    case FigureParam::rdisp:
        return "rdisp";
    case FigureParam::i:
        return "i";
    case FigureParam::data:
        return "data";
    case FigureParam::amplitude:
        return "amplitude_um";
    case FigureParam::frequency:
        return "frequency_khz";
    case FigureParam::start:
        return "start";
    }
    return "";
}

} // namespace

FigureSpec registered_figure(const std::string& id, const FigureInputs& inputs) {
    const FigureEntry* e = find_registered(id);
    if (!e) throw std::invalid_argument("unknown figure '" + id + "'; allowed: " + figure_ids());
    if (const std::optional<FigureParam> p = missing_param(*e, inputs))
        throw std::invalid_argument("figure " + id + " needs FigureInputs::" + input_name(*p));
    // The checks every door applies (lists where the figure takes one value, ranges, the family's size).
    if (const std::string why = input_error(*e, inputs, [](FigureParam p) { return input_name(p); });
        !why.empty())
        throw std::invalid_argument("figure " + id + ": " + why);
    return e->make(inputs);
}

namespace {

gfx::ContextOptions headless(const PictureSize& size) {
    if (const std::string err = picture_size_error(size); !err.empty()) throw std::invalid_argument(err);
    gfx::ContextOptions o;
    o.backend = gfx::Backend::Headless;
    o.width = size.width;
    o.height = size.height;
    o.scale = static_cast<float>(size.scale);
    return o;
}

} // namespace

FigureRenderer::FigureRenderer(const PictureSize& size)
    : session_(std::make_unique<RenderSession>(headless(size))) {}

FigureRenderer::~FigureRenderer() = default;

std::string FigureRenderer::render(const FigureData& figure, PictureFormat format,
                                   const PrintOptions& print) {
    // The command line's path (render_figures.cpp): PNG from the drawn frame, SVG and PDF from the display
    // list, through the same encoders.
    PictureFormats formats;
    formats.png = format == PictureFormat::png;
    formats.svg = format == PictureFormat::svg;
    formats.pdf = format == PictureFormat::pdf;
    const gfx::Vec2 logical = session_->logical_page();
    const PrintLayout layout = print_layout(print.page, logical.x, logical.y, !print.caption.empty());
    gfx::Image image;
    gfx::DisplayList list;
    gfx::VectorPage page;
    draw_pictures(*session_, figure, formats, layout, print.caption, image, list, page);
    return encode_pictures(figure.id, formats, image, list, page).front().second;
}

} // namespace fv::app
