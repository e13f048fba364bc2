// Draws a computed figure (core/figure_data) onto a canvas: one code path for headless PNGs and the window.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"

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

gfx::Color ink_color(Ink ink, std::size_t series_index);

} // namespace fv::app
