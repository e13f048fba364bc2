// Draws a computed figure (core/figure_data) onto a canvas: one code path for headless PNGs and the window.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"

#include <string>

namespace fv::app {

// Lays the panels out inside `bounds` under the figure title: one panel fills it; three panels (the scene)
// put the top view on the left and the two plots stacked on the right.
// On a page smaller than 640x400 units all of the figure's text and its spacing shrink with the page (a
// journal's one-column figure, ~250 pt wide), by page_text_factor: the smaller of width / 640 and height /
// 400, at least kSmallestTextFactor (tick labels and legends 13 x 0.6 = 7.8 units at 320x240, the smallest
// page).
// `text_factor` > 0 replaces page_text_factor (a printed page: render --page lays a figure out on a small
// logical page whose text must print at full size).
void paint_figure(gfx::Canvas& canvas, const FigureData& fig, const gfx::Rect& bounds, float text_factor = 0);
constexpr float kSmallestTextFactor = 0.6f;
float page_text_factor(const gfx::Rect& page);

// One panel inside `bounds` (used by the app's own layouts too). Returns its data <-> pixel mapping.
// `legend_below`: gfx::Plot::legend_below (figures, whose pages may be narrow; the app's panels keep their
// legends inside).
gfx::PlotTransform paint_panel(gfx::Canvas& canvas, const PanelData& panel, const gfx::Rect& bounds,
                               bool legend_below = false);

// The plot paint_panel draws (its legend, titles, series and the overlays of its shapes, markers and labels),
// to draw or to measure; it refers to `panel`, which must outlive it.
gfx::Plot panel_plot(const PanelData& panel, const gfx::Rect& bounds, bool legend_below = false);

// The figure's title centred at the top of `bounds`, within its width: at 22 units where it fits, else
// smaller down to 16, else on two lines broken after the ", ", "; " or ": " that balances them best (as
// large as both fit, at most 22). All three sizes times `factor` (page_text_factor). Returns where the title
// ends; `draw` false: only that, nothing drawn.
float paint_title(gfx::Canvas& canvas, const std::string& title, const gfx::Rect& bounds, float factor,
                  bool draw = true);

// Small multiples (FigureData::columns, a family of maps): the panels on a grid, row by row, sharing their
// axes as matplotlib's supxlabel/supylabel label them: one x title under the grid, one y title left of it,
// none on the panels. The cells are placed so that every data area has the same size and they line up in
// rows and columns whatever each panel's title takes (a long one wraps on a small page): each panel's
// margins are measured (its layout, nothing drawn) and every row (column) gets the largest of its panels'.
// Right of the grid one colour bar on the panels' shared scale, as tall as their data areas; below it one
// legend naming each labelled line or mark of any panel once. Text at `factor` (page_text_factor).
void paint_grid(gfx::Canvas& canvas, const FigureData& fig, const gfx::Rect& body, float factor);
// The height paint_grid keeps under the grid `width` wide: the shared x title and the legend.
float grid_margin_height(gfx::Canvas& canvas, const FigureData& fig, float width, float factor);

gfx::Color ink_color(Ink ink, std::size_t series_index);

} // namespace fv::app
