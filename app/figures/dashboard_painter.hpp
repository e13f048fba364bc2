// The app's picture without its controls: the top view above, the force plot and one more panel (r_x(zeta),
// the map, the hysteresis loop or the mechanism) side by side below. The window, the headless app and the
// animation export paint it here, from panels the live builders (fv/live_panels.hpp) made.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"

#include <optional>

namespace fv::app {

struct DashboardLayout {
    gfx::Rect top_view, force, ratio;
    gfx::Rect top_view_b; // compare mode: setup B's top view beside A's (empty otherwise)
};
// The top view above, the force and lower panels side by side below; in an upright area (taller than 1.1
// times its width) the three stacked. compare: the top view's place split in two, A's and B's side by side
// (one above the other where that place is upright).
DashboardLayout layout_dashboard(const gfx::Rect& area, bool compare = false);

struct DashboardPanels {
    PanelData top_view, force, lower;
    std::optional<PanelData> top_view_b; // compare mode: setup B's top view
};
// Each panel's data <-> pixel mapping (the mouse reads positions through them).
struct DashboardTransforms {
    gfx::PlotTransform top_view, force, ratio;
    gfx::PlotTransform top_view_b; // compare mode (an empty area otherwise)
};

// The panel with its text, lines and markers k times larger (presentation mode).
PanelData enlarged(PanelData panel, float k);

// Paints the three panels into their places in `area`, each enlarged by `style`.
DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const DashboardPanels& panels,
                                    float style = 1);

} // namespace fv::app
