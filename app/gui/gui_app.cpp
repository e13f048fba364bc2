#include "gui_app.hpp"

#include "app_state.hpp"
#include "controls.hpp"
#include "dashboard.hpp"
#include "dashboard_input.hpp"
#include "frame_stats.hpp"
#include "help_overlay.hpp"
#include "platform.hpp"
#include "script.hpp"

#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace fv::app {
namespace {

using Clock = std::chrono::steady_clock;
using Ms = std::chrono::duration<double, std::milli>;
constexpr float kPanelWidth = 340;
// Presentation mode: type, lines and markers this much larger (the panel's font 22 px instead of 15).
constexpr float kPresentationScale = 1.4f;

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

LowerPanel lower_panel(const UiState& ui) {
    return ui.show_mechanism ? LowerPanel::mechanism
           : ui.show_loop    ? LowerPanel::loop
           : ui.show_map     ? LowerPanel::map
                             : LowerPanel::curves;
}

// The ImGui context for the app's lifetime: fonts from the session's atlas (rasterised at the pixel ratio),
// input from the platform.
class ImGuiScope {
  public:
    ImGuiScope(RenderSession& session, Platform& platform) : platform_(platform) {
        ctx_ = ImGui::CreateContext(&session.fonts().atlas());
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.FontDefault = session.fonts().font_for(15);
        io.FontGlobalScale = 1.0f / session.pixel_ratio(); // the atlas is rasterised at ratio x size
        ImGui::StyleColorsLight();
        ImGuiStyle& style = ImGui::GetStyle();
        style.WindowRounding = 0;
        // Slider handles never hide the value printed across the slider: a thin, translucent grab.
        style.GrabMinSize = 5;
        style.Colors[ImGuiCol_SliderGrab].w = 0.45f;
        style.Colors[ImGuiCol_SliderGrabActive].w = 0.6f;
        platform_.connect_imgui();
    }
    ~ImGuiScope() {
        platform_.disconnect_imgui();
        ImGui::DestroyContext(ctx_);
    }
    ImGuiScope(const ImGuiScope&) = delete;
    ImGuiScope& operator=(const ImGuiScope&) = delete;

  private:
    Platform& platform_;
    ImGuiContext* ctx_;
};

// The files a frame's actions ask for; the status line says what was written or why not.
void write_requested_files(const AppState::Actions& act, const std::string& screenshot_path,
                           const RenderSession& session, AppState& app, int& shots, int& exports) {
    auto report = [&](const std::string& path, const std::string& err, const char* what) {
        app.ui().status = err.empty() ? "wrote " + path + what : err;
        if (!err.empty()) std::fprintf(stderr, "frictionviz: %s\n", err.c_str());
    };
    if (act.screenshot || !screenshot_path.empty()) {
        const std::string path = !screenshot_path.empty()
                                     ? screenshot_path
                                     : "frictionviz-screenshot-" + std::to_string(++shots) + ".png";
        report(path, session.save_png(path), "");
    }
    if (act.export_csv) {
        const std::string path = "frictionviz-trace-" + std::to_string(++exports) + ".csv";
        report(path, write_file_atomic(path, trace_csv(app.sim())),
               " (the trail shown: tau,Px,Py,Tx,Ty,z,Fx,Fy)");
    }
    if (!act.save_session.empty())
        report(act.save_session, write_session(act.save_session, session_of(app.ui())), " (session)");
}

} // namespace

int run_gui(const GuiOptions& o) {
    PlatformOptions po;
    po.width = o.width;
    po.height = o.height;
    po.scale = o.scale;
    po.title = "frictionviz — friction reduction by in-plane vibrations";
    const std::unique_ptr<Platform> platform = make_platform(o.platform, po);
    RenderSession session(platform->context(), platform->pixel_ratio());
    ImGuiScope imgui(session, *platform);

    const bool scripted = o.frames > 0 || o.bench_frames > 0;
    const bool real_time = platform->interactive() && !scripted; // else a fixed 1/60 s per frame, no mouse
    const Script script = o.script.empty() ? Script{} : load_script(o.script);
    AppState app(o.start, o.data, o.session_file);
    FileDialogs dialog;
    ExportDialog export_dialog;
    AnimationExportJob animation(o.animation_exporter);
    UiEdits queued;
    DashboardTransforms transforms{};
    FrameStats stats;
    int shots = 0, exports = 0;
    const int total_frames = o.bench_frames > 0 ? o.bench_frames : o.frames;
    auto last = Clock::now();

    for (int frame = 0; total_frames == 0 || frame < total_frames; ++frame) {
        const auto t0 = Clock::now();
        PlatformEvents events = platform->poll();
        if (events.close) break;
        // 1. All edits of the previous frame (panel, keys, mouse, drops) and of the script land here, at one
        //    point. A drop shows the last file (one data set at a time).
        if (!events.dropped.empty()) queued.load_data = std::move(events.dropped.back());
        if (events.help_key) queued.show_help = !app.ui().show_help;
        queued.merge(script_edits(script, frame, app.ui()));
        if (o.bench_frames > 0) queued.params = bench_params(app.ui().params, frame);
        const AppState::Actions act = app.sync(queued, scripted);
        if (act.quit) break;
        if (o.on_state) o.on_state(app.ui());
        queued = UiEdits{};
        if (act.open_export_dialog) export_dialog.open_requested = true;
        if (act.export_animation) {
            app.ui().status = animation.start(*act.export_animation);
            if (scripted) animation.wait(); // the file is there before the next frame
        }
        if (auto status = animation.poll()) app.ui().status = *status;

        // 2. Simulation time: fixed steps, their number from the elapsed wall time (a fixed 1/60 s per frame
        //    when not real time, so that scripted runs are reproducible).
        const auto now = Clock::now();
        app.advance(real_time ? std::min(0.1, std::chrono::duration<double>(now - last).count()) : 1.0 / 60);
        last = now;
        if (scripted && o.bench_frames == 0) app.worker().wait_idle(); // reproducible pictures

        // 3. Draw: the dashboard through the canvas, the panel through ImGui on top; the panel's and the
        //    mouse's edits are queued for the next frame.
        const gfx::Vec2 logical = session.logical_page();
        const bool present = app.ui().presentation;
        const float panel_w = present ? 450 : kPanelWidth;
        ImGui::GetIO().FontDefault = session.fonts().font_for(present ? 22 : 15);
        platform->imgui_new_frame(logical);
        if (!real_time) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX); // window == headless pixels
        ImGui::NewFrame();
        const UiState& ui = app.ui();
        // Without threads (the browser) the curves are computed here, a few milliseconds a frame.
        app.worker().run_slice(std::chrono::milliseconds(6));
        const auto curves = app.worker().latest();
        const bool busy = app.worker().busy();
        queued.merge(draw_controls(ui, app.sim(), curves, busy, panel_w, logical.y, dialog));
        queued.export_animation = draw_export_dialog(export_dialog, ui.speed, animation.running());
        queued.merge(keyboard_edits(ui));
        handle_dashboard_mouse(app.ui().view, app.sim(), transforms);
        if (ui.show_help && !draw_help_overlay(true, {panel_w, 0, logical.x, logical.y}))
            queued.show_help = false;
        ImGui::Render();
        const auto t_ui = Clock::now();
        gfx::Canvas& canvas = session.canvas();
        canvas.begin(logical, session.pixel_ratio(), gfx::colors::white);
        transforms = paint_dashboard(canvas, {panel_w + 6, 4, logical.x - 4, logical.y - 4}, app.sim(),
                                     ui.view, curves, busy, lower_panel(ui),
                                     {ui.data ? &*ui.data : nullptr, ui.vv_m_s, &ui.pins},
                                     present ? kPresentationScale : 1.0f);
        const auto t_layout = Clock::now();
        canvas.end();
        session.imgui().render(*ImGui::GetDrawData());
        session.context().gl().Finish();
        const auto t_gl = Clock::now();

        // 4. Files, then show the frame.
        const bool last_frame = total_frames > 0 && frame + 1 == total_frames;
        write_requested_files(act, last_frame ? o.screenshot : std::string(), session, app, shots, exports);
        platform->present();
        const double ms = Ms(Clock::now() - t0).count();
        if (o.bench_frames > 0)
            stats.record(ms, Ms(t_ui - t0).count(), Ms(t_layout - t_ui).count(), Ms(t_gl - t_layout).count());
            // Without vsync (e.g. Xvfb) do not spin: about 60 frames per second are plenty. (The web platform
            // paces its frames in present(), where it hands control back to the browser.)
#if !defined(__EMSCRIPTEN__)
        if (real_time && ms < 15) std::this_thread::sleep_for(Ms(15 - ms));
#endif
    }
    const gfx::Size fb = session.context().framebuffer_size();
    stats.print(fb.width, fb.height, session.pixel_ratio(), session.context().describe());
    return 0;
}

} // namespace fv::app
