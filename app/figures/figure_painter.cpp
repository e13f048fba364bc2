#include "figure_painter.hpp"

#include "fv/gfx/plot.hpp"

#include <cmath>

namespace fv::app {
namespace {

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

// Labels go on the side of a point that faces away from the middle of all marked points, so that labels
// of nearby points (P(t), P(t+dt), ...) do not overlap each other or the lines between them.
void label_point(gfx::Canvas& c, gfx::Vec2 at, gfx::Vec2 centre, const PointData& p, float size) {
    const std::string& text = p.label;
    if (text.empty()) return;
    gfx::TextStyle ts;
    ts.size = size;
    const float dx = p.label_dx != 0 ? static_cast<float>(p.label_dx) : at.x - centre.x;
    const float dy = p.label_dy != 0 ? static_cast<float>(p.label_dy) : at.y - centre.y;
    ts.halign = dx >= 0 ? gfx::HAlign::Left : gfx::HAlign::Right;
    ts.valign = dy >= 0 ? gfx::VAlign::Top : gfx::VAlign::Bottom;
    c.text({at.x + (dx >= 0 ? 9.f : -9.f), at.y + (dy >= 0 ? 7.f : -7.f)}, text, ts);
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
    case Ink::automatic:
        break;
    }
    return gfx::palette(series_index);
}

gfx::PlotTransform paint_panel(gfx::Canvas& canvas, const PanelData& panel, const gfx::Rect& bounds) {
    gfx::Plot plot(bounds);
    plot.title = panel.title;
    plot.x_axis.title = panel.x_title;
    plot.y_axis.title = panel.y_title;
    plot.x_axis.min = panel.x_min;
    plot.x_axis.max = panel.x_max;
    plot.y_axis.min = panel.y_min;
    plot.y_axis.max = panel.y_max;
    plot.equal_aspect = panel.equal_aspect;
    plot.font_size *= panel.text_scale;
    plot.top_scale = panel.top_scale;
    plot.top_title = panel.top_title;
    if (panel.legend == "none")
        plot.legend = gfx::LegendPosition::None;
    else if (panel.legend == "top-left")
        plot.legend = gfx::LegendPosition::TopLeft;
    else if (panel.legend == "top-right")
        plot.legend = gfx::LegendPosition::TopRight;
    else if (panel.legend == "bottom-left")
        plot.legend = gfx::LegendPosition::BottomLeft;
    else if (panel.legend == "bottom-right")
        plot.legend = gfx::LegendPosition::BottomRight;
    if (panel.heatmap) {
        const HeatmapData& h = *panel.heatmap;
        gfx::HeatMap m;
        m.values = h.values;
        m.nx = h.nx, m.ny = h.ny;
        m.x0 = h.x0, m.x1 = h.x1, m.y0 = h.y0, m.y1 = h.y1;
        m.label = h.label;
        plot.set_heatmap(std::move(m));
    }
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
        const SeriesData& s = panel.series[k];
        gfx::SeriesStyle st;
        st.color =
            ink_color(s.ink, s.palette >= 0 ? static_cast<std::size_t>(s.palette) : k).with_alpha(s.opacity);
        st.line_width = s.width;
        st.line = line_style(s.dash);
        st.marker = marker_shape(s.mark);
        st.draw_line = s.width > 0;
        plot.add_series(s.label, s.x, s.y, st).y_err = s.y_err;
    }
    const PanelData* pd = &panel;
    if (!panel.bands.empty())
        plot.add_underlay([pd](gfx::Canvas& c, const gfx::PlotTransform& tf) {
            for (const BandData& b : pd->bands) {
                const float x0 = tf.to_pixel(b.x0, tf.y0).x, x1 = tf.to_pixel(b.x1, tf.y0).x;
                if (x1 > x0)
                    c.fill_rect({x0, tf.area.y0, x1, tf.area.y1}, ink_color(b.ink, 0).with_alpha(b.opacity));
            }
        });
    plot.add_overlay([pd](gfx::Canvas& c, const gfx::PlotTransform& tf) {
        // Shapes first, then every label: text and shapes are separate draw batches, and the software
        // renderer pays per batch. Labels belong on top anyway.
        for (const CircleData& ci : pd->circles)
            c.circle(to_px(tf, ci.center), static_cast<float>(ci.radius) * tf.pixels_per_unit_x(),
                     {ink_color(ci.ink, 0), ci.width, line_style(ci.dash)});
        gfx::Vec2 centre{0, 0};
        for (const PointData& p : pd->points)
            centre = centre + to_px(tf, p.at) * (1.0f / static_cast<float>(pd->points.size()));
        for (const SegmentData& s : pd->segments)
            c.line(to_px(tf, s.a), to_px(tf, s.b), {ink_color(s.ink, 0), s.width, line_style(s.dash)});
        for (const ArrowData& a : pd->arrows) {
            const gfx::Vec2 from = to_px(tf, a.from), to = to_px(tf, a.to);
            const float len = std::hypot(to.x - from.x, to.y - from.y);
            if (len < 2) continue;
            c.arrow(from, to,
                    {{ink_color(a.ink, 0), a.width, gfx::LineStyle::Solid},
                     std::min(14.f, 0.5f * len),
                     std::min(10.f, 0.4f * len)});
        }
        for (const PointData& p : pd->points)
            c.marker(to_px(tf, p.at),
                     {marker_shape(p.mark), p.size, ink_color(p.ink, 0), gfx::colors::white, 1.5f});

        for (const SegmentData& s : pd->segments) {
            if (s.label.empty()) continue;
            const gfx::Vec2 a = to_px(tf, s.a), b = to_px(tf, s.b);
            const gfx::Vec2 m = a + (b - a) * s.label_at;
            // Unit normal pointing left of a->b on screen (y down).
            float nx = b.y - a.y, ny = -(b.x - a.x);
            const float len = std::max(1e-3f, std::hypot(nx, ny));
            nx /= len, ny /= len;
            const bool flip =
                s.label_side == 0 ? nx * (m.x - centre.x) + ny * (m.y - centre.y) < 0 : s.label_side < 0;
            if (flip) nx = -nx, ny = -ny;
            gfx::TextStyle ts;
            ts.size = 15 * pd->text_scale;
            ts.color = ink_color(s.ink, 0);
            ts.halign =
                nx > 0.3f ? gfx::HAlign::Left : (nx < -0.3f ? gfx::HAlign::Right : gfx::HAlign::Center);
            ts.valign =
                ny > 0.3f ? gfx::VAlign::Top : (ny < -0.3f ? gfx::VAlign::Bottom : gfx::VAlign::Middle);
            c.text({m.x + nx * 8, m.y + ny * 8}, s.label, ts);
        }
        for (const ArrowData& a : pd->arrows) {
            const gfx::Vec2 from = to_px(tf, a.from), to = to_px(tf, a.to);
            const float len = std::hypot(to.x - from.x, to.y - from.y);
            if (len < 2 || a.label.empty()) continue;
            gfx::TextStyle ts;
            ts.size = 14 * pd->text_scale;
            ts.color = ink_color(a.ink, 0);
            if (a.label_dy != 0) {
                ts.halign = gfx::HAlign::Center;
                ts.valign = a.label_dy < 0 ? gfx::VAlign::Bottom : gfx::VAlign::Top;
                c.text({to.x, to.y + (a.label_dy < 0 ? -9.f : 9.f)}, a.label, ts);
                continue;
            }
            const float ux = (to.x - from.x) / len, uy = (to.y - from.y) / len;
            ts.halign =
                ux > 0.3f ? gfx::HAlign::Left : (ux < -0.3f ? gfx::HAlign::Right : gfx::HAlign::Center);
            ts.valign =
                uy > 0.3f ? gfx::VAlign::Top : (uy < -0.3f ? gfx::VAlign::Bottom : gfx::VAlign::Middle);
            c.text({to.x + ux * 6, to.y + uy * 6}, a.label, ts);
        }
        for (const PointData& p : pd->points) label_point(c, to_px(tf, p.at), centre, p, 15 * pd->text_scale);
    });
    plot.draw(canvas);
    return plot.layout(canvas);
}

void paint_figure(gfx::Canvas& canvas, const FigureData& fig, const gfx::Rect& bounds) {
    gfx::TextStyle ts;
    ts.size = 22;
    ts.halign = gfx::HAlign::Center;
    ts.valign = gfx::VAlign::Top;
    canvas.text({(bounds.x0 + bounds.x1) / 2, bounds.y0 + 12}, fig.title, ts);
    const gfx::Rect body{bounds.x0 + 8, bounds.y0 + 48, bounds.x1 - 8, bounds.y1 - 8};
    if (fig.panels.size() == 3) {
        const float split = body.x0 + body.width() * 0.5f, mid = (body.y0 + body.y1) / 2;
        paint_panel(canvas, fig.panels[0], {body.x0, body.y0, split - 6, body.y1});
        paint_panel(canvas, fig.panels[1], {split + 6, body.y0, body.x1, mid - 6});
        paint_panel(canvas, fig.panels[2], {split + 6, mid + 6, body.x1, body.y1});
        return;
    }
    const float w = body.width() / static_cast<float>(fig.panels.size());
    for (std::size_t k = 0; k < fig.panels.size(); ++k) {
        const float x0 = body.x0 + w * static_cast<float>(k);
        paint_panel(canvas, fig.panels[k], {x0, body.y0, x0 + w, body.y1});
    }
}

} // namespace fv::app
