#pragma once
// Canvas: immediate-style 2D drawing in logical pixels (top-left origin) with antialiased,
// shader-based primitives and text. Calls are recorded in order between begin() and end() into a
// DisplayList (display_list.hpp); end() replays it through GL, so shapes and text interleave exactly as
// called. The same list replays to SVG and PDF (vector_output.hpp).
// The canvas does not know which backend (headless or window) it renders on.
#include "fv/gfx/display_list.hpp"
#include "fv/gfx/gl_api.hpp"
#include "fv/gfx/image.hpp"
#include "fv/gfx/text.hpp"
#include "fv/gfx/types.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fv::gfx {

class FontSet;
class ImGuiRenderer;

class Canvas {
  public:
    /// `renderer` must have uploaded `fonts.atlas()` already (it holds the texture).
    Canvas(const GlApi& gl, const FontSet& fonts, ImGuiRenderer& renderer);
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    /// Starts recording a frame of `logical` size; `pixel_ratio` framebuffer pixels per unit.
    void begin(Vec2 logical_size, float pixel_ratio, Color background);
    /// Renders everything recorded since begin() into the current framebuffer.
    void end();
    /// Stops recording without drawing (the list is for another backend).
    void end_recording();
    /// What was recorded since the last begin() (complete after end() or end_recording()).
    const DisplayList& display_list() const;
    /// Replays any display list through GL into the current framebuffer, `pixel_ratio` framebuffer pixels
    /// per logical unit (what end() does with the recorded one).
    void draw(const DisplayList& list, float pixel_ratio);

    /// A point in the recording: rewind() drops everything recorded after it (commands and regions), so
    /// that a layout can be redrawn after looking at what it drew. Draw calls between mark() and rewind()
    /// must leave the clip stack as they found it.
    struct Mark {
        std::size_t commands = 0, regions = 0;
    };
    Mark mark() const;
    void rewind(const Mark& m);
    /// Names the commands recorded since `since` (up to now) as a region (see dl Region).
    void add_region(std::string role, const Rect& rect, const Mark& since);

    /// Clip rectangle stack (scissor per draw). The initial clip is the whole canvas.
    void push_clip(const Rect& r, bool intersect = true);
    void pop_clip();
    const Rect& clip() const;

    void fill_rect(const Rect& r, Color c);
    void stroke_rect(const Rect& r, const Stroke& s);
    void line(Vec2 a, Vec2 b, const Stroke& s);
    /// Thick polyline with round joins and caps; dash patterns continue across vertices.
    /// Non-finite points break the line. `closed` joins the last point to the first.
    void polyline(const Vec2* pts, std::size_t n, const Stroke& s, bool closed = false);
    void polyline(const std::vector<Vec2>& pts, const Stroke& s, bool closed = false) {
        polyline(pts.data(), pts.size(), s, closed);
    }
    /// Circle outline (solid via an exact SDF ring; dashed/dotted as a closed polyline).
    void circle(Vec2 center, float radius, const Stroke& s);
    void fill_circle(Vec2 center, float radius, Color c);
    void fill_triangle(Vec2 a, Vec2 b, Vec2 c, Color col);
    void marker(Vec2 center, const MarkerStyle& m);
    /// Shaft from `from` to `to` with a filled head at `to`.
    void arrow(Vec2 from, Vec2 to, const ArrowStyle& s);

    /// Draws an RGBA image stretched over `dst` (nearest-neighbour when `smooth` is false, e.g. heat-map
    /// cells). The pixels are copied into the display list and uploaded to a texture when drawn.
    void image(const Rect& dst, const Image& pixels, bool smooth = false);

    void text(Vec2 anchor, std::string_view str, const TextStyle& style);
    Vec2 measure_text(std::string_view str, float size, bool markup = true) const;
    const FontSet& fonts() const { return fonts_; }
    Vec2 size() const { return size_; }

  private:
    void record(dl::Command c);
    struct Impl;
    std::unique_ptr<Impl> impl_;
    const FontSet& fonts_;
    Vec2 size_;
};

} // namespace fv::gfx
