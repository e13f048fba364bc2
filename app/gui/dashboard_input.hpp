// The mouse over the dashboard: wheel zoom and drag pan in the top view, a value tooltip over the force plot.
#pragma once

#include "dashboard.hpp"

#include "fv/live_sim.hpp"

namespace fv::app {

// Reads ImGui's mouse state (logical units); does nothing while ImGui wants the mouse.
void handle_dashboard_mouse(ViewState& view, const LiveSim& sim, const DashboardTransforms& t);

} // namespace fv::app
