// The app's picture: top view (P, T, spring, z_ss circle, arrows, fading trails), live force plot and the
// r_x(zeta) plot. Built as figure panels and painted by the figure painter, so the window, the headless
// render and the screenshots share one drawing path.
#pragma once

#include "ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"
#include "fv/live_sim.hpp"
#include "fv/measurements.hpp"

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
// What the ratio plot shows besides the model: measured points and the physical scale of zeta.
struct RatioOverlay {
    const MeasurementSet* data = nullptr; // measured r_x(zeta), or none
    double vv_m_s = 0;                    // v_v = 2 pi f A; > 0 adds the v_b scale to the axis title
};

// The zeta range the ratio plot spans: [0, 3], wider when measured points lie further out.
double ratio_zeta_max(const MeasurementSet* data);

PanelData ratio_panel_live(const std::optional<RatioCurves>& curves, bool busy,
                           const RatioOverlay& overlay = {});

struct DashboardTransforms {
    gfx::PlotTransform top_view, force, ratio;
};

// The map panel with the current (zeta, theta) marked.
PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy);

// show_map: the lower-right panel shows the (zeta, theta) map instead of the r_x(zeta) curves.
DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const LiveSim& sim,
                                    const ViewState& view, const std::optional<RatioCurves>& curves,
                                    bool busy, bool show_map = false, const RatioOverlay& overlay = {});

} // namespace fv::app
