#include "fv/gfx/text.hpp"

#include "fv/gfx/display_list.hpp"

#include <imgui.h>
#include <imgui_internal.h> // ImTextCharFromUtf8

#include <cmath>
#include <vector>

namespace fv::gfx {
namespace {

constexpr float kScriptScale = 0.7f; // Sub/superscript size relative to the base size.
constexpr float kSubShift = 0.22f;   // Baseline shifts in units of the base size (down positive).
constexpr float kSupShift = -0.38f;

struct Run {
    std::string_view text;
    float size;     // Logical size of this run.
    float baseline; // Baseline offset from the main baseline (down positive).
};

std::vector<Run> split_runs(std::string_view s, float size, bool markup) {
    std::vector<Run> runs;
    if (!markup) {
        runs.push_back({s, size, 0});
        return runs;
    }
    std::size_t start = 0, i = 0;
    while (i < s.size()) {
        if ((s[i] == '_' || s[i] == '^') && i + 1 < s.size() && s[i + 1] == '{') {
            const std::size_t close = s.find('}', i + 2);
            if (close != std::string_view::npos) {
                if (i > start) runs.push_back({s.substr(start, i - start), size, 0});
                const float shift = (s[i] == '_' ? kSubShift : kSupShift) * size;
                runs.push_back({s.substr(i + 2, close - i - 2), size * kScriptScale, shift});
                i = start = close + 1;
                continue;
            }
        }
        ++i;
    }
    if (start < s.size()) runs.push_back({s.substr(start), size, 0});
    return runs;
}

struct Glyph {
    const ImFontGlyph* g;
    float x, top, k; // Pen x and line top of the run (logical, relative to the text's top-left), scale.
};

struct RunStart {
    std::string_view text;
    float size, x, baseline; // Pen x and baseline below the line top of the run's first glyph (logical).
};

struct Layout {
    std::vector<Glyph> glyphs;
    std::vector<RunStart> runs;
    float width = 0;
    float ascent = 0;  // Main font ascent (logical).
    float cap_top = 0; // Top of capital 'H' below the line top (logical).
};

Layout layout(const FontSet& fonts, std::string_view text, float size, bool markup) {
    Layout out;
    const ImFont* main = fonts.font_for(size);
    const float k_main = size / main->FontSize;
    out.ascent = main->Ascent * k_main;
    const ImFontGlyph* h = main->FindGlyphNoFallback('H');
    out.cap_top = h ? h->Y0 * k_main : 0.25f * size;
    float x = 0;
    for (const Run& run : split_runs(text, size, markup)) {
        const ImFont* f = fonts.font_for(run.size);
        const float k = run.size / f->FontSize;
        const float top = out.ascent + run.baseline - f->Ascent * k; // Align run baselines.
        out.runs.push_back({run.text, run.size, x, out.ascent + run.baseline});
        const char* p = run.text.data();
        const char* end = p + run.text.size();
        while (p < end) {
            unsigned int c = 0;
            const int n = ImTextCharFromUtf8(&c, p, end);
            p += n > 0 ? n : 1;
            if (c == 0) break;
            const ImFontGlyph* g = f->FindGlyph(static_cast<ImWchar>(c));
            if (!g) continue;
            out.glyphs.push_back({g, x, top, k});
            x += g->AdvanceX * k;
        }
    }
    out.width = x;
    return out;
}

} // namespace

Vec2 measure_text(const FontSet& fonts, std::string_view text, float size, bool markup) {
    return {layout(fonts, text, size, markup).width, size};
}

namespace {

// Where a laid-out text goes: the offset of its top-left corner from the anchor in its own (unrotated)
// frame, and the rotation.
struct Placement {
    Vec2 anchor;
    float ox = 0, oy = 0, c = 1, s = 0;
    // Screen y is down, so a counter-clockwise angle maps local (u,v) to (u c + v s, -u s + v c).
    Vec2 at(float u, float v) const { return {anchor.x + u * c + v * s, anchor.y - u * s + v * c}; }
};

Placement place(const FontSet& fonts, const Layout& lay, Vec2 anchor, const TextStyle& style) {
    Placement p;
    if (style.halign == HAlign::Center) p.ox = -0.5f * lay.width;
    if (style.halign == HAlign::Right) p.ox = -lay.width;
    switch (style.valign) {
    case VAlign::Top:
        break;
    case VAlign::Middle:
        p.oy = -0.5f * (lay.cap_top + lay.ascent);
        break;
    case VAlign::Baseline:
        p.oy = -lay.ascent;
        break;
    case VAlign::Bottom:
        p.oy = -style.size;
        break;
    }
    // Rotation: exact for multiples of 90 degrees, so axis titles can be pixel-snapped.
    const float a = std::fmod(std::fmod(style.angle_deg, 360.0f) + 360.0f, 360.0f);
    p.c = std::cos(a * 3.14159265f / 180.0f), p.s = std::sin(a * 3.14159265f / 180.0f);
    const bool right_angle = std::fmod(a, 90.0f) == 0.0f;
    if (right_angle) {
        const int q = static_cast<int>(a / 90.0f);
        const float cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
        p.c = cs[q];
        p.s = sn[q];
    }
    // Snap anchor and offsets to whole framebuffer pixels so unrotated (and 90°) glyphs stay crisp.
    const float r = fonts.pixel_ratio();
    if (right_angle) {
        anchor = {std::round(anchor.x * r) / r, std::round(anchor.y * r) / r};
        p.ox = std::round(p.ox * r) / r;
        p.oy = std::round(p.oy * r) / r;
    }
    p.anchor = anchor;
    return p;
}

} // namespace

std::vector<dl::TextRun> text_runs(const FontSet& fonts, Vec2 anchor, std::string_view text,
                                   const TextStyle& style) {
    const Layout lay = layout(fonts, text, style.size, style.markup);
    const Placement p = place(fonts, lay, anchor, style);
    std::vector<dl::TextRun> runs;
    runs.reserve(lay.runs.size());
    for (const RunStart& r : lay.runs)
        if (!r.text.empty())
            runs.push_back({std::string(r.text), r.size, p.at(p.ox + r.x, p.oy + r.baseline)});
    return runs;
}

Rect text_bounds(const dl::Text& t, const FontSet& fonts) {
    const Layout lay = layout(fonts, t.text, t.style.size, t.style.markup);
    const Placement p = place(fonts, lay, t.anchor, t.style);
    // The line box (ascent + descent of the main size) in the text's frame, rotated with it.
    Rect b{1e30f, 1e30f, -1e30f, -1e30f};
    for (const auto& [u, v] : {std::pair{p.ox, p.oy},
                               {p.ox + lay.width, p.oy},
                               {p.ox, p.oy + t.style.size},
                               {p.ox + lay.width, p.oy + t.style.size}}) {
        const Vec2 q = p.at(u, v);
        b = {std::min(b.x0, q.x), std::min(b.y0, q.y), std::max(b.x1, q.x), std::max(b.y1, q.y)};
    }
    return b;
}

void emit_text(ImDrawList& list, const FontSet& fonts, Vec2 anchor, std::string_view text,
               const TextStyle& style) {
    const Layout lay = layout(fonts, text, style.size, style.markup);
    const Placement p = place(fonts, lay, anchor, style);
    const ImU32 col = style.color.packed();
    auto xf = [&p](float u, float v) {
        const Vec2 q = p.at(u, v);
        return ImVec2(q.x, q.y);
    };
    const float ox = p.ox, oy = p.oy;
    for (const Glyph& gl : lay.glyphs) {
        if (!gl.g->Visible) continue;
        const float u0 = ox + gl.x + gl.g->X0 * gl.k, u1 = ox + gl.x + gl.g->X1 * gl.k;
        const float v0 = oy + gl.top + gl.g->Y0 * gl.k, v1 = oy + gl.top + gl.g->Y1 * gl.k;
        list.PrimReserve(6, 4);
        list.PrimQuadUV(xf(u0, v0), xf(u1, v0), xf(u1, v1), xf(u0, v1), ImVec2(gl.g->U0, gl.g->V0),
                        ImVec2(gl.g->U1, gl.g->V0), ImVec2(gl.g->U1, gl.g->V1), ImVec2(gl.g->U0, gl.g->V1),
                        col);
    }
}

} // namespace fv::gfx
