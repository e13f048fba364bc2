// What the app's dashboard shows: the live panels (fv/live_panels.hpp) for the simulation, the view and the
// chosen lower panel, painted by the figures layer (figures/dashboard_painter.hpp).
#pragma once

#include "lower_panel.hpp"

#include "figures/dashboard_painter.hpp"

#include "fv/live_panels.hpp"
#include "fv/param_ranges.hpp"

#include <optional>

namespace fv::app {

// What the mouse can set (and a session file and a share link may hold), zoom factor and each pan
// coordinate: kZoomRange and kPanRange of the shared table (fv/param_ranges.hpp).

// Compare mode's setup B as the dashboard draws it: its simulation, its view (A's, with B's frame), its
// curves.
struct CompareSetup {
    const LiveSim& sim;
    ViewState view;
    const std::optional<RatioCurves>& curves;
    bool busy = false;
};

// The three panels: top view and force at the view's moment, and the lower panel asked for.
// mechanism: the base kept between frames (nullptr: computed for this call). b: compare mode's setup B (its
// top view beside A's, its force trace and r_x point on the shared plots; the map, loop and why panels are
// A's).
DashboardPanels dashboard_panels(const LiveSim& sim, const ViewState& view,
                                 const std::optional<RatioCurves>& curves, bool busy,
                                 LowerPanel lower = LowerPanel::curves, const RatioOverlay& overlay = {},
                                 MechanismBase* mechanism = nullptr, const CompareSetup* b = nullptr);

} // namespace fv::app
