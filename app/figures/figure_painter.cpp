#include "figure_painter.hpp"

#include "fv/gfx/plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace fv::app {
namespace {

gfx::LegendPosition legend_position(Legend l) {
    switch (l) {
    case Legend::best:
        return gfx::LegendPosition::Best;
    case Legend::none:
        return gfx::LegendPosition::None;
    case Legend::top_left:
        return gfx::LegendPosition::TopLeft;
    case Legend::top_right:
        return gfx::LegendPosition::TopRight;
    case Legend::bottom_left:
        return gfx::LegendPosition::BottomLeft;
    case Legend::bottom_right:
        return gfx::LegendPosition::BottomRight;
    case Legend::outside:
        return gfx::LegendPosition::Outside;
    case Legend::above:
        return gfx::LegendPosition::Above;
    }
    return gfx::LegendPosition::Best;
}

gfx::LineStyle line_style(Dash d) {
    switch (d) {
    case Dash::dashed:
        return gfx::LineStyle::Dashed;
    case Dash::dotted:
        return gfx::LineStyle::Dotted;
    default:
        return gfx::LineStyle::Solid;
    }
}

gfx::MarkerShape marker_shape(Mark m) {
    switch (m) {
    case Mark::circle:
        return gfx::MarkerShape::Circle;
    case Mark::square:
        return gfx::MarkerShape::Square;
    case Mark::triangle:
        return gfx::MarkerShape::Triangle;
    case Mark::diamond:
        return gfx::MarkerShape::Diamond;
    case Mark::cross:
        return gfx::MarkerShape::Cross;
    default:
        return gfx::MarkerShape::None;
    }
}

gfx::Vec2 to_px(const gfx::PlotTransform& tf, const fv::Vec2& p) {
    return tf.to_pixel(p.x(), p.y());
}

// Text colour of a label in an ink: light inks (the spring's grey) are darkened so that labels stay legible.
gfx::Color label_color(Ink ink) {
    return ink == Ink::spring ? gfx::Color::hex(0x505050) : ink_color(ink, 0);
}

gfx::TextStyle label_style(float size, gfx::Color color, float dx, float dy) {
    gfx::TextStyle ts;
    ts.size = size;
    ts.color = color;
    ts.halign = dx > 0.3f ? gfx::HAlign::Left : (dx < -0.3f ? gfx::HAlign::Right : gfx::HAlign::Center);
    ts.valign = dy > 0.3f ? gfx::VAlign::Top : (dy < -0.3f ? gfx::VAlign::Bottom : gfx::VAlign::Middle);
    return ts;
}

// A label and the places it may go, in order of preference.
struct LabelCandidate {
    gfx::Vec2 anchor;
    gfx::TextStyle style;
    bool far = false; ///< Tried only when every place before lies on text, a marker or an arrow.
};

// Places labels one after the other where they cover the least of what is drawn in the data area (series,
// shapes, markers) and of the labels placed before them, inside the data area when possible.
class LabelPlacer {
  public:
    // `walls`: lines no label may touch (as solid as a marker), though drawn as lines.
    LabelPlacer(gfx::Canvas& c, const gfx::PlotTransform& tf, std::vector<gfx::dl::Command> walls = {})
        : canvas_(c), tf_(tf), walls_(std::move(walls)) {}

    // `own`: the shape the label names (its marker, arrow or segment), which it may touch. `leader_to`: the
    // point it names; where every candidate lies on a solid shape (text, marker, arrow), the label goes to
    // the nearest free place in the data area instead, with a thin leader line to that point (matplotlib's
    // annotate). `optional`: a label that is left out where every candidate lies on text, a marker or an
    // arrow, or crosses two lines or more.
    void place(const std::string& text, const std::vector<LabelCandidate>& candidates,
               const std::function<bool(const gfx::dl::Command&)>& own,
               std::optional<gfx::Vec2> leader_to = std::nullopt, bool optional = false) {
        if (text.empty() || candidates.empty()) return;
        refresh_boxes();
        double best_score = 1e300;
        gfx::dl::Text best;
        for (const LabelCandidate& cand : candidates) {
            if (cand.far && best_score < 100) break;
            gfx::dl::Text t{cand.anchor, text, cand.style, {}};
            const double score = cost(t, own);
            if (score < best_score) best_score = score, best = t;
            if (score == 0) break;
        }
        if (optional && best_score >= 2) return;
        if (best_score >= 100 && leader_to) {
            const gfx::Rect& A = tf_.area;
            gfx::TextStyle st = candidates.front().style;
            st.halign = gfx::HAlign::Center, st.valign = gfx::VAlign::Middle;
            // The grid's places nearest the point first: the best place is the nearest one that covers
            // nothing (a score of 1 outweighs any distance within the plot), so the search mostly ends
            // after a few places instead of scoring the whole area (thousands of places, every frame, in
            // a crowded compare view). Ties keep the grid's row order.
            std::vector<std::pair<float, gfx::Vec2>> grid;
            for (float y = A.y0 + 6; y < A.y1 - 6; y += 6)
                for (float x = A.x0 + 6; x < A.x1 - 6; x += 6)
                    grid.push_back({std::hypot(x - leader_to->x, y - leader_to->y), {x, y}});
            std::stable_sort(grid.begin(), grid.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
            double best_far = 1e300;
            gfx::dl::Text far;
            for (const auto& [distance, at] : grid) {
                const gfx::dl::Text t{at, text, st, {}};
                const double score = cost(t, own);
                if (score >= 100) continue;
                const double far_score = score * 1e4 + distance;
                if (far_score < best_far) best_far = far_score, far = t;
                if (score == 0) break;
            }
            if (best_far < 1e300) {
                best = far;
                const gfx::Rect b = gfx::text_bounds(far, canvas_.fonts());
                const gfx::Vec2 p = *leader_to;
                const gfx::Vec2 q{std::clamp(p.x, b.x0, b.x1), std::clamp(p.y, b.y0, b.y1)};
                // From the box's edge to 4 units short of the point.
                const float d = std::hypot(p.x - q.x, p.y - q.y);
                if (d > 6) leaders_.push_back({q, q + (p - q) * ((d - 4) / d)});
            }
        }
        placed_.push_back(gfx::text_bounds(best, canvas_.fonts()));
        pending_.push_back(best);
    }
    // Draws the placed labels (after every placement, so that each was placed against the shapes only).
    // Each leader line is recorded as a region "leader" (a label that found no free place near what it names:
    // the column layout gives such a panel more room).
    void draw() {
        for (const auto& [a, b] : leaders_) {
            const gfx::Canvas::Mark at = canvas_.mark();
            canvas_.line(a, b, {gfx::Color::hex(0x606060), 0.8f});
            canvas_.add_region(
                "leader", {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)},
                at);
        }
        for (const auto& t : pending_) canvas_.text(t.anchor, t.text, t.style);
    }

  private:
    gfx::Canvas& canvas_;
    const gfx::PlotTransform& tf_;
    std::vector<gfx::dl::Command> walls_;
    std::vector<gfx::Rect> placed_;
    std::vector<gfx::dl::Text> pending_;
    std::vector<std::pair<gfx::Vec2, gfx::Vec2>> leaders_;
    std::vector<gfx::Rect> boxes_; ///< command_bounds of each data command, for a quick test in cost()

    // The data commands' boxes as the display list stands now: those drawn since the last label added (the
    // list only grows while the labels are placed, in one overlay's call; all again should it have shrunk).
    void refresh_boxes() {
        const auto& cmds = canvas_.display_list().commands;
        if (cmds.size() < tf_.first_data_command + boxes_.size()) boxes_.clear();
        for (std::size_t k = tf_.first_data_command + boxes_.size(); k < cmds.size(); ++k)
            boxes_.push_back(gfx::command_bounds(cmds[k], canvas_.fonts()));
    }

    // What a label at `t` covers: 1000 outside the data area, 100 per text, marker or arrow (unreadable), 1
    // per line it crosses (untidy), 100 per label placed before.
    double cost(const gfx::dl::Text& t, const std::function<bool(const gfx::dl::Command&)>& own) const {
        const auto& cmds = canvas_.display_list().commands;
        const gfx::Rect b = gfx::text_bounds(t, canvas_.fonts());
        // Every test below comes within 1.5 units of the box; one more for rounding.
        const gfx::Rect near{b.x0 - 2.5f, b.y0 - 2.5f, b.x1 + 2.5f, b.y1 + 2.5f};
        double score = 0;
        const gfx::Rect& A = tf_.area;
        if (b.x0 < A.x0 || b.x1 > A.x1 || b.y0 < A.y0 || b.y1 > A.y1) score += 1000;
        for (std::size_t k = tf_.first_data_command; k < cmds.size(); ++k) {
            if (!boxes_[k - tf_.first_data_command].overlaps(near)) continue;
            const auto& cmd = cmds[k];
            // What the label names it may touch, but its glyphs (the box less 2 units each side: the
            // leading) not lie on it (P's label on P's dot where the dot grew in presentation mode, −F's on
            // its arrow).
            if (own(cmd)) {
                if ((std::holds_alternative<gfx::dl::Marker>(cmd) ||
                     std::holds_alternative<gfx::dl::Arrow>(cmd)) &&
                    gfx::command_touches(cmd, b.inset(2), canvas_.fonts(), 0.0f))
                    score += 100;
                continue;
            }
            if (!gfx::command_touches(cmd, b, canvas_.fonts(), 1.5f)) continue;
            const bool solid = std::holds_alternative<gfx::dl::Text>(cmd) ||
                               std::holds_alternative<gfx::dl::Marker>(cmd) ||
                               std::holds_alternative<gfx::dl::Arrow>(cmd);
            score += solid ? 100 : 1;
        }
        for (const gfx::Rect& r : placed_)
            if (r.overlaps(b)) score += 100;
        for (const gfx::dl::Command& w : walls_)
            if (gfx::command_touches(w, b, canvas_.fonts(), 1.5f)) score += 100;
        return score;
    }
};

bool same(gfx::Vec2 a, gfx::Vec2 b) {
    return std::fabs(a.x - b.x) < 1e-3f && std::fabs(a.y - b.y) < 1e-3f;
}

// The eight places around a point, `r` from it (r ~ 9 units, 8 up or down, at text scale 1: past a marker
// of the same scale), starting with direction (dx, dy) and turning away from it. Crowded (every place near
// lies on text, a marker or an arrow): the same eight places twice as far out.
std::vector<LabelCandidate> around(gfx::Vec2 at, float dx, float dy, float size, gfx::Color color, float r0) {
    const float a0 = std::atan2(dy, dx);
    std::vector<LabelCandidate> out;
    for (float r : {r0, 2 * r0})
        for (int k : {0, 1, -1, 2, -2, 3, -3, 4}) {
            const float a = a0 + static_cast<float>(k) * 0.25f * static_cast<float>(kPi);
            const float ux = std::cos(a), uy = std::sin(a);
            out.push_back({{at.x + 9 * r * ux, at.y + 8 * r * uy}, label_style(size, color, ux, uy), r > r0});
        }
    return out;
}

} // namespace

gfx::Color ink_color(Ink ink, std::size_t series_index) {
    switch (ink) {
    case Ink::body:
        return gfx::palette(0); // blue
    case Ink::tip:
        return gfx::palette(1); // vermillion
    case Ink::pull:
        return gfx::palette(2); // green
    case Ink::slip:
        return gfx::palette(3); // reddish purple
    case Ink::force:
        return gfx::palette(0);
    case Ink::magnitude:
        return gfx::colors::black;
    case Ink::rigid:
        return gfx::colors::black;
    case Ink::spring:
        return gfx::Color::hex(0x8A8A8A);
    case Ink::black:
        return gfx::colors::black;
    case Ink::setup_b:
        return gfx::palette(4); // orange (setup A is blue)
    case Ink::automatic:
        break;
    }
    return gfx::palette(series_index);
}

namespace {

// The titles, axis ranges, text size, top axis and legend as the panel asks.
void set_axes(gfx::Plot& plot, const PanelData& panel) {
    plot.title = panel.title;
    plot.x_axis.title = panel.x_title;
    plot.x_axis.short_title = panel.x_title_short;
    plot.y_axis.title = panel.y_title;
    plot.x_axis.min = panel.x_min;
    plot.x_axis.max = panel.x_max;
    plot.x_axis.log = panel.log_x;
    plot.y_axis.min = panel.y_min;
    plot.y_axis.max = panel.y_max;
    plot.equal_aspect = panel.equal_aspect;
    plot.axes = panel.axes;
    plot.font_size *= panel.text_scale;
    plot.top_scale = panel.top_scale;
    plot.top_title = panel.top_title;
    plot.legend = legend_position(panel.legend);
}

gfx::HeatMap heat_map_of(const HeatmapData& h) {
    gfx::HeatMap m;
    m.values = h.values;
    m.nx = h.nx, m.ny = h.ny;
    m.x0 = h.x0, m.x1 = h.x1, m.y0 = h.y0, m.y1 = h.y1;
    m.label = h.label;
    m.vmin = h.vmin, m.vmax = h.vmax;
    m.color_bar = h.color_bar;
    return m;
}

// Series k's style: its ink (the palette's colour `palette`, else k's), line, dash and marker.
gfx::SeriesStyle series_style(const SeriesData& s, std::size_t k) {
    gfx::SeriesStyle st;
    st.color =
        ink_color(s.ink, s.palette >= 0 ? static_cast<std::size_t>(s.palette) : k).with_alpha(s.opacity);
    st.line_width = s.width;
    st.line = line_style(s.dash);
    st.marker = marker_shape(s.mark);
    if (s.mark_size > 0) st.marker_size = s.mark_size;
    st.draw_line = s.width > 0;
    return st;
}

// The shaded x ranges behind the series.
void draw_bands(gfx::Canvas& c, const gfx::PlotTransform& tf, const PanelData& panel) {
    for (const BandData& b : panel.bands) {
        const float x0 = tf.to_pixel(b.x0, tf.y0).x, x1 = tf.to_pixel(b.x1, tf.y0).x;
        if (x1 > x0) c.fill_rect({x0, tf.area.y0, x1, tf.area.y1}, ink_color(b.ink, 0).with_alpha(b.opacity));
    }
}

// The pixels an arrow of the panel is drawn between; none for one shorter than 2 pixels. The points'
// markers are drawn over the arrows: one that starts in a marker (v and −F at P) starts at its edge instead,
// and is at least kMinArrow x the text scale long beyond it (in presentation mode P's dot was larger than a
// short v, which hid under it); one whose tip would end under another marker (−F pointing at T) ends at
// that marker's nearer edge (the far one where the near one would leave it too short).
constexpr float kMinArrow = 10;
std::optional<std::pair<gfx::Vec2, gfx::Vec2>> arrow_pixels(const gfx::PlotTransform& tf,
                                                            const PanelData& panel, const ArrowData& a) {
    gfx::Vec2 from = to_px(tf, a.from), to = to_px(tf, a.to);
    const float len = std::hypot(to.x - from.x, to.y - from.y);
    if (!(len >= 2)) return std::nullopt;
    const gfx::Vec2 u{(to.x - from.x) / len, (to.y - from.y) / len};
    // Each marker as a disc around its shape (a square's corners included), its edge and a pixel of gap.
    struct Disc {
        gfx::Vec2 c;
        float r;
    };
    std::vector<Disc> discs;
    for (const PointData& p : panel.points)
        if (p.mark != Mark::none)
            discs.push_back(
                {to_px(tf, p.at), 0.5f * p.size * (p.mark == Mark::circle ? 1.0f : 1.42f) + 2.5f});
    // Where the line from + t u enters and leaves a disc (t_in > t_out: it misses the disc).
    auto crossing = [&](const Disc& d, gfx::Vec2 o) {
        const float b = u.x * (o.x - d.c.x) + u.y * (o.y - d.c.y);
        const float q = b * b - ((o.x - d.c.x) * (o.x - d.c.x) + (o.y - d.c.y) * (o.y - d.c.y) - d.r * d.r);
        const float w = q > 0 ? std::sqrt(q) : -1;
        return std::pair{-b - w, -b + w};
    };
    auto inside = [](const Disc& d, gfx::Vec2 p) { return std::hypot(p.x - d.c.x, p.y - d.c.y) < d.r; };
    float start = 0;
    for (const Disc& d : discs)
        if (inside(d, from)) start = std::max(start, crossing(d, from).second);
    const float min_len = kMinArrow * std::max(1.0f, panel.text_scale);
    float end = std::max(len, start + min_len);
    // Again while a move put the tip under another marker (P and T close together), a few times at most.
    for (std::size_t k = 0, moves = 0; k < discs.size(); ++k) {
        if (!inside(discs[k], from + u * end)) continue;
        if (++moves > 2 * discs.size()) break;
        const auto [t_in, t_out] = crossing(discs[k], from);
        // Back to the marker's near edge where the tip is nearer it (and the arrow stays long enough),
        // else on past its far edge (the head seen beyond it).
        end = t_in >= start + min_len && end - t_in <= t_out - end ? t_in : t_out + 0.5f * min_len;
        k = static_cast<std::size_t>(-1); // from the first marker again
    }
    to = from + u * end;
    from = from + u * start;
    return std::pair{from, to};
}

// Whether the drawn arrow a runs along the drawn arrow b: a third of a's shaft within the two shafts' half
// widths and a pixel of b's, where one hides the other.
bool runs_along_px(std::pair<gfx::Vec2, gfx::Vec2> a, std::pair<gfx::Vec2, gfx::Vec2> b, float reach) {
    const gfx::Vec2 d = b.second - b.first;
    const float l2 = d.x * d.x + d.y * d.y;
    int near = 0;
    constexpr int kN = 24;
    for (int k = 0; k <= kN; ++k) {
        const gfx::Vec2 p = a.first + (a.second - a.first) * (static_cast<float>(k) / kN);
        const float t =
            l2 > 0 ? std::clamp(((p.x - b.first.x) * d.x + (p.y - b.first.y) * d.y) / l2, 0.f, 1.f) : 0.f;
        near += std::hypot(p.x - b.first.x - t * d.x, p.y - b.first.y - t * d.y) <= reach;
    }
    return near * 3 > kN + 1;
}

// Circles, segments and arrows (those shorter than 2 pixels left out). A faded arrow (the why panel's
// instants behind the live ones) that runs along a later arrow on screen is left out: on a small panel in
// presentation mode instants apart in the data met in pixels, and the later one stands in for it.
void draw_shapes(gfx::Canvas& c, const gfx::PlotTransform& tf, const PanelData& panel) {
    for (const CircleData& ci : panel.circles)
        c.circle(to_px(tf, ci.center), static_cast<float>(ci.radius) * tf.pixels_per_unit_x(),
                 {ink_color(ci.ink, 0), ci.width, line_style(ci.dash)});
    for (const SegmentData& s : panel.segments)
        c.line(to_px(tf, s.a), to_px(tf, s.b), {ink_color(s.ink, 0), s.width, line_style(s.dash)});
    std::vector<std::optional<std::pair<gfx::Vec2, gfx::Vec2>>> pixels;
    for (const ArrowData& a : panel.arrows) pixels.push_back(arrow_pixels(tf, panel, a));
    for (std::size_t i = 0; i < panel.arrows.size(); ++i) {
        const ArrowData& a = panel.arrows[i];
        const auto& drawn = pixels[i];
        if (!drawn) continue;
        bool hidden = false;
        for (std::size_t j = i + 1; j < panel.arrows.size() && a.opacity < 1 && !hidden; ++j) {
            const float reach = 0.5f * (a.width + panel.arrows[j].width) + 1.5f;
            hidden = pixels[j] &&
                     (runs_along_px(*drawn, *pixels[j], reach) || runs_along_px(*pixels[j], *drawn, reach));
        }
        if (hidden) continue;
        const gfx::Vec2 from = drawn->first, to = drawn->second;
        const float len = std::hypot(to.x - from.x, to.y - from.y);
        gfx::Color color = ink_color(a.ink, 0);
        color.a *= a.opacity;
        c.arrow(from, to,
                {{color, a.width, gfx::LineStyle::Solid},
                 std::min(14.f, 0.5f * len),
                 std::min(10.f, 0.4f * len)});
    }
}

// The points' markers, where they are in the data area (or on its frame: `inside`).
void draw_point_markers(gfx::Canvas& c, const gfx::PlotTransform& tf, const PanelData& panel,
                        const gfx::Rect& inside) {
    for (const PointData& p : panel.points)
        if (inside.contains(to_px(tf, p.at)))
            c.marker(to_px(tf, p.at),
                     {marker_shape(p.mark), p.size, ink_color(p.ink, 0), gfx::colors::white, 1.5f});
}

// The middle of all marked points (pixels): labels go away from it unless a side is asked.
gfx::Vec2 points_centre(const gfx::PlotTransform& tf, const PanelData& panel) {
    gfx::Vec2 centre{0, 0};
    for (const PointData& p : panel.points)
        centre = centre + to_px(tf, p.at) * (1.0f / static_cast<float>(panel.points.size()));
    return centre;
}

void place_point_labels(LabelPlacer& placer, const gfx::PlotTransform& tf, const PanelData& panel,
                        const gfx::Rect& inside, gfx::Vec2 centre) {
    for (const PointData& p : panel.points) {
        const gfx::Vec2 at = to_px(tf, p.at);
        if (p.label.empty() || !inside.contains(at)) continue;
        // Preferred side: as asked, else away from the middle of all marked points.
        const float dx = p.label_dx != 0 ? static_cast<float>(p.label_dx) : at.x - centre.x;
        const float dy = p.label_dy != 0 ? static_cast<float>(p.label_dy) : at.y - centre.y;
        placer.place(
            p.label,
            around(at, dx >= 0 ? 1.f : -1.f, dy >= 0 ? 1.f : -1.f, 15 * panel.text_scale, gfx::colors::text,
                   std::max(1.0f, panel.text_scale)),
            [&](const gfx::dl::Command& cmd) {
                const auto* m = std::get_if<gfx::dl::Marker>(&cmd);
                return m && same(m->center, at);
            },
            at, p.optional);
    }
}

// The places for the label of the arrow from -> to (pixels, at least 2 apart): beyond the head, then beside
// the head or the shaft on either side; centred above or below the head first when asked (arrows along one
// line).
std::vector<LabelCandidate> arrow_label_places(const ArrowData& a, gfx::Vec2 from, gfx::Vec2 to, float size) {
    const float len = std::hypot(to.x - from.x, to.y - from.y);
    const float ux = (to.x - from.x) / len, uy = (to.y - from.y) / len;
    const gfx::Color color = ink_color(a.ink, 0);
    const float k = std::max(1.0f, size / 14); // the offsets grow with the text (presentation mode)
    std::vector<LabelCandidate> cands;
    if (a.label_dy != 0)
        cands.push_back({{to.x, to.y + (a.label_dy < 0 ? -9 * k : 9 * k)},
                         label_style(size, color, 0, static_cast<float>(a.label_dy))});
    cands.push_back({{to.x + ux * 6 * k, to.y + uy * 6 * k}, label_style(size, color, ux, uy)});
    // Beside the shaft; further off it where the label is asked above or below (the why panel's live arrows
    // slope every way: 9 units off a sloping shaft a label's corner may touch it).
    const float off = k * (a.label_dy != 0 ? 13.f : 9.f);
    for (float along : {0.85f, 0.5f})
        for (float side : {1.f, -1.f}) {
            const float nx = -uy * side, ny = ux * side;
            const gfx::Vec2 m = from + (to - from) * along;
            cands.push_back({{m.x + nx * off, m.y + ny * off}, label_style(size, color, nx, ny)});
        }
    // Crowded (a short arrow among other labels): the same places further out.
    cands.push_back({{to.x + ux * 20 * k, to.y + uy * 20 * k}, label_style(size, color, ux, uy)});
    for (float side : {1.f, -1.f})
        cands.push_back({{to.x - uy * side * 22 * k, to.y + ux * side * 22 * k},
                         label_style(size, color, -uy * side, ux * side)});
    cands.push_back({{to.x + ux * 36 * k, to.y + uy * 36 * k}, label_style(size, color, ux, uy), true});
    return cands;
}

void place_arrow_labels(LabelPlacer& placer, const gfx::PlotTransform& tf, const PanelData& panel) {
    for (const ArrowData& a : panel.arrows) {
        const auto drawn = arrow_pixels(tf, panel, a);
        if (!drawn || a.label.empty()) continue;
        const gfx::Vec2 from = drawn->first, to = drawn->second;
        placer.place(
            a.label, arrow_label_places(a, from, to, 14 * panel.text_scale),
            [&](const gfx::dl::Command& cmd) {
                const auto* ar = std::get_if<gfx::dl::Arrow>(&cmd);
                return ar && same(ar->from, from) && same(ar->to, to);
            },
            to);
    }
}

void place_segment_labels(LabelPlacer& placer, const gfx::PlotTransform& tf, const PanelData& panel,
                          gfx::Vec2 centre) {
    for (const SegmentData& s : panel.segments) {
        if (s.label.empty()) continue;
        const gfx::Vec2 a = to_px(tf, s.a), b = to_px(tf, s.b);
        // Unit normal pointing left of a->b on screen (y down). A segment shorter than its label's offset is
        // not labelled: the label would name a point, on top of the points' own labels.
        float nx = b.y - a.y, ny = -(b.x - a.x);
        if (std::hypot(nx, ny) < 8) continue;
        const float len = std::hypot(nx, ny);
        nx /= len, ny /= len;
        const gfx::Vec2 m = a + (b - a) * s.label_at;
        const bool flip =
            s.label_side == 0 ? nx * (m.x - centre.x) + ny * (m.y - centre.y) < 0 : s.label_side < 0;
        if (flip) nx = -nx, ny = -ny;
        // The asked side first, at the asked place and then further along; the other side only when no side
        // was asked.
        std::vector<LabelCandidate> cands;
        for (float side : {1.f, -1.f}) {
            if (side < 0 && s.label_side != 0) break;
            for (float at : {s.label_at, 0.3f, 0.7f}) {
                const gfx::Vec2 q = a + (b - a) * at;
                cands.push_back(
                    {{q.x + side * nx * 8, q.y + side * ny * 8},
                     label_style(15 * panel.text_scale, label_color(s.ink), side * nx, side * ny)});
            }
        }
        placer.place(s.label, cands, [&](const gfx::dl::Command& cmd) {
            const auto* pl = std::get_if<gfx::dl::Polyline>(&cmd);
            return pl && pl->points.size() == 2 && same(pl->points[0], a) && same(pl->points[1], b);
        });
    }
}

// The points' markers, then every label: points first (their labels name them), then arrows, then
// segments; each label where it covers the least of what is drawn and of the labels before it.
void draw_marks_and_labels(gfx::Canvas& c, const gfx::PlotTransform& tf, const PanelData& panel) {
    const gfx::Rect inside = tf.area.inset(-1);
    draw_point_markers(c, tf, panel, inside);
    const gfx::Vec2 centre = points_centre(tf, panel);
    std::vector<gfx::dl::Command> walls;
    for (const SeriesData& s : panel.series)
        if (s.labels_off && s.x.size() == s.y.size()) {
            gfx::dl::Polyline pl;
            pl.stroke.width = s.width;
            for (std::size_t k = 0; k < s.x.size(); ++k) pl.points.push_back(tf.to_pixel(s.x[k], s.y[k]));
            walls.emplace_back(std::move(pl));
        }
    LabelPlacer placer(c, tf, std::move(walls));
    place_point_labels(placer, tf, panel, inside, centre);
    place_arrow_labels(placer, tf, panel);
    place_segment_labels(placer, tf, panel, centre);
    placer.draw();
}

} // namespace

gfx::PlotTransform paint_panel(gfx::Canvas& canvas, const PanelData& panel, const gfx::Rect& bounds,
                               bool legend_below) {
    return panel_plot(panel, bounds, legend_below).draw(canvas);
}

gfx::Plot panel_plot(const PanelData& panel, const gfx::Rect& bounds, bool legend_below) {
    gfx::Plot plot(bounds);
    plot.legend_below = legend_below;
    set_axes(plot, panel);
    if (panel.heatmap) plot.set_heatmap(heat_map_of(*panel.heatmap));
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
        const SeriesData& s = panel.series[k];
        plot.add_series(s.label, s.x, s.y, series_style(s, k)).y_err = s.y_err;
    }
    const PanelData* pd = &panel;
    if (!panel.bands.empty())
        plot.add_underlay([pd](gfx::Canvas& c, const gfx::PlotTransform& tf) { draw_bands(c, tf, *pd); });
    // Shapes, clipped to the data area. Shapes first, then every label: text and shapes are separate draw
    // batches, and the software renderer pays per batch. Labels belong on top anyway.
    plot.add_overlay([pd](gfx::Canvas& c, const gfx::PlotTransform& tf) { draw_shapes(c, tf, *pd); });
    // Markers and labels, not clipped: a marker on the frame (theta = 90 deg on the map) is drawn whole.
    plot.add_overlay(
        [pd](gfx::Canvas& c, const gfx::PlotTransform& tf) { draw_marks_and_labels(c, tf, *pd); }, false);
    return plot;
}

float paint_title(gfx::Canvas& canvas, const std::string& title, const gfx::Rect& bounds, float factor,
                  bool draw) {
    const float kSize = 22 * factor, kMinOneLine = 16 * factor, kTop = 12 * factor;
    constexpr float kLeading = 1.15f;
    const float avail = std::max(1.0f, bounds.width() - 16);
    gfx::TextStyle ts;
    ts.halign = gfx::HAlign::Center;
    ts.valign = gfx::VAlign::Top;
    const float cx = (bounds.x0 + bounds.x1) / 2;
    auto width = [&](std::string_view s, float size) { return canvas.measure_text(s, size).x; };
    // The largest size (in steps of 0.5) at which every line fits, not below `floor`.
    auto fit = [&](const std::vector<std::string_view>& lines, float floor) {
        float size = kSize;
        for (;;) {
            bool fits = true;
            for (std::string_view l : lines) fits = fits && width(l, size) <= avail;
            if (fits || size - 0.5f < floor) return size;
            size -= 0.5f;
        }
    };
    const float one = fit({title}, kMinOneLine);
    std::string_view first, second;
    if (width(title, one) > avail) {
        float best = 1e30f;
        int depth = 0; // no break inside markup braces
        for (std::size_t k = 0; k + 1 < title.size(); ++k) {
            depth += title[k] == '{' ? 1 : (title[k] == '}' ? -1 : 0);
            if (depth != 0 || title[k + 1] != ' ' || (title[k] != ',' && title[k] != ';' && title[k] != ':'))
                continue;
            const std::string_view a(title.data(), k + 1), b(title.data() + k + 2, title.size() - k - 2);
            const float w = std::max(width(a, kSize), width(b, kSize));
            if (w < best) best = w, first = a, second = b;
        }
    }
    if (second.empty()) {
        ts.size = one;
        if (draw) canvas.text({cx, bounds.y0 + kTop}, title, ts);
        return bounds.y0 + kTop + one;
    }
    ts.size = fit({first, second}, 1);
    if (draw) {
        canvas.text({cx, bounds.y0 + kTop}, std::string(first), ts);
        canvas.text({cx, bounds.y0 + kTop + kLeading * ts.size}, std::string(second), ts);
    }
    return bounds.y0 + kTop + (1 + kLeading) * ts.size;
}

namespace {

// A panel of small multiples as it is drawn: its legend left to the figure, no colour bar of its own, its
// text at `factor`.
PanelData grid_panel(const PanelData& panel, float factor) {
    PanelData p = panel;
    p.legend = Legend::none;
    p.text_scale *= factor;
    if (p.heatmap) p.heatmap->color_bar = false;
    return p;
}

// Where the data area of `panel` would be inside `bounds` (its layout, nothing drawn).
gfx::Rect data_area(const gfx::Canvas& canvas, const PanelData& panel, const gfx::Rect& bounds) {
    gfx::Plot plot(bounds);
    set_axes(plot, panel);
    if (panel.heatmap) plot.set_heatmap(heat_map_of(*panel.heatmap));
    return plot.layout(canvas).area;
}

// The legend of small multiples: each labelled line or mark of any panel once, in order of appearance (a
// mark that only some maps have is named too).
std::vector<gfx::Series> merged_legend(const FigureData& fig) {
    std::vector<gfx::Series> legend;
    for (const PanelData& p : fig.panels)
        for (std::size_t k = 0; k < p.series.size(); ++k) {
            const SeriesData& s = p.series[k];
            if (s.label.empty() || std::any_of(legend.begin(), legend.end(),
                                               [&](const gfx::Series& e) { return e.label == s.label; }))
                continue;
            gfx::Series e;
            e.label = s.label;
            e.style = series_style(s, k);
            legend.push_back(std::move(e));
        }
    return legend;
}

// What a grid of small multiples `width` wide keeps around its panels, text at `factor`: the shared x
// title's band below them and the y title's band left of them (none without a title), and the merged
// legend's rows under it all, a gap above them.
struct GridMargins {
    float fs = 0, title_fs = 0, below = 0, left = 0, gap = 0;
    std::vector<gfx::Series> legend;
    gfx::Vec2 legend_size{0, 0};
    // All that is kept below the panels.
    float bottom() const { return below + (legend_size.y > 0 ? legend_size.y + gap : 0); }
};

GridMargins grid_margins(gfx::Canvas& canvas, const FigureData& fig, float width, float factor) {
    GridMargins g;
    g.fs = 13 * factor, g.title_fs = g.fs + factor, g.gap = std::round(10 * factor);
    g.legend = merged_legend(fig);
    g.legend_size = gfx::legend_rows(canvas, g.legend, {0, 0}, width, g.fs, false);
    const PanelData& first = fig.panels.front();
    g.below = first.x_title.empty() ? 0 : std::round(g.title_fs * 1.7f);
    g.left = first.y_title.empty() ? 0 : std::round(g.title_fs * 1.7f);
    return g;
}

} // namespace

float grid_margin_height(gfx::Canvas& canvas, const FigureData& fig, float width, float factor) {
    return grid_margins(canvas, fig, width, factor).bottom();
}

void paint_grid(gfx::Canvas& canvas, const FigureData& fig, const gfx::Rect& body, float factor) {
    const std::size_t n = fig.panels.size(), cols = static_cast<std::size_t>(fig.columns);
    const std::size_t rows = (n + cols - 1) / cols;
    const GridMargins gm = grid_margins(canvas, fig, body.width(), factor);
    const float fs = gm.fs, title_fs = gm.title_fs, below = gm.below, left = gm.left;
    const std::vector<gfx::Series>& legend = gm.legend;
    const gfx::Vec2 legend_size = gm.legend_size;
    const PanelData& first = fig.panels.front();
    const gfx::Rect grid{body.x0 + left, body.y0, body.x1 - gfx::kColorBarSpace, body.y1 - gm.bottom()};
    std::vector<PanelData> panels;
    for (const PanelData& p : fig.panels) {
        panels.push_back(grid_panel(p, factor));
        panels.back().x_title.clear(), panels.back().y_title.clear();
    }
    // Each panel's margins around its data area (left, top, right, bottom), measured in its cell; twice, the
    // second time in the cells the first gave (a title may wrap differently in a cell of another width).
    std::vector<gfx::Rect> cells(n), margins(n);
    for (std::size_t k = 0; k < n; ++k) {
        const float w = grid.width() / static_cast<float>(cols), h = grid.height() / static_cast<float>(rows);
        const float x0 = grid.x0 + w * static_cast<float>(k % cols),
                    y0 = grid.y0 + h * static_cast<float>(k / cols);
        cells[k] = {x0, y0, x0 + w, y0 + h};
    }
    std::vector<gfx::Rect> areas(n);
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t k = 0; k < n; ++k) {
            const gfx::Rect a = data_area(canvas, panels[k], cells[k]);
            margins[k] = {a.x0 - cells[k].x0, a.y0 - cells[k].y0, cells[k].x1 - a.x1, cells[k].y1 - a.y1};
        }
        std::vector<float> col_l(cols, 0), col_r(cols, 0), row_t(rows, 0), row_b(rows, 0);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t c = k % cols, r = k / cols;
            col_l[c] = std::max(col_l[c], margins[k].x0), col_r[c] = std::max(col_r[c], margins[k].x1);
            row_t[r] = std::max(row_t[r], margins[k].y0), row_b[r] = std::max(row_b[r], margins[k].y1);
        }
        float sum_x = 0, sum_y = 0;
        for (std::size_t c = 0; c < cols; ++c) sum_x += col_l[c] + col_r[c];
        for (std::size_t r = 0; r < rows; ++r) sum_y += row_t[r] + row_b[r];
        const float w = std::max(1.0f, (grid.width() - sum_x) / static_cast<float>(cols)),
                    h = std::max(1.0f, (grid.height() - sum_y) / static_cast<float>(rows));
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t c = k % cols, r = k / cols;
            float x = grid.x0, y = grid.y0;
            for (std::size_t j = 0; j < c; ++j) x += col_l[j] + w + col_r[j];
            for (std::size_t j = 0; j < r; ++j) y += row_t[j] + h + row_b[j];
            areas[k] = {std::round(x + col_l[c]), std::round(y + row_t[r]), 0, 0};
            areas[k].x1 = areas[k].x0 + std::round(w), areas[k].y1 = areas[k].y0 + std::round(h);
            cells[k] = {areas[k].x0 - margins[k].x0, areas[k].y0 - margins[k].y0, areas[k].x1 + margins[k].x1,
                        areas[k].y1 + margins[k].y1};
        }
    }
    float top = grid.y1, bottom = grid.y0, right = grid.x0, x_left = grid.x1;
    for (std::size_t k = 0; k < n; ++k) {
        const gfx::Rect a = paint_panel(canvas, panels[k], cells[k]).area;
        top = std::min(top, a.y0), bottom = std::max(bottom, a.y1);
        right = std::max(right, a.x1), x_left = std::min(x_left, a.x0);
    }
    gfx::TextStyle ts;
    ts.size = title_fs, ts.halign = gfx::HAlign::Center;
    if (below > 0) {
        ts.valign = gfx::VAlign::Bottom;
        canvas.text({std::round((x_left + right) / 2), grid.y1 + below}, first.x_title, ts);
    }
    if (left > 0) {
        ts.valign = gfx::VAlign::Top, ts.angle_deg = 90;
        canvas.text({body.x0, std::round((top + bottom) / 2)}, first.y_title, ts);
    }
    if (first.heatmap)
        gfx::draw_color_bar(canvas, {grid.x0, top, right, bottom}, heat_map_of(*first.heatmap), fs);
    if (legend_size.y > 0)
        gfx::legend_rows(canvas, legend,
                         {std::round((body.x0 + body.x1 - legend_size.x) / 2), body.y1 - legend_size.y},
                         body.width(), fs);
}

float page_text_factor(const gfx::Rect& page) {
    return std::clamp(std::min(page.width() / 640.0f, page.height() / 400.0f), kSmallestTextFactor, 1.0f);
}

void paint_figure(gfx::Canvas& canvas, const FigureData& fig, const gfx::Rect& bounds, float text_factor) {
    const float k = text_factor > 0 ? text_factor : page_text_factor(bounds);
    const float title_end = paint_title(canvas, fig.title, bounds, k);
    const float inset = std::round(8 * k), gap = std::round(6 * k);
    const gfx::Rect body{bounds.x0 + inset, title_end + std::round(14 * k), bounds.x1 - inset,
                         bounds.y1 - inset};
    // Each panel's text at the page's factor (a copy only on a small page).
    auto panel = [&](std::size_t i, const gfx::Rect& r) {
        if (k >= 1) {
            paint_panel(canvas, fig.panels[i], r, true);
            return;
        }
        PanelData p = fig.panels[i];
        p.text_scale *= k;
        paint_panel(canvas, p, r, true);
    };
    if (fig.columns > 0 && !fig.panels.empty()) {
        paint_grid(canvas, fig, body, k);
        return;
    }
    if (fig.panels.size() == 3) {
        const float split = body.x0 + body.width() * 0.5f, mid = (body.y0 + body.y1) / 2;
        panel(0, {body.x0, body.y0, split - gap, body.y1});
        panel(1, {split + gap, body.y0, body.x1, mid - gap});
        panel(2, {split + gap, mid + gap, body.x1, body.y1});
        return;
    }
    const float w = body.width() / static_cast<float>(fig.panels.size());
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        const float x0 = body.x0 + w * static_cast<float>(i);
        panel(i, {x0, body.y0, x0 + w, body.y1});
    }
}

} // namespace fv::app
