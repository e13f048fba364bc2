#include "render_output.hpp"

#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include "errors.hpp"
#include "validators.hpp"

#include "figures/render_session.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace fv::cli {
namespace {

constexpr const char* kFormats = "png, svg, pdf (comma separated)";

// Every item a known format; the flags set as a side effect when `out` is given.
std::string parse_formats(const std::string& s, OutputArgs* out) {
    std::stringstream ss(s);
    std::string item;
    bool any = false;
    while (std::getline(ss, item, ',')) {
        any = true;
        if (item == "png") {
            if (out) out->png = true;
        } else if (item == "svg") {
            if (out) out->svg = true;
        } else if (item == "pdf") {
            if (out) out->pdf = true;
        } else {
            return "unknown format '" + item + "'; allowed: " + kFormats;
        }
    }
    if (!any || s.back() == ',') return "'" + s + "' has an empty item; allowed: " + kFormats;
    return {};
}

std::string pretty(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

} // namespace

std::string scale_range_text() {
    return "[" + pretty(kMinScale) + ", " + pretty(kMaxScale) + "]";
}

namespace {

// "WxH" (or "WXH") read by the shared reader: each side a whole integer in its range, so that an overflow
// (4294967616x240, which sscanf("%d") wrapped to 320) is refused, not wrapped.
std::string read_size(const std::string& s, PixelSize& out) {
    std::ostringstream allowed;
    allowed << "allowed: WxH with W in [" << kMinSizeW << ", " << kMaxSizeW << "] and H in [" << kMinSizeH
            << ", " << kMaxSizeH << "]";
    const auto x = s.find_first_of("xX");
    if (x == std::string::npos || s.find_first_of("xX", x + 1) != std::string::npos)
        return quoted_text(s) + " is not a size; " + allowed.str();
    long long w = 0, h = 0;
    const std::string why_w = read_integer("", s.substr(0, x), kMinSizeW, kMaxSizeW, w);
    const std::string why_h = read_integer("", s.substr(x + 1), kMinSizeH, kMaxSizeH, h);
    for (const std::string* why : {&why_w, &why_h})
        if (why->find("not an integer") != std::string::npos)
            return quoted_text(s) + " is not a size; " + allowed.str();
    if (!why_w.empty() || !why_h.empty()) return quoted_text(s) + " is out of range; " + allowed.str();
    out = {static_cast<int>(w), static_cast<int>(h)};
    return {};
}

} // namespace

CLI::Validator size_spec() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            PixelSize unused;
            return read_size(s, unused);
        },
        "WxH");
}

PixelSize parse_size(const std::string& s) {
    PixelSize sz;
    read_size(s, sz);
    return sz;
}

void add_output_options(CLI::App& cmd, OutputArgs& args) {
    cmd.add_option(
           "--format", args.format,
           std::string("output formats: ") + kFormats +
               "; FIGURE.png, FIGURE.svg, FIGURE.pdf (SVG and PDF: vectors, the page the logical size in "
               "points; PDF text is text, SVG text glyph outlines)")
        ->check(CLI::Validator([](std::string& s) { return parse_formats(s, nullptr); }, "png|svg|pdf,.."))
        ->capture_default_str();
    cmd.add_option("--scale", args.scale,
                   "device pixel ratio: image pixels per logical unit, in " + scale_range_text() +
                       "; lengths are logical, the page is --size / --scale (--size 2560x1600 --scale 2 is "
                       "the 1280x800 picture at twice the resolution)")
        ->transform(number_in({kMinScale, kMaxScale}))
        ->capture_default_str();
}

void check_output_args(OutputArgs& args, int width, int height) {
    args.png = args.svg = args.pdf = false;
    if (const std::string err = parse_formats(args.format, &args); !err.empty())
        throw UsageError("--format: " + err);
    if (!(args.scale >= kMinScale && args.scale <= kMaxScale))
        throw UsageError("--scale: " + pretty(args.scale) + " is out of range; allowed: [" +
                         pretty(kMinScale) + ", " + pretty(kMaxScale) + "]");
    const double pw = width / args.scale, ph = height / args.scale;
    if (pw < kMinPageW - 1e-9 || ph < kMinPageH - 1e-9 || pw > kMaxPageW + 1e-9 || ph > kMaxPageH + 1e-9) {
        std::ostringstream m;
        m << "--size " << width << "x" << height << " at --scale " << pretty(args.scale) << " is a page of "
          << pretty(pw) << "x" << pretty(ph) << " logical units; allowed: --size / --scale between "
          << kMinPageW << "x" << kMinPageH << " and " << kMaxPageW << "x" << kMaxPageH;
        throw UsageError(m.str());
    }
}

void check_gl_limits(app::RenderSession& session, const OutputArgs& args) {
    const gfx::GlApi& gl = session.context().gl();
    GLint renderbuffer = 0, texture = 0, viewport[2] = {0, 0};
    gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    gl.GetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const gfx::Size fb = session.context().framebuffer_size();
    const int max_fb = std::min({renderbuffer, viewport[0], viewport[1]});
    if (fb.width > max_fb || fb.height > max_fb)
        throw UsageError("--size " + std::to_string(fb.width) + "x" + std::to_string(fb.height) +
                         " passes the GL limit; allowed: at most " + std::to_string(max_fb) +
                         " pixels a side");
    const ImFontAtlas& atlas = session.fonts().atlas();
    if (atlas.TexWidth > texture || atlas.TexHeight > texture)
        throw UsageError("--scale " + pretty(args.scale) + ": the text at that scale needs a " +
                         std::to_string(atlas.TexWidth) + "x" + std::to_string(atlas.TexHeight) +
                         " font texture, past the GL limit of " + std::to_string(texture) +
                         "; allowed: a smaller --scale");
}

} // namespace fv::cli
