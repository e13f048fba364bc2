#pragma once
// A small scientific 2D plot (ImPlot is not packaged): axes with nice ticks, grid, titles with
// Greek and sub/superscripts, several styled series, error bars, legend, clipping, fixed or
// auto-fit ranges, log axes and an equal-aspect mode. Draws onto a Canvas inside a pixel rectangle.
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/types.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fv::gfx {

/// Colour-blind-friendly palette (Okabe & Ito), cycled by series index.
Color palette(std::size_t index);

struct Axis {
    std::string title; ///< Markup allowed, e.g. "friction ratio r_{x}".
    /// Drawn instead of `title` where that does not fit the plot's width (x axis): the same meaning, fewer
    /// words. Empty: the title, smaller.
    std::string short_title;
    bool log = false; ///< Log10 scale; non-positive values are skipped.
    bool grid = true;
    std::optional<double> min, max; ///< Fixed ends; unset ends are auto-fitted with a little padding.
    void set_range(double lo, double hi) { min = lo, max = hi; }
};

struct SeriesStyle {
    std::optional<Color> color; ///< Default: palette(series index).
    float line_width = 2.0f;
    LineStyle line = LineStyle::Solid;
    bool draw_line = true;
    MarkerShape marker = MarkerShape::None;
    float marker_size = 7.0f;
    bool marker_filled = true; ///< false: outline in the series colour on white.
};

struct Series {
    std::string label; ///< Empty: not in the legend.
    std::vector<double> x, y;
    std::vector<double> y_err; ///< Optional symmetric error bars (same length as y).
    SeriesStyle style;
};

/// A grid of values shown as a viridis image under the series, with a colour bar at the right.
struct HeatMap {
    std::vector<double> values; ///< nx*ny, row-major, row 0 at y0 (bottom). NaN cells are transparent.
    int nx = 0, ny = 0;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1; ///< Data extent of the grid (outer cell edges).
    std::optional<double> vmin, vmax;      ///< Colour range; default: the finite min/max.
    std::string label;                     ///< Colour bar title (markup allowed).
    /// false: no colour bar (and no room for one): small multiples on one scale draw a single bar for all of
    /// them (draw_color_bar).
    bool color_bar = true;
};

/// The room a colour bar takes right of the data area: the bar, its tick labels and its title.
inline constexpr float kColorBarSpace = 90;

/// Best: the first of the corners and edge middles inside the axes (top right, top left, bottom right,
/// bottom left, top, bottom, right, left) whose box touches nothing drawn in the data area (series samples
/// and segments, markers, error bars, overlays and their text); outside the axes, right of them, when none is
/// free (in a plot too small for that, the place covering least). Outside: always there (e.g. for an animated
/// plot, whose free corner moves). Above: between the title and the axes, the entries side by side in rows as
/// wide as the data area (a small animated plot: nothing it draws can run under its legend). Below: always
/// below the axes, under the x axis title, the plot shorter by its height (legend_below's place, taken
/// whatever it covers inside: a printed journal column, whose panels are too small for a box on their data).
enum class LegendPosition { None, Best, TopRight, TopLeft, BottomRight, BottomLeft, Outside, Above, Below };

/// Data <-> pixel mapping of a laid-out plot.
struct PlotTransform {
    Rect area; ///< Data area in canvas pixels.
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    bool log_x = false, log_y = false;
    Vec2 to_pixel(double x, double y) const;
    /// Pixels per data unit along x (linear axes; used e.g. for radii in equal-aspect plots).
    float pixels_per_unit_x() const { return static_cast<float>(area.width() / (x1 - x0)); }
    /// While overlays draw: the index of the first display-list command of the data area (series onwards),
    /// so that an overlay can place its labels against what is already drawn.
    std::size_t first_data_command = 0;
};

class Plot {
  public:
    explicit Plot(const Rect& bounds) : bounds_(bounds) {}

    std::string title;
    Axis x_axis, y_axis;
    /// A second x axis along the top showing top_scale * x (e.g. a velocity in m/s beside a ratio); none
    /// when top_scale is 0.
    double top_scale = 0;
    std::string top_title;
    bool equal_aspect = false; ///< One data unit spans the same pixels in x and y (linear axes).
    /// false: a drawing, not a plot: no grid, frame, ticks or axis titles; the data area takes their room.
    bool axes = true;
    LegendPosition legend = LegendPosition::Best;
    /// Where the legend's place inside the axes covers data and it cannot go right of them (a third of the
    /// plot's width at most): below the axes, under the x axis title, the plot shorter, instead of the place
    /// covering least. Only where its height fits a third of the plot's (45% with text below 13 units: small
    /// pages); for a fixed corner too. There it takes as many columns as fit the plot's width; one column too
    /// wide for it has its long entries on two lines.
    bool legend_below = false;
    /// Tick labels; titles are a little larger. Below 13 (small pages) the legend's spacing and the ticks'
    /// spacing shrink with it. Titles too long for the plot shrink (down to font_size), then wrap to two
    /// lines; tick labels too close to a neighbour are left out.
    float font_size = 13;

    Series& add_series(std::string label, std::vector<double> x, std::vector<double> y,
                       SeriesStyle style = {});
    /// Shows a heat map (at most one per plot; linear axes). Unset axis ends fit its extent exactly.
    void set_heatmap(HeatMap h) { heatmap_ = std::move(h); }
    /// Extra drawing in data space after the series, clipped to the data area; `clipped` false: not clipped
    /// (markers on the frame, labels), drawn after the clipped ones. Both count as data for the legend.
    void add_overlay(std::function<void(Canvas&, const PlotTransform&)> fn, bool clipped = true) {
        (clipped ? overlays_ : unclipped_overlays_).push_back(std::move(fn));
    }
    /// Drawing behind the series (after the grid and heat map, clipped to the data area): shading.
    void add_underlay(std::function<void(Canvas&, const PlotTransform&)> fn) {
        underlays_.push_back(std::move(fn));
    }

    /// Computes ranges, ticks and margins (needs the canvas for text metrics), with the legend inside.
    PlotTransform layout(const Canvas& canvas) const;
    /// The height a legend below the axes takes in this plot (its box and the gap above it; 0 without
    /// labelled series): what LegendPosition::Below makes the plot shorter by.
    float legend_below_height(const Canvas& canvas) const;
    /// Draws the plot; returns the data <-> pixel mapping it used (narrower than layout() when the legend
    /// went outside). Records the regions "data" and "legend" (display_list.hpp).
    PlotTransform draw(Canvas& canvas) const;

  private:
    Rect bounds_;
    std::vector<Series> series_;
    std::optional<HeatMap> heatmap_;
    std::vector<std::function<void(Canvas&, const PlotTransform&)>> overlays_, unclipped_overlays_;
    enum class LegendPlace { Inside, Right, Below };
    PlotTransform draw_with_legend(Canvas& canvas, LegendPlace place, LegendPlace& redraw) const;
    /// Height of the band above the axes that a LegendPosition::Above legend takes (0 for other legends).
    float legend_band(const Canvas& canvas) const;
    std::vector<std::function<void(Canvas&, const PlotTransform&)>> underlays_;
};

/// For small multiples, whose plots leave out their own (HeatMap::color_bar false): the colour bar of `hm`
/// right of `area` (as a plot draws it beside its data area: from area.x1 on, as tall as `area`), its text at
/// `font_size`.
void draw_color_bar(Canvas& canvas, const Rect& area, const HeatMap& hm, float font_size = 13);

/// For small multiples, whose plots leave out their own legends: the legend of `series` (each labelled one
/// an entry: its line, marker and label) side by side in rows at most `width` wide, from `origin` (top
/// left), as a LegendPosition::Above legend. Returns its size; draws only when `draw`.
Vec2 legend_rows(Canvas& canvas, const std::vector<Series>& series, Vec2 origin, float width,
                 float font_size = 13, bool draw = true);

} // namespace fv::gfx
