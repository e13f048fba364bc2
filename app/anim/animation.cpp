#include "animation.hpp"

#include "gif_encoder.hpp"
#include "mp4_encoder.hpp"

#include "figures/dashboard_painter.hpp"
#include "figures/figure_painter.hpp"
#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"
#include "fv/format.hpp"
#include "fv/live_panels.hpp"
#include "fv/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fv::anim {
namespace {

// Periods the animation's stepping may take to settle on its own steady state after starting from the
// continuous-time solver's (usually 1-3; slowly contracting cases are stopped here, well below a pixel).
constexpr int kMaxSettlePeriods = 400;
constexpr double kSettleTolerance = 1e-7; // of z_ss, per period

std::string pretty(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

std::string caption_of(const Spec& s, double rx) {
    const Params& p = s.params;
    std::string c = s.model == Model::rigid ? "rigid model" : "Dahl model, i = " + format_number("%g", p.i);
    c += "   ζ = " + format_number("%g", p.zeta) + "   θ = " + format_number("%g", p.theta * 180 / kPi) + "°";
    if (s.model == Model::dahl) c += "   r_{disp} = " + format_number("%g", p.rdisp);
    c += "   steady state: r_{x} = " + format_number("%.4f", rx);
    return c;
}

// The top view's frame for the loop: the parameters' (top_view_frame.hpp). In the ground frame the body
// drifts D = zeta 2 pi per period; where the loop carries it across the frame at least once, the frame is
// widened (about its centre, both ways) to D / k for whole k, so that the last frame wraps onto the first.
FrameBox loop_frame(const Spec& s, double aspect) {
    FrameBox b = steady_frame(s.model, s.params, ViewState{}.trail_periods, aspect);
    const double drift = s.periods * 2 * kPi * s.params.zeta, w = b.width();
    if (s.frame != FrameChoice::ground || !(w > 0) || drift < w) return b;
    const double k = (drift / std::floor(drift / w)) / w;
    const double mx = 0.5 * (b.x0 + b.x1), my = 0.5 * (b.y0 + b.y1);
    return {mx + k * (b.x0 - mx), mx + k * (b.x1 - mx), my + k * (b.y0 - my), my + k * (b.y1 - my)};
}

} // namespace

std::optional<Format> format_for_path(const std::string& path) {
    return animation_format(path);
}

const char* allowed_extensions() {
    return "FILE.gif, FILE.mp4";
}

void even_size(Spec& spec) {
    if (spec.format != Format::mp4) return;
    spec.width += spec.width % 2;
    spec.height += spec.height % 2;
}

int frame_count(const Spec& s) {
    return static_cast<int>(std::lround(s.periods * s.fps / s.speed));
}

std::string check_spec(const Spec& s) {
    if (s.periods < kMinPeriods || s.periods > kMaxPeriods)
        return "--periods " + std::to_string(s.periods) + " is out of range; allowed: integers in [" +
               std::to_string(kMinPeriods) + ", " + std::to_string(kMaxPeriods) + "]";
    const double max_fps = s.format == Format::gif ? kMaxGifFps : kMaxFps;
    if (!(s.fps >= kMinFps && s.fps <= max_fps))
        return "--fps " + pretty(s.fps) + " is out of range; allowed: [" + pretty(kMinFps) + ", " +
               pretty(max_fps) + "]" +
               (s.format == Format::gif ? " for a GIF (its frames last whole 1/100 s, at least 2)" : "");
    if (!(s.speed >= kMinSpeed && s.speed <= kMaxSpeed))
        return "--speed " + pretty(s.speed) + " is out of range; allowed: [" + pretty(kMinSpeed) + ", " +
               pretty(kMaxSpeed) + "] periods per second";
    if (frame_count(s) > kMaxFrames)
        return "--periods " + std::to_string(s.periods) + " at --fps " + pretty(s.fps) + " and --speed " +
               pretty(s.speed) + " is " + std::to_string(frame_count(s)) + " frames; allowed: at most " +
               std::to_string(kMaxFrames) + " (periods x fps / speed)";
    if (frame_count(s) < 2)
        return "--periods " + std::to_string(s.periods) + " at --fps " + pretty(s.fps) + " and --speed " +
               pretty(s.speed) + " is fewer than 2 frames; allowed: periods x fps / speed >= 2";
    if (s.format == Format::mp4 && (s.width % 2 || s.height % 2))
        return "an MP4 (yuv420p) needs an even width and height";
    if (s.format == Format::mp4)
        if (std::string why = h264_unavailable(); !why.empty()) return "cannot write MP4: " + why;
    return {};
}

Frames::Frames(const Spec& spec)
    : spec_(spec), count_(frame_count(spec)), start_(spec.model, spec.params), sim_(spec.model, spec.params) {
    const SteadyResult steady = steady_ratio(spec.model, spec.params, spec.steady);
    rx_ = steady.rx;
    if (spec.view == View::dashboard)
        curves_ = compute_ratio_curves(
            {spec.model, spec.params, false, ratio_zeta_max(nullptr), spec.steady.start});
    // Start where the continuous-time solver's period ends (its fixed point), then let the animation's own
    // stepping settle on its fixed point, a whole number of periods at a time.
    Vec2 lag = Vec2::Zero();
    if (spec.model == Model::dahl && !steady.period.empty())
        lag = steady.period.back().P - steady.period.back().T;
    const int n = start_.steps_per_period();
    // Two periods (the force plot's) less half a step: the history then always holds 2n samples (with
    // exactly two periods rounding would make it 2n or 2n + 1 by turns, and the oldest sample would sit on
    // the plot's edge), so the panels draw the same samples every period.
    start_.set_history_periods(2 - 0.5 / n);
    start_.start_steady(lag);
    const double tol = kSettleTolerance * spec.params.zss();
    for (int k = 0; k < kMaxSettlePeriods; ++k) {
        const Vec2 before = start_.P() - start_.T();
        start_.step(n);
        if (((start_.P() - start_.T()) - before).norm() <= tol) break;
    }
    // Two more periods: the trails and the force plot's history are the steady ones. And one step: no frame
    // falls on a multiple of pi, where the picture's choices that go by the phase (which end of the vibration
    // line is labelled) would be decided by rounding.
    start_.step(2 * n + 1);
    sim_ = start_;
    box_ = loop_frame(spec, 0);
    if (!spec.title.empty()) top_ = 46;
}

gfx::Rect Frames::top_view_area(gfx::Vec2 page) const {
    const gfx::Rect area{4, top_, page.x - 4, page.y - 4};
    return spec_.view == View::scene ? area : app::layout_dashboard(area).top_view;
}

void Frames::fit(gfx::Canvas& canvas, gfx::Vec2 page, float pixel_ratio) {
    // Twice: the y tick labels' width depends on the frame, the frame on the area they leave.
    for (int pass = 0; pass < 2; ++pass) {
        canvas.begin(page, pixel_ratio, gfx::colors::white);
        ViewState view;
        view.frame = spec_.frame;
        view.box = box_;
        const gfx::PlotTransform t =
            app::paint_panel(canvas, top_view_panel(sim_at(0), view), top_view_area(page));
        canvas.end_recording();
        if (t.area.width() > 0 && t.area.height() > 0) aspect_ = t.area.width() / t.area.height();
        box_ = loop_frame(spec_, aspect_);
    }
}

const LiveSim& Frames::sim_at(int k) {
    if (k < at_) {
        sim_ = start_;
        at_ = 0;
    }
    // Frame k sits floor(k N / count) steps into the loop of N = periods x n steps: frame count is the
    // loop's start again.
    const long n = static_cast<long>(spec_.periods) * sim_.steps_per_period();
    const auto steps_to = [&](int f) { return static_cast<long>(f) * n / count_; };
    sim_.step(static_cast<int>(steps_to(k) - steps_to(at_)));
    at_ = k;
    return sim_;
}

int Frames::still_frame() {
    const double w = box_.width();
    if (spec_.frame != FrameChoice::ground || !(w > 0)) return 0;
    // Where the top view puts the vibration centre: its x modulo the frame's width (live_panels.cpp).
    const auto off_middle = [&](int k) {
        const double x = sim_at(k).vibration_centre().x();
        return std::abs(x - w * std::floor((x - box_.x0) / w) - (box_.x0 + 0.5 * w));
    };
    int best = 0;
    double best_off = off_middle(0);
    for (int k = 1; k < count_; ++k)
        if (const double off = off_middle(k); off < best_off) best = k, best_off = off;
    return best;
}

void Frames::paint(gfx::Canvas& canvas, gfx::Vec2 page, int k) {
    const LiveSim& sim = sim_at(k);
    gfx::TextStyle ts;
    ts.size = 14;
    ts.halign = gfx::HAlign::Center;
    if (!spec_.title.empty()) {
        gfx::TextStyle title = ts;
        title.size = 17;
        canvas.text({page.x / 2, 4}, spec_.title, title);
    }
    canvas.text({page.x / 2, top_ - 19}, caption_of(spec_, rx_), ts);
    const gfx::Rect area{4, top_, page.x - 4, page.y - 4};

    // The top view in the frame fixed for the loop's parameters (it never re-frames). Body frame: the camera
    // moves with the body's mean velocity v_b, on where P would be without vibrating, the axis reading
    // x - v_b t; the trails stay where they were laid down. Ground frame: the floor stands still and the
    // body wraps round at the edges.
    ViewState view;
    view.frame = spec_.frame;
    view.box = box_;
    view.aspect = aspect_;
    PanelData top = top_view_panel(sim, view);
    if (spec_.frame == FrameChoice::body) {
        const double centre = sim.vibration_centre().x();
        shift_panel_x(top, -centre);
        // Set rather than shifted back: the same numbers in every frame, not the same up to round-off.
        top.x_min = box_.x0, top.x_max = box_.x1;
        top.x_title = "(x − v_{b}t) / x_{v}: the view moves with the body";
    }
    if (spec_.view == View::scene) {
        app::paint_panel(canvas, top, area);
        return;
    }
    // The force plot's time axis counts back from now, so that it reads the same every period.
    PanelData force = force_panel_live(sim, curves_);
    shift_panel_x(force, -sim.tau());
    force.x_title = "time τ − τ_{now}";
    app::paint_dashboard(
        canvas, area,
        {std::move(top), std::move(force), ratio_panel_live(curves_, false, {nullptr, spec_.vv_m_s})});
}

namespace {

gfx::ContextOptions context_for(const Spec& spec) {
    gfx::ContextOptions o;
    o.width = spec.width;
    o.height = spec.height;
    o.scale = spec.scale;
    return o;
}

// A headless session at the spec's size and scale, with the loop's frames fitted to its page.
struct Stage {
    app::RenderSession session;
    Frames frames;
    gfx::Vec2 page;

    explicit Stage(const Spec& spec)
        : session(context_for(spec)), frames(spec), page(session.logical_page()) {
        frames.fit(session.canvas(), page, session.pixel_ratio());
    }
    // Frame k drawn (the caller reads the pixels back, then presents).
    void draw(int k) {
        session.canvas().begin(page, session.pixel_ratio(), gfx::colors::white);
        frames.paint(session.canvas(), page, k);
        session.canvas().end();
    }
};

} // namespace

Still render_still(const Spec& spec) {
    Stage stage(spec);
    stage.draw(stage.frames.still_frame());
    Still still{stage.session.context().read_pixels(), stage.session.canvas().display_list()};
    stage.session.context().present();
    return still;
}

std::string export_animation(const Spec& spec, const std::string& path, const Progress& progress) {
    Stage stage(spec);
    app::RenderSession& session = stage.session;
    const int total = stage.frames.count();
    auto render = [&](int k) {
        stage.draw(k);
        gfx::Image img = session.context().read_pixels();
        session.context().present();
        return img;
    };
    auto cancelled = [&] { return progress.cancel && progress.cancel->load(); };
    std::string bytes;
    try {
        if (spec.format == Format::gif) {
            // One palette for the loop, from four frames spread over a period.
            std::vector<gfx::Image> samples;
            for (int q = 0; q < 4; ++q) samples.push_back(render(q * total / (4 * spec.periods)));
            std::vector<const gfx::Image*> ptrs;
            for (const gfx::Image& s : samples) ptrs.push_back(&s);
            GifEncoder gif(session.context().framebuffer_size().width,
                           session.context().framebuffer_size().height, build_palette(ptrs));
            samples.clear();
            for (int k = 0; k < total; ++k) {
                if (cancelled()) return "cancelled";
                gif.add(render(k), gif_delay_cs(k, spec.fps));
                if (progress.report) progress.report(k + 1, total);
            }
            bytes = gif.finish();
        } else {
            Mp4Encoder mp4(spec.width, spec.height, spec.fps);
            for (int k = 0; k < total; ++k) {
                if (cancelled()) return "cancelled";
                mp4.add(render(k));
                if (progress.report) progress.report(k + 1, total);
            }
            bytes = mp4.finish();
        }
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return write_file_atomic(path, bytes);
}

} // namespace fv::anim
