// The app's picture without its controls: the top view above, the force plot and one more panel (r_x(zeta),
// the map, the hysteresis loop or the mechanism) side by side below. The window, the headless app and the
// animation export paint it here, from panels the live builders (fv/live_panels.hpp) made.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"

namespace fv::app {

struct DashboardLayout {
    gfx::Rect top_view, force, ratio;
};
// The top view above, the force and lower panels side by side below; in an upright area (taller than 1.1
// times its width) the three stacked.
DashboardLayout layout_dashboard(const gfx::Rect& area);

struct DashboardPanels {
    PanelData top_view, force, lower;
};
// Each panel's data <-> pixel mapping (the mouse reads positions through them).
struct DashboardTransforms {
    gfx::PlotTransform top_view, force, ratio;
};

// The panel with its text, lines and markers k times larger (presentation mode).
PanelData enlarged(PanelData panel, float k);

// Paints the three panels into their places in `area`, each enlarged by `style`.
DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const DashboardPanels& panels,
                                    float style = 1);

} // namespace fv::app
