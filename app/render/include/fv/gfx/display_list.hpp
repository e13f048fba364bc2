#pragma once
// The display list: what a Canvas records between begin() and end(), backend-neutral and in logical units
// (top-left origin, y down). Backends replay it: the GL canvas (PNG, window) and cairo (SVG, PDF; see
// vector_output.hpp). Commands are kept in call order, so shapes, images and text interleave as drawn.
#include "fv/gfx/image.hpp"
#include "fv/gfx/text.hpp"
#include "fv/gfx/types.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fv::gfx {

enum class LineStyle { Solid, Dashed, Dotted };

struct Stroke {
    Color color = colors::black;
    float width = 1.5f; ///< Logical pixels.
    LineStyle style = LineStyle::Solid;
};

/// Dash pattern of a stroke along its arc length: dash cores [k period, k period + on] (logical units), each
/// drawn with round caps of half the width; period 0 is solid. Dash lengths scale with the width but keep a
/// minimum so thin lines still read as dashed. Every backend uses this one definition.
struct DashPattern {
    float on = 0, period = 0;
};
DashPattern dash_pattern(const Stroke& s);

enum class MarkerShape { None, Circle, Square, Triangle, Diamond, Cross, Plus };

struct MarkerStyle {
    MarkerShape shape = MarkerShape::Circle;
    float size = 7;             ///< Diameter-like extent in logical pixels.
    Color fill = colors::black; ///< Alpha 0 for an outline-only marker.
    Color edge = colors::black;
    float edge_width = 0; ///< 0: no outline (fill only).
};

/// A marker's outline as a closed polygon around (0, 0) (logical units); empty for a circle (radius
/// size/2). The GL shader draws the same shapes as signed distances.
std::vector<Vec2> marker_outline(MarkerShape shape, float size);

struct ArrowStyle {
    Stroke shaft;
    float head_length = 12; ///< Logical pixels.
    float head_width = 9;
};

/// An arrow's parts: the shaft (from `from` to a point inside the head, so its round cap never pokes out of
/// the tip) and the head triangle. `valid` is false for a zero-length arrow (nothing drawn).
struct ArrowGeometry {
    bool valid = false;
    Vec2 shaft_from, shaft_to, tip, left, right;
};
ArrowGeometry arrow_geometry(Vec2 from, Vec2 to, const ArrowStyle& s);

namespace dl {

struct FillRect {
    Rect rect;
    Color color;
};
struct StrokeRect {
    Rect rect;
    Stroke stroke;
};
/// Non-finite points break the line; `closed` joins the last point to the first (unbroken lines only).
struct Polyline {
    std::vector<Vec2> points;
    Stroke stroke;
    bool closed = false;
};
struct Circle {
    Vec2 center;
    float radius = 0;
    Stroke stroke;
};
struct FillCircle {
    Vec2 center;
    float radius = 0;
    Color color;
};
struct FillTriangle {
    Vec2 a, b, c;
    Color color;
};
struct Marker {
    Vec2 center;
    MarkerStyle style;
};
struct Arrow {
    Vec2 from, to;
    ArrowStyle style;
};
/// RGBA pixels stretched over `dst`; `smooth` false: nearest neighbour (heat-map cells).
struct Picture {
    Rect dst;
    std::shared_ptr<const Image> pixels;
    bool smooth = false;
};
/// One run of text in one size: a piece of a Text between markup changes. `origin` is the start of its
/// baseline (logical units); the run is drawn rotated by the Text's angle about that point.
struct TextRun {
    std::string text;
    float size = 14; ///< Line height of DejaVu Sans (ascent + descent), logical units.
    Vec2 origin;
};
/// A text as called (anchor, string with its markup, style) and laid out into runs: sub- and superscripts
/// are runs of their own size and baseline.
struct Text {
    Vec2 anchor;
    std::string text;
    TextStyle style;
    std::vector<TextRun> runs;
};
/// Intersected with the current clip when recorded (`rect` is the resulting clip).
struct PushClip {
    Rect rect;
};
struct PopClip {};

using Command = std::variant<FillRect, StrokeRect, Polyline, Circle, FillCircle, FillTriangle, Marker, Arrow,
                             Picture, Text, PushClip, PopClip>;

} // namespace dl

/// Lays a text out into runs (markup, alignment and rotation as emit_text draws it; FontSet metrics).
std::vector<dl::TextRun> text_runs(const FontSet& fonts, Vec2 anchor, std::string_view text,
                                   const TextStyle& style);

/// A named range of commands [first, last) and the rectangle it stands for, recorded by plots for tests and
/// layout: "data" (a plot's series, markers and annotations, drawn inside `rect`, its data area) and
/// "legend" (a legend box `rect` and what is drawn in it). Backends ignore regions.
struct Region {
    std::string role;
    Rect rect;
    std::size_t first = 0, last = 0;
};

struct DisplayList {
    Vec2 size; ///< Logical size of the page.
    Color background = colors::white;
    std::vector<dl::Command> commands;
    std::vector<Region> regions;
};

/// Whether what a command draws (stroke widths, marker and arrow-head extents, text boxes included) comes
/// within `pad` of the rectangle `r`; clips, images and page-sized fills never do. Text boxes use the
/// FontSet's metrics.
bool command_touches(const dl::Command& c, const Rect& r, const FontSet& fonts, float pad = 0);
/// A box around everything command_touches can meet (stroke widths and text boxes included): a command
/// whose box stays more than `pad` away from `r` does not touch it. Commands that touch nothing (fills,
/// images, clips) get an empty box (x0 > x1).
Rect command_bounds(const dl::Command& c, const FontSet& fonts);
/// Clips segment a-b to the rectangle [x0, x1] x [y0, y1] (Liang–Barsky); false when it misses it.
bool clip_segment(double& ax, double& ay, double& bx, double& by, double x0, double y0, double x1, double y1);
/// The box a text occupies (its runs, rotated with it), in logical units.
Rect text_bounds(const dl::Text& t, const FontSet& fonts);

} // namespace fv::gfx
