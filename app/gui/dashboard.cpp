#include "dashboard.hpp"

namespace fv::app {

DashboardPanels dashboard_panels(const LiveSim& sim, const ViewState& view,
                                 const std::optional<RatioCurves>& curves, bool busy, LowerPanel lower,
                                 const RatioOverlay& overlay, MechanismBase* mechanism,
                                 const CompareSetup* b) {
    MechanismBase once;
    DashboardPanels panels;
    CompareOverlay on_plots;
    if (b) {
        panels.top_view_b = top_view_panel(b->sim, b->view, "B");
        on_plots = {&b->sim, b->curves ? &*b->curves : nullptr, b->busy};
    }
    panels.top_view = top_view_panel(sim, view, b ? "A" : nullptr);
    panels.force = force_panel_live(sim, curves, view.rewind, on_plots);
    RatioOverlay o = overlay;
    o.b = on_plots;
    panels.lower = lower_panel_live(lower, sim, curves, busy, o, mechanism ? *mechanism : once, view.rewind);
    return panels;
}

} // namespace fv::app
