#include "figures/dashboard_painter.hpp"

#include "figures/figure_painter.hpp"

namespace fv::app {

DashboardLayout layout_dashboard(const gfx::Rect& a) {
    // An upright area (the app's pictures below its panel on a phone): the three one above the other, each
    // the full width, rather than two plots side by side half as wide.
    if (a.height() > 1.1f * a.width()) {
        const float s1 = a.y0 + a.height() * 0.40f, s2 = a.y0 + a.height() * 0.70f;
        return {{a.x0, a.y0, a.x1, s1 - 4}, {a.x0, s1 + 4, a.x1, s2 - 4}, {a.x0, s2 + 4, a.x1, a.y1}};
    }
    const float split = a.y0 + a.height() * 0.6f;
    const float mid = (a.x0 + a.x1) / 2;
    return {
        {a.x0, a.y0, a.x1, split - 4}, {a.x0, split + 4, mid - 4, a.y1}, {mid + 4, split + 4, a.x1, a.y1}};
}

PanelData enlarged(PanelData panel, float k) {
    if (k == 1) return panel;
    panel.text_scale *= k;
    for (SeriesData& x : panel.series) x.width *= k;
    for (SegmentData& x : panel.segments) x.width *= k;
    for (ArrowData& x : panel.arrows) x.width *= k;
    for (CircleData& x : panel.circles) x.width *= k;
    for (PointData& x : panel.points) x.size *= k;
    return panel;
}

DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const DashboardPanels& panels,
                                    float style) {
    const DashboardLayout l = layout_dashboard(area);
    DashboardTransforms t;
    t.top_view = paint_panel(canvas, enlarged(panels.top_view, style), l.top_view);
    t.force = paint_panel(canvas, enlarged(panels.force, style), l.force);
    t.ratio = paint_panel(canvas, enlarged(panels.lower, style), l.ratio);
    return t;
}

} // namespace fv::app
