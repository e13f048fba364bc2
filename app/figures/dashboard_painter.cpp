#include "figures/dashboard_painter.hpp"

#include "figures/figure_painter.hpp"

namespace fv::app {

namespace {

DashboardLayout layout_one(const gfx::Rect& a) {
    // An upright area (the app's pictures below its panel on a phone): the three one above the other, each
    // the full width, rather than two plots side by side half as wide.
    if (a.height() > 1.1f * a.width()) {
        const float s1 = a.y0 + a.height() * 0.40f, s2 = a.y0 + a.height() * 0.70f;
        return {{a.x0, a.y0, a.x1, s1 - 4}, {a.x0, s1 + 4, a.x1, s2 - 4}, {a.x0, s2 + 4, a.x1, a.y1}, {}};
    }
    const float split = a.y0 + a.height() * 0.6f;
    const float mid = (a.x0 + a.x1) / 2;
    return {{a.x0, a.y0, a.x1, split - 4},
            {a.x0, split + 4, mid - 4, a.y1},
            {mid + 4, split + 4, a.x1, a.y1},
            {}};
}

} // namespace

DashboardLayout layout_dashboard(const gfx::Rect& a, bool compare) {
    DashboardLayout l = layout_one(a);
    if (!compare) return l;
    // A's and B's top views share the top view's place, the same size each, 8 px apart.
    const gfx::Rect t = l.top_view;
    if (t.height() > t.width()) {
        const float mid = (t.y0 + t.y1) / 2;
        l.top_view = {t.x0, t.y0, t.x1, mid - 4}, l.top_view_b = {t.x0, mid + 4, t.x1, t.y1};
    } else {
        const float mid = (t.x0 + t.x1) / 2;
        l.top_view = {t.x0, t.y0, mid - 4, t.y1}, l.top_view_b = {mid + 4, t.y0, t.x1, t.y1};
    }
    return l;
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
    const DashboardLayout l = layout_dashboard(area, panels.top_view_b.has_value());
    DashboardTransforms t;
    t.top_view = paint_panel(canvas, enlarged(panels.top_view, style), l.top_view);
    if (panels.top_view_b)
        t.top_view_b = paint_panel(canvas, enlarged(*panels.top_view_b, style), l.top_view_b);
    t.force = paint_panel(canvas, enlarged(panels.force, style), l.force);
    t.ratio = paint_panel(canvas, enlarged(panels.lower, style), l.ratio);
    return t;
}

} // namespace fv::app
