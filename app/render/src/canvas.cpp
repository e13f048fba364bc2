#include "fv/gfx/canvas.hpp"

#include "fv/gfx/fonts.hpp"
#include "fv/gfx/imgui_renderer.hpp"
#include "shape_renderer.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fv::gfx {

std::uint32_t Color::packed() const {
    auto byte = [](float v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    return byte(r) | (byte(g) << 8) | (byte(b) << 16) | (byte(a) << 24);
}

using detail::ShapeVertex;

namespace {

// A run of consecutive draws of one kind under one clip rectangle. Batches are drawn in order,
// which is what lets text sit on top of a legend box that sits on top of data lines.
struct Batch {
    bool text = false;
    bool clear = false; // Opaque pixel-aligned rectangle done as a scissored glClear (llvmpipe: ~free).
    Color clear_color;
    detail::ShapeKind kind = detail::kSegment; // Shapes: one program per kind.
    Rect clip;
    std::size_t first = 0, count = 0; // Shapes: index range.
    std::size_t list = 0;             // Text: index into the draw-list pool.
};

// Logical units added to every bounding quad beyond the farthest pixel its shape can touch (rounding).
constexpr float kQuadMargin = 0.05f;

bool same_rect(const Rect& a, const Rect& b) {
    return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
}

bool finite(Vec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

// A dashed circle as a fine closed polyline, counter-clockwise on screen from angle 0.
std::vector<Vec2> circle_points(Vec2 center, float radius) {
    const int n = std::max(48, static_cast<int>(std::ceil(2.0f * 3.14159265f * radius / 3.0f)));
    std::vector<Vec2> pts(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * 3.141592653589793 * i / n;
        pts[static_cast<std::size_t>(i)] = {center.x + radius * static_cast<float>(std::cos(t)),
                                            center.y - radius * static_cast<float>(std::sin(t))};
    }
    return pts;
}

} // namespace

// Dash lengths scale with the width but keep a minimum so thin lines still read as dashed.
DashPattern dash_pattern(const Stroke& s) {
    const float w = s.width;
    switch (s.style) {
    case LineStyle::Solid:
        return {};
    case LineStyle::Dashed: {
        const float on = std::max(2.5f * w, 5.0f), gap = std::max(2.0f * w, 4.0f);
        return {on, on + w + gap}; // Round caps add w to each visible dash.
    }
    case LineStyle::Dotted:
        return {0.0f, w + std::max(1.3f * w, 2.5f)};
    }
    return {};
}

std::vector<Vec2> marker_outline(MarkerShape shape, float size) {
    // The shapes of shapes.frag.glsl (marker_alpha), r = size / 2.
    const float r = 0.5f * size;
    auto rotate45 = [](std::vector<Vec2> v) {
        const float k = 0.70710678f;
        for (Vec2& p : v) p = {(p.x - p.y) * k, (p.x + p.y) * k};
        return v;
    };
    switch (shape) {
    case MarkerShape::None:
    case MarkerShape::Circle:
        return {};
    case MarkerShape::Square: {
        const float h = 0.88f * r;
        return {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    }
    case MarkerShape::Triangle:
        return {{0.0f, -1.25f * r}, {1.08f * r, 0.62f * r}, {-1.08f * r, 0.62f * r}};
    case MarkerShape::Diamond: {
        const float h = 0.85f * r;
        return rotate45({{-h, -h}, {h, -h}, {h, h}, {-h, h}});
    }
    case MarkerShape::Cross:
    case MarkerShape::Plus: {
        const float a = shape == MarkerShape::Cross ? 1.1f * r : r, t = std::max(0.75f, 0.1f * size);
        std::vector<Vec2> v = {{t, -a}, {t, -t}, {a, -t}, {a, t},   {t, t},   {t, a},
                               {-t, a}, {-t, t}, {-a, t}, {-a, -t}, {-t, -t}, {-t, -a}};
        return shape == MarkerShape::Cross ? rotate45(std::move(v)) : v;
    }
    }
    return {};
}

ArrowGeometry arrow_geometry(Vec2 from, Vec2 to, const ArrowStyle& s) {
    ArrowGeometry g;
    Vec2 d = to - from;
    const float len = std::hypot(d.x, d.y);
    if (!(len > 0)) return g;
    d = d * (1.0f / len);
    const float head = std::min(s.head_length, len);
    const Vec2 n{-d.y, d.x};
    const Vec2 base = to - d * head;
    g.valid = true;
    g.shaft_from = from;
    g.shaft_to = base + d * (0.4f * head);
    g.tip = to;
    g.left = base + n * (0.5f * s.head_width);
    g.right = base - n * (0.5f * s.head_width);
    return g;
}

// The GL backend: replays a display list into batches (shapes by kind, text and images through the ImGui
// renderer) and draws them.
struct Canvas::Impl {
    const GlApi& gl;
    const FontSet& fonts;
    ImGuiRenderer& imgui;
    detail::ShapeRenderer shapes;
    ImDrawListSharedData shared; // Our own: text is emitted without an ImGui frame.
    std::vector<ShapeVertex> verts;
    std::vector<std::uint32_t> indices;
    std::vector<Batch> batches;
    std::vector<std::unique_ptr<ImDrawList>> lists;
    std::size_t lists_used = 0;
    std::vector<GLuint> textures; // Pool for images; reused from frame to frame.
    std::size_t textures_used = 0;
    std::vector<Rect> clips; // Replay's clip stack.
    float ratio = 1;

    // Recording.
    DisplayList list;
    std::vector<Rect> rec_clips;
    bool recording = false;

    Impl(const GlApi& g, const FontSet& f, ImGuiRenderer& r) : gl(g), fonts(f), imgui(r), shapes(g) {}
    ~Impl() {
        if (!textures.empty()) gl.DeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    }

    Batch& batch_for(bool text, detail::ShapeKind kind, ImTextureID tex) {
        const Rect& clip = clips.back();
        if (batches.empty() || batches.back().clear || batches.back().text != text ||
            (!text && batches.back().kind != kind) || !same_rect(batches.back().clip, clip)) {
            Batch b;
            b.text = text;
            b.kind = kind;
            b.clip = clip;
            b.first = indices.size();
            if (text) {
                if (lists_used == lists.size()) lists.push_back(std::make_unique<ImDrawList>(&shared));
                ImDrawList& l = *lists[lists_used];
                l._ResetForNewFrame();
                l.Flags = ImDrawListFlags_AllowVtxOffset;
                l.PushClipRect(ImVec2(clip.x0, clip.y0), ImVec2(clip.x1, clip.y1), false);
                l.PushTextureID(tex);
                b.list = lists_used++;
            }
            batches.push_back(b);
        }
        return batches.back();
    }

    // Appends a quad (corners q0..q3) carrying the same shape parameters on all four vertices.
    void quad(const Vec2 (&q)[4], int kind, const float (&a)[4], const float (&b)[4], const float (&c)[4],
              const float (&d3)[3], Color col) {
        Batch& batch = batch_for(false, static_cast<detail::ShapeKind>(kind), nullptr);
        const auto base = static_cast<std::uint32_t>(verts.size());
        const std::uint32_t packed = col.packed();
        for (const Vec2& p : q) {
            ShapeVertex v{};
            v.pos[0] = p.x;
            v.pos[1] = p.y;
            std::copy(std::begin(a), std::end(a), v.a);
            std::copy(std::begin(b), std::end(b), v.b);
            std::copy(std::begin(c), std::end(c), v.c);
            v.d[0] = static_cast<float>(kind);
            std::copy(std::begin(d3), std::end(d3), v.d + 1);
            v.color = packed;
            verts.push_back(v);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
        batch.count += 6;
    }

    void box_quad(float x0, float y0, float x1, float y1, int kind, const float (&a)[4], const float (&b)[4],
                  Color col) {
        const Vec2 q[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
        quad(q, kind, a, b, {0, 0, 0, 0}, {0, 0, 0}, col);
    }

    // How far beyond a shape's edge its antialiasing ramp has coverage > 0 (half a framebuffer pixel), with a
    // margin for rounding: the bounding quads reach this far and no farther, as llvmpipe pays for every pixel
    // a quad covers, discarded or not.
    float aa_reach() const { return 0.5f / ratio + kQuadMargin; }

    // Whether the line turns by at most 90 degrees at the joint a -> j -> b.
    static bool gentle_turn(Vec2 a, Vec2 j, Vec2 b) {
        const Vec2 d0 = j - a, d1 = b - j;
        return d0.x * d1.x + d0.y * d1.y >= 0;
    }

    static Vec2 unit(Vec2 v) { return v * (1.0f / std::hypot(v.x, v.y)); }
    static float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

    // A segment's quad covers every pixel the shader may shade, and as few others as it can: llvmpipe pays
    // for each pixel a quad covers, and a densely sampled curve (segments shorter than a pixel: 2000 of the
    // 2500 in the compare bench frame) would lay many quads over each of its pixels. The shader shades a
    // pixel only where its distance to the nearest core (this segment's or a neighbour's) is below
    // r = hw + 0.5/ratio, and at a joint only on its own side of the bisector (the neighbour discards the
    // other side, which it owns, wherever that neighbour's core is within the shader's reach
    // hw + 1/ratio + 0.5). Where the line turns by at most 90 degrees at both ends:
    // - a pixel this segment shades lies within r of its line: one nearer the neighbour's core, on this
    //   side of the bisector, is at least as near this segment's ray from the joint (reflect the
    //   neighbour's ray across the bisector);
    // - a pixel beyond the bisector within r of this segment's core lies within sqrt(2) r of the joint,
    //   so within the reach of the neighbour's core, which discards it here: when sqrt(2) r fits in the
    //   reach, the quad ends at the bisectors (each pixel of a dense curve is then shaded about once).
    // Sharper turns keep the quad of the shader's whole reach. Same pixels in every case.
    void segment(Vec2 prev, Vec2 p0, Vec2 p1, Vec2 next, bool has_prev, bool has_next, float s0,
                 const Stroke& s, const DashPattern& dp) {
        const float hw = 0.5f * s.width;
        const float reach = hw + 1.0f / ratio + 0.5f; // the shader's
        const bool gentle =
            (!has_prev || gentle_turn(prev, p0, p1)) && (!has_next || gentle_turn(p0, p1, next));
        const float e = gentle ? hw + aa_reach() : reach + kQuadMargin;
        const bool cut = gentle && 1.41422f * e <= reach;
        const Vec2 dir = unit(p1 - p0), n{-dir.y, dir.x};
        const float len = std::hypot(p1.x - p0.x, p1.y - p0.y);
        // Where each long side of the quad starts and ends, along dir from p0: at the ends' bisectors
        // (pushed out by the margin) or e beyond the ends.
        float from[2] = {-e, -e}, to[2] = {len + e, len + e};
        if (cut) {
            for (int side = 0; side < 2; ++side) {
                const float off = side == 0 ? -e : e;
                if (has_prev) {
                    const Vec2 b = unit(unit(p0 - prev) + dir);
                    from[side] = (-kQuadMargin - off * dot(n, b)) / dot(dir, b);
                }
                if (has_next) {
                    const Vec2 b = unit(dir + unit(next - p1));
                    to[side] = len + (kQuadMargin - off * dot(n, b)) / dot(dir, b);
                }
            }
            // Bisectors that cross within the quad (a very short segment at turns): the plain quad.
            if (!(from[0] < to[0] && from[1] < to[1])) from[0] = from[1] = -e, to[0] = to[1] = len + e;
        }
        const Vec2 q[4] = {p0 + dir * from[0] - n * e, p0 + dir * to[0] - n * e, p0 + dir * to[1] + n * e,
                           p0 + dir * from[1] + n * e};
        // Solid lines use a cheaper program without the dash evaluation.
        quad(q, dp.period > 0 ? detail::kSegment : detail::kSolidSegment, {prev.x, prev.y, p0.x, p0.y},
             {p1.x, p1.y, next.x, next.y}, {hw, s0, dp.on, dp.period},
             {has_prev ? 1.0f : 0.0f, has_next ? 1.0f : 0.0f, 0.0f}, s.color);
    }

    // The vertices of a run that are drawn, with each one's arc length along the whole run: a vertex is left
    // out where the chord that skips it passes within kThinning framebuffer pixels of every vertex it skips
    // (and so of the path between them), chords no longer than kMaxChord. Densely sampled curves (the force
    // traces and trails: 2000 of the 2500 segments of the compare bench frame are shorter than 2 logical
    // px) cost llvmpipe per segment, not per pixel: each segment's two triangles are set up, binned and
    // shaded in 4x4-pixel blocks. The line moves by at most kThinning of a pixel, so an edge pixel's
    // coverage by at most that share (13 of 255 levels); dashes keep their phase (the arc lengths are the
    // original path's).
    static constexpr float kThinning = 0.05f, kMaxChord = 8;
    std::vector<Vec2> thin_pts;
    std::vector<double> thin_arc;

    void thin_out(const std::vector<Vec2>& pts, float thinning) {
        const std::size_t n = pts.size();
        const float tol = thinning / ratio;
        thin_pts.assign(1, pts[0]);
        thin_arc.assign(1, 0.0);
        double arc = 0; // at pts[i], in double so that long lines keep an exact dash phase
        for (std::size_t i = 0; i + 1 < n;) {
            std::size_t j = i + 1;
            double arc_j = arc + length(pts[i], pts[j]);
            for (std::size_t c = j + 1; c < n && length(pts[i], pts[c]) <= kMaxChord; ++c) {
                bool near = true;
                for (std::size_t k = i + 1; k < c && near; ++k)
                    near = segment_distance(pts[k], pts[i], pts[c]) <= tol;
                if (!near) break;
                arc_j += length(pts[j], pts[c]);
                j = c;
            }
            thin_pts.push_back(pts[j]);
            thin_arc.push_back(arc_j);
            arc = arc_j, i = j;
        }
    }

    static double length(Vec2 a, Vec2 b) {
        return std::hypot(static_cast<double>(b.x - a.x), static_cast<double>(b.y - a.y));
    }

    static float segment_distance(Vec2 p, Vec2 a, Vec2 b) {
        const Vec2 ab = b - a, ap = p - a;
        const float len2 = dot(ab, ab);
        const float t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0f, 1.0f) : 0.0f;
        const Vec2 d = ap - ab * t;
        return std::hypot(d.x, d.y);
    }

    void polyline_run(const std::vector<Vec2>& run, const Stroke& s, bool closed) {
        if (run.size() < 2) return;
        const DashPattern dp = dash_pattern(s);
        thin_out(run, dp.period > 0 ? -1.0f : kThinning); // dashes: every vertex
        const std::vector<Vec2>& pts = thin_pts;
        const std::size_t n = pts.size();
        closed = closed && n >= 3;
        const std::size_t nseg = closed ? n : n - 1;
        for (std::size_t i = 0; i < nseg; ++i) {
            const Vec2 p0 = pts[i], p1 = pts[(i + 1) % n];
            const bool has_prev = closed || i > 0;
            const bool has_next = closed || i + 1 < nseg;
            const Vec2 prev = has_prev ? pts[(i + n - 1) % n] : p0;
            const Vec2 next = has_next ? pts[(i + 2) % n] : p1;
            segment(prev, p0, p1, next, has_prev, has_next, static_cast<float>(thin_arc[i]), s, dp);
        }
    }

    void clear_rect(const Rect& area, Color col) {
        const Rect& cur = clips.back();
        Batch b;
        b.clear = true;
        b.clear_color = col;
        b.clip = {std::max(area.x0, cur.x0), std::max(area.y0, cur.y0), std::min(area.x1, cur.x1),
                  std::min(area.y1, cur.y1)};
        batches.push_back(b);
    }

    // --- One function per display-list command. ---

    void draw(const dl::FillRect& cmd) {
        const Rect& r = cmd.rect;
        const Color c = cmd.color;
        auto on_pixel = [this](float v) { return std::floor(v * ratio) == v * ratio; };
        if (c.a >= 1.0f && on_pixel(r.x0) && on_pixel(r.y0) && on_pixel(r.x1) && on_pixel(r.y1)) {
            // Same pixels as the SDF path would give (full coverage inside, none outside), much cheaper.
            clear_rect(r, c);
            return;
        }
        const float e = aa_reach();
        // Large: the pixels fully inside (with a pixel to spare) get the same colour from a scissored clear
        // (opaque) or a flat quad (translucent) as from the SDF, whose coverage is 1 there; only the border
        // bands need the SDF. llvmpipe pays per shaded pixel, and plot backgrounds and slip shading are
        // large.
        const float ix0 = (std::ceil(r.x0 * ratio) + 1) / ratio, iy0 = (std::ceil(r.y0 * ratio) + 1) / ratio;
        const float ix1 = (std::floor(r.x1 * ratio) - 1) / ratio,
                    iy1 = (std::floor(r.y1 * ratio) - 1) / ratio;
        if (ix1 - ix0 > 4 && iy1 - iy0 > 4) {
            if (c.a >= 1.0f) {
                clear_rect({ix0, iy0, ix1, iy1}, c);
            } else {
                box_quad(ix0, iy0, ix1, iy1, detail::kFlat, {0, 0, 0, 0}, {0, 0, 0, 0}, c);
            }
            const float a[4] = {r.x0, r.y0, r.x1, r.y1}, b[4] = {0, 1, 0, 0};
            box_quad(r.x0 - e, r.y0 - e, r.x1 + e, iy0, detail::kRect, a, b, c); // top
            box_quad(r.x0 - e, iy1, r.x1 + e, r.y1 + e, detail::kRect, a, b, c); // bottom
            box_quad(r.x0 - e, iy0, ix0, iy1, detail::kRect, a, b, c);           // left
            box_quad(ix1, iy0, r.x1 + e, iy1, detail::kRect, a, b, c);           // right
            return;
        }
        box_quad(r.x0 - e, r.y0 - e, r.x1 + e, r.y1 + e, detail::kRect, {r.x0, r.y0, r.x1, r.y1},
                 {0, 1, 0, 0}, c);
    }

    void draw(const dl::StrokeRect& cmd) {
        const Rect& r = cmd.rect;
        const Stroke& s = cmd.stroke;
        if (s.style != LineStyle::Solid) {
            polyline({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, s, true);
            return;
        }
        const float hw = 0.5f * s.width, e = hw + aa_reach();
        const float a[4] = {r.x0, r.y0, r.x1, r.y1}, b[4] = {hw, 0, 0, 0};
        if (r.width() > 2 * e + 2 && r.height() > 2 * e + 2) {
            // The outline's SDF evaluated only on four bands along the edges (same pixels as one quad over
            // the whole rectangle, whose inside would all be discarded, at a fraction of the cost).
            box_quad(r.x0 - e, r.y0 - e, r.x1 + e, r.y0 + e, detail::kRect, a, b, s.color);
            box_quad(r.x0 - e, r.y1 - e, r.x1 + e, r.y1 + e, detail::kRect, a, b, s.color);
            box_quad(r.x0 - e, r.y0 + e, r.x0 + e, r.y1 - e, detail::kRect, a, b, s.color);
            box_quad(r.x1 - e, r.y0 + e, r.x1 + e, r.y1 - e, detail::kRect, a, b, s.color);
            return;
        }
        box_quad(r.x0 - e, r.y0 - e, r.x1 + e, r.y1 + e, detail::kRect, a, b, s.color);
    }

    void polyline(const std::vector<Vec2>& pts, const Stroke& s, bool closed) {
        // Split at non-finite points and drop repeated points (zero-length segments have no direction).
        std::vector<Vec2> run;
        run.reserve(pts.size());
        bool broken = false;
        for (const Vec2& p : pts) {
            if (!finite(p)) {
                polyline_run(run, s, false);
                run.clear();
                broken = true;
                continue;
            }
            if (!run.empty() && std::fabs(run.back().x - p.x) < 1e-4f &&
                std::fabs(run.back().y - p.y) < 1e-4f)
                continue;
            run.push_back(p);
        }
        if (closed && run.size() >= 2) {
            const Vec2 f = run.front(), l = run.back();
            if (std::fabs(f.x - l.x) < 1e-4f && std::fabs(f.y - l.y) < 1e-4f) run.pop_back();
        }
        polyline_run(run, s, closed && !broken);
    }

    void draw(const dl::Polyline& cmd) { polyline(cmd.points, cmd.stroke, cmd.closed); }

    void draw(const dl::Circle& cmd) {
        const Vec2 center = cmd.center;
        const float radius = cmd.radius;
        const Stroke& s = cmd.stroke;
        if (s.style == LineStyle::Solid) {
            const float hw = 0.5f * s.width, e = radius + hw + aa_reach();
            box_quad(center.x - e, center.y - e, center.x + e, center.y + e, detail::kMarker,
                     {center.x, center.y, radius, hw}, {1, 0, 0, 0}, s.color);
            return;
        }
        // Dashed circles: a fine closed polyline keeps the dash pattern continuous all round.
        polyline(circle_points(center, radius), s, true);
    }

    void draw(const dl::FillCircle& cmd) {
        const float e = cmd.radius + aa_reach();
        box_quad(cmd.center.x - e, cmd.center.y - e, cmd.center.x + e, cmd.center.y + e, detail::kMarker,
                 {cmd.center.x, cmd.center.y, cmd.radius, 0}, {1, 1, 0, 0}, cmd.color);
    }

    void fill_triangle(Vec2 a, Vec2 b, Vec2 c, Color col) {
        const float e = aa_reach();
        const float x0 = std::min({a.x, b.x, c.x}) - e, x1 = std::max({a.x, b.x, c.x}) + e;
        const float y0 = std::min({a.y, b.y, c.y}) - e, y1 = std::max({a.y, b.y, c.y}) + e;
        box_quad(x0, y0, x1, y1, detail::kTriangle, {a.x, a.y, b.x, b.y}, {c.x, c.y, 0, 0}, col);
    }

    void draw(const dl::FillTriangle& cmd) { fill_triangle(cmd.a, cmd.b, cmd.c, cmd.color); }

    void draw(const dl::Marker& cmd) {
        const MarkerStyle& m = cmd.style;
        const Vec2 center = cmd.center;
        const float r = 0.5f * m.size;
        const float shape =
            static_cast<float>(static_cast<int>(m.shape)); // Circle=1 ... Plus=6, as in the shader.
        const float e = 1.6f * r + m.edge_width + 2;
        const float x0 = center.x - e, y0 = center.y - e, x1 = center.x + e, y1 = center.y + e;
        // Cross and plus are filled bars whose thickness follows the size; they take fill and edge like
        // the others.
        const float bar = std::max(0.75f, 0.1f * m.size);
        if (m.fill.a > 0)
            box_quad(x0, y0, x1, y1, detail::kMarker, {center.x, center.y, r, 0}, {shape, 1, bar, 0}, m.fill);
        if (m.edge_width > 0 && m.edge.a > 0)
            box_quad(x0, y0, x1, y1, detail::kMarker, {center.x, center.y, r, 0.5f * m.edge_width},
                     {shape, 0, bar, 0}, m.edge);
    }

    void draw(const dl::Arrow& cmd) {
        const ArrowGeometry g = arrow_geometry(cmd.from, cmd.to, cmd.style);
        if (!g.valid) return;
        polyline({g.shaft_from, g.shaft_to}, cmd.style.shaft, false);
        fill_triangle(g.tip, g.left, g.right, cmd.style.shaft.color);
    }

    void draw(const dl::Picture& cmd) {
        const Image& pixels = *cmd.pixels;
        if (textures_used == textures.size()) {
            GLuint t = 0;
            gl.GenTextures(1, &t);
            textures.push_back(t);
        }
        const GLuint tex = textures[textures_used++];
        const GLint filter = cmd.smooth ? GL_LINEAR : GL_NEAREST;
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, tex);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, pixels.width, pixels.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                      pixels.rgba.data());
        // Images go through the ImGui renderer (texture per command), as textured quads in a draw list.
        Batch& b = batch_for(true, detail::kSegment, fonts.atlas().TexID);
        ImDrawList& l = *lists[b.list];
        const Rect& dst = cmd.dst;
        l.PushTextureID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(tex)));
        l.PrimReserve(6, 4);
        l.PrimRectUV(ImVec2(dst.x0, dst.y0), ImVec2(dst.x1, dst.y1), ImVec2(0, 0), ImVec2(1, 1),
                     IM_COL32_WHITE);
        l.PopTextureID();
    }

    void draw(const dl::Text& cmd) {
        Batch& b = batch_for(true, detail::kSegment, fonts.atlas().TexID);
        emit_text(*lists[b.list], fonts, cmd.anchor, cmd.text, cmd.style);
    }

    void draw(const dl::PushClip& cmd) { clips.push_back(cmd.rect); }
    void draw(const dl::PopClip&) {
        if (clips.size() > 1) clips.pop_back();
    }

    // Whether a fill repeats the page under it: opaque, in the page's colour, over pixels that no earlier
    // command may have drawn (a plot's white background on the white page). Such a fill leaves every pixel
    // as it is, and llvmpipe pays about 2 ns per pixel for it (a scissored clear is a quad there): 2.3 ms of
    // the compare bench frame at 1920x1080 scale 1.5.
    bool on_blank_page(const DisplayList& dl, std::size_t index, const dl::FillRect& fill) const {
        const Color &c = fill.color, &bg = dl.background;
        if (c.a < 1.0f || c.r != bg.r || c.g != bg.g || c.b != bg.b || c.a != bg.a) return false;
        constexpr float kPad = 2; // beyond any antialiasing ramp and quad margin, in logical units
        const Rect r{fill.rect.x0 - kPad, fill.rect.y0 - kPad, fill.rect.x1 + kPad, fill.rect.y1 + kPad};
        for (std::size_t i = 0; i < index; ++i) {
            const dl::Command& earlier = dl.commands[i];
            if (const auto* f = std::get_if<dl::FillRect>(&earlier); f && f->rect.overlaps(r)) return false;
            if (const auto* p = std::get_if<dl::Picture>(&earlier); p && p->dst.overlaps(r)) return false;
            if (command_touches(earlier, r, fonts)) return false;
        }
        return true;
    }

    void render(const DisplayList& dl, float pixel_ratio);
};

void Canvas::Impl::render(const DisplayList& dl, float pixel_ratio) {
    ratio = pixel_ratio;
    verts.clear();
    indices.clear();
    batches.clear();
    lists_used = 0;
    textures_used = 0;
    const Vec2 size = dl.size;
    clips.assign(1, Rect{0, 0, size.x, size.y});
    shared.ClipRectFullscreen = ImVec4(0, 0, size.x, size.y);
    shared.TexUvWhitePixel = fonts.atlas().TexUvWhitePixel;
    shared.Font = fonts.font_for(14);
    shared.FontSize = 14;
    for (std::size_t i = 0; i < dl.commands.size(); ++i) {
        const dl::Command& c = dl.commands[i];
        if (const auto* fill = std::get_if<dl::FillRect>(&c); fill && on_blank_page(dl, i, *fill)) continue;
        std::visit([this](const auto& cmd) { draw(cmd); }, c);
    }

    const int fb_w = static_cast<int>(std::lround(size.x * ratio));
    const int fb_h = static_cast<int>(std::lround(size.y * ratio));
    gl.Viewport(0, 0, fb_w, fb_h);
    gl.Disable(GL_SCISSOR_TEST);
    gl.ClearColor(dl.background.r, dl.background.g, dl.background.b, dl.background.a);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    shapes.upload(verts, indices);
    bool shapes_bound = false;
    for (const Batch& b : batches) {
        if (b.text) {
            ImDrawList* l = lists[b.list].get();
            ImDrawData dd;
            dd.Valid = true;
            dd.CmdListsCount = 1;
            dd.CmdLists = &l;
            dd.TotalVtxCount = l->VtxBuffer.Size;
            dd.TotalIdxCount = l->IdxBuffer.Size;
            dd.DisplayPos = ImVec2(0, 0);
            dd.DisplaySize = ImVec2(size.x, size.y);
            dd.FramebufferScale = ImVec2(ratio, ratio);
            imgui.render(dd);
            shapes_bound = false; // The ImGui renderer changed program, VAO and scissor.
            continue;
        }
        if (!shapes_bound) {
            shapes.bind(size.x, size.y, ratio, fb_h);
            gl.Enable(GL_SCISSOR_TEST);
            gl.Viewport(0, 0, fb_w, fb_h);
            shapes_bound = true;
        }
        // Same rounding as the ImGui renderer so text and shapes clip identically.
        const float fw = static_cast<float>(fb_w), fh = static_cast<float>(fb_h);
        const float x0 = std::clamp(b.clip.x0 * ratio, 0.0f, fw),
                    y0 = std::clamp(b.clip.y0 * ratio, 0.0f, fh);
        const float x1 = std::clamp(b.clip.x1 * ratio, 0.0f, fw),
                    y1 = std::clamp(b.clip.y1 * ratio, 0.0f, fh);
        if (x1 <= x0 || y1 <= y0) continue;
        gl.Scissor(static_cast<GLint>(x0), static_cast<GLint>(fh - y1), static_cast<GLsizei>(x1 - x0),
                   static_cast<GLsizei>(y1 - y0));
        if (b.clear) {
            gl.ClearColor(b.clear_color.r, b.clear_color.g, b.clear_color.b, b.clear_color.a);
            gl.Clear(GL_COLOR_BUFFER_BIT);
            continue;
        }
        shapes.draw(b.kind, b.first, b.count);
    }
    gl.BindVertexArray(0);
    gl.Disable(GL_SCISSOR_TEST);
}

Canvas::Canvas(const GlApi& gl, const FontSet& fonts, ImGuiRenderer& renderer)
    : impl_(std::make_unique<Impl>(gl, fonts, renderer)), fonts_(fonts) {
    if (!fonts.atlas().TexID)
        throw std::logic_error("Canvas: upload the font atlas to the ImGuiRenderer first");
}

Canvas::~Canvas() = default;

void Canvas::begin(Vec2 logical_size, float pixel_ratio, Color background) {
    Impl& m = *impl_;
    size_ = logical_size;
    m.ratio = pixel_ratio;
    m.list.size = logical_size;
    m.list.background = background;
    m.list.commands.clear();
    m.list.regions.clear();
    m.rec_clips.assign(1, Rect{0, 0, logical_size.x, logical_size.y});
    m.recording = true;
}

void Canvas::end_recording() {
    impl_->recording = false;
}

void Canvas::end() {
    end_recording();
    impl_->render(impl_->list, impl_->ratio);
}

const DisplayList& Canvas::display_list() const {
    return impl_->list;
}

void Canvas::draw(const DisplayList& list, float pixel_ratio) {
    impl_->render(list, pixel_ratio);
}

void Canvas::record(dl::Command c) {
    if (!impl_->recording) throw std::logic_error("Canvas: draw call outside begin()/end()");
    impl_->list.commands.push_back(std::move(c));
}

Canvas::Mark Canvas::mark() const {
    return {impl_->list.commands.size(), impl_->list.regions.size()};
}

void Canvas::rewind(const Mark& m) {
    if (m.commands > impl_->list.commands.size() || m.regions > impl_->list.regions.size())
        throw std::logic_error("Canvas::rewind past the end of the recording");
    impl_->list.commands.erase(impl_->list.commands.begin() + static_cast<std::ptrdiff_t>(m.commands),
                               impl_->list.commands.end());
    impl_->list.regions.resize(m.regions);
}

void Canvas::add_region(std::string role, const Rect& rect, const Mark& since) {
    impl_->list.regions.push_back({std::move(role), rect, since.commands, impl_->list.commands.size()});
}

void Canvas::push_clip(const Rect& r, bool intersect) {
    Rect c = r;
    if (intersect) {
        const Rect& cur = impl_->rec_clips.back();
        c = {std::max(c.x0, cur.x0), std::max(c.y0, cur.y0), std::min(c.x1, cur.x1), std::min(c.y1, cur.y1)};
    }
    record(dl::PushClip{c});
    impl_->rec_clips.push_back(c);
}

void Canvas::pop_clip() {
    if (impl_->rec_clips.size() <= 1) throw std::logic_error("Canvas::pop_clip without push_clip");
    record(dl::PopClip{});
    impl_->rec_clips.pop_back();
}

const Rect& Canvas::clip() const {
    return impl_->rec_clips.back();
}

void Canvas::fill_rect(const Rect& r, Color c) {
    record(dl::FillRect{r, c});
}

void Canvas::stroke_rect(const Rect& r, const Stroke& s) {
    record(dl::StrokeRect{r, s});
}

void Canvas::line(Vec2 a, Vec2 b, const Stroke& s) {
    record(dl::Polyline{{a, b}, s, false});
}

void Canvas::polyline(const Vec2* pts, std::size_t n, const Stroke& s, bool closed) {
    record(dl::Polyline{std::vector<Vec2>(pts, pts + n), s, closed});
}

void Canvas::circle(Vec2 center, float radius, const Stroke& s) {
    record(dl::Circle{center, radius, s});
}

void Canvas::fill_circle(Vec2 center, float radius, Color c) {
    record(dl::FillCircle{center, radius, c});
}

void Canvas::fill_triangle(Vec2 a, Vec2 b, Vec2 c, Color col) {
    record(dl::FillTriangle{a, b, c, col});
}

void Canvas::marker(Vec2 center, const MarkerStyle& m) {
    if (m.shape == MarkerShape::None || !finite(center)) return;
    record(dl::Marker{center, m});
}

void Canvas::arrow(Vec2 from, Vec2 to, const ArrowStyle& s) {
    record(dl::Arrow{from, to, s});
}

void Canvas::text(Vec2 anchor, std::string_view str, const TextStyle& style) {
    if (!impl_->recording) throw std::logic_error("Canvas: draw call outside begin()/end()");
    record(dl::Text{anchor, std::string(str), style, text_runs(fonts_, anchor, str, style)});
}

void Canvas::image(const Rect& dst, const Image& pixels, bool smooth) {
    if (!impl_->recording) throw std::logic_error("Canvas: draw call outside begin()/end()");
    if (pixels.empty()) return;
    record(dl::Picture{dst, std::make_shared<const Image>(pixels), smooth});
}

Vec2 Canvas::measure_text(std::string_view str, float size, bool markup) const {
    return fv::gfx::measure_text(fonts_, str, size, markup);
}

} // namespace fv::gfx
