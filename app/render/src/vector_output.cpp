#include "fv/gfx/vector_output.hpp"

#include "fv/gfx/fonts.hpp"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace fv::gfx {
namespace {

constexpr double kPi = 3.14159265358979323846;

// DejaVu Sans from the file the GL path's atlas is built from, loaded once for the process. `em_per_height`
// turns the canvas's text size (ascent + descent, as ImGui/stb size a font) into cairo's em size.
struct Font {
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    cairo_font_face_t* cairo = nullptr;
    double em_per_height = 1;
};

const Font& font() {
    static const Font f = [] {
        Font r;
        const std::string path = FontSetOptions{}.path;
        if (FT_Init_FreeType(&r.lib) != 0) throw std::runtime_error("FreeType could not be initialised");
        if (FT_New_Face(r.lib, path.c_str(), 0, &r.face) != 0)
            throw std::runtime_error("font not found: " + path + " (Debian: fonts-dejavu-core)");
        const double height = static_cast<double>(r.face->ascender - r.face->descender);
        r.em_per_height = height > 0 ? r.face->units_per_EM / height : 1.0;
        r.cairo = cairo_ft_font_face_create_for_ft_face(r.face, 0);
        return r; // Never freed: cairo may hold the face until exit.
    }();
    return f;
}

bool finite(Vec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

void set_color(cairo_t* cr, Color c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

void set_stroke(cairo_t* cr, const Stroke& s) {
    set_color(cr, s.color);
    cairo_set_line_width(cr, s.width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    const DashPattern dp = dash_pattern(s);
    if (dp.period > 0) {
        const double dashes[2] = {dp.on, dp.period - dp.on};
        cairo_set_dash(cr, dashes, 2, 0);
    } else {
        cairo_set_dash(cr, nullptr, 0, 0);
    }
}

// The GL polyline's rules: non-finite points break the line, repeated points are dropped, `closed` closes
// an unbroken line; each run restarts the dash pattern.
void polyline_path(cairo_t* cr, const std::vector<Vec2>& pts, bool closed) {
    std::vector<Vec2> run;
    bool broken = false;
    auto flush = [&](bool close) {
        if (run.size() >= 2) {
            cairo_move_to(cr, run[0].x, run[0].y);
            for (std::size_t i = 1; i < run.size(); ++i) cairo_line_to(cr, run[i].x, run[i].y);
            if (close && run.size() >= 3) cairo_close_path(cr);
        }
        run.clear();
    };
    for (const Vec2& p : pts) {
        if (!finite(p)) {
            flush(false);
            broken = true;
            continue;
        }
        if (!run.empty() && std::fabs(run.back().x - p.x) < 1e-4f && std::fabs(run.back().y - p.y) < 1e-4f)
            continue;
        run.push_back(p);
    }
    flush(closed && !broken);
}

void polygon_path(cairo_t* cr, const std::vector<Vec2>& pts, Vec2 at) {
    cairo_move_to(cr, at.x + pts[0].x, at.y + pts[0].y);
    for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr, at.x + pts[i].x, at.y + pts[i].y);
    cairo_close_path(cr);
}

struct Replay {
    cairo_t* cr;
    bool svg = false; // SVG viewers smooth every image: nearest-neighbour ones are sent enlarged.

    void operator()(const dl::FillRect& c) {
        cairo_rectangle(cr, c.rect.x0, c.rect.y0, c.rect.width(), c.rect.height());
        set_color(cr, c.color);
        cairo_fill(cr);
    }
    void operator()(const dl::StrokeRect& c) {
        cairo_rectangle(cr, c.rect.x0, c.rect.y0, c.rect.width(), c.rect.height());
        set_stroke(cr, c.stroke);
        cairo_stroke(cr);
    }
    void operator()(const dl::Polyline& c) {
        polyline_path(cr, c.points, c.closed);
        set_stroke(cr, c.stroke);
        cairo_stroke(cr);
    }
    void operator()(const dl::Circle& c) {
        cairo_new_sub_path(cr);
        cairo_arc_negative(cr, c.center.x, c.center.y, c.radius, 0, -2 * kPi); // From angle 0, as on GL.
        cairo_close_path(cr);
        set_stroke(cr, c.stroke);
        cairo_stroke(cr);
    }
    void operator()(const dl::FillCircle& c) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, c.center.x, c.center.y, c.radius, 0, 2 * kPi);
        set_color(cr, c.color);
        cairo_fill(cr);
    }
    void operator()(const dl::FillTriangle& c) {
        polygon_path(cr, {c.a, c.b, c.c}, {0, 0});
        set_color(cr, c.color);
        cairo_fill(cr);
    }
    void operator()(const dl::Marker& c) {
        const MarkerStyle& m = c.style;
        auto path = [&] {
            const std::vector<Vec2> outline = marker_outline(m.shape, m.size);
            if (outline.empty()) {
                cairo_new_sub_path(cr);
                cairo_arc(cr, c.center.x, c.center.y, 0.5 * m.size, 0, 2 * kPi);
                cairo_close_path(cr);
            } else {
                polygon_path(cr, outline, c.center);
            }
        };
        if (m.fill.a > 0) {
            path();
            set_color(cr, m.fill);
            cairo_fill(cr);
        }
        if (m.edge_width > 0 && m.edge.a > 0) {
            path();
            set_stroke(cr, {m.edge, m.edge_width, LineStyle::Solid});
            cairo_stroke(cr);
        }
    }
    void operator()(const dl::Arrow& c) {
        const ArrowGeometry g = arrow_geometry(c.from, c.to, c.style);
        if (!g.valid) return;
        cairo_move_to(cr, g.shaft_from.x, g.shaft_from.y);
        cairo_line_to(cr, g.shaft_to.x, g.shaft_to.y);
        set_stroke(cr, c.style.shaft);
        cairo_stroke(cr);
        polygon_path(cr, {g.tip, g.left, g.right}, {0, 0});
        set_color(cr, c.style.shaft.color);
        cairo_fill(cr);
    }
    void operator()(const dl::Picture& c) {
        const Image& img = *c.pixels;
        if (img.empty() || c.dst.width() == 0 || c.dst.height() == 0) return;
        // Each cell k x k pixels, so that smoothing blurs only a pixel at the cells' edges (at most 4 Mpx).
        int kx = 1, ky = 1;
        if (svg && !c.smooth) {
            kx = std::clamp(
                static_cast<int>(std::ceil(std::fabs(static_cast<double>(c.dst.width())) / img.width)), 1,
                16);
            ky = std::clamp(
                static_cast<int>(std::ceil(std::fabs(static_cast<double>(c.dst.height())) / img.height)), 1,
                16);
            while (static_cast<double>(kx) * kx * ky * img.width * img.height > 4e6 && kx * ky > 1)
                kx > ky ? --kx : --ky;
        }
        const int w = img.width * kx, h = img.height * ky;
        cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
        cairo_surface_flush(s);
        unsigned char* data = cairo_image_surface_get_data(s);
        const int stride = cairo_image_surface_get_stride(s);
        for (int y = 0; y < h; ++y) {
            auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
            for (int x = 0; x < w; ++x) {
                const std::uint8_t* p = img.pixel(x / kx, y / ky);
                const std::uint32_t a = p[3];
                auto pm = [a](std::uint32_t v) { return (v * a + 127) / 255; }; // Cairo wants premultiplied.
                row[x] = (a << 24) | (pm(p[0]) << 16) | (pm(p[1]) << 8) | pm(p[2]);
            }
        }
        cairo_surface_mark_dirty(s);
        cairo_save(cr);
        cairo_translate(cr, c.dst.x0, c.dst.y0);
        cairo_scale(cr, static_cast<double>(c.dst.width()) / w, static_cast<double>(c.dst.height()) / h);
        cairo_set_source_surface(cr, s, 0, 0);
        cairo_pattern_set_filter(cairo_get_source(cr),
                                 c.smooth ? CAIRO_FILTER_BILINEAR : CAIRO_FILTER_NEAREST);
        cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
        cairo_rectangle(cr, 0, 0, w, h);
        cairo_fill(cr);
        cairo_restore(cr);
        cairo_surface_destroy(s);
    }
    void operator()(const dl::Text& c) {
        const Font& f = font();
        set_color(cr, c.style.color);
        cairo_set_font_face(cr, f.cairo);
        for (const dl::TextRun& r : c.runs) {
            cairo_save(cr);
            cairo_translate(cr, r.origin.x, r.origin.y);
            if (c.style.angle_deg != 0) cairo_rotate(cr, -c.style.angle_deg * kPi / 180.0);
            cairo_set_font_size(cr, r.size * f.em_per_height);
            cairo_move_to(cr, 0, 0);
            cairo_show_text(cr, r.text.c_str());
            cairo_restore(cr);
        }
    }
    void operator()(const dl::PushClip& c) {
        cairo_save(cr);
        cairo_rectangle(cr, c.rect.x0, c.rect.y0, std::max(0.0f, c.rect.width()),
                        std::max(0.0f, c.rect.height()));
        cairo_clip(cr);
    }
    void operator()(const dl::PopClip&) { cairo_restore(cr); }
};

// Unhinted metrics and outlines: the same advances on every surface (a caption measured on an image surface
// is drawn on a PDF one).
void unhinted(cairo_t* cr) {
    cairo_font_options_t* fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
}

void replay(cairo_t* cr, const DisplayList& list, bool svg) {
    unhinted(cr);
    set_color(cr, list.background);
    cairo_paint(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    Replay r{cr, svg};
    int depth = 0;
    for (const dl::Command& c : list.commands) {
        if (std::holds_alternative<dl::PopClip>(c)) {
            if (depth == 0) continue; // Unbalanced pop: ignored, as on GL.
            --depth;
        } else if (std::holds_alternative<dl::PushClip>(c)) {
            ++depth;
        }
        std::visit(r, c);
    }
    while (depth-- > 0) cairo_restore(cr);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

// SOURCE_DATE_EPOCH as cairo's ISO-8601 date ("1970-01-01T00:00:00Z"), or "" when unset or not a whole
// number of seconds >= 0.
std::string source_date() {
    const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
    if (!epoch || !*epoch) return "";
    char* end = nullptr;
    errno = 0;
    const long long t = std::strtoll(epoch, &end, 10);
    if (*end != '\0' || errno != 0 || t < 0) return "";
    const std::time_t when = static_cast<std::time_t>(t);
    std::tm utc{};
    if (!gmtime_r(&when, &utc)) return "";
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return buf;
}

// `word` (wider than `width`) in pieces that fit, each but the last on a line of its own: broken after the
// last '/', '_' or '-' that keeps a piece inside the width (a data file's path in a caption), else between
// characters; never inside a UTF-8 sequence. The last piece is returned to go on as a word.
std::string break_word(const std::string& word, const std::function<bool(const std::string&)>& fits,
                       std::vector<std::string>& lines) {
    std::string rest = word;
    while (!fits(rest)) {
        std::size_t end = 0, at_mark = 0; // the longest prefix that fits; the one ending after a mark
        for (std::size_t k = 1; k <= rest.size(); ++k) {
            if (k < rest.size() && (static_cast<unsigned char>(rest[k]) & 0xC0) == 0x80) continue;
            if (!fits(rest.substr(0, k))) break;
            end = k;
            if (rest[k - 1] == '/' || rest[k - 1] == '_' || rest[k - 1] == '-') at_mark = k;
        }
        const std::size_t cut = at_mark > 0 ? at_mark : std::max<std::size_t>(end, 1);
        lines.push_back(rest.substr(0, cut));
        rest.erase(0, cut);
    }
    return rest;
}

// `text` in words, as lines no wider than `width` at the font size set on `cr` (a word wider than that in
// pieces: break_word).
std::vector<std::string> wrap_text(cairo_t* cr, const std::string& text, double width) {
    std::vector<std::string> lines;
    std::string line, word;
    auto fits = [&](const std::string& s) {
        cairo_text_extents_t e;
        cairo_text_extents(cr, s.c_str(), &e);
        return e.x_advance <= width;
    };
    auto flush_word = [&] {
        if (word.empty()) return;
        if (!fits(word)) {
            if (!line.empty()) lines.push_back(line);
            line.clear();
            word = break_word(word, fits, lines);
        }
        const std::string joined = line.empty() ? word : line + " " + word;
        if (line.empty() || fits(joined)) {
            line = joined;
        } else {
            lines.push_back(line);
            line = word;
        }
        word.clear();
    };
    for (const char ch : text) {
        if (ch == ' ' || ch == '\n' || ch == '\t')
            flush_word();
        else
            word += ch;
    }
    flush_word();
    if (!line.empty()) lines.push_back(line);
    return lines;
}

// The caption's lines at `size` (a text size: line box height) wrapped to `width`, and the height they take.
struct CaptionLines {
    std::vector<std::string> lines;
    double em = 0, line_height = 0;
    double height() const { return line_height * static_cast<double>(lines.size()); }
};

CaptionLines caption_lines(const std::string& caption, double width, double size) {
    CaptionLines c;
    if (caption.empty()) return c;
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t* cr = cairo_create(s);
    unhinted(cr);
    cairo_set_font_face(cr, font().cairo);
    c.em = size * font().em_per_height;
    c.line_height = size * 1.15;
    cairo_set_font_size(cr, c.em);
    c.lines = wrap_text(cr, caption, width);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return c;
}

// Draws the lines with their first line box's top-left at (x, y), in black.
void draw_caption(cairo_t* cr, const CaptionLines& c, double x, double y) {
    cairo_save(cr);
    unhinted(cr);
    cairo_set_font_face(cr, font().cairo);
    cairo_set_font_size(cr, c.em);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    for (std::size_t k = 0; k < c.lines.size(); ++k) {
        cairo_move_to(cr, x, y + c.line_height * static_cast<double>(k) + fe.ascent);
        cairo_show_text(cr, c.lines[k].c_str());
    }
    cairo_restore(cr);
}

// Text as SVG character data: &, < and > escaped.
std::string xml_text(const std::string& s) {
    std::string out;
    for (const char ch : s) {
        if (ch == '&')
            out += "&amp;";
        else if (ch == '<')
            out += "&lt;";
        else if (ch == '>')
            out += "&gt;";
        else
            out += ch;
    }
    return out;
}

// cairo 1.16 names an SVG's <g id="surfaceN"> and <image id="imageN"> after process-wide counters of the
// surfaces created, so the same figure got surface1 or surface10 depending on what other threads (the PNG
// encoders, another figure) had created first. Renumbered here in order of first appearance, so that the same
// figure is the same bytes (the ids are only referenced within the document: "#imageN").
std::string stable_svg_ids(const std::string& svg) {
    std::string out;
    out.reserve(svg.size());
    std::map<std::string, int> renamed[2];
    const char* const kinds[2] = {"surface", "image"};
    std::size_t k = 0;
    while (k < svg.size()) {
        bool done = false;
        for (int t = 0; t < 2 && !done; ++t) {
            const std::string kind = kinds[t];
            for (const char* lead : {"id=\"", "#"}) {
                const std::string head = std::string(lead) + kind;
                if (svg.compare(k, head.size(), head) != 0) continue;
                std::size_t e = k + head.size();
                while (e < svg.size() && std::isdigit(static_cast<unsigned char>(svg[e]))) ++e;
                if (e == k + head.size()) continue;
                const std::string old = svg.substr(k + head.size(), e - k - head.size());
                const auto it = renamed[t].emplace(old, static_cast<int>(renamed[t].size()) + 1).first;
                out += head + std::to_string(it->second);
                k = e;
                done = true;
                break;
            }
        }
        if (!done) out += svg[k++];
    }
    return out;
}

} // namespace

std::string render_vector(const DisplayList& list, VectorFormat format, const VectorPage& page) {
    font(); // Throws if the font is missing, before a surface exists.
    std::string out;
    // The figure's box on the page, and the caption's lines under it (a gap of half a line between).
    const double fw = list.size.x * page.scale, fh = list.size.y * page.scale;
    const CaptionLines cap = caption_lines(page.caption, fw, page.caption_size);
    const double cap_top = page.origin.y + fh + (cap.lines.empty() ? 0 : 0.5 * cap.line_height);
    const bool own_page = page.size.x <= 0 || page.size.y <= 0;
    const double w = own_page ? fw + 2 * page.origin.x : page.size.x;
    const double h =
        own_page ? cap_top + cap.height() + page.origin.y + (cap.lines.empty() ? 0 : 0.5 * cap.line_height)
                 : page.size.y;
    cairo_surface_t* s = format == VectorFormat::Pdf
                             ? cairo_pdf_surface_create_for_stream(append, &out, w, h)
                             : cairo_svg_surface_create_for_stream(append, &out, w, h);
    if (format == VectorFormat::Pdf) {
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, "frictionviz");
        // The creation date cairo writes into every PDF is the one byte range that differs run after run:
        // SOURCE_DATE_EPOCH (the reproducible-builds convention, seconds since 1970) fixes it, so that a
        // snapshot test gets the same bytes for the same command. Without it, the time of writing.
        if (const std::string date = source_date(); !date.empty())
            cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
    } else {
        cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_PT);
    }
    cairo_t* cr = cairo_create(s);
    if (!own_page || page.scale != 1 || page.origin.x != 0 || page.origin.y != 0) {
        // The page's background, then the figure placed and scaled on it.
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        cairo_save(cr);
        cairo_translate(cr, page.origin.x, page.origin.y);
        cairo_scale(cr, page.scale, page.scale);
        cairo_rectangle(cr, 0, 0, list.size.x, list.size.y);
        cairo_clip(cr);
        replay(cr, list, format == VectorFormat::Svg);
        cairo_restore(cr);
    } else {
        replay(cr, list, format == VectorFormat::Svg);
    }
    if (!cap.lines.empty()) {
        if (own_page && fh + 2 * page.origin.y < h) { // the band under the figure, white like its page
            cairo_rectangle(cr, 0, page.origin.y + fh, w, h - page.origin.y - fh);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_fill(cr);
        }
        draw_caption(cr, cap, page.origin.x, cap_top);
    }
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(s); // Writes the rest of the document.
    if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(s);
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(st));
    if (format == VectorFormat::Svg) out = stable_svg_ids(out);
    if (format == VectorFormat::Svg && !page.caption.empty()) {
        // The caption as text a reader (or a search) finds: SVG's <desc>, right after the root's start tag.
        const std::size_t root = out.find("<svg");
        const std::size_t end = root == std::string::npos ? root : out.find('>', root);
        if (end != std::string::npos) out.insert(end + 1, "\n<desc>" + xml_text(page.caption) + "</desc>");
    }
    return out;
}

Image render_caption_image(const std::string& caption, float width, float size, float pad, float scale) {
    const CaptionLines cap = caption_lines(caption, width - 2 * pad, size);
    const int w = static_cast<int>(std::lround(width * scale));
    const int h = static_cast<int>(std::lround((cap.height() + 2 * pad) * scale));
    if (w <= 0 || h <= 0) return {};
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_scale(cr, scale, scale);
    draw_caption(cr, cap, pad, pad);
    const cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    Image img(w, h);
    const unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    for (int y = 0; y < h; ++y) {
        const auto* row =
            reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        for (int x = 0; x < w; ++x) { // opaque: no alpha to undo
            std::uint8_t* p = img.pixel(x, y);
            p[0] = static_cast<std::uint8_t>((row[x] >> 16) & 0xFF);
            p[1] = static_cast<std::uint8_t>((row[x] >> 8) & 0xFF);
            p[2] = static_cast<std::uint8_t>(row[x] & 0xFF);
            p[3] = 255;
        }
    }
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(st));
    return img;
}

Image stack_images(const Image& top, const Image& bottom) {
    Image out(std::max(top.width, bottom.width), top.height + bottom.height);
    std::fill(out.rgba.begin(), out.rgba.end(), std::uint8_t{255});
    for (int y = 0; y < top.height; ++y)
        std::copy_n(top.pixel(0, y), static_cast<std::size_t>(top.width) * 4, out.pixel(0, y));
    for (int y = 0; y < bottom.height; ++y)
        std::copy_n(bottom.pixel(0, y), static_cast<std::size_t>(bottom.width) * 4,
                    out.pixel(0, top.height + y));
    return out;
}

Image render_cairo_image(const DisplayList& list, float scale) {
    font();
    const int w = static_cast<int>(std::lround(list.size.x * scale)),
              h = static_cast<int>(std::lround(list.size.y * scale));
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* cr = cairo_create(s);
    cairo_scale(cr, scale, scale);
    replay(cr, list, false);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    Image img(w, h);
    if (st == CAIRO_STATUS_SUCCESS) {
        const unsigned char* data = cairo_image_surface_get_data(s);
        const int stride = cairo_image_surface_get_stride(s);
        for (int y = 0; y < h; ++y) {
            const auto* row =
                reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
            for (int x = 0; x < w; ++x) {
                const std::uint32_t v = row[x], a = v >> 24;
                auto un = [a](std::uint32_t c) {
                    return a ? std::min<std::uint32_t>(255, (c * 255 + a / 2) / a) : 0;
                };
                std::uint8_t* p = img.pixel(x, y);
                p[0] = static_cast<std::uint8_t>(un((v >> 16) & 0xFF));
                p[1] = static_cast<std::uint8_t>(un((v >> 8) & 0xFF));
                p[2] = static_cast<std::uint8_t>(un(v & 0xFF));
                p[3] = static_cast<std::uint8_t>(a);
            }
        }
    }
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(st));
    return img;
}

} // namespace fv::gfx
