// The app's picture: top view (P, T, spring, z_ss circle, arrows, fading trails), live force plot and the
// r_x(zeta) plot. Built as figure panels and painted by the figure painter, so the window, the headless
// render and the screenshots share one drawing path.
#pragma once

#include "ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"
#include "fv/live_sim.hpp"

#include <optional>

namespace fv::app {

struct ViewState {
    double zoom = 1;    // > 1 shows less
    Vec2 pan{0, 0};     // data units, added to the followed centre
    bool follow = true; // keep P's drift in view
    double trail_periods = 1.5;
};

struct DashboardLayout {
    gfx::Rect top_view, force, ratio;
};

DashboardLayout layout_dashboard(const gfx::Rect& area);

PanelData top_view_panel(const LiveSim& sim, const ViewState& view);
PanelData force_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves);
PanelData ratio_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy);

struct DashboardTransforms {
    gfx::PlotTransform top_view, force, ratio;
};

// The map panel with the current (zeta, theta) marked.
PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy);

// show_map: the lower-right panel shows the (zeta, theta) map instead of the r_x(zeta) curves.
DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const LiveSim& sim,
                                    const ViewState& view, const std::optional<RatioCurves>& curves,
                                    bool busy, bool show_map = false);

} // namespace fv::app
