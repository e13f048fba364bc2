#include "figures/column_layout.hpp"

#include "figure_painter.hpp"

#include "fv/gfx/display_list.hpp"
#include "fv/gfx/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <variant>
#include <vector>

namespace fv::app {
namespace {

constexpr float kInset = 8, kTitleGap = 14, kPanelGap = 12; // units, as paint_figure's at full size

// The height of a row of small multiples, one map a row (two a row leave each map some 70 units, 50 pt,
// between its tick labels and the colour bar: their titles collide): a panel's height for up to three maps,
// then the rows share three panels' height, down to kColumnMinMapRow of the width (a family of six maps
// stays within a page).
constexpr float kColumnMinMapRow = 0.4f;
float map_row_height(std::size_t maps, float width) {
    const float panel = kColumnPanelAspect * width;
    return std::round(
        std::max(kColumnMinMapRow * width, panel * std::min(1.0f, 3.0f / static_cast<float>(maps))));
}

// A panel's legend in the column: below its axes unless it has none.
bool legend_below(const PanelData& panel) {
    return panel.legend != Legend::none;
}

// A panel's first height in a column `width` wide: kColumnPanelAspect of the width, taller where its titles
// and top axis leave the data area less than kColumnDataAspect of its width (fig19's panels), or where its
// axes have equal aspect (top views) as tall as its data's ranges need at the full width, up to a square (a
// panel that short would draw a top view as a strip, its arrows and labels crowded into its middle); and its
// legend below.
constexpr float kColumnDataAspect = 0.45f;
float first_height(gfx::Canvas& canvas, const PanelData& panel, float width) {
    float h = std::round(kColumnPanelAspect * width);
    const gfx::Rect cell{0, 0, width, h};
    // The ranges the axes fit before equal aspect widens one of them to the data area's shape.
    gfx::Plot plain = panel_plot(panel, cell);
    plain.equal_aspect = false;
    const gfx::PlotTransform tf = plain.layout(canvas);
    const double need = panel.equal_aspect ? tf.area.width() * (tf.y1 - tf.y0) / (tf.x1 - tf.x0)
                                           : kColumnDataAspect * tf.area.width();
    if (std::isfinite(need) && need > tf.area.height())
        h = std::min(width, std::round(h + static_cast<float>(need) - tf.area.height()));
    return legend_below(panel) ? h + panel_plot(panel, cell).legend_below_height(canvas) : h;
}

void draw_panel(gfx::Canvas& canvas, const PanelData& panel, const gfx::Rect& cell) {
    gfx::Plot plot = panel_plot(panel, cell);
    if (legend_below(panel)) plot.legend = gfx::LegendPosition::Below;
    plot.draw(canvas);
}

// Whether what was recorded since `from` is crowded: two texts overlap by more than a unit or stand side by
// side, at the same height, less than 2 units apart (labels run together: "π/45π/4"), or a label in the
// data area lies on an arrow or a marker (its glyphs' box, 2 units inside its line box) — the layout tests'
// measures — or found no free place near what it names (a leader line to it: LabelPlacer).
bool crowded(const gfx::Canvas& canvas, const gfx::Canvas::Mark& from) {
    const gfx::DisplayList& list = canvas.display_list();
    std::vector<gfx::Rect> boxes;
    for (std::size_t k = from.commands; k < list.commands.size(); ++k)
        if (const auto* t = std::get_if<gfx::dl::Text>(&list.commands[k]))
            boxes.push_back(gfx::text_bounds(*t, canvas.fonts()));
    for (std::size_t a = 0; a < boxes.size(); ++a)
        for (std::size_t b = a + 1; b < boxes.size(); ++b)
            if (std::min(boxes[a].x1, boxes[b].x1) - std::max(boxes[a].x0, boxes[b].x0) > -2 &&
                std::min(boxes[a].y1, boxes[b].y1) - std::max(boxes[a].y0, boxes[b].y0) > 1)
                return true;
    for (std::size_t r = from.regions; r < list.regions.size(); ++r) {
        const gfx::Region& data = list.regions[r];
        if (data.role == "leader") return true;
        if (data.role != "data") continue;
        for (std::size_t k = data.first; k < data.last; ++k) {
            const auto* t = std::get_if<gfx::dl::Text>(&list.commands[k]);
            if (!t) continue;
            const gfx::Rect l = gfx::text_bounds(*t, canvas.fonts()),
                            glyphs{l.x0 + 2, l.y0 + 2, l.x1 - 2, l.y1 - 2};
            for (std::size_t j = data.first; j < data.last; ++j) {
                const gfx::dl::Command& c = list.commands[j];
                if ((std::holds_alternative<gfx::dl::Arrow>(c) ||
                     std::holds_alternative<gfx::dl::Marker>(c)) &&
                    gfx::command_touches(c, glyphs, canvas.fonts(), 0))
                    return true;
            }
        }
    }
    return false;
}

// The panel's height: its first height, grown by a tenth of the width at a time, up to the width more, until
// it is not crowded (fig. 4 along the sliding line: nine rows of arrows up a time axis, each with
// its instant's label, need a panel about as tall as wide). Each try is drawn and rewound; where none is
// free, the first height.
float panel_height(gfx::Canvas& canvas, const PanelData& panel, float width) {
    const float first = first_height(canvas, panel, width), step = std::round(0.1f * width);
    for (float h = first; h <= first + width + 0.5f; h += step) {
        const gfx::Canvas::Mark start = canvas.mark();
        draw_panel(canvas, panel, {0, 0, width, h});
        const bool collide = crowded(canvas, start);
        canvas.rewind(start);
        if (!collide) return h;
    }
    return first;
}

} // namespace

ColumnLayout column_layout(gfx::Canvas& canvas, const FigureData& fig, float width) {
    ColumnLayout l;
    const float title_end = paint_title(canvas, fig.title, {0, 0, width, 1}, kColumnTitleFactor, false);
    const float x0 = kInset, x1 = width - kInset;
    float y = std::round(title_end + kTitleGap);
    if (fig.columns > 0 && !fig.panels.empty()) {
        const std::size_t maps = fig.panels.size();
        const float h = static_cast<float>(maps) * map_row_height(maps, x1 - x0) +
                        grid_margin_height(canvas, fig, x1 - x0, 1);
        l.cells.push_back({x0, y, x1, y + h});
        y += h;
    } else {
        for (const PanelData& panel : fig.panels) {
            const float h = panel_height(canvas, panel, x1 - x0);
            if (!l.cells.empty()) y += kPanelGap;
            l.cells.push_back({x0, y, x1, y + h});
            y += h;
        }
    }
    l.page = {width, std::round(y + kInset)};
    return l;
}

void paint_column_figure(gfx::Canvas& canvas, const FigureData& fig, const ColumnLayout& layout) {
    paint_title(canvas, fig.title, {0, 0, layout.page.x, 1}, kColumnTitleFactor);
    if (fig.columns > 0 && !fig.panels.empty()) {
        FigureData grid = fig;
        grid.columns = 1;
        paint_grid(canvas, grid, layout.cells.front(), 1);
        return;
    }
    for (std::size_t i = 0; i < fig.panels.size(); ++i) draw_panel(canvas, fig.panels[i], layout.cells[i]);
}

} // namespace fv::app
