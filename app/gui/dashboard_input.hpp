// The mouse over the dashboard: wheel zoom and drag pan in the top view, a value tooltip over the force plot.
#pragma once

#include "dashboard.hpp"
#include "ui_state.hpp"

#include "fv/live_sim.hpp"

namespace fv::app {

// Reads ImGui's mouse state (logical units) and returns the view edits it asks for (applied by
// AppState::sync with every other edit); none while ImGui wants the mouse. Shows the force plot's tooltip.
UiEdits dashboard_mouse_edits(const ViewState& view, const LiveSim& sim, const DashboardTransforms& t);

} // namespace fv::app
