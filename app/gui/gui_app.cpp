#include "gui_app.hpp"

#include "app_state.hpp"
#include "controls.hpp"
#include "dashboard.hpp"
#include "measured_data.hpp"
#include "ratio_worker.hpp"
#include "script.hpp"

#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figures.hpp"
#include "fv/gfx/png.hpp"
#include "fv/live_sim.hpp"
#include "fv/units.hpp"

#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

namespace fv::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr float kPanelWidth = 340;

std::string png_string(const gfx::Image& img) {
    const auto v = gfx::encode_png(img);
    return {reinterpret_cast<const char*>(v.data()), v.size()};
}

std::string trace_csv(const LiveSim& sim) {
    std::string s = "tau,Px,Py,Tx,Ty,z,Fx,Fy\n";
    char buf[256];
    for (const LiveSample& h : sim.history()) {
        std::snprintf(buf, sizeof buf, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", h.tau, h.P.x(),
                      h.P.y(), h.T.x(), h.T.y(), (h.P - h.T).norm(), h.F.x(), h.F.y());
        s += buf;
    }
    return s;
}

// Mouse over the top view: wheel zooms, left-drag pans (and stops following the drift). Over the force plot
// a tooltip reads the values under the cursor.
void handle_mouse(ViewState& view, const LiveSim& sim, const DashboardTransforms& t) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    const gfx::Vec2 m{io.MousePos.x, io.MousePos.y};
    const auto& tv = t.top_view;
    if (tv.area.contains(m)) {
        if (io.MouseWheel != 0) view.zoom = std::clamp(view.zoom * std::pow(0.85, io.MouseWheel), 0.05, 20.0);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
            const double sx = (tv.x1 - tv.x0) / tv.area.width(), sy = (tv.y1 - tv.y0) / tv.area.height();
            view.pan += Vec2(-io.MouseDelta.x * sx, io.MouseDelta.y * sy);
        }
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
            view = ViewState{1, {0, 0}, true, view.trail_periods};
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
}

struct Percentiles {
    double p50, p95, p99, max;
};
Percentiles percentiles(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    auto at = [&](double q) {
        return v[std::min(v.size() - 1,
                          static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5))];
    };
    return {at(0.5), at(0.95), at(0.99), v.back()};
}

} // namespace

int run_gui(const GuiOptions& o) {
    gfx::ContextOptions co;
    co.backend = o.headless ? gfx::Backend::Headless : gfx::Backend::Window;
    co.width = o.width;
    co.height = o.height;
    co.title = "frictionviz — friction reduction by in-plane vibrations";
    RenderSession session(co);
    gfx::GpuContext& ctx = session.context();
    auto* window = o.headless ? nullptr : dynamic_cast<gfx::WindowContext*>(&ctx);

    const bool scripted = o.frames > 0 || o.bench_frames > 0;
    const Script script = o.script.empty() ? Script{} : load_script(o.script);

    ImGuiContext* imgui_ctx = ImGui::CreateContext(&session.fonts().atlas());
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    const float ratio = ctx.pixel_ratio();
    io.FontDefault = session.fonts().font_for(15);
    io.FontGlobalScale = 1.0f / ratio; // the atlas is rasterised at ratio x size
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0;
    if (window) ImGui_ImplGlfw_InitForOpenGL(window->native(), true);

    AppState app(o.model, o.params, o.amplitude_um, o.frequency_khz, o.data);
    OpenDataDialog dialog;

    UiEdits queued;
    DashboardTransforms transforms{};
    auto last = Clock::now();
    std::vector<double> frame_ms;
    double phase_ms[3] = {0, 0, 0}; // simulation + UI, dashboard layout, GL drawing (bench only)
    int shots = 0, exports = 0;
    const int total_frames = o.bench_frames > 0 ? o.bench_frames : o.frames;

    for (int frame = 0; total_frames == 0 || frame < total_frames; ++frame) {
        const auto t0 = Clock::now();
        if (window) {
            window->poll_events();
            if (window->should_close()) break;
            // Files dropped onto the window: the last one is shown (one data set at a time).
            for (std::string& path : window->take_dropped_paths()) queued.load_data = std::move(path);
        }
        // 1. All edits of the previous frame (panel, keys, mouse) and of the script land here, at one point.
        queued.merge(script_edits(script, frame, app.ui()));
        if (o.bench_frames > 0) {
            // Benchmark: a slider dragged every frame, the worst case for the UI thread.
            Params p = app.ui().params;
            p.zeta = 0.1 + 0.8 * (0.5 + 0.5 * std::sin(frame * 0.05));
            queued.params = p;
        }
        const AppState::Actions act = app.sync(queued, scripted);
        if (act.quit) break;

        // 2. Simulation time: a fixed dtau per step, the number of steps from the elapsed time (fixed 1/60 s
        //    per frame in scripted runs, so that they are reproducible).
        const auto now = Clock::now();
        const double dt = scripted || o.headless
                              ? 1.0 / 60
                              : std::min(0.1, std::chrono::duration<double>(now - last).count());
        last = now;
        app.advance(dt);
        queued = UiEdits{};
        if (scripted && o.bench_frames == 0) app.worker().wait_idle(); // reproducible pictures

        // 3. Draw: the dashboard through the canvas, the panel through ImGui on top.
        const gfx::Size fb = ctx.framebuffer_size();
        const gfx::Vec2 logical{static_cast<float>(fb.width) / ratio, static_cast<float>(fb.height) / ratio};
        if (window) ImGui_ImplGlfw_NewFrame();
        io.DisplaySize = ImVec2(logical.x, logical.y);
        io.DisplayFramebufferScale = ImVec2(ratio, ratio);
        if (scripted || !window) {
            io.DeltaTime = 1.0f / 60;
            io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX); // no stray hover: window and headless see the same
        }
        ImGui::NewFrame();
        const UiState& ui = app.ui();
        const LiveSim& sim = app.sim();
        const auto curves = app.worker().latest();
        const bool busy = app.worker().busy();
        queued.merge(draw_controls(ui, sim, curves, busy, kPanelWidth, logical.y, dialog));
        queued.merge(keyboard_edits(ui));
        handle_mouse(app.ui().view, sim, transforms);
        ImGui::Render();

        const auto t_ui = Clock::now();
        gfx::Canvas& canvas = session.canvas();
        canvas.begin(logical, ratio, gfx::colors::white);
        transforms = paint_dashboard(canvas, {kPanelWidth + 6, 4, logical.x - 4, logical.y - 4}, sim, ui.view,
                                     curves, busy, ui.show_map, {ui.data ? &*ui.data : nullptr, ui.vv_m_s});
        const auto t_build = Clock::now();
        canvas.end();
        session.imgui().render(*ImGui::GetDrawData());
        ctx.gl().Finish();
        const auto t_gl = Clock::now();

        const bool last_frame = total_frames > 0 && frame + 1 == total_frames;
        if (act.screenshot || (last_frame && !o.screenshot.empty())) {
            const std::string path = last_frame && !o.screenshot.empty()
                                         ? o.screenshot
                                         : "frictionviz-screenshot-" + std::to_string(++shots) + ".png";
            const std::string err = write_file_atomic(path, png_string(ctx.read_pixels()));
            app.ui().status = err.empty() ? "wrote " + path : err;
            if (!err.empty()) std::fprintf(stderr, "frictionviz: %s\n", err.c_str());
        }
        if (act.export_csv) {
            const std::string path = "frictionviz-trace-" + std::to_string(++exports) + ".csv";
            const std::string err = write_file_atomic(path, trace_csv(sim));
            app.ui().status =
                err.empty() ? "wrote " + path + " (the trail shown: tau,Px,Py,Tx,Ty,z,Fx,Fy)" : err;
        }
        ctx.present();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        if (o.bench_frames > 0) {
            frame_ms.push_back(ms);
            using ms_d = std::chrono::duration<double, std::milli>;
            phase_ms[0] += ms_d(t_ui - t0).count();
            phase_ms[1] += ms_d(t_build - t_ui).count();
            phase_ms[2] += ms_d(t_gl - t_build).count();
        }
        // Without vsync (e.g. Xvfb) do not spin: about 60 frames per second are plenty.
        if (window && !scripted && ms < 15)
            std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(15 - ms));
    }

    if (window) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(imgui_ctx);
    if (!frame_ms.empty()) {
        // The first frames build shaders and caches: report the steady part.
        std::vector<double> steady(frame_ms.begin() + std::min<std::size_t>(5, frame_ms.size() - 1),
                                   frame_ms.end());
        const Percentiles p = percentiles(steady);
        std::printf("frame time over %zu frames at %dx%d (%s, a slider changing every frame): p50 %.1f ms, "
                    "p95 %.1f ms, "
                    "p99 %.1f ms, max %.1f ms\n",
                    steady.size(), o.width, o.height, ctx.describe().c_str(), p.p50, p.p95, p.p99, p.max);
        const double n = static_cast<double>(frame_ms.size());
        std::printf(
            "mean per frame: simulation + controls %.1f ms, dashboard layout %.1f ms, GL drawing %.1f ms\n",
            phase_ms[0] / n, phase_ms[1] / n, phase_ms[2] / n);
    }
    return 0;
}

} // namespace fv::app
