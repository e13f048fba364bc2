#pragma once
// The demo page: two plots (r_x(ζ) curves; an equal-aspect trajectory) and a strip showing
// every primitive, line style, marker and text feature. Used by fvrender_demo.
#include "fv/gfx/canvas.hpp"

namespace fv::demo {

void draw_demo_page(gfx::Canvas& canvas);
/// Second page: a heat map with colour bar and a log-log plot.
void draw_heatmap_page(gfx::Canvas& canvas);

} // namespace fv::demo
