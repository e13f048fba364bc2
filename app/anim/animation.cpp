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

std::string caption_of(const Setup& s, double rx) {
    const Params& p = s.params;
    std::string c = s.model == Model::rigid ? "rigid model" : "Dahl model, i = " + format_number("%g", p.i);
    c += "   ζ = " + format_number("%g", p.zeta) + "   θ = " + format_number("%g", p.theta * 180 / kPi) + "°";
    if (s.model == Model::dahl) c += "   r_{disp} = " + format_number("%g", p.rdisp);
    c += "   steady state: r_{x} = " + format_number("%.4f", rx);
    return c;
}

// The compare view's caption: each setup's angle and r_x, then what else differs per setup, then what the two
// share once.
std::string compare_caption_of(const Setup& a, double rx_a, const Setup& b, double rx_b) {
    struct Item {
        std::string name, va, vb;
    };
    const auto num = [](double v) { return format_number("%g", v); };
    const bool dahl = a.model == Model::dahl || b.model == Model::dahl;
    std::vector<Item> items{
        {"model", a.model == Model::rigid ? "rigid" : "Dahl", b.model == Model::rigid ? "rigid" : "Dahl"},
        {"ζ", num(a.params.zeta), num(b.params.zeta)}};
    if (dahl) {
        items.push_back({"r_{disp}", num(a.params.rdisp), num(b.params.rdisp)});
        items.push_back({"i", num(a.params.i), num(b.params.i)});
    }
    std::string da, db, shared;
    for (const Item& it : items) {
        const std::string eq = it.name == "model" ? "" : it.name + " = ";
        if (it.va == it.vb)
            shared += (shared.empty() ? "" : ", ") + eq + it.va;
        else
            da += ", " + eq + it.va, db += ", " + eq + it.vb;
    }
    const auto side = [&](const char* n, const Setup& s, double rx, const std::string& more) {
        return std::string(n) + ": θ = " + format_number("%g", s.params.theta * 180 / kPi) + "°" + more +
               ", r_{x} = " + format_number("%.4f", rx);
    };
    return side("A", a, rx_a, da) + "    " + side("B", b, rx_b, db) +
           (shared.empty() ? "" : "    (" + shared + ")");
}

// The top view's frame for the loop: the setup's (top_view_frame.hpp). In the ground frame the body
// drifts D = zeta 2 pi per period; where the loop carries it across the frame at least once, the frame is
// widened (about its centre, both ways) to D / k for whole k, so that the last frame wraps onto the first.
FrameBox loop_frame(const Spec& spec, const Setup& s, double aspect) {
    FrameBox b = steady_frame(s.model, s.params, ViewState{}.trail_periods, aspect);
    const double drift = spec.periods * 2 * kPi * s.params.zeta, w = b.width();
    if (spec.frame != FrameChoice::ground || !(w > 0) || drift < w) return b;
    const double k = (drift / std::floor(drift / w)) / w;
    const double mx = 0.5 * (b.x0 + b.x1), my = 0.5 * (b.y0 + b.y1);
    return {mx + k * (b.x0 - mx), mx + k * (b.x1 - mx), my + k * (b.y0 - my), my + k * (b.y1 - my)};
}

// An x title wider than its panel (a narrow page: a printed column of `render --lesson --page column`)
// keeps its first part, the axis's name, and drops the explanation after ": " or " (", which the painter
// would otherwise cut off at the page's edges.
void shorten_x_title(const gfx::Canvas& canvas, PanelData& p, float room) {
    constexpr float kTickText = 13; // gfx::Plot::font_size, the x title's smallest size
    if (canvas.measure_text(p.x_title, kTickText * p.text_scale).x <= room) return;
    for (const char* cut : {": ", " ("})
        if (const std::size_t k = p.x_title.find(cut); k != std::string::npos && k > 0) {
            p.x_title.resize(k);
            return;
        }
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

SetupLoop::SetupLoop(const Spec& spec, const Setup& s, bool with_curves, bool with_map)
    : setup(s), start(s.model, s.params), sim(s.model, s.params) {
    SteadyOptions opt = spec.steady;
    opt.start = s.start;
    const SteadyResult steady = steady_ratio(s.model, s.params, opt);
    rx = steady.rx;
    // The map only where it is shown (A's lower panel; it takes a few seconds), as the app asks for it.
    if (with_curves)
        curves = compute_ratio_curves(
            {s.model, s.params, with_map, ratio_zeta_max(spec.data ? &*spec.data : nullptr), s.start});
    // Start where the continuous-time solver's period ends (its fixed point), then let the animation's own
    // stepping settle on its fixed point, a whole number of periods at a time.
    Vec2 lag = Vec2::Zero();
    if (s.model == Model::dahl && !steady.period.empty())
        lag = steady.period.back().P - steady.period.back().T;
    const int n = start.steps_per_period();
    // Two periods (the force plot's) less half a step: the history then always holds 2n samples (with
    // exactly two periods rounding would make it 2n or 2n + 1 by turns, and the oldest sample would sit on
    // the plot's edge), so the panels draw the same samples every period.
    start.set_history_periods(2 - 0.5 / n);
    start.start_steady(lag);
    const double tol = kSettleTolerance * s.params.zss();
    for (int k = 0; k < kMaxSettlePeriods; ++k) {
        const Vec2 before = start.P() - start.T();
        start.step(n);
        if (((start.P() - start.T()) - before).norm() <= tol) break;
    }
    // Two more periods: the trails and the force plot's history are the steady ones. And one step: no frame
    // falls on a multiple of pi, where the picture's choices that go by the phase (which end of the vibration
    // line is labelled) would be decided by rounding.
    start.step(2 * n + 1);
    sim = start;
    box = loop_frame(spec, s, 0);
}

const LiveSim& SetupLoop::at_frame(int k, int count, int periods) {
    if (k < at) {
        sim = start;
        at = 0;
    }
    const long n = static_cast<long>(periods) * sim.steps_per_period();
    const auto steps_to = [&](int f) { return static_cast<long>(f) * n / count; };
    sim.step(static_cast<int>(steps_to(k) - steps_to(at)));
    at = k;
    return sim;
}

Frames::Frames(const Spec& spec)
    : spec_(spec), count_(frame_count(spec)),
      a_(spec, {spec.model, spec.params, spec.steady.start}, spec.view != View::scene,
         spec.view != View::scene && spec.panel == LowerPanel::map) {
    if (spec.view == View::compare) {
        b_.emplace(spec, spec.b, true, false);
        // One time base: each settled for as many periods as it needed; the one behind runs on by whole
        // periods (its steady state repeats), so that both loops start at the same tau up to a step.
        const long ahead = std::lround((a_.start.tau() - b_->start.tau()) / (2 * kPi));
        SetupLoop& behind = ahead > 0 ? *b_ : a_;
        behind.start.step(static_cast<int>(std::labs(ahead)) * behind.start.steps_per_period());
        behind.sim = behind.start;
    }
    if (!spec.title.empty()) top_ = 46;
}

gfx::Rect Frames::top_view_area(gfx::Vec2 page) const {
    const gfx::Rect area{4, top_, page.x - 4, page.y - 4};
    return spec_.view == View::scene ? area : app::layout_dashboard(area, b_.has_value()).top_view;
}

void Frames::fit(gfx::Canvas& canvas, gfx::Vec2 page, float pixel_ratio) {
    // Twice: the y tick labels' width depends on the frame, the frame on the area they leave. (B's view is
    // A's size: it takes A's aspect.)
    for (int pass = 0; pass < 2; ++pass) {
        canvas.begin(page, pixel_ratio, gfx::colors::white);
        ViewState view;
        view.frame = spec_.frame;
        view.box = a_.box;
        const gfx::PlotTransform t = app::paint_panel(
            canvas, top_view_panel(a_.at_frame(0, count_, spec_.periods), view), top_view_area(page));
        canvas.end_recording();
        if (t.area.width() > 0 && t.area.height() > 0) aspect_ = t.area.width() / t.area.height();
        a_.box = loop_frame(spec_, a_.setup, aspect_);
        if (b_) b_->box = loop_frame(spec_, b_->setup, aspect_);
    }
}

int Frames::still_frame() {
    const FrameBox& box = a_.box;
    const double w = box.width();
    if (spec_.frame != FrameChoice::ground || !(w > 0)) return 0;
    // Where the top view puts the vibration centre: its x modulo the frame's width (live_panels.cpp).
    const auto off_middle = [&](int k) {
        const double x = a_.at_frame(k, count_, spec_.periods).vibration_centre().x();
        return std::abs(x - w * std::floor((x - box.x0) / w) - (box.x0 + 0.5 * w));
    };
    int best = 0;
    double best_off = off_middle(0);
    for (int k = 1; k < count_; ++k)
        if (const double off = off_middle(k); off < best_off) best = k, best_off = off;
    return best;
}

PanelData Frames::top_view(SetupLoop& loop, int k, const char* name) {
    const LiveSim& sim = loop.at_frame(k, count_, spec_.periods);
    // The top view in the frame fixed for the loop's parameters (it never re-frames). Body frame: the camera
    // moves with the body's mean velocity v_b, on where P would be without vibrating, the axis reading
    // x - v_b t; the trails stay where they were laid down. Ground frame: the floor stands still and the
    // body wraps round at the edges.
    ViewState view;
    view.frame = spec_.frame;
    view.box = loop.box;
    view.aspect = aspect_;
    PanelData top = top_view_panel(sim, view, name);
    if (spec_.frame == FrameChoice::body) {
        const double centre = sim.vibration_centre().x();
        shift_panel_x(top, -centre);
        // Set rather than shifted back: the same numbers in every frame, not the same up to round-off.
        top.x_min = loop.box.x0, top.x_max = loop.box.x1;
        top.x_title = "(x − v_{b}t) / x_{v}: the view moves with the body";
    }
    return top;
}

void Frames::paint(gfx::Canvas& canvas, gfx::Vec2 page, int k) {
    gfx::TextStyle ts;
    ts.size = 14;
    ts.halign = gfx::HAlign::Center;
    // Each line at its size where it fits the page's width, else smaller (a narrow page: a printed column,
    // the smallest --size): cut off at the edges it would say less than it does smaller.
    const auto line = [&](float y, const std::string& text, float size) {
        gfx::TextStyle style = ts;
        const float w = canvas.measure_text(text, size).x, room = page.x - 8;
        style.size = w > room ? size * room / w : size;
        canvas.text({page.x / 2, y}, text, style);
    };
    if (!spec_.title.empty()) line(4, spec_.title, 17);
    line(top_ - 19, b_ ? compare_caption_of(a_.setup, a_.rx, b_->setup, b_->rx) : caption_of(a_.setup, a_.rx),
         14);
    const gfx::Rect area{4, top_, page.x - 4, page.y - 4};
    PanelData top = top_view(a_, k, b_ ? "A" : nullptr);
    const float room = top_view_area(page).width(); // B's top view is as wide as A's
    shorten_x_title(canvas, top, room);
    if (spec_.view == View::scene) {
        app::paint_panel(canvas, top, area);
        return;
    }
    const LiveSim& sim = a_.sim;
    app::DashboardPanels panels;
    CompareOverlay b;
    if (b_) {
        panels.top_view_b = top_view(*b_, k, "B");
        shorten_x_title(canvas, *panels.top_view_b, room);
        b = {&b_->sim, b_->curves ? &*b_->curves : nullptr, false};
    }
    // The force plot's time axis counts back from now, so that it reads the same every period.
    PanelData force = force_panel_live(sim, a_.curves, 0, b);
    shift_panel_x(force, -sim.tau());
    force.x_title = "time τ − τ_{now}";
    RatioOverlay overlay{spec_.data ? &*spec_.data : nullptr, spec_.vv_m_s};
    overlay.b = b;
    panels.top_view = std::move(top);
    panels.force = std::move(force);
    panels.lower = lower_panel_live(spec_.panel, sim, a_.curves, false, overlay, mechanism_);
    app::paint_dashboard(canvas, area, panels);
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

Still render_still(const Spec& spec, gfx::Vec2 vector_page) {
    Stage stage(spec);
    stage.draw(stage.frames.still_frame());
    Still still{stage.session.context().read_pixels(), stage.session.canvas().display_list()};
    stage.session.context().present();
    if (vector_page.x > 0 && vector_page.y > 0) {
        // The same frame laid out again on the printed page: its top view fitted to the area it gets there
        // (and, in the ground frame, the still frame chosen for that box), recorded without drawing.
        gfx::Canvas& canvas = stage.session.canvas();
        const float ratio = stage.session.pixel_ratio();
        stage.frames.fit(canvas, vector_page, ratio);
        const int k = stage.frames.still_frame();
        canvas.begin(vector_page, ratio, gfx::colors::white);
        stage.frames.paint(canvas, vector_page, k);
        canvas.end_recording();
        still.list = canvas.display_list();
    }
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
