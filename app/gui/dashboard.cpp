#include "dashboard.hpp"

namespace fv::app {

DashboardPanels dashboard_panels(const LiveSim& sim, const ViewState& view,
                                 const std::optional<RatioCurves>& curves, bool busy, LowerPanel lower,
                                 const RatioOverlay& overlay, MechanismBase* mechanism) {
    MechanismBase once;
    DashboardPanels panels;
    panels.top_view = top_view_panel(sim, view);
    panels.force = force_panel_live(sim, curves, view.rewind);
    switch (lower) {
    case LowerPanel::map:
        panels.lower = map_panel_live(sim, curves, busy);
        break;
    case LowerPanel::loop:
        panels.lower = loop_panel_live(sim, view.rewind);
        break;
    case LowerPanel::why:
        panels.lower = mechanism_panel_live(sim, mechanism ? *mechanism : once, view.rewind);
        break;
    case LowerPanel::curves:
        panels.lower = ratio_panel_live(curves, busy, overlay);
        break;
    }
    return panels;
}

} // namespace fv::app
