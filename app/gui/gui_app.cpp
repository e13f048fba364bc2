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
#include <ctime>

namespace fv::app {
namespace {

using Clock = std::chrono::steady_clock;
using Ms = std::chrono::duration<double, std::milli>;
// Without threads (the browser), how long a control held still keeps the curves' slices waiting.
constexpr std::chrono::milliseconds kSliceRest(200);

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

// The files a frame's actions ask for; the status line says what was written or why not (through `next`, the
// next frame's edits). The S key and the trail export take the next free number and never replace a file
// (this run's or an earlier one's); an explicit path (--screenshot, a session) is replaced atomically.
// Returns false when a write failed.
bool write_requested_files(const AppState::Actions& act, const std::string& screenshot_path,
                           const RenderSession& session, Platform& platform, const AppState& app,
                           UiEdits& next) {
    bool ok = true;
    auto report = [&](const std::string& path, const std::string& err, const char* what) {
        next.status = err.empty() ? "wrote " + path + what : err;
        if (!err.empty()) std::fprintf(stderr, "frictionviz: %s\n", err.c_str());
        if (err.empty()) platform.file_written(path);
        ok = ok && err.empty();
    };
    if (!screenshot_path.empty()) report(screenshot_path, session.save_png(screenshot_path), "");
    if (act.screenshot) {
        const std::vector<unsigned char> png = session.encode_png();
        std::string path;
        const std::string err = write_numbered_file(
            [](int n) { return "frictionviz-screenshot-" + std::to_string(n) + ".png"; },
            std::string_view(reinterpret_cast<const char*>(png.data()), png.size()), path);
        report(path, err, "");
    }
    if (act.export_csv) {
        std::string path;
        const std::string err =
            write_numbered_file([](int n) { return "frictionviz-trace-" + std::to_string(n) + ".csv"; },
                                trace_csv(app.sim()), path);
        report(path, err, " (the trail shown: tau,Px,Py,Tx,Ty,z,Fx,Fy)");
    }
    if (!act.save_session.empty())
        report(act.save_session, write_session(act.save_session, session_of(app.ui())), " (session)");
    return ok;
}

// This thread's CPU time: with LP_NUM_THREADS=0 llvmpipe draws on it, and then it is the frame's cost with
// little of the machine's load in it (wall times on a shared machine are mostly the load).
double thread_cpu_ms() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

// The app's frame loop, one method per phase: poll → build the panel (its edits queued) → sync (every edit
// at one point) → advance (fixed simulation steps) → draw → finish (files, present, frame times). The panel
// is built before the sync, so a slider moved in a frame moves the scene in that same frame (one frame from
// input to picture, not two: the browser's 33 ms slider-to-frame budget is two frames at 60 Hz).
class GuiLoop {
  public:
    explicit GuiLoop(const GuiOptions& o)
        : o_(o), platform_(make_platform(o.platform, platform_options(o))),
          session_(platform_->context(), platform_->pixel_ratio()), imgui_(session_, *platform_),
          scripted_(o.frames > 0 || o.bench_frames > 0),
          real_time_(platform_->interactive() && !scripted_), // else a fixed 1/60 s per frame, no mouse
          script_(o.script.empty() ? Script{} : load_script(o.script)), app_(o.start, o.data, o.session_file),
          animation_(o.animation_exporter), total_frames_(o.bench_frames > 0 ? o.bench_frames : o.frames) {
        dialog_.choose = [this](const std::string& accept) { return platform_->choose_file(accept); };
        if (o.lesson > 0) queued_.lesson = o.lesson; // applied by the first frame's sync, as a menu click
        if (!o.start_notice.empty()) queued_.status = o.start_notice;
    }

    int run() {
        for (int frame = 0; total_frames_ == 0 || frame < total_frames_; ++frame) {
            times_.start = Clock::now();
            cpu_start_ = thread_cpu_ms();
            events_ = platform_->poll();
            if (events_.close) break;
            build_ui();
            if (!sync(frame)) break;
            advance();
            draw();
            finish(frame);
        }
        const gfx::Size fb = session_.context().framebuffer_size();
        stats_.print(fb.width, fb.height, session_.pixel_ratio(), session_.context().describe());
        // A scripted or headless run has nobody to read the status line: a failed write is its exit status
        // (each reason is on stderr already). A person at the window has seen it in the status line.
        return failed_writes_ > 0 && (scripted_ || !platform_->interactive()) ? 1 : 0;
    }

  private:
    struct FrameTimes {
        Clock::time_point start, ui, synced, sim, layout, gl;
        double slice_ms = 0; // the curves' slice, inside the panel's phase (without threads)
        bool sliced = false; // a slice of the curves ran
    };

    static PlatformOptions platform_options(const GuiOptions& o) {
        PlatformOptions po;
        po.width = o.width;
        po.height = o.height;
        po.scale = o.scale;
        po.title = "frictionviz — friction reduction by in-plane vibrations";
        return po;
    }

    // 1. The panel through ImGui, from the state after the previous frame's sync; its edits, the keys' and
    //    the mouse's are queued for this frame's sync.
    void build_ui() {
        const gfx::Vec2 logical = session_.logical_page();
        const UiState& ui = app_.ui();
        layout_ = screen_layout(logical, ui.session.presentation);
        controls_.rect = layout_.controls;
        ImGui::GetIO().FontDefault = session_.fonts().font_for(ui.session.presentation ? 22 : 15);
        platform_->imgui_new_frame(logical);
        if (!real_time_) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX); // window == headless pixels
        ImGui::NewFrame();
        queued_.merge(draw_controls(ui, app_.sim(), app_.worker().latest(), app_.worker().busy(), controls_,
                                    dialog_, o_.share));
        queued_.export_animation = draw_export_dialog(export_dialog_, ui.session.speed, animation_.running());
        queued_.merge(keyboard_edits(ui));
        // Without threads (the browser) the curves are computed here, a few milliseconds a frame; not in a
        // frame that moves the model's parameters: the sync below supersedes the job in progress, so the
        // slice would be wasted, and the frame that shows the edit would come that much later (while a
        // slider is dragged, every frame).
        // B's curves (compare mode) get the frame's slice once A's are done.
        // Nor while a control is held that moved them less than kSliceRest ago: a slider dragged with short
        // pauses would otherwise meet a slice at its next move, and the move would wait for it (a step of the
        // work cannot be cut: up to about 20 ms in the browser). They are computed when it rests or is let
        // go.
        const auto slice_start = Clock::now();
        if (queued_.moves_curves()) last_curve_edit_ = slice_start;
        const bool dragging = ImGui::IsAnyItemActive() && slice_start - last_curve_edit_ < kSliceRest;
        times_.sliced = !queued_.moves_curves() && !dragging;
        if (times_.sliced)
            (app_.worker().busy() || !ui.session.compare ? app_.worker() : app_.worker_b())
                .run_slice(std::chrono::milliseconds(6));
        times_.slice_ms = Ms(Clock::now() - slice_start).count();
        queued_.merge(dashboard_mouse_edits(app_.ui().session.view, app_.sim(), transforms_));
        if (const gfx::Rect& a = transforms_.top_view.area; a.width() > 0 && a.height() > 0)
            queued_.view_aspect = static_cast<double>(a.width()) / a.height();
        if (ui.show_help && !draw_help_overlay(true, layout_.beside)) queued_.show_help = false;
        ImGui::Render();
        times_.ui = Clock::now();
    }

    // 2. All edits — the panel's, keys, mouse, drops and the script's — applied at one point. A dropped
    //    .json opens as a session, anything else as data (the last file: one data set at a time). False: the
    //    app closes.
    bool sync(int frame) {
        if (!events_.dropped.empty()) {
            std::string& path = events_.dropped.back();
            const bool session = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
            (session ? queued_.open_session : queued_.load_data) = std::move(path);
        }
        if (events_.help_key) queued_.show_help = !app_.ui().show_help;
        queued_.merge(script_edits(script_, frame, app_.ui()));
        if (o_.bench_frames > 0) queued_.params = bench_params(app_.ui().session.params, frame);
        act_ = app_.sync(queued_, scripted_);
        if (act_.quit) return false;
        if (o_.on_state) o_.on_state(app_.ui());
        queued_ = UiEdits{};
        if (act_.open_export_dialog) export_dialog_.open_requested = true;
        if (act_.export_animation) {
            queued_.status = animation_.start(*act_.export_animation); // shown from the next frame
            if (scripted_) animation_.wait(); // the file is there before the next frame
        }
        if (auto status = animation_.poll()) queued_.status = *status;
        if (animation_.take_failure()) {
            std::fprintf(stderr, "frictionviz: %s\n", queued_.status.value_or(app_.ui().status).c_str());
            ++failed_writes_;
        }
        times_.synced = Clock::now();
        return true;
    }

    // 3. Simulation time: fixed steps, their number from the elapsed wall time (a fixed 1/60 s per frame when
    //    not real time, so that scripted runs are reproducible).
    void advance() {
        const auto now = Clock::now();
        app_.advance(real_time_ ? std::min(0.1, std::chrono::duration<double>(now - last_).count())
                                : 1.0 / 60);
        last_ = now;
        // Reproducible pictures: both setups' curves are done before the frame is drawn (waiting for A's
        // alone, compare mode's snapshot showed B's curve or not as the machine's load had it).
        if (scripted_ && o_.bench_frames == 0) app_.worker().wait_idle(), app_.worker_b().wait_idle();
        times_.sim = Clock::now();
    }

    // 4. Draw: the dashboard through the canvas from the state after this frame's sync, the panel on top.
    void draw() {
        const gfx::Vec2 logical = session_.logical_page();
        const UiState& ui = app_.ui();
        const bool present = ui.session.presentation;
        const auto curves = app_.worker().latest();
        const bool busy = app_.worker().busy();
        gfx::Canvas& canvas = session_.canvas();
        canvas.begin(logical, session_.pixel_ratio(), gfx::colors::white);
        const auto curves_b = ui.session.compare ? app_.worker_b().latest() : std::nullopt;
        const CompareSetup b{app_.sim_b(), app_.view_b(), curves_b, app_.worker_b().busy()};
        const DashboardPanels panels =
            dashboard_panels(app_.sim(), app_.view(), curves, busy, ui.session.panel,
                             {ui.data ? &*ui.data : nullptr, ui.vv_m_s, &ui.session.pins}, &app_.mechanism(),
                             ui.session.compare ? &b : nullptr);
        // Beside the panel as built (presentation may have changed since).
        transforms_ = paint_dashboard(canvas, layout_.pictures, panels, present ? kPresentationScale : 1.0f);
        if (o_.on_layout)
            o_.on_layout({logical, session_.pixel_ratio(), session_.context().framebuffer_size(), layout_,
                          layout_dashboard(layout_.pictures, ui.session.compare), controls_.scroll_max});
        times_.layout = Clock::now();
        // The curves' threads wait while the frame is drawn (RatioWorker::hold).
        app_.worker().hold(true);
        app_.worker_b().hold(true);
        canvas.end();
        session_.imgui().render(*ImGui::GetDrawData());
        session_.context().gl().Finish();
        app_.worker().hold(false);
        app_.worker_b().hold(false);
        times_.gl = Clock::now();
    }

    // 5. Files, then show the frame, then its times.
    void finish(int frame) {
        const bool last_frame = total_frames_ > 0 && frame + 1 == total_frames_;
        if (!write_requested_files(act_, last_frame ? o_.screenshot : std::string(), session_, *platform_,
                                   app_, queued_))
            ++failed_writes_;
        platform_->frame_work({Ms(times_.ui - times_.start).count() - times_.slice_ms, times_.slice_ms,
                               Ms(times_.synced - times_.ui).count(), Ms(times_.sim - times_.synced).count(),
                               Ms(times_.layout - times_.sim).count(),
                               Ms(times_.gl - times_.layout).count()});
        platform_->work_pending(times_.sliced && (app_.worker().busy() || app_.worker_b().busy()));
        platform_->present();
        const double ms = Ms(Clock::now() - times_.start).count();
        if (o_.bench_frames > 0)
            stats_.record(ms, Ms(times_.sim - times_.start).count(), Ms(times_.layout - times_.sim).count(),
                          Ms(times_.gl - times_.layout).count(), thread_cpu_ms() - cpu_start_);
        if (real_time_) platform_->rest_after_frame(ms);
    }

    const GuiOptions& o_;
    const std::unique_ptr<Platform> platform_;
    RenderSession session_;
    ImGuiScope imgui_;
    const bool scripted_, real_time_;
    const Script script_;
    AppState app_;
    FileDialogs dialog_;
    ExportDialog export_dialog_;
    AnimationExportJob animation_;
    const int total_frames_;
    PlatformEvents events_;   // this frame's, polled before the panel is built
    ScreenLayout layout_;     // this frame's, from the page's size when the panel was built
    ControlsPlace controls_;  // where the panel went and how far it scrolls
    UiEdits queued_;          // the panel's, keys' and mouse's edits, applied by this frame's sync
    AppState::Actions act_{}; // what this frame's sync asks for (files, dialogs)
    DashboardTransforms transforms_{};
    FrameStats stats_;
    FrameTimes times_;
    double cpu_start_ = 0;
    int failed_writes_ = 0; // files asked for and not written (the exit status of a scripted run)
    Clock::time_point last_ = Clock::now();
    // The last frame whose edits moved the curves (the sliced worker rests after it while a control is held).
    Clock::time_point last_curve_edit_;
};

} // namespace

int run_gui(const GuiOptions& o) {
    return GuiLoop(o).run();
}

} // namespace fv::app
