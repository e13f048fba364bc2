#include "fv/gfx/plot.hpp"

#include "fv/gfx/colormap.hpp"
#include "fv/gfx/display_list.hpp"
#include "fv/gfx/ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

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

// A title within `avail` units: at `size` where it fits, else smaller (steps of 0.5) down to `floor`, else
// (when `may_wrap`) on two lines broken at the space that balances them best, outside markup braces and
// parentheses ("F / F_c =" over "(P − T) / z_ss", not "(P" over "− T) / z_ss"), as large as both fit down to
// `floor`. Too long even so: at `floor`, and its centre kept on the page by the caller.
struct FittedText {
    float size = 0;
    std::string first, second; ///< second empty: one line
    float width = 0;           ///< of the wider line
};

constexpr float kTitleLeading = 1.15f;

FittedText fit_text(const Canvas& c, const std::string& s, float size, float floor, float avail,
                    bool may_wrap) {
    auto width = [&](const std::string& t, float z) { return c.measure_text(t, z).x; };
    FittedText f{size, s, "", width(s, size)};
    if (s.empty() || f.width <= avail) return f;
    floor = std::min(floor, size);
    for (float z = size - 0.5f; z >= floor - 1e-3f; z -= 0.5f)
        if (const float w = width(s, z); w <= avail) return {z, s, "", w};
    f.size = floor, f.width = width(s, floor);
    if (!may_wrap) return f;
    float best = 1e30f;
    std::string a, b;
    int depth = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        depth += s[k] == '{' || s[k] == '(' ? 1 : (s[k] == '}' || s[k] == ')' ? -1 : 0);
        if (depth != 0 || s[k] != ' ' || k == 0 || k + 1 == s.size()) continue;
        const std::string l = s.substr(0, k), r = s.substr(k + 1);
        const float w = std::max(width(l, size), width(r, size));
        if (w < best) best = w, a = l, b = r;
    }
    if (b.empty()) return f;
    for (float z = size; z >= floor - 1e-3f; z -= 0.5f) {
        const float w = std::max(width(a, z), width(b, z));
        if (w <= avail || z - 0.5f < floor - 1e-3f) return {z, a, b, w};
    }
    return f;
}

// The panel title fitted to the plot's width (at most 16 units below the tick labels' size), and the band it
// takes above the axes: twice its size for one line, as before; a line more for two.
FittedText panel_title(const Plot& plot, const Canvas& c, const Rect& bounds) {
    return fit_text(c, plot.title, plot.font_size + 3, plot.font_size, bounds.width() - 4, true);
}
float title_band(const FittedText& t) {
    return std::round(t.size * (t.second.empty() ? 2.0f : 2.0f + kTitleLeading));
}
// The y axis title fitted to the data area's height (rotated); its band left of the tick labels.
FittedText y_title(const Plot& plot, const Canvas& c, float area_height) {
    return fit_text(c, plot.y_axis.title, plot.font_size + 1, plot.font_size, area_height + plot.font_size,
                    true);
}
float y_title_band(const FittedText& t) {
    return t.second.empty() ? t.size * 1.5f + 6 : t.size * (1.5f + kTitleLeading) + 6;
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
static void draw_top_axis(Canvas& canvas, const Plot& plot, const PlotTransform& tf, const Rect& bounds) {
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
        // Too long for the plot's width (small pages): smaller, down to the tick labels' size, and kept
        // within the plot's bounds.
        const float size = plot.font_size + 1;
        const FittedText f = fit_text(canvas, plot.top_title, size, plot.font_size, bounds.width(), false);
        ts.size = f.size;
        const float cx = 0.5f * (A.x0 + A.x1);
        canvas.text({f.width >= bounds.width()
                         ? 0.5f * (bounds.x0 + bounds.x1)
                         : std::clamp(cx, bounds.x0 + 0.5f * f.width, bounds.x1 - 0.5f * f.width),
                     A.y0 - top_axis_band(plot) + size * 1.3f},
                    plot.top_title, ts);
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
    const float fs = plot.font_size, title_fs = plot.font_size + 1;
    const float top = bounds.y0 + (plot.title.empty() ? 10 : title_band(panel_title(plot, canvas, bounds))) +
                      top_axis_band(plot) + band;
    const float bottom =
        bounds.y1 - reserve_below -
        (plot.axes
             ? std::round(kTickLength + 4 + fs * 1.2f + (plot.x_axis.title.empty() ? 6 : title_fs * 1.5f + 4))
             : 6.0f);
    // Room for the last x tick label's overhang, or for the colour bar.
    const float right = bounds.x1 - (reserve > 0 ? reserve : std::round(fs * 1.5f)) -
                        (hm && hm->color_bar ? kColorBarSpace : 0.0f);
    float left_margin = plot.axes ? 50.0f : 6.0f;
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
        // Tick spacing in proportion to the labels' size where they are smaller than 13 units (small pages).
        const float spacing = std::min(1.0f, fs / 13.0f);
        const int nx = std::max(2, static_cast<int>(tf.area.width() / (95 * spacing)));
        const int ny = std::max(2, static_cast<int>(tf.area.height() / (60 * spacing)));
        // Decade labels are short: log axes can carry about twice as many.
        L.x_ticks = tf.log_x ? log_ticks(tf.x0, tf.x1, 2 * nx) : linear_ticks(tf.x0, tf.x1, nx);
        L.y_ticks = tf.log_y ? log_ticks(tf.y0, tf.y1, 2 * ny) : linear_ticks(tf.y0, tf.y1, ny);
        if (!plot.axes) {
            L.x_ticks.clear(), L.y_ticks.clear();
            break;
        }
        left_margin =
            std::round(kTickLength + 5 + max_label_width(canvas, L.y_ticks, fs) +
                       (plot.y_axis.title.empty() ? 8 : y_title_band(y_title(plot, canvas, bottom - top))));
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

// The legend's geometry: entries in `cols` columns (row by row), spacing shrinking with text smaller than 13
// units (figures on small pages), never growing with larger text (the app's presentation mode). One column
// wider than `wrap_width` (> 0): its long labels on two lines.
struct LegendGeom {
    float pad, sample, sep, row, col_w, col_gap;
    int cols;
    Vec2 size;
    std::vector<std::string> first, second; ///< Per entry: its label's lines (second empty: one line).
    std::vector<float> middle;              ///< Per entry in one column: its middle below the box's top.
};

// `label` cut at a character boundary and ended with "…" so that it is at most `width` wide (labels from
// users' files, say a pinned curve's, can be any length; the figures' own always fit and are kept whole).
std::string elided(const Canvas& canvas, const std::string& label, float fs, float width) {
    if (width <= 0 || canvas.measure_text(label, fs).x <= width) return label;
    // The ends of its characters (UTF-8 lead bytes start them) outside any markup group ("r_{disp}").
    std::vector<std::size_t> ends;
    int depth = 0;
    for (std::size_t k = 1; k <= label.size(); ++k) {
        depth += label[k - 1] == '{' ? 1 : label[k - 1] == '}' ? -1 : 0;
        const bool lead = k == label.size() || (static_cast<unsigned char>(label[k]) & 0xC0) != 0x80;
        if (lead && depth <= 0 && label[k - 1] != '_' && label[k - 1] != '^') ends.push_back(k);
    }
    std::size_t lo = 0, hi = ends.size(); // the longest prefix of `lo` characters that fits
    while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (canvas.measure_text(label.substr(0, ends[mid - 1]) + "…", fs).x <= width)
            lo = mid;
        else
            hi = mid - 1;
    }
    return (lo == 0 ? std::string() : label.substr(0, ends[lo - 1])) + "…";
}

// `max_width` > 0: the box at most that wide, labels too long for it elided.
LegendGeom legend_geom(const Canvas& canvas, const std::vector<Series>& series,
                       const std::vector<std::size_t>& entries, float fs, int cols = 1, float wrap_width = 0,
                       float max_width = 0) {
    const float k = std::min(1.0f, fs / 13.0f);
    LegendGeom g{};
    g.pad = std::round(kLegendPad * k), g.sample = std::round(kLegendSample * k), g.sep = std::round(8 * k);
    g.row = std::round(fs * 1.6f), g.col_gap = std::round(kLegendGap * k);
    g.cols = std::max(1, std::min(cols, static_cast<int>(entries.size())));
    const float max_label = max_width > 0 ? max_width - 2 * g.pad - g.sample - g.sep : 0;
    std::vector<std::string> labels;
    for (std::size_t i : entries) labels.push_back(elided(canvas, series[i].label, fs, max_label));
    float label_w = 0;
    for (const std::string& l : labels) label_w = std::max(label_w, canvas.measure_text(l, fs).x);
    const float label_avail = wrap_width - 2 * g.pad - g.sample - g.sep;
    const bool wrap = g.cols == 1 && wrap_width > 0 && 2 * g.pad + g.sample + g.sep + label_w > wrap_width;
    float y = g.pad * 0.75f;
    if (wrap) label_w = 0;
    for (std::size_t n = 0; n < entries.size(); ++n) {
        FittedText f{fs, labels[n], "", 0};
        if (wrap) {
            f = fit_text(canvas, labels[n], fs, fs, label_avail, true);
            label_w = std::max(label_w, f.width);
        }
        const float h = f.second.empty() ? g.row : g.row + kTitleLeading * fs;
        g.first.push_back(f.first), g.second.push_back(f.second), g.middle.push_back(y + 0.5f * h);
        y += h;
    }
    g.col_w = g.sample + g.sep + label_w;
    const int rows = (static_cast<int>(entries.size()) + g.cols - 1) / g.cols;
    g.size = {
        std::round(2 * g.pad + static_cast<float>(g.cols) * g.col_w +
                   static_cast<float>(g.cols - 1) * g.col_gap),
        std::round(g.cols == 1 ? y + g.pad * 0.75f : g.pad * 0.75f * 2 + g.row * static_cast<float>(rows))};
    return g;
}

// Below the axes: as many columns as fit `width`; one column too wide for it: its long labels on two lines.
LegendGeom legend_below_geom(const Canvas& canvas, const std::vector<Series>& series,
                             const std::vector<std::size_t>& entries, float fs, float width) {
    LegendGeom g = legend_geom(canvas, series, entries, fs, 1);
    if (g.size.x > width) return legend_geom(canvas, series, entries, fs, 1, width);
    for (int c = 2; c <= static_cast<int>(entries.size()); ++c) {
        const LegendGeom more = legend_geom(canvas, series, entries, fs, c);
        if (more.size.x > width) break;
        g = more;
    }
    return g;
}

// Every `stride`-th label of `ticks` such that neighbours keep `gap` units between them (`along`: the
// labels' extent along the axis), the others emptied: labels skip rather than collide.
void thin_labels(std::vector<Tick>& ticks, const std::function<float(const Tick&)>& pos,
                 const std::function<float(const Tick&)>& along, float gap) {
    std::vector<std::size_t> labelled;
    for (std::size_t i = 0; i < ticks.size(); ++i)
        if (!ticks[i].label.empty()) labelled.push_back(i);
    for (std::size_t stride = 1; stride < labelled.size(); ++stride) {
        bool clear = true;
        for (std::size_t j = stride; j < labelled.size() && clear; j += stride) {
            const Tick &a = ticks[labelled[j - stride]], &b = ticks[labelled[j]];
            clear = std::fabs(pos(b) - pos(a)) - 0.5f * (along(a) + along(b)) >= gap;
        }
        if (clear) {
            for (std::size_t j = 0; j < labelled.size(); ++j)
                if (j % stride != 0) ticks[labelled[j]].label.clear();
            return;
        }
    }
    for (std::size_t j = 1; j < labelled.size(); ++j) ticks[labelled[j]].label.clear();
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

float Plot::legend_below_height(const Canvas& canvas) const {
    const auto entries = legend_entries(series_);
    if (entries.empty()) return 0;
    return legend_below_geom(canvas, series_, entries, font_size, bounds_.width()).size.y + kLegendGap;
}

float Plot::legend_band(const Canvas& canvas) const {
    const auto entries = legend_entries(series_);
    if (legend != LegendPosition::Above || entries.empty()) return 0;
    // The rows wrap at the data area's width, which the band hardly changes (only through the y ticks).
    const Rect area = compute_layout(*this, series_, heatmap_, bounds_, canvas).tf.area;
    const float band = above_layout(canvas, series_, entries, font_size, area.width()).size.y + kAboveSpace;
    // No room: rows that would leave the data area less than their own height (and three lines of type) are
    // left out, not drawn over a data area squeezed to nothing (the app's force plot on a 360 x 640 phone).
    return area.height() - band < std::max(band, 3 * font_size) ? 0.0f : band;
}

PlotTransform Plot::draw(Canvas& canvas) const {
    const auto entries = legend_entries(series_);
    const bool has_legend = legend != LegendPosition::None && !entries.empty();
    LegendPlace redraw = LegendPlace::Inside;
    if (has_legend && legend == LegendPosition::Outside)
        return draw_with_legend(canvas, LegendPlace::Right, redraw);
    if (has_legend && legend == LegendPosition::Below)
        return draw_with_legend(canvas, LegendPlace::Below, redraw);
    const Canvas::Mark start = canvas.mark();
    const PlotTransform tf = draw_with_legend(canvas, LegendPlace::Inside, redraw);
    if (redraw == LegendPlace::Inside) return tf;
    // Every place inside the axes covers data: draw the plot again, narrower with the legend right of it,
    // or shorter with the legend below it.
    canvas.rewind(start);
    return draw_with_legend(canvas, redraw, redraw);
}
namespace {

// What drawing a plot carries from one artist to the next.
struct Frame {
    Layout layout;
    Rect bounds;     // the plot's
    float below = 0; // room kept under the x axis title for a legend below the axes
    float band = 0;  // room kept above the axes (and their top axis) for a legend above them
    // The commands drawn in the data area (series onwards): what a legend must not cover.
    Canvas::Mark data_start, data_end;
};

// x of a tick on the x axis and y of a tick on the y axis, on pixel centres so that 1-px lines stay crisp (a
// log axis is read at 1 where the other range starts at or below 0).
float tick_x(const PlotTransform& tf, const Tick& t) {
    return std::floor(tf.to_pixel(t.value, tf.y0 > 0 ? tf.y0 : 1).x) + 0.5f;
}
float tick_y(const PlotTransform& tf, const Tick& t) {
    return std::floor(tf.to_pixel(tf.x0 > 0 ? tf.x0 : 1, t.value).y) + 0.5f;
}

void draw_grid(Canvas& canvas, const Plot& plot, const Layout& L) {
    const PlotTransform& tf = L.tf;
    const Rect& A = tf.area;
    const Stroke major{colors::grid, 1.0f, LineStyle::Solid},
        minor{colors::minor_grid, 1.0f, LineStyle::Solid};
    if (plot.x_axis.grid)
        for (const Tick& t : L.x_ticks) {
            const float x = tick_x(tf, t);
            canvas.line({x, A.y0}, {x, A.y1}, t.major ? major : minor);
        }
    if (plot.y_axis.grid)
        for (const Tick& t : L.y_ticks) {
            const float y = tick_y(tf, t);
            canvas.line({A.x0, y}, {A.x1, y}, t.major ? major : minor);
        }
}

// The heat map's image, where it has all its values.
void draw_heatmap(Canvas& canvas, const HeatMap& hm, const PlotTransform& tf) {
    if (!(hm.nx > 0 && hm.ny > 0 &&
          hm.values.size() >= static_cast<std::size_t>(hm.nx) * static_cast<std::size_t>(hm.ny)))
        return;
    const auto [vlo, vhi] = value_range(hm);
    const Vec2 tl = tf.to_pixel(hm.x0, hm.y1), br = tf.to_pixel(hm.x1, hm.y0);
    canvas.image({tl.x, tl.y, br.x, br.y}, heatmap_image(hm.values.data(), hm.nx, hm.ny, vlo, vhi));
}

void draw_error_bars(Canvas& canvas, const Series& s, Color c, const PlotTransform& tf) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    const Stroke eb{c, 1.2f, LineStyle::Solid};
    for (std::size_t k = 0; k < n && k < s.y_err.size(); ++k) {
        if (!std::isfinite(s.y_err[k])) continue;
        const Vec2 a = tf.to_pixel(s.x[k], s.y[k] - s.y_err[k]), b = tf.to_pixel(s.x[k], s.y[k] + s.y_err[k]);
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.y)) continue;
        canvas.line(a, b, eb);
        canvas.line({a.x - 3.5f, a.y}, {a.x + 3.5f, a.y}, eb);
        canvas.line({b.x - 3.5f, b.y}, {b.x + 3.5f, b.y}, eb);
    }
}

// Each series' error bars, line and markers, in series order; points far outside the data area are left
// out (the caller clips to it).
void draw_series(Canvas& canvas, const std::vector<Series>& series, const PlotTransform& tf) {
    const Rect& A = tf.area;
    const Rect clip_box = {A.x0 - 100, A.y0 - 100, A.x1 + 100, A.y1 + 100};
    for (std::size_t i = 0; i < series.size(); ++i) {
        const Series& s = series[i];
        const Color c = series_color(s, i);
        if (!s.y_err.empty()) draw_error_bars(canvas, s, c, tf);
        if (s.style.draw_line) {
            const Stroke st{c, s.style.line_width, s.style.line};
            for (const auto& run : series_runs(s, tf, clip_box)) canvas.polyline(run, st);
        }
        if (s.style.marker != MarkerShape::None) {
            const MarkerStyle m = series_marker(s, c);
            const std::size_t n = std::min(s.x.size(), s.y.size());
            for (std::size_t k = 0; k < n; ++k) {
                const Vec2 p = tf.to_pixel(s.x[k], s.y[k]);
                if (clip_box.contains(p)) canvas.marker(p, m);
            }
        }
    }
}

// The frame, outward ticks and their labels (those too close to a neighbour left out).
void draw_frame_and_ticks(Canvas& canvas, const Layout& L, float fs) {
    const PlotTransform& tf = L.tf;
    const Rect& A = tf.area;
    const Stroke axis{colors::axis, 1.0f, LineStyle::Solid};
    canvas.stroke_rect({A.x0 + 0.5f, A.y0 + 0.5f, A.x1 - 0.5f, A.y1 - 0.5f}, axis);
    // All tick marks first, then all labels: text and shapes are separate draw batches, and llvmpipe
    // pays per batch (they do not overlap, so the order does not change a pixel).
    for (const Tick& t : L.x_ticks) {
        const float x = tick_x(tf, t);
        canvas.line({x, A.y1}, {x, A.y1 + (t.major ? kTickLength : kTickLength * 0.6f)}, axis);
    }
    for (const Tick& t : L.y_ticks) {
        const float y = tick_y(tf, t);
        canvas.line({A.x0 - (t.major ? kTickLength : kTickLength * 0.6f), y}, {A.x0, y}, axis);
    }
    TextStyle ts;
    ts.size = fs;
    std::vector<Tick> x_ticks = L.x_ticks, y_ticks = L.y_ticks;
    thin_labels(
        x_ticks, [&](const Tick& t) { return tf.to_pixel(t.value, tf.y0 > 0 ? tf.y0 : 1).x; },
        [&](const Tick& t) { return canvas.measure_text(t.label, fs).x; }, 0.5f * fs);
    thin_labels(
        y_ticks, [&](const Tick& t) { return tf.to_pixel(tf.x0 > 0 ? tf.x0 : 1, t.value).y; },
        [&](const Tick& t) { return canvas.measure_text(t.label, fs).y; }, 0.2f * fs);
    for (const Tick& t : x_ticks) {
        if (t.label.empty()) continue;
        ts.halign = HAlign::Center, ts.valign = VAlign::Top;
        canvas.text({tick_x(tf, t), A.y1 + kTickLength + 3}, t.label, ts);
    }
    for (const Tick& t : y_ticks) {
        if (t.label.empty()) continue;
        ts.halign = HAlign::Right, ts.valign = VAlign::Middle;
        canvas.text({A.x0 - kTickLength - 4, tick_y(tf, t)}, t.label, ts);
    }
}

// A title's centre: centred on the data area, moved as little as keeps it within [lo, hi] (small pages).
float centred(float c, float w, float lo, float hi) {
    return w >= hi - lo ? 0.5f * (lo + hi) : std::clamp(c, lo + 0.5f * w, hi - 0.5f * w);
}

// The x title within the plot's width: the title, else its short form, else the shorter of them made as
// small as fits (two plots side by side: a title wider than its plot overlapped its neighbour's and was cut
// off at the window's edges).
void draw_x_title(Canvas& canvas, const Plot& plot, const Frame& fr) {
    const Rect& A = fr.layout.tf.area;
    const float avail = fr.bounds.width() - 4;
    std::string title = plot.x_axis.title;
    FittedText f = fit_text(canvas, title, plot.font_size + 1, plot.font_size, avail, false);
    if (f.width > avail && !plot.x_axis.short_title.empty()) {
        title = plot.x_axis.short_title;
        f = fit_text(canvas, title, plot.font_size + 1, plot.font_size, avail, false);
    }
    if (f.width > avail) f.size *= avail / f.width, f.width = avail;
    TextStyle tt;
    tt.size = f.size, tt.halign = HAlign::Center, tt.valign = VAlign::Bottom;
    canvas.text(
        {centred(0.5f * (A.x0 + A.x1), f.width, fr.bounds.x0, fr.bounds.x1), fr.bounds.y1 - fr.below - 4},
        title, tt);
}

void draw_y_title(Canvas& canvas, const Plot& plot, const Frame& fr) {
    const Rect& A = fr.layout.tf.area;
    const FittedText f = y_title(plot, canvas, A.height());
    TextStyle tt;
    tt.size = f.size, tt.halign = HAlign::Center, tt.valign = VAlign::Top, tt.angle_deg = 90;
    // Longer than the data area (a short plot on a small page): below the panel title, down beside the x
    // tick labels.
    const float cy =
        centred(0.5f * (A.y0 + A.y1), f.width, A.y0 - 0.4f * plot.font_size, fr.bounds.y1 - fr.below);
    canvas.text({fr.bounds.x0 + 4, cy}, f.first, tt);
    if (!f.second.empty()) canvas.text({fr.bounds.x0 + 4 + kTitleLeading * f.size, cy}, f.second, tt);
}

// The panel title, on one or two lines, between the plot's top and the axes (and what is above them).
void draw_panel_title(Canvas& canvas, const Plot& plot, const Frame& fr) {
    const Rect& A = fr.layout.tf.area;
    const FittedText f = panel_title(plot, canvas, fr.bounds);
    TextStyle tt;
    tt.size = f.size, tt.halign = HAlign::Center, tt.valign = VAlign::Middle;
    const float cx = centred(0.5f * (A.x0 + A.x1), f.width, fr.bounds.x0, fr.bounds.x1);
    const float cy = 0.5f * (fr.bounds.y0 + A.y0 - top_axis_band(plot) - fr.band);
    if (f.second.empty()) {
        canvas.text({cx, cy}, plot.title, tt);
    } else {
        canvas.text({cx, cy - 0.5f * kTitleLeading * f.size}, f.first, tt);
        canvas.text({cx, cy + 0.5f * kTitleLeading * f.size}, f.second, tt);
    }
}

// A legend entry's sample centred at height cy from x0 on: its line, else its error bar (`bar` long either
// side), and its marker.
void draw_legend_sample(Canvas& canvas, const Series& s, Color c, float x0, float cy, float sample,
                        float bar) {
    if (s.style.draw_line) canvas.line({x0, cy}, {x0 + sample, cy}, {c, s.style.line_width, s.style.line});
    if (!s.y_err.empty() && !s.style.draw_line)
        canvas.line({x0 + 0.5f * sample, cy - bar}, {x0 + 0.5f * sample, cy + bar},
                    {c, 1.2f, LineStyle::Solid});
    if (s.style.marker != MarkerShape::None) canvas.marker({x0 + 0.5f * sample, cy}, series_marker(s, c));
}

// Legend entries side by side in rows (above_layout's), from `origin` (top left), samples `sample` long.
void draw_legend_rows(Canvas& canvas, const std::vector<Series>& series,
                      const std::vector<std::size_t>& entries, const AboveLayout& above, Vec2 origin,
                      float sample, float fs) {
    const float above_row = std::round(fs * kAboveRow);
    const Canvas::Mark legend_start = canvas.mark();
    TextStyle lt;
    lt.size = fs, lt.valign = VAlign::Middle;
    // Samples first, labels after (fewer draw batches; they do not overlap).
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const Series& s = series[entries[k]];
        draw_legend_sample(canvas, s, series_color(s, entries[k]), origin.x + above.at[k].x,
                           std::floor(origin.y + above.at[k].y + 0.5f * above_row) + 0.5f, sample, 6);
    }
    for (std::size_t k = 0; k < entries.size(); ++k)
        canvas.text({origin.x + above.at[k].x + sample + 8, origin.y + above.at[k].y + 0.5f * above_row},
                    series[entries[k]].label, lt);
    canvas.add_region("legend", {origin.x, origin.y, origin.x + above.size.x, origin.y + above.size.y},
                      legend_start);
}

// The legend above the axes: entries side by side in rows as wide as the data area, in the band kept for it.
void draw_legend_above(Canvas& canvas, const Plot& plot, const std::vector<Series>& series,
                       const std::vector<std::size_t>& entries, float sample, const Frame& fr) {
    const Rect& A = fr.layout.tf.area;
    const float fs = plot.font_size;
    const AboveLayout above = above_layout(canvas, series, entries, fs, A.width());
    const Vec2 origin{A.x0, A.y0 - top_axis_band(plot) - fr.band};
    draw_legend_rows(canvas, series, entries, above, origin, sample, fs);
}

// The eight places for a legend box of `size` inside the data area: corners (top right, top left, bottom
// right, bottom left), then the middles of the edges (top, bottom, right, left).
Rect box_inside(const Rect& A, Vec2 size, int k) {
    const float m = kLegendMargin, w = size.x, h = size.y;
    const float left = A.x0 + m, right = A.x1 - m - w, cx = std::round(0.5f * (A.x0 + A.x1 - w));
    const float top = A.y0 + m, bottom = A.y1 - m - h, cy = std::round(0.5f * (A.y0 + A.y1 - h));
    static constexpr int kX[] = {2, 0, 2, 0, 1, 1, 2, 0}, kY[] = {0, 0, 2, 2, 0, 2, 1, 1};
    const float x0 = kX[k] == 0 ? left : (kX[k] == 1 ? cx : right);
    const float y0 = kY[k] == 0 ? top : (kY[k] == 1 ? cy : bottom);
    return Rect{x0, y0, x0 + w, y0 + h};
}

// The index (box_inside) of a fixed corner; the top right for the others.
int corner_of(LegendPosition legend) {
    switch (legend) {
    case LegendPosition::TopLeft:
        return 1;
    case LegendPosition::BottomRight:
        return 2;
    case LegendPosition::BottomLeft:
        return 3;
    default:
        return 0;
    }
}

// How much of what is drawn in the data area `r` covers: lines count by their segments.
std::size_t covered(const Canvas& canvas, const Frame& fr, const Rect& r) {
    const auto& cmds = canvas.display_list().commands;
    std::size_t n = 0;
    for (std::size_t k = fr.data_start.commands; k < fr.data_end.commands; ++k) {
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
}

// Where a boxed legend goes. Right of the axes or below them when drawn for that place; else inside, where
// the plot is asked to be drawn again with it right of or below the axes (`again`) when every place inside
// covers data.
enum class Again { no, right, below };
struct BoxSpot {
    Rect box;
    Again again = Again::no;
};

// `below_size`: the size of the legend below the axes, where it may go there.
BoxSpot legend_spot(const Canvas& canvas, const Plot& plot, bool outside, bool below_place, Vec2 size,
                    const std::optional<Vec2>& below_size, bool has_heatmap, const Frame& fr) {
    const Rect& A = fr.layout.tf.area;
    const float w = size.x, h = size.y;
    BoxSpot spot{box_inside(A, size, corner_of(plot.legend))};
    // Below the axes: where it fits (a third of the plot's height; 45% for text below 13 units, on small
    // pages), else inside.
    const bool below_fits =
        plot.legend_below && below_size->x <= fr.bounds.width() &&
        below_size->y + kLegendGap <= fr.bounds.height() * (plot.font_size < 13 ? 0.45f : 1.0f / 3);
    if (outside) {
        const float x0 = A.x1 + (has_heatmap ? kColorBarSpace : 0.0f) + kLegendGap;
        spot.box = {x0, A.y0, x0 + w, A.y0 + h};
    } else if (below_place) {
        const float x0 = std::clamp(std::round(0.5f * (A.x0 + A.x1 - w)), fr.bounds.x0, fr.bounds.x1 - w);
        spot.box = {x0, fr.bounds.y1 - h, x0 + w, fr.bounds.y1};
    } else if (plot.legend == LegendPosition::Best) {
        std::size_t least = std::numeric_limits<std::size_t>::max();
        for (int k = 0; k < 8 && least > 0; ++k)
            if (const std::size_t n = covered(canvas, fr, box_inside(A, size, k)); n < least)
                least = n, spot.box = box_inside(A, size, k);
        // None is free: the plot is drawn again with the legend outside, unless that would take more than a
        // third of the plot's width (a small panel): then below it where allowed, else the place covering
        // least.
        if (least > 0 && w + 2 * kLegendGap <= fr.bounds.width() / 3)
            spot.again = Again::right;
        else if (least > 0 && below_fits)
            spot.again = Again::below;
    } else if (below_fits && covered(canvas, fr, spot.box) > 0) {
        spot.again = Again::below; // the figure's corner covers data on this page
    }
    return spot;
}

// The boxed legend: its background and border, each entry's sample, then the labels (on one or two lines).
void draw_legend_box(Canvas& canvas, const std::vector<Series>& series,
                     const std::vector<std::size_t>& entries, const LegendGeom& lg, const Rect& box,
                     float fs) {
    const float row = lg.row, sample = lg.sample, pad = lg.pad;
    const Canvas::Mark legend_start = canvas.mark();
    canvas.fill_rect(box, colors::white.with_alpha(0.92f));
    canvas.stroke_rect({box.x0 + 0.5f, box.y0 + 0.5f, box.x1 - 0.5f, box.y1 - 0.5f},
                       {Color::hex(0xB0B0B0), 1.0f, LineStyle::Solid});
    TextStyle lt;
    lt.size = fs, lt.valign = VAlign::Middle;
    // Samples first, labels after (fewer draw batches; they do not overlap).
    const float y_first = box.y0 + pad * 0.75f + 0.5f * row;
    auto entry_at = [&](std::size_t n) {
        const int c = static_cast<int>(n) % lg.cols, r = static_cast<int>(n) / lg.cols;
        return Vec2{box.x0 + pad + static_cast<float>(c) * (lg.col_w + lg.col_gap),
                    lg.cols == 1 ? box.y0 + lg.middle[n] : y_first + static_cast<float>(r) * row};
    };
    for (std::size_t n = 0; n < entries.size(); ++n) {
        const Series& s = series[entries[n]];
        const Vec2 at = entry_at(n);
        draw_legend_sample(canvas, s, series_color(s, entries[n]), at.x, std::floor(at.y) + 0.5f, sample,
                           std::min(6.0f, 0.45f * row));
    }
    for (std::size_t n = 0; n < entries.size(); ++n) {
        const Vec2 at = entry_at(n);
        if (lg.second[n].empty()) {
            canvas.text({at.x + sample + lg.sep, at.y}, lg.first[n], lt);
        } else {
            canvas.text({at.x + sample + lg.sep, at.y - 0.5f * kTitleLeading * fs}, lg.first[n], lt);
            canvas.text({at.x + sample + lg.sep, at.y + 0.5f * kTitleLeading * fs}, lg.second[n], lt);
        }
    }
    canvas.add_region("legend", box, legend_start);
}

} // namespace

// The steps, matplotlib style (each artist by its own function): the layout with room for the legend, the
// data area (grid, heat map, underlays, series, overlays), the frame and ticks, the titles, the top axis and
// colour bar, then the legend (which looks at what the data area holds to find its place).
PlotTransform Plot::draw_with_legend(Canvas& canvas, LegendPlace place, LegendPlace& redraw) const {
    redraw = LegendPlace::Inside;
    const bool outside = place == LegendPlace::Right;
    const std::vector<std::size_t> entries = legend_entries(series_);
    // The geometry below the axes only where the legend may go there: it measures every label for each
    // column count, and the app draws its plots every frame.
    std::optional<LegendGeom> below_geom;
    if (place == LegendPlace::Below || legend_below)
        below_geom = legend_below_geom(canvas, series_, entries, font_size, bounds_.width());
    LegendGeom lg =
        place == LegendPlace::Below ? *below_geom : legend_geom(canvas, series_, entries, font_size);
    // A legend beside the axes that would take more than half the panel's width or more than its height (the
    // app's top view on a 360 x 640 phone) leaves the data area no room and spills over the next panel: it is
    // left out (the app's help overlay names every symbol), as compare mode leaves it out.
    const bool no_room = outside && (lg.size.x > 0.5f * bounds_.width() || lg.size.y > bounds_.height());
    Frame fr;
    fr.bounds = bounds_;
    fr.below = place == LegendPlace::Below ? lg.size.y + kLegendGap : 0.0f;
    fr.band = legend_band(canvas);
    fr.layout = compute_layout(*this, series_, heatmap_, bounds_, canvas,
                               outside && !no_room ? lg.size.x + 2 * kLegendGap : 0.0f, fr.below, fr.band);
    const PlotTransform& tf = fr.layout.tf;
    const Rect& A = tf.area;

    canvas.fill_rect(A, colors::white);
    canvas.push_clip(A);
    if (axes) draw_grid(canvas, *this, fr.layout);
    if (heatmap_) draw_heatmap(canvas, *heatmap_, tf);
    for (const auto& fn : underlays_) fn(canvas, tf);
    fr.data_start = canvas.mark();
    draw_series(canvas, series_, tf);
    PlotTransform otf = tf;
    otf.first_data_command = fr.data_start.commands;
    for (const auto& fn : overlays_) fn(canvas, otf);
    canvas.pop_clip();
    for (const auto& fn : unclipped_overlays_) fn(canvas, otf);
    canvas.add_region("data", A, fr.data_start);
    fr.data_end = canvas.mark();

    if (axes) draw_frame_and_ticks(canvas, fr.layout, font_size);
    if (axes && !x_axis.title.empty()) draw_x_title(canvas, *this, fr);
    if (axes && !y_axis.title.empty()) draw_y_title(canvas, *this, fr);
    if (!title.empty()) draw_panel_title(canvas, *this, fr);
    if (top_scale > 0) draw_top_axis(canvas, *this, tf, bounds_);
    if (heatmap_ && heatmap_->color_bar) draw_colorbar(canvas, A, *heatmap_, font_size, font_size + 1);

    if (legend == LegendPosition::None || entries.empty() || no_room) return tf;
    if (legend == LegendPosition::Above) {
        if (fr.band > 0) draw_legend_above(canvas, *this, series_, entries, lg.sample, fr);
        return tf;
    }
    // Inside the axes, the box no wider than they are: labels too long for that (a user's, say a pinned
    // curve's from a session file) are elided. The figures' own labels always fit, so nothing else changes.
    if (!outside && place != LegendPlace::Below && lg.size.x > A.width() - 2 * kLegendMargin)
        lg = legend_geom(canvas, series_, entries, font_size, 1, 0, A.width() - 2 * kLegendMargin);
    // A box inside the axes taller than they are (the app's ratio plot on a 360 x 640 phone) would hang below
    // them over the ticks: left out, like a legend beside the axes that has no room.
    if (!outside && place == LegendPlace::Inside && lg.size.y > A.height()) return tf;
    std::optional<Vec2> below_size;
    if (below_geom) below_size = below_geom->size;
    const BoxSpot spot = legend_spot(canvas, *this, outside, place == LegendPlace::Below, lg.size, below_size,
                                     heatmap_ && heatmap_->color_bar, fr);
    if (spot.again != Again::no) {
        redraw = spot.again == Again::right ? LegendPlace::Right : LegendPlace::Below;
        return tf;
    }
    draw_legend_box(canvas, series_, entries, lg, spot.box, font_size);
    return tf;
}

void draw_color_bar(Canvas& canvas, const Rect& area, const HeatMap& hm, float font_size) {
    draw_colorbar(canvas, area, hm, font_size, font_size + 1);
}

Vec2 legend_rows(Canvas& canvas, const std::vector<Series>& series, Vec2 origin, float width, float font_size,
                 bool draw) {
    const std::vector<std::size_t> entries = legend_entries(series);
    const AboveLayout above = above_layout(canvas, series, entries, font_size, width);
    if (draw && !entries.empty())
        draw_legend_rows(canvas, series, entries, above, origin,
                         legend_geom(canvas, series, entries, font_size).sample, font_size);
    return above.size;
}

} // namespace fv::gfx
