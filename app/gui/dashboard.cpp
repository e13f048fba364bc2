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
    case LowerPanel::curves: {
        RatioOverlay o = overlay;
        o.b = on_plots;
        panels.lower = ratio_panel_live(curves, busy, o);
        break;
    }
    }
    // The panels that show A alone say so beside B.
    if (b && lower != LowerPanel::curves) panels.lower.title = "A: " + panels.lower.title;
    return panels;
}

} // namespace fv::app
