#include "dashboard_input.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace fv::app {

// Wheel zooms, left-drag pans (and stops following the drift), double-click resets the view. Over the force
// plot a tooltip reads the values under the cursor.
UiEdits dashboard_mouse_edits(const ViewState& view, const LiveSim& sim, const DashboardTransforms& t) {
    UiEdits e;
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return e;
    const gfx::Vec2 m{io.MousePos.x, io.MousePos.y};
    // Compare mode's two top views share one view: the mouse over either zooms and pans both.
    for (const gfx::PlotTransform* tv : {&t.top_view, &t.top_view_b}) {
        if (!tv->area.contains(m)) continue;
        if (io.MouseWheel != 0) e.zoom = view.zoom * std::pow(0.85, io.MouseWheel);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
            const double sx = (tv->x1 - tv->x0) / tv->area.width(),
                         sy = (tv->y1 - tv->y0) / tv->area.height();
            e.pan = Vec2(view.pan + Vec2(-io.MouseDelta.x * sx, io.MouseDelta.y * sy));
        }
        e.reset_view = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
    }
    const auto& fp = t.force;
    if (fp.area.contains(m) && !sim.history().empty()) {
        const double tau = fp.x0 + (m.x - fp.area.x0) / fp.area.width() * (fp.x1 - fp.x0);
        const auto& h = sim.history();
        auto it = std::lower_bound(h.begin(), h.end(), tau,
                                   [](const LiveSample& s, double v) { return s.tau < v; });
        if (it != h.end()) {
            ImGui::SetTooltip("τ = %.3f\nF_x = %+.4f\nF_y = %+.4f\n|F| = %.4f", it->tau, it->F.x(), it->F.y(),
                              it->F.norm());
        }
    }
    return e;
}

} // namespace fv::app
