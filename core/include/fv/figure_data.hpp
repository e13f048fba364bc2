// The numbers behind a figure, as drawable panels (series, segments, marks) and tables. No drawing here:
// the render layer maps these onto plots, the CLI writes the tables as CSV next to the PNG.
#pragma once

#include "fv/figures.hpp"
#include "fv/paper_scheme.hpp"
#include "fv/sweep.hpp"
#include "fv/vec2.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fv {

// Colours by meaning; the renderer owns the actual palette.
// body: P (blue); tip: T (vermilion); pull: the asperity sticks (green); slip: it slips (reddish purple).
// setup_b: the app's compare mode marks what belongs to setup B in it (setup A's in body's blue).
enum class Ink { automatic, body, tip, spring, pull, force, magnitude, rigid, black, slip, setup_b };
enum class Dash { solid, dashed, dotted };
enum class Mark { none, circle, square, triangle, diamond, cross };

struct SeriesData {
    std::string label; // empty: not in the legend
    std::vector<double> x, y;
    Ink ink = Ink::automatic;
    Dash dash = Dash::solid;
    Mark mark = Mark::none;
    float width = 2;
    float opacity = 1;         // < 1: faded (older parts of a trail)
    std::vector<double> y_err; // symmetric error bars (measured data); width 0 draws markers only
    int palette = -1;          // Ink::automatic: this palette entry (-1: the series' index)
    float mark_size = 0;       // 0: the renderer's default (the map's cell marks are smaller, to fit a cell)
    bool labels_off = false;   // no label may touch the line (the top view's body outline, small round P)
};

struct SegmentData {
    Vec2 a, b;
    Ink ink = Ink::spring;
    Dash dash = Dash::solid;
    float width = 1.5f;
    std::string label;     // drawn beside the segment,
    float label_at = 0.5f; // this far along from a to b,
    int label_side = 0; // on this side: +1 left of a->b (on screen), -1 right, 0 away from the marked points
};

struct PointData {
    Vec2 at;
    Ink ink = Ink::black;
    Mark mark = Mark::circle;
    std::string label; // drawn beside the point,
    float size = 9;
    int label_dx = 0, label_dy = 0; // on this side (+1 right / below on screen, -1 left / above; 0: away from
                                    // the middle of all marked points)
    // The label is left out where every place for it lies on text, a marker or an arrow, or crosses two
    // lines (a small panel: the setup picture's words on a phone).
    bool optional = false;
};

struct ArrowData {
    Vec2 from, to; // data coordinates
    Ink ink = Ink::black;
    std::string label; // drawn beyond the head,
    float width = 2.5f;
    int label_dy = 0;  // or centred above (-1) or below (+1) it on screen (arrows along one line)
    float opacity = 1; // < 1: faded (the why panel's instants behind the live arrows)
};

struct CircleData {
    Vec2 center;
    double radius = 1;
    Ink ink = Ink::spring;
    Dash dash = Dash::dotted;
    float width = 1.2f;
};

// Values on a regular grid, drawn as a colour map with a colour bar.
struct HeatmapData {
    std::vector<double> values; // nx * ny, row-major, row 0 at y0
    int nx = 0, ny = 0;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1; // outer cell edges
    std::string label;                     // colour bar title
    std::optional<double> vmin, vmax;      // the colour scale's ends; unset: the values' finite min, max
    bool color_bar = true;                 // false: none beside this panel (small multiples draw one)
};

// A shaded interval of the x axis over the whole height (e.g. the times the tip slips).
struct BandData {
    double x0 = 0, x1 = 0;
    Ink ink = Ink::tip;
    float opacity = 0.15f;
};

// Where a panel's legend goes (the painter maps it to the render layer's placement).
enum class Legend {
    best,     // a free place inside the axes, else outside
    none,     // no legend
    top_left, // inside, in that corner
    top_right,
    bottom_left,
    bottom_right,
    outside, // right of the axes
    above,   // between the title and the axes, in rows
};

struct PanelData {
    std::string title, x_title, y_title; // markup: r_{x} subscript, Greek as UTF-8
    std::string x_title_short; // drawn where x_title does not fit the panel's width (empty: x_title, smaller)
    bool equal_aspect = false;
    bool axes = true;   // false: a drawing (the experiment's picture): no frame, ticks, grid or axis titles
    bool log_x = false; // a logarithmic x axis (x_min > 0)
    std::optional<double> x_min, x_max, y_min, y_max;
    std::vector<SeriesData> series;
    std::vector<SegmentData> segments;
    std::vector<PointData> points;
    std::vector<CircleData> circles;
    std::vector<ArrowData> arrows;
    std::optional<HeatmapData> heatmap;
    std::vector<BandData> bands; // behind the series
    Legend legend = Legend::best;
    float text_scale = 1; // all of the panel's text (the app's presentation mode)
    // A second x axis along the top: top value = top_scale * x (fig19: v_b in m/s beside zeta); 0: none.
    double top_scale = 0;
    std::string top_title;
};

// A table written next to the PNG: "<id><suffix>.csv".
struct TableData {
    std::string suffix;             // "" for the main table
    std::vector<SweepPoint> ratios; // ratio rows (model,i,theta_deg,...), or
    std::vector<Sample> trace;      // trace rows (tau,Px,...), or
    std::string text;               // a ready-made table (the map's theta*(zeta) curve)
    // Trace rows of a steady period: the solver's status for it (the worse of the two for an overlay).
    SteadyStatus status = SteadyStatus::converged;
};

struct FigureData {
    std::string id, title;
    std::vector<PanelData> panels; // laid out side by side
    // > 0: small multiples (a family of maps): the panels on a grid of this many columns, row by row, their
    // heat maps on one colour scale drawn once beside the grid, their legends merged into one below it.
    int columns = 0;
    std::vector<TableData> tables;
};

// Computes everything a figure shows. Ratio curves are spread over all cores.
FigureData compute_figure(const FigureSpec& spec, int threads = 0);

// The suffixes of the tables compute_figure(spec) will give ("" for ID.csv, "-ratio", "-best-angle", "-b"),
// known without computing anything, so that `render` can check every file it will write before it starts.
std::vector<std::string> table_suffixes(const FigureSpec& spec);

// The map figure's panel in steps, for a caller that spreads the work over time (the browser's ratio worker
// computes a few cells per frame): the grid's points, not yet computed (sweep_grid order: theta, then zeta
// fastest), each to be computed in order with map_cell(spec, points, k) (a cell may start from the cells
// before it in its theta row: fv::ode_map_cell), then the panel from the computed points (and the
// theta*(zeta) table when best_table is given). compute_figure on a map spec is these three in one go (rows
// spread over the cores), so both give the same panel. A cell equals steady_ratio(Model::dahl,
// point.params, map_options(spec)) within the map's tolerance.
std::vector<SweepPoint> map_points(const MapFigure& spec);
SteadyOptions map_options(const MapFigure& spec);
SteadyResult map_cell(const MapFigure& spec, const std::vector<SweepPoint>& points, std::size_t k);
PanelData map_panel_of(const MapFigure& spec, const std::vector<SweepPoint>& rows,
                       std::string* best_table = nullptr, int threads = 0);

} // namespace fv
