#include "fv/gfx/plot.hpp"

#include "fv/gfx/colormap.hpp"
#include "fv/gfx/display_list.hpp"
#include "fv/gfx/ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fv::gfx {

Color palette(std::size_t index) {
    // Okabe–Ito; yellow (#F0E442) is left out: too faint on white.
    static constexpr std::array<Color, 7> kColors = {
        Color::hex(0x0072B2), Color::hex(0xD55E00), Color::hex(0x009E73), Color::hex(0xCC79A7),
        Color::hex(0xE69F00), Color::hex(0x56B4E9), Color::hex(0x000000)};
    return kColors[index % kColors.size()];
}

Vec2 PlotTransform::to_pixel(double x, double y) const {
    if (log_x) x = x > 0 ? std::log10(x) : std::numeric_limits<double>::quiet_NaN();
    if (log_y) y = y > 0 ? std::log10(y) : std::numeric_limits<double>::quiet_NaN();
    const double a0 = log_x ? std::log10(x0) : x0, a1 = log_x ? std::log10(x1) : x1;
    const double b0 = log_y ? std::log10(y0) : y0, b1 = log_y ? std::log10(y1) : y1;
    const double px = area.x0 + (x - a0) / (a1 - a0) * area.width();
    const double py = area.y1 - (y - b0) / (b1 - b0) * area.height();
    return {static_cast<float>(px), static_cast<float>(py)};
}

Series& Plot::add_series(std::string label, std::vector<double> x, std::vector<double> y, SeriesStyle style) {
    series_.push_back({std::move(label), std::move(x), std::move(y), {}, style});
    return series_.back();
}

namespace {

constexpr float kTickLength = 5;

struct Range {
    double lo, hi;
};

// Auto-fit one axis over all finite (and, for log axes, positive) values, including error bars.
Range fit_range(const std::vector<Series>& series, bool is_x, const Axis& axis) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Series& s : series) {
        const std::vector<double>& v = is_x ? s.x : s.y;
        for (std::size_t i = 0; i < v.size(); ++i) {
            double a = v[i], b = v[i];
            if (!is_x && i < s.y_err.size() && std::isfinite(s.y_err[i])) a -= s.y_err[i], b += s.y_err[i];
            for (double w : {a, b}) {
                if (!std::isfinite(w) || (axis.log && w <= 0)) continue;
                lo = std::min(lo, w), hi = std::max(hi, w);
            }
        }
    }
    if (axis.min) lo = *axis.min;
    if (axis.max) hi = *axis.max;
    if (!std::isfinite(lo) || !std::isfinite(hi)) { // No data: a default range.
        lo = axis.min ? *axis.min : (axis.log ? 1 : 0);
        hi = axis.max ? *axis.max : lo + (axis.log ? 9 * lo : 1);
    }
    if (axis.log) {
        lo = std::log10(lo), hi = std::log10(hi);
    }
    if (hi < lo) std::swap(lo, hi);
    if (hi == lo) { // All equal: open a window around the value.
        const double d = lo != 0 && !axis.log ? 0.5 * std::fabs(lo) : 0.5;
        lo -= d, hi += d;
    } else {
        const double pad = 0.04 * (hi - lo);
        if (!axis.min) lo -= pad;
        if (!axis.max) hi += pad;
    }
    if (axis.log) lo = std::pow(10.0, lo), hi = std::pow(10.0, hi);
    return {lo, hi};
}

struct Layout {
    PlotTransform tf;
    std::vector<Tick> x_ticks, y_ticks;
};

float max_label_width(const Canvas& c, const std::vector<Tick>& ticks, float size) {
    float w = 0;
    for (const Tick& t : ticks) w = std::max(w, c.measure_text(t.label, size).x);
    return w;
}

// Pixel-space polyline runs of a series, clipped to a margin around the area so far-away
// points (huge pixel coordinates) never reach the GPU; NaN points split runs.
std::vector<std::vector<Vec2>> series_runs(const Series& s, const PlotTransform& tf, const Rect& box) {
    std::vector<std::vector<Vec2>> runs(1);
    const std::size_t n = std::min(s.x.size(), s.y.size());
    bool have_prev = false;
    double px = 0, py = 0;
    auto to_px = [&](std::size_t i, double& ox, double& oy) {
        const Vec2 p = tf.to_pixel(s.x[i], s.y[i]);
        // Recompute in double precision for clipping.
        ox = p.x, oy = p.y;
        return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && std::isfinite(p.x) && std::isfinite(p.y);
    };
    for (std::size_t i = 0; i < n; ++i) {
        double cx, cy;
        if (!to_px(i, cx, cy)) {
            have_prev = false;
            if (!runs.back().empty()) runs.emplace_back();
            continue;
        }
        if (have_prev) {
            double ax = px, ay = py, bx = cx, by = cy;
            if (clip_segment(ax, ay, bx, by, box.x0, box.y0, box.x1, box.y1)) {
                auto& run = runs.back();
                const Vec2 a{static_cast<float>(ax), static_cast<float>(ay)};
                if (run.empty() || std::fabs(run.back().x - a.x) > 1e-3f ||
                    std::fabs(run.back().y - a.y) > 1e-3f) {
                    if (!run.empty()) runs.emplace_back();
                    runs.back().push_back(a);
                }
                runs.back().push_back({static_cast<float>(bx), static_cast<float>(by)});
            } else if (!runs.back().empty()) {
                runs.emplace_back();
            }
        }
        px = cx, py = cy, have_prev = true;
    }
    return runs;
}

Color series_color(const Series& s, std::size_t i) {
    return s.style.color ? *s.style.color : palette(i);
}

MarkerStyle series_marker(const Series& s, Color c) {
    MarkerStyle m;
    m.shape = s.style.marker;
    m.size = s.style.marker_size;
    m.fill = s.style.marker_filled ? c : colors::white;
    m.edge = s.style.marker_filled ? colors::white : c;
    m.edge_width = s.style.marker_filled ? 1.0f : 1.5f;
    if (m.shape == MarkerShape::Cross || m.shape == MarkerShape::Plus)
        m.fill = c, m.edge_width = 0; // Thin bars: no halo.
    return m;
}

} // namespace

static constexpr float kColorBarSpace = 90; // Bar, its tick labels and its title, right of the data area.

// Range of an axis when a heat map is present: exactly its extent (series beyond it are clipped).
static Range with_heatmap(double lo, double hi, const Axis& axis) {
    Range r{lo, hi};
    if (axis.min) r.lo = *axis.min;
    if (axis.max) r.hi = *axis.max;
    return r;
}

static std::pair<double, double> value_range(const HeatMap& h) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double v : h.values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (h.vmin) lo = *h.vmin;
    if (h.vmax) hi = *h.vmax;
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
    if (hi <= lo) hi = lo + 1;
    return {lo, hi};
}

// Height of the top axis (ticks, labels, title) above the data area; 0 without one.
static float top_axis_band(const Plot& plot) {
    if (!(plot.top_scale > 0)) return 0;
    return std::round(kTickLength + 4 + plot.font_size * 1.2f +
                      (plot.top_title.empty() ? 4 : (plot.font_size + 1) * 1.5f + 2));
}

// The top axis: ticks at nice values of top_scale * x, labels above them, its title above those.
static void draw_top_axis(Canvas& canvas, const Plot& plot, const PlotTransform& tf) {
    const Rect& A = tf.area;
    const double k = plot.top_scale;
    const Stroke axis{colors::axis, 1.0f, LineStyle::Solid};
    TextStyle ts;
    ts.size = plot.font_size, ts.halign = HAlign::Center, ts.valign = VAlign::Bottom;
    for (const Tick& t : linear_ticks(k * tf.x0, k * tf.x1, std::max(2, static_cast<int>(A.width() / 95)))) {
        const float x = std::floor(tf.to_pixel(t.value / k, tf.y0).x) + 0.5f;
        if (x < A.x0 - 0.5f || x > A.x1 + 0.5f) continue;
        canvas.line({x, A.y0 - (t.major ? kTickLength : kTickLength * 0.6f)}, {x, A.y0}, axis);
        if (!t.label.empty()) canvas.text({x, A.y0 - kTickLength - 3}, t.label, ts);
    }
    if (!plot.top_title.empty()) {
        ts.size = plot.font_size + 1;
        canvas.text({0.5f * (A.x0 + A.x1), A.y0 - top_axis_band(plot) + ts.size * 1.3f}, plot.top_title, ts);
    }
}

// `reserve`: room kept free right of the data area (and of the colour bar) for a legend outside the axes.
// `band`: room kept free above the data area (and its top axis) for a legend above the axes.
static Layout compute_layout(const Plot& plot, const std::vector<Series>& series,
                             const std::optional<HeatMap>& hm, const Rect& bounds, const Canvas& canvas,
                             float reserve = 0, float reserve_below = 0, float band = 0) {
    Layout L;
    Range xr = fit_range(series, true, plot.x_axis), yr = fit_range(series, false, plot.y_axis);
    if (hm) {
        xr = with_heatmap(hm->x0, hm->x1, plot.x_axis);
        yr = with_heatmap(hm->y0, hm->y1, plot.y_axis);
    }
    PlotTransform& tf = L.tf;
    tf.log_x = plot.x_axis.log, tf.log_y = plot.y_axis.log;
    const float fs = plot.font_size, title_fs = plot.font_size + 1, head_fs = plot.font_size + 3;
    const float top =
        bounds.y0 + (plot.title.empty() ? 10 : std::round(head_fs * 2.0f)) + top_axis_band(plot) + band;
    const float bottom =
        bounds.y1 - reserve_below -
        std::round(kTickLength + 4 + fs * 1.2f + (plot.x_axis.title.empty() ? 6 : title_fs * 1.5f + 4));
    // Room for the last x tick label's overhang, or for the colour bar.
    const float right =
        bounds.x1 - (reserve > 0 ? reserve : std::round(fs * 1.5f)) - (hm ? kColorBarSpace : 0.0f);
    float left_margin = 50;
    // Two passes: the y tick labels' width sets the left margin, which changes the area and,
    // with equal aspect, the ranges and ticks.
    for (int pass = 0; pass < 2; ++pass) {
        tf.area = {std::round(bounds.x0 + left_margin), top, right, bottom};
        tf.x0 = xr.lo, tf.x1 = xr.hi, tf.y0 = yr.lo, tf.y1 = yr.hi;
        if (plot.equal_aspect && !tf.log_x && !tf.log_y) {
            const double ux = (tf.x1 - tf.x0) / tf.area.width(), uy = (tf.y1 - tf.y0) / tf.area.height();
            const double u = std::max(ux, uy);
            const double cx = 0.5 * (tf.x0 + tf.x1), cy = 0.5 * (tf.y0 + tf.y1);
            tf.x0 = cx - 0.5 * u * tf.area.width(), tf.x1 = cx + 0.5 * u * tf.area.width();
            tf.y0 = cy - 0.5 * u * tf.area.height(), tf.y1 = cy + 0.5 * u * tf.area.height();
        }
        const int nx = std::max(2, static_cast<int>(tf.area.width() / 95));
        const int ny = std::max(2, static_cast<int>(tf.area.height() / 60));
        // Decade labels are short: log axes can carry about twice as many.
        L.x_ticks = tf.log_x ? log_ticks(tf.x0, tf.x1, 2 * nx) : linear_ticks(tf.x0, tf.x1, nx);
        L.y_ticks = tf.log_y ? log_ticks(tf.y0, tf.y1, 2 * ny) : linear_ticks(tf.y0, tf.y1, ny);
        left_margin = std::round(kTickLength + 5 + max_label_width(canvas, L.y_ticks, fs) +
                                 (plot.y_axis.title.empty() ? 8 : title_fs * 1.5f + 6));
    }
    return L;
}

// Vertical colour bar right of the data area, with ticks and a rotated title.
static void draw_colorbar(Canvas& canvas, const Rect& A, const HeatMap& hm, float fs, float title_fs) {
    const auto [vlo, vhi] = value_range(hm);
    const Rect bar{A.x1 + 14, A.y0, A.x1 + 30, A.y1};
    Image grad(1, 256);
    for (int i = 0; i < 256; ++i) {
        const std::uint32_t c = viridis(1.0 - i / 255.0).packed();
        std::uint8_t* p = grad.pixel(0, i);
        p[0] = static_cast<std::uint8_t>(c), p[1] = static_cast<std::uint8_t>(c >> 8);
        p[2] = static_cast<std::uint8_t>(c >> 16), p[3] = 255;
    }
    canvas.image(bar, grad, true);
    const Stroke axis{colors::axis, 1.0f, LineStyle::Solid};
    canvas.stroke_rect({bar.x0 + 0.5f, bar.y0 + 0.5f, bar.x1 - 0.5f, bar.y1 - 0.5f}, axis);
    TextStyle ts;
    ts.size = fs, ts.halign = HAlign::Left, ts.valign = VAlign::Middle;
    const auto ticks = linear_ticks(vlo, vhi, std::max(2, static_cast<int>(bar.height() / 60)));
    float label_w = 0;
    for (const Tick& t : ticks) {
        const float y =
            std::floor(bar.y1 - static_cast<float>((t.value - vlo) / (vhi - vlo)) * bar.height()) + 0.5f;
        canvas.line({bar.x1, y}, {bar.x1 + kTickLength, y}, axis);
        canvas.text({bar.x1 + kTickLength + 3, y}, t.label, ts);
        label_w = std::max(label_w, canvas.measure_text(t.label, fs).x);
    }
    if (!hm.label.empty()) {
        TextStyle tt;
        tt.size = title_fs, tt.halign = HAlign::Center, tt.valign = VAlign::Bottom, tt.angle_deg = 90;
        canvas.text(
            {std::round(bar.x1 + kTickLength + 6 + label_w + title_fs * 1.3f), 0.5f * (bar.y0 + bar.y1)},
            hm.label, tt);
    }
}

PlotTransform Plot::layout(const Canvas& canvas) const {
    return compute_layout(*this, series_, heatmap_, bounds_, canvas, 0, 0, legend_band(canvas)).tf;
}

namespace {

constexpr float kLegendPad = 8, kLegendSample = 30, kLegendMargin = 10, kLegendGap = 12;

std::vector<std::size_t> legend_entries(const std::vector<Series>& series) {
    std::vector<std::size_t> entries;
    for (std::size_t i = 0; i < series.size(); ++i)
        if (!series[i].label.empty()) entries.push_back(i);
    return entries;
}

// Width and height of the legend box.
Vec2 legend_size(const Canvas& canvas, const std::vector<Series>& series,
                 const std::vector<std::size_t>& entries, float fs) {
    const float row = std::round(fs * 1.6f);
    float label_w = 0;
    for (std::size_t i : entries) label_w = std::max(label_w, canvas.measure_text(series[i].label, fs).x);
    return {std::round(kLegendPad + kLegendSample + 8 + label_w + kLegendPad),
            std::round(kLegendPad * 0.75f * 2 + row * static_cast<float>(entries.size()))};
}

// Between entries in a row; between the rows and the axes; rows in font sizes (tighter than a boxed
// legend's).
constexpr float kAboveGap = 16, kAboveSpace = 6, kAboveRow = 1.4f;

// A legend above the axes: each entry's offset (sample's left, row's top) from the block's top-left corner,
// in rows no wider than `width` (an entry wider than that gets a row of its own), and the block's size.
struct AboveLayout {
    std::vector<Vec2> at;
    Vec2 size{0, 0};
};

AboveLayout above_layout(const Canvas& canvas, const std::vector<Series>& series,
                         const std::vector<std::size_t>& entries, float fs, float width) {
    AboveLayout out;
    const float row = std::round(fs * kAboveRow);
    float x = 0, y = 0;
    for (std::size_t i : entries) {
        const float w = std::ceil(kLegendSample + 8 + canvas.measure_text(series[i].label, fs).x);
        if (x > 0 && x + w > width) x = 0, y += row;
        out.at.push_back({x, y});
        out.size.x = std::max(out.size.x, x + w);
        x += w + kAboveGap;
    }
    out.size.y = entries.empty() ? 0 : y + row;
    return out;
}

} // namespace

float Plot::legend_band(const Canvas& canvas) const {
    const auto entries = legend_entries(series_);
    if (legend != LegendPosition::Above || entries.empty()) return 0;
    // The rows wrap at the data area's width, which the band hardly changes (only through the y ticks).
    const float width = compute_layout(*this, series_, heatmap_, bounds_, canvas).tf.area.width();
    return above_layout(canvas, series_, entries, font_size, width).size.y + kAboveSpace;
}

PlotTransform Plot::draw(Canvas& canvas) const {
    const auto entries = legend_entries(series_);
    const bool has_legend = legend != LegendPosition::None && !entries.empty();
    LegendPlace redraw = LegendPlace::Inside;
    if (has_legend && legend == LegendPosition::Outside)
        return draw_with_legend(canvas, LegendPlace::Right, redraw);
    const Canvas::Mark start = canvas.mark();
    const PlotTransform tf = draw_with_legend(canvas, LegendPlace::Inside, redraw);
    if (redraw == LegendPlace::Inside) return tf;
    // Every place inside the axes covers data: draw the plot again, narrower with the legend right of it,
    // or shorter with the legend below it.
    canvas.rewind(start);
    return draw_with_legend(canvas, redraw, redraw);
}

PlotTransform Plot::draw_with_legend(Canvas& canvas, LegendPlace place, LegendPlace& redraw) const {
    redraw = LegendPlace::Inside;
    const bool outside = place == LegendPlace::Right;
    const std::vector<std::size_t> entries = legend_entries(series_);
    const Vec2 lsize = legend_size(canvas, series_, entries, font_size);
    const float below = place == LegendPlace::Below ? lsize.y + kLegendGap : 0.0f;
    const float band = legend_band(canvas);
    const Layout L = compute_layout(*this, series_, heatmap_, bounds_, canvas,
                                    outside ? lsize.x + 2 * kLegendGap : 0.0f, below, band);
    const PlotTransform& tf = L.tf;
    const Rect& A = tf.area;
    const float fs = font_size, title_fs = font_size + 1, head_fs = font_size + 3;

    canvas.fill_rect(A, colors::white);
    // Grid: 1-px lines centred on pixel centres so they stay crisp.
    canvas.push_clip(A);
    const Stroke major{colors::grid, 1.0f, LineStyle::Solid},
        minor{colors::minor_grid, 1.0f, LineStyle::Solid};
    if (x_axis.grid) {
        for (const Tick& t : L.x_ticks) {
            const float x = std::floor(tf.to_pixel(t.value, tf.y0 > 0 ? tf.y0 : 1).x) + 0.5f;
            canvas.line({x, A.y0}, {x, A.y1}, t.major ? major : minor);
        }
    }
    if (y_axis.grid) {
        for (const Tick& t : L.y_ticks) {
            const float y = std::floor(tf.to_pixel(tf.x0 > 0 ? tf.x0 : 1, t.value).y) + 0.5f;
            canvas.line({A.x0, y}, {A.x1, y}, t.major ? major : minor);
        }
    }

    if (heatmap_ && heatmap_->nx > 0 && heatmap_->ny > 0 &&
        heatmap_->values.size() >=
            static_cast<std::size_t>(heatmap_->nx) * static_cast<std::size_t>(heatmap_->ny)) {
        const auto [vlo, vhi] = value_range(*heatmap_);
        const Vec2 tl = tf.to_pixel(heatmap_->x0, heatmap_->y1), br = tf.to_pixel(heatmap_->x1, heatmap_->y0);
        canvas.image({tl.x, tl.y, br.x, br.y},
                     heatmap_image(heatmap_->values.data(), heatmap_->nx, heatmap_->ny, vlo, vhi));
    }

    for (const auto& fn : underlays_) fn(canvas, tf);
    // Series, clipped to the data area.
    const Canvas::Mark data_start = canvas.mark();
    const Rect clip_box = {A.x0 - 100, A.y0 - 100, A.x1 + 100, A.y1 + 100};
    for (std::size_t i = 0; i < series_.size(); ++i) {
        const Series& s = series_[i];
        const Color c = series_color(s, i);
        const std::size_t n = std::min(s.x.size(), s.y.size());
        if (!s.y_err.empty()) {
            const Stroke eb{c, 1.2f, LineStyle::Solid};
            for (std::size_t k = 0; k < n && k < s.y_err.size(); ++k) {
                if (!std::isfinite(s.y_err[k])) continue;
                const Vec2 a = tf.to_pixel(s.x[k], s.y[k] - s.y_err[k]),
                           b = tf.to_pixel(s.x[k], s.y[k] + s.y_err[k]);
                if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.y)) continue;
                canvas.line(a, b, eb);
                canvas.line({a.x - 3.5f, a.y}, {a.x + 3.5f, a.y}, eb);
                canvas.line({b.x - 3.5f, b.y}, {b.x + 3.5f, b.y}, eb);
            }
        }
        if (s.style.draw_line) {
            const Stroke st{c, s.style.line_width, s.style.line};
            for (const auto& run : series_runs(s, tf, clip_box)) canvas.polyline(run, st);
        }
        if (s.style.marker != MarkerShape::None) {
            const MarkerStyle m = series_marker(s, c);
            for (std::size_t k = 0; k < n; ++k) {
                const Vec2 p = tf.to_pixel(s.x[k], s.y[k]);
                if (clip_box.contains(p)) canvas.marker(p, m);
            }
        }
    }
    PlotTransform otf = tf;
    otf.first_data_command = data_start.commands;
    for (const auto& fn : overlays_) fn(canvas, otf);
    canvas.pop_clip();
    for (const auto& fn : unclipped_overlays_) fn(canvas, otf);
    canvas.add_region("data", A, data_start);
    const Canvas::Mark data_end = canvas.mark();

    // Frame and outward ticks.
    const Stroke axis{colors::axis, 1.0f, LineStyle::Solid};
    canvas.stroke_rect({A.x0 + 0.5f, A.y0 + 0.5f, A.x1 - 0.5f, A.y1 - 0.5f}, axis);
    // All tick marks first, then all labels: text and shapes are separate draw batches, and llvmpipe
    // pays per batch (they do not overlap, so the order does not change a pixel).
    for (const Tick& t : L.x_ticks) {
        const float x = std::floor(tf.to_pixel(t.value, tf.y0 > 0 ? tf.y0 : 1).x) + 0.5f;
        canvas.line({x, A.y1}, {x, A.y1 + (t.major ? kTickLength : kTickLength * 0.6f)}, axis);
    }
    for (const Tick& t : L.y_ticks) {
        const float y = std::floor(tf.to_pixel(tf.x0 > 0 ? tf.x0 : 1, t.value).y) + 0.5f;
        canvas.line({A.x0 - (t.major ? kTickLength : kTickLength * 0.6f), y}, {A.x0, y}, axis);
    }
    TextStyle ts;
    ts.size = fs;
    for (const Tick& t : L.x_ticks) {
        if (t.label.empty()) continue;
        const float x = std::floor(tf.to_pixel(t.value, tf.y0 > 0 ? tf.y0 : 1).x) + 0.5f;
        ts.halign = HAlign::Center, ts.valign = VAlign::Top;
        canvas.text({x, A.y1 + kTickLength + 3}, t.label, ts);
    }
    for (const Tick& t : L.y_ticks) {
        if (t.label.empty()) continue;
        const float y = std::floor(tf.to_pixel(tf.x0 > 0 ? tf.x0 : 1, t.value).y) + 0.5f;
        ts.halign = HAlign::Right, ts.valign = VAlign::Middle;
        canvas.text({A.x0 - kTickLength - 4, y}, t.label, ts);
    }

    // Titles.
    TextStyle tt;
    tt.size = title_fs;
    if (!x_axis.title.empty()) {
        tt.halign = HAlign::Center, tt.valign = VAlign::Bottom;
        canvas.text({0.5f * (A.x0 + A.x1), bounds_.y1 - below - 4}, x_axis.title, tt);
    }
    if (!y_axis.title.empty()) {
        tt.halign = HAlign::Center, tt.valign = VAlign::Top, tt.angle_deg = 90;
        canvas.text({bounds_.x0 + 4, 0.5f * (A.y0 + A.y1)}, y_axis.title, tt);
        tt.angle_deg = 0;
    }
    if (!title.empty()) {
        tt.size = head_fs, tt.halign = HAlign::Center, tt.valign = VAlign::Middle;
        canvas.text({0.5f * (A.x0 + A.x1), 0.5f * (bounds_.y0 + A.y0 - top_axis_band(*this) - band)}, title,
                    tt);
    }
    if (top_scale > 0) draw_top_axis(canvas, *this, tf);

    if (heatmap_) draw_colorbar(canvas, A, *heatmap_, fs, title_fs);

    // Legend.
    if (legend == LegendPosition::None || entries.empty()) return tf;
    const float row = std::round(fs * 1.6f), sample = kLegendSample, pad = kLegendPad;
    if (legend == LegendPosition::Above) {
        const AboveLayout above = above_layout(canvas, series_, entries, fs, A.width());
        const float above_row = std::round(fs * kAboveRow);
        const Vec2 origin{A.x0, A.y0 - top_axis_band(*this) - band};
        const Canvas::Mark legend_start = canvas.mark();
        TextStyle lt;
        lt.size = fs, lt.valign = VAlign::Middle;
        // Samples first, labels after (fewer draw batches; they do not overlap).
        for (std::size_t k = 0; k < entries.size(); ++k) {
            const Series& s = series_[entries[k]];
            const Color c = series_color(s, entries[k]);
            const float x0 = origin.x + above.at[k].x,
                        cy = std::floor(origin.y + above.at[k].y + 0.5f * above_row) + 0.5f;
            if (s.style.draw_line)
                canvas.line({x0, cy}, {x0 + sample, cy}, {c, s.style.line_width, s.style.line});
            if (!s.y_err.empty() && !s.style.draw_line)
                canvas.line({x0 + 0.5f * sample, cy - 6}, {x0 + 0.5f * sample, cy + 6},
                            {c, 1.2f, LineStyle::Solid});
            if (s.style.marker != MarkerShape::None)
                canvas.marker({x0 + 0.5f * sample, cy}, series_marker(s, c));
        }
        for (std::size_t k = 0; k < entries.size(); ++k)
            canvas.text({origin.x + above.at[k].x + sample + 8, origin.y + above.at[k].y + 0.5f * above_row},
                        series_[entries[k]].label, lt);
        canvas.add_region("legend", {origin.x, origin.y, origin.x + above.size.x, origin.y + above.size.y},
                          legend_start);
        return tf;
    }
    const float w = lsize.x, h = lsize.y;
    const float m = kLegendMargin;
    // Inside the axes: corners, then the middles of the edges.
    auto box_at = [&](int k) {
        const float left = A.x0 + m, right = A.x1 - m - w, cx = std::round(0.5f * (A.x0 + A.x1 - w));
        const float top = A.y0 + m, bottom = A.y1 - m - h, cy = std::round(0.5f * (A.y0 + A.y1 - h));
        static constexpr int kX[] = {2, 0, 2, 0, 1, 1, 2, 0}, kY[] = {0, 0, 2, 2, 0, 2, 1, 1};
        const float x0 = kX[k] == 0 ? left : (kX[k] == 1 ? cx : right);
        const float y0 = kY[k] == 0 ? top : (kY[k] == 1 ? cy : bottom);
        return Rect{x0, y0, x0 + w, y0 + h};
    };
    int pos = 0;
    switch (legend) {
    case LegendPosition::TopLeft:
        pos = 1;
        break;
    case LegendPosition::BottomRight:
        pos = 2;
        break;
    case LegendPosition::BottomLeft:
        pos = 3;
        break;
    default:
        break;
    }
    Rect box = box_at(pos);
    // Everything drawn in the data area is what the legend must not cover; how much it covers counts lines
    // by their segments.
    const auto& cmds = canvas.display_list().commands;
    auto covered = [&](const Rect& r) {
        std::size_t n = 0;
        for (std::size_t k = data_start.commands; k < data_end.commands; ++k) {
            if (!command_touches(cmds[k], r, canvas.fonts(), 2.0f)) continue;
            const auto* pl = std::get_if<dl::Polyline>(&cmds[k]);
            if (!pl) {
                ++n;
                continue;
            }
            const float g = 2.0f + 0.5f * pl->stroke.width;
            for (std::size_t i = 1; i < pl->points.size(); ++i) {
                double ax = pl->points[i - 1].x, ay = pl->points[i - 1].y, bx = pl->points[i].x,
                       by = pl->points[i].y;
                n += clip_segment(ax, ay, bx, by, r.x0 - g, r.y0 - g, r.x1 + g, r.y1 + g);
            }
        }
        return n;
    };
    // Below the axes: where it fits (a third of the plot's height), else inside.
    const bool below_fits = legend_below && w <= bounds_.width() && h + kLegendGap <= bounds_.height() / 3;
    if (outside) {
        const float x0 = A.x1 + (heatmap_ ? kColorBarSpace : 0.0f) + kLegendGap;
        box = {x0, A.y0, x0 + w, A.y0 + h};
    } else if (place == LegendPlace::Below) {
        const float x0 = std::clamp(std::round(0.5f * (A.x0 + A.x1 - w)), bounds_.x0, bounds_.x1 - w);
        box = {x0, bounds_.y1 - h, x0 + w, bounds_.y1};
    } else if (legend == LegendPosition::Best) {
        std::size_t least = std::numeric_limits<std::size_t>::max();
        for (int k = 0; k < 8 && least > 0; ++k)
            if (const std::size_t n = covered(box_at(k)); n < least) least = n, box = box_at(k);
        // None is free: the plot is drawn again with the legend outside, unless that would take more than a
        // third of the plot's width (a small panel): then below it where allowed, else the place covering
        // least.
        if (least > 0 && w + 2 * kLegendGap <= bounds_.width() / 3) {
            redraw = LegendPlace::Right;
            return tf;
        }
        if (least > 0 && below_fits) {
            redraw = LegendPlace::Below;
            return tf;
        }
    } else if (below_fits && covered(box) > 0) {
        redraw = LegendPlace::Below; // the figure's corner covers data on this page
        return tf;
    }
    const Canvas::Mark legend_start = canvas.mark();
    canvas.fill_rect(box, colors::white.with_alpha(0.92f));
    canvas.stroke_rect({box.x0 + 0.5f, box.y0 + 0.5f, box.x1 - 0.5f, box.y1 - 0.5f},
                       {Color::hex(0xB0B0B0), 1.0f, LineStyle::Solid});
    TextStyle lt;
    lt.size = fs, lt.valign = VAlign::Middle;
    // Samples first, labels after (fewer draw batches; they do not overlap).
    const float y_first = box.y0 + pad * 0.75f + 0.5f * row;
    float y = y_first;
    for (std::size_t i : entries) {
        const Series& s = series_[i];
        const Color c = series_color(s, i);
        const float x0 = box.x0 + pad, cy = std::floor(y) + 0.5f;
        if (s.style.draw_line)
            canvas.line({x0, cy}, {x0 + sample, cy}, {c, s.style.line_width, s.style.line});
        if (!s.y_err.empty() && !s.style.draw_line)
            canvas.line({x0 + 0.5f * sample, cy - 6}, {x0 + 0.5f * sample, cy + 6},
                        {c, 1.2f, LineStyle::Solid});
        if (s.style.marker != MarkerShape::None) canvas.marker({x0 + 0.5f * sample, cy}, series_marker(s, c));
        y += row;
    }
    y = y_first;
    for (std::size_t i : entries) {
        canvas.text({box.x0 + pad + sample + 8, y}, series_[i].label, lt);
        y += row;
    }
    canvas.add_region("legend", box, legend_start);
    return tf;
}

} // namespace fv::gfx
