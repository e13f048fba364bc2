// A figure laid out for a printed journal column (render --page column: 3.3 in wide with 8 pt tick labels,
// about 330 logical units at full-size text). Side by side, two panels get some 160 units each: their
// legends cover the data or are elided to "…", tick labels and labels collide. So in a column every panel
// spans the width, one above another, each kColumnPanelAspect of the width tall plus its legend, which goes
// below its axes (LegendPosition::Below); small multiples take one map a row (shorter rows from four maps
// on); the figure's title is at kColumnTitleFactor of its size (the caption states the rest). The page is as
// tall as that takes (column_figure_height), not a fixed aspect.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"

#include <vector>

namespace fv::app {

inline constexpr float kColumnPanelAspect = 0.6f; // a panel's height over the column's width, legend aside
inline constexpr float kColumnTitleFactor = 0.9f; // titles 19.8 units (12 pt), one line down to 14.4

// Where a column `width` wide puts `fig`: its page (width x as tall as the figure takes) and one cell per
// panel (one for the grid of small multiples), top to bottom. `canvas` must be recording, on a page at least
// 2 x `width` tall: a panel's height is chosen by drawing it (each try rewound; nothing stays).
struct ColumnLayout {
    gfx::Vec2 page{0, 0};
    std::vector<gfx::Rect> cells;
};
ColumnLayout column_layout(gfx::Canvas& canvas, const FigureData& fig, float width);

// Draws `fig` as `layout` places it, on a canvas begun at layout.page.
void paint_column_figure(gfx::Canvas& canvas, const FigureData& fig, const ColumnLayout& layout);

} // namespace fv::app
