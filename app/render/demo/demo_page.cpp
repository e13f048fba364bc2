#include "demo_page.hpp"

#include "fv/gfx/plot.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fv::demo {

using namespace gfx;

namespace {

constexpr double kPi = 3.141592653589793;

void velocity_ratio_plot(Canvas& c, const Rect& r) {
    Plot p(r);
    p.title = "θ = 90°, r_{disp} = 2";
    p.x_axis.title = "velocity ratio ζ = v_{b}/v_{v}";
    p.y_axis.title = "friction ratio r_{x}";
    p.x_axis.set_range(0, 3);
    p.y_axis.min = 0;
    std::vector<double> z, rigid, smooth, compliant, weak;
    for (int i = 0; i <= 300; ++i) {
        const double x = 3.0 * i / 300;
        z.push_back(x);
        rigid.push_back(x < 1 ? 2 / kPi * std::asin(x) : 1.0);
        smooth.push_back(x / std::sqrt(1 + x * x));
        compliant.push_back(x / std::sqrt(0.3 + x * x) * 0.97);
        weak.push_back(i >= 140 && i <= 160 ? std::nan("")
                                            : 0.5 * x / std::sqrt(0.05 + x * x)); // NaN: a break in the line
    }
    p.add_series("rigid: 2/π·asin ζ", z, rigid);
    p.add_series("ζ/√(1+ζ²)", z, smooth, {std::nullopt, 2.0f, LineStyle::Dashed});
    p.add_series("compliant, i = 1", z, compliant, {std::nullopt, 2.0f, LineStyle::Dotted});
    p.add_series("with NaN break", z, weak, {std::nullopt, 1.5f, LineStyle::Solid});
    Series& m =
        p.add_series("measured (±σ)", {0.25, 0.5, 1.0, 1.5, 2.0, 2.5}, {0.2, 0.41, 0.69, 0.83, 0.89, 0.93});
    m.y_err = {0.04, 0.05, 0.06, 0.04, 0.05, 0.03};
    m.style.draw_line = false;
    m.style.marker = MarkerShape::Circle;
    m.style.marker_size = 8;
    p.draw(c);
}

void trajectory_plot(Canvas& c, const Rect& r) {
    Plot p(r);
    p.title = "top view: P(τ) and lagging tip T";
    p.x_axis.title = "x / x_{v}";
    p.y_axis.title = "y / x_{v}";
    p.equal_aspect = true;
    const double lag = 0.6;
    std::vector<double> px, py, tx, ty;
    for (int i = 0; i <= 400; ++i) {
        const double t = 4 * kPi * i / 400;
        px.push_back(0.15 * t), py.push_back(std::sin(t));
        tx.push_back(0.15 * (t - lag)), ty.push_back(0.8 * std::sin(t - lag));
    }
    p.add_series("body point P", px, py);
    p.add_series("asperity tip T", tx, ty, {std::nullopt, 2.0f, LineStyle::Dashed});
    const double t0 = 2.3;
    const double Px = 0.15 * t0, Py = std::sin(t0), Tx = 0.15 * (t0 - lag), Ty = 0.8 * std::sin(t0 - lag);
    p.add_overlay([=](Canvas& cv, const PlotTransform& tf) {
        const Vec2 P = tf.to_pixel(Px, Py), T = tf.to_pixel(Tx, Ty);
        cv.circle(T, 0.5f * tf.pixels_per_unit_x(),
                  {Color::hex(0x666666), 1.2f, LineStyle::Dashed});     // z_ss circle
        cv.line(P, T, {Color::hex(0x444444), 1.5f, LineStyle::Dotted}); // spring
        const Vec2 V = tf.to_pixel(Px + 0.15 * 2.0, Py + std::cos(t0) * 2.0 * 0.5);
        cv.arrow(P, V, {{Color::hex(0xD55E00), 2.0f, LineStyle::Solid}, 12, 9}); // velocity
        cv.marker(P, {MarkerShape::Circle, 10, palette(0), colors::white, 1.5f});
        cv.marker(T, {MarkerShape::Square, 9, colors::white, palette(1), 2.0f});
        TextStyle ts;
        ts.size = 14, ts.halign = HAlign::Left, ts.valign = VAlign::Bottom;
        cv.text({P.x + 8, P.y - 6}, "P", ts);
        ts.halign = HAlign::Right, ts.valign = VAlign::Top;
        cv.text({T.x - 8, T.y + 6}, "T", ts);
        ts.halign = HAlign::Left, ts.valign = VAlign::Middle, ts.size = 12;
        const Vec2 Z = tf.to_pixel(Tx + 0.36, Ty - 0.36);
        cv.text({Z.x + 4, Z.y + 4}, "z_{ss} = 1/r_{disp}", ts);
    });
    p.draw(c);
}

void primitives_strip(Canvas& c, const Rect& r) {
    c.stroke_rect({r.x0 + 0.5f, r.y0 + 0.5f, r.x1 - 0.5f, r.y1 - 0.5f},
                  {Color::hex(0xCCCCCC), 1, LineStyle::Solid});
    TextStyle ts;
    ts.size = 13;
    // Line styles at three widths.
    const LineStyle styles[3] = {LineStyle::Solid, LineStyle::Dashed, LineStyle::Dotted};
    const char* names[3] = {"solid", "dashed", "dotted"};
    for (int s = 0; s < 3; ++s) {
        const float y = r.y0 + 24 + 26.0f * static_cast<float>(s);
        ts.valign = VAlign::Middle;
        c.text({r.x0 + 12, y}, names[s], ts);
        const float widths[3] = {1.0f, 2.0f, 4.0f};
        for (int w = 0; w < 3; ++w) {
            const float x = r.x0 + 70 + 70.0f * static_cast<float>(w);
            c.line({x, y}, {x + 60, y}, {palette(static_cast<std::size_t>(s)), widths[w], styles[s]});
        }
    }
    // Sharp zigzag: joins must have no gaps or spikes; translucent one must not darken at joints.
    std::vector<Vec2> zig;
    for (int i = 0; i < 9; ++i)
        zig.push_back({r.x0 + 20 + 30.0f * static_cast<float>(i), r.y0 + (i % 2 ? 110.0f : 215.0f)});
    c.polyline(zig, {palette(0).with_alpha(0.5f), 10.0f, LineStyle::Solid});
    c.polyline(zig, {colors::black, 1.5f, LineStyle::Solid});
    std::vector<Vec2> zig2;
    for (int i = 0; i < 7; ++i)
        zig2.push_back({r.x0 + 300 + 14.0f * static_cast<float>(i), r.y0 + (i % 2 ? 120.0f : 210.0f)});
    c.polyline(zig2, {palette(1), 2.5f, LineStyle::Dashed});
    // Markers: filled row, outline row.
    const MarkerShape shapes[6] = {MarkerShape::Circle,  MarkerShape::Square, MarkerShape::Triangle,
                                   MarkerShape::Diamond, MarkerShape::Cross,  MarkerShape::Plus};
    for (int i = 0; i < 6; ++i) {
        const float x = r.x0 + 440 + 34.0f * static_cast<float>(i);
        const Color col = palette(static_cast<std::size_t>(i));
        c.marker({x, r.y0 + 30}, {shapes[i], 14, col, colors::white, 1.0f});
        c.marker({x, r.y0 + 64}, {shapes[i], 14, colors::white, col, 1.8f});
        c.marker({x, r.y0 + 96}, {shapes[i], 7, col, col, 0.0f});
    }
    // Arrows in several directions, circles, rectangles.
    const Vec2 o{r.x0 + 520, r.y0 + 170};
    for (int k = 0; k < 8; ++k) {
        const double a = kPi / 4 * k;
        c.arrow(o, {o.x + 45 * static_cast<float>(std::cos(a)), o.y - 45 * static_cast<float>(std::sin(a))},
                {{palette(static_cast<std::size_t>(k)), 1.8f, LineStyle::Solid}, 10, 8});
    }
    c.circle({r.x0 + 640, r.y0 + 170}, 34, {colors::black, 1.5f, LineStyle::Solid});
    c.circle({r.x0 + 640, r.y0 + 170}, 24, {palette(2), 2.0f, LineStyle::Dashed});
    c.fill_circle({r.x0 + 640, r.y0 + 170}, 8, palette(4).with_alpha(0.7f));
    c.fill_rect({r.x0 + 700, r.y0 + 20, r.x0 + 780, r.y0 + 70}, palette(5).with_alpha(0.5f));
    c.fill_rect({r.x0 + 740, r.y0 + 45, r.x0 + 820, r.y0 + 95}, palette(1).with_alpha(0.5f));
    c.stroke_rect({r.x0 + 700, r.y0 + 120, r.x0 + 820, r.y0 + 215}, {colors::black, 2.0f, LineStyle::Dotted});
    // Text: Greek, sub/superscripts, alignment, rotation, clipping.
    ts.valign = VAlign::Top;
    ts.size = 16;
    c.text({r.x0 + 850, r.y0 + 14}, "αβγδεζηθικλμνξπρστφχψω ΓΔΘΛΞΠΣΦΨΩ", ts);
    ts.size = 14;
    c.text({r.x0 + 850, r.y0 + 42}, "r_{disp} = 2, z_{ss} = F_{c}/σ_{0}, x^{2} + y^{2}, 10^{−3}", ts);
    c.text({r.x0 + 850, r.y0 + 66}, "Unicode: x₀ r² −0.5 ±1 · × ° µm", ts);
    const Vec2 anchor{r.x0 + 1000, r.y0 + 150};
    c.line({anchor.x - 90, anchor.y + 0.5f}, {anchor.x + 90, anchor.y + 0.5f},
           {Color::hex(0xBBBBBB), 1, LineStyle::Solid});
    c.line({anchor.x + 0.5f, anchor.y - 50}, {anchor.x + 0.5f, anchor.y + 50},
           {Color::hex(0xBBBBBB), 1, LineStyle::Solid});
    ts.size = 13;
    const HAlign ha[3] = {HAlign::Right, HAlign::Center, HAlign::Left};
    const VAlign va[3] = {VAlign::Bottom, VAlign::Middle, VAlign::Top};
    const char* hv[3][3] = {{"RB", "CB", "LB"}, {"RM", "CM", "LM"}, {"RT", "CT", "LT"}};
    for (int v = 0; v < 3; ++v)
        for (int h = 0; h < 3; ++h) {
            ts.halign = ha[h], ts.valign = va[v];
            c.text(
                {anchor.x + static_cast<float>(h - 1) * 60.0f, anchor.y + static_cast<float>(v - 1) * 35.0f},
                hv[v][h], ts);
        }
    ts.halign = HAlign::Center, ts.valign = VAlign::Middle;
    for (int k = 0; k < 3; ++k) {
        ts.angle_deg = 90.0f - 45.0f * static_cast<float>(k);
        c.text({r.x0 + 1150 + 40.0f * static_cast<float>(k), r.y0 + 185}, "rotated θ", ts);
    }
    ts.angle_deg = 0;
    c.push_clip({r.x0 + 1110, r.y0 + 100, r.x0 + 1240, r.y0 + 130});
    c.fill_rect({r.x0 + 1100, r.y0 + 90, r.x0 + 1250, r.y0 + 140}, Color::hex(0xEEEEFF));
    ts.size = 20, ts.halign = HAlign::Left, ts.valign = VAlign::Middle;
    c.text({r.x0 + 1090, r.y0 + 115}, "clipped text ζζζζ", ts);
    c.pop_clip();
}

} // namespace

void draw_demo_page(Canvas& c) {
    const Vec2 s = c.size();
    velocity_ratio_plot(c, {0, 0, std::round(s.x * 0.5f), s.y - 240});
    trajectory_plot(c, {std::round(s.x * 0.5f), 0, s.x, s.y - 240});
    primitives_strip(c, {8, s.y - 236, s.x - 8, s.y - 8});
}

void draw_heatmap_page(Canvas& c) {
    const Vec2 s = c.size();
    Plot h({0, 0, std::round(s.x * 0.5f), s.y});
    h.title = "mean friction ratio r_{x}(ζ, θ), rigid";
    h.x_axis.title = "velocity ratio ζ";
    h.y_axis.title = "angle θ [°]";
    HeatMap m;
    m.nx = 120, m.ny = 90, m.x0 = 0, m.x1 = 3, m.y0 = 0, m.y1 = 90, m.label = "r_{x}";
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i < m.nx; ++i) {
            const double z = (i + 0.5) / m.nx * 3, th = (j + 0.5) / m.ny * kPi / 2;
            m.values.push_back(z / std::sqrt(z * z + std::sin(th) * std::sin(th) + 0.02 * std::cos(th)));
        }
    h.set_heatmap(m);
    std::vector<double> zx, zy;
    for (int j = 0; j <= 90; ++j) zx.push_back(std::sin(j * kPi / 180)), zy.push_back(j);
    h.add_series("ζ = sin θ", zx, zy, {Color::hex(0xD55E00), 2.0f, LineStyle::Dashed});
    h.legend = LegendPosition::TopRight;
    h.draw(c);

    Plot l({std::round(s.x * 0.5f), 0, s.x, s.y});
    l.title = "convergence: error vs steps per period";
    l.x_axis.title = "n";
    l.y_axis.title = "|r_{x} − r_{x,ref}|";
    l.x_axis.log = l.y_axis.log = true;
    std::vector<double> n, e1, e2;
    for (int k = 0; k <= 20; ++k) {
        const double nn = 10 * std::pow(10.0, k / 5.0);
        n.push_back(nn), e1.push_back(0.8 / nn), e2.push_back(3.0 / (nn * nn));
    }
    l.add_series("paper scheme ∝ 1/n", n, e1,
                 {std::nullopt, 2.0f, LineStyle::Solid, true, MarkerShape::Circle});
    l.add_series("RK4 ∝ 1/n²", n, e2,
                 {std::nullopt, 2.0f, LineStyle::Dashed, true, MarkerShape::Triangle, 8, false});
    l.draw(c);
}

} // namespace fv::demo
