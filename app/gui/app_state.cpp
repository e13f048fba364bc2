#include "app_state.hpp"

#include "lessons.hpp"

#include "fv/figures.hpp"
#include "fv/format.hpp"
#include "fv/ode_solver.hpp"
#include "fv/units.hpp"

#include <algorithm>
#include <cmath>

namespace fv::app {

namespace {

Session start_of(Model model, const Params& params, double amplitude_um, double frequency_khz) {
    Session s;
    s.model = model;
    s.params = params;
    s.amplitude_um = amplitude_um;
    s.frequency_khz = frequency_khz;
    return s;
}

// A lesson step or a concept preset as the edits a user would make by hand: the model, the parameters, the
// start, the panel and the speed of its setup, played from the start.
void set_up(UiEdits& e, const LessonSetup& u) {
    e.model = u.model;
    e.params = u.params;
    e.vb_m_s.reset(), e.zss_um.reset();
    e.start = u.start;
    e.panel = u.panel;
    e.speed = u.speed;
    e.frame = u.frame;
    e.playing = true;
    e.reset = true;
}

// The status line after a session has been opened.
std::string opened(const std::string& file, const std::string& loaded) {
    return "opened session " + file + (loaded.empty() ? "" : "; " + loaded);
}

} // namespace

AppState::AppState(const Session& start, std::optional<MeasurementSet> data, const std::string& session_file)
    : sim_(start.model, start.params) {
    const std::string loaded = show_session(start, std::move(data));
    ui_.status = session_file.empty() ? loaded : opened(session_file, loaded);
}

AppState::AppState(Model model, const Params& params, double amplitude_um, double frequency_khz,
                   std::optional<MeasurementSet> data)
    : AppState(start_of(model, params, amplitude_um, frequency_khz), std::move(data)) {}

std::string AppState::show_session(const Session& s, std::optional<MeasurementSet> data) {
    ui_.session = s;             // the session's state, without its data file (read by the caller)
    ui_.session.view.rewind = 0; // the simulation restarts: no history to look back into
    ui_.data.reset();
    const std::string loaded = data ? show_measured(ui_, std::move(*data)) : "";
    sim_.set_history_periods(std::max(ui_.session.view.trail_periods, kHistoryPeriods));
    sim_.apply(ui_.session.model, ui_.session.params);
    sim_.reset(ui_.session.start);
    step_carry_ = 0;
    step_pending_ = false;
    refresh_units();
    retarget_frame(true);
    worker_.request(ratio_request());
    return loaded;
}

RatioRequest AppState::ratio_request() const {
    return RatioRequest{ui_.session.model, ui_.session.params, ui_.session.panel == LowerPanel::map,
                        ratio_zeta_max(ui_.data ? &*ui_.data : nullptr), ui_.session.start};
}

void AppState::refresh_units() {
    // Each on its own: one quantity out of the doubles must not blank the others (every door checks the
    // physical view, units::physical_view_error, so none is expected to be).
    const auto value = [](auto f) {
        try {
            return f();
        } catch (const units::UnitError&) {
            return std::nan("");
        }
    };
    ui_.vv_m_s =
        value([&] { return units::vibration_velocity(ui_.session.amplitude_um, ui_.session.frequency_khz); });
    ui_.vb_m_s = value([&] { return vb_of(ui_); });
    ui_.zss_um = value([&] { return zss_of(ui_); });
}

AppState::Actions AppState::sync(const UiEdits& edits, bool wait) {
    ++syncs_;
    UiEdits e = edits;
    if (e.lesson) {
        const int n = static_cast<int>(lesson_steps().size());
        if (*e.lesson == 0) {
            ui_.session.lesson = 0;
        } else if (*e.lesson >= 1 && *e.lesson <= n) {
            ui_.session.lesson = *e.lesson;
            set_up(e, lesson_steps()[static_cast<std::size_t>(*e.lesson - 1)].setup);
        } else {
            e.status = "lesson step " + std::to_string(*e.lesson) +
                       " does not exist; allowed: " + lesson_range_text();
        }
    }
    if (e.preset)
        if (const LessonStep* step = find_lesson_step(*e.preset)) set_up(e, step->setup), e.preset.reset();
    if (e.status) ui_.status = *e.status; // older than what this frame's edits say below
    if (e.open_session) {
        try {
            LoadedSession l = load_session(*e.open_session);
            const std::string loaded = show_session(l.session, std::move(l.data));
            drop_fit_ = fit_.running();
            ui_.status = opened(*e.open_session, loaded);
        } catch (const SessionError& x) {
            ui_.status = std::string(x.what()) + " (session not opened; nothing changed)";
        }
    }
    std::optional<Params> params = e.params;
    std::optional<Model> model = e.model;
    bool reset = e.reset;
    if (e.preset) {
        const FigureSpec* f = find_figure(*e.preset);
        if (const auto* view = f ? std::get_if<PeriodViewFigure>(&f->content) : nullptr) { // presets()
            params = view->params;
            model = Model::dahl;
            reset = true;
        }
    }
    bool model_changed = false, data_changed = false;
    if (model && *model != ui_.session.model) ui_.session.model = *model, model_changed = true;
    // Another start: the motion begins again from it (the teaching moment: switched to sliding, the
    // students see it end in the other state where two coexist), and the readouts report its state.
    bool start_changed = false;
    if (e.start && *e.start != ui_.session.start) {
        ui_.session.start = *e.start, start_changed = reset = true;
        ui_.status = ui_.session.start == Start::sliding
                         ? "started again from steady sliding: the asperity fully deflected against v_b"
                         : "started again from rest: the asperity unstretched (the paper's start)";
    }
    // Parameters and their physical inputs: one candidate, checked once against the range table.
    if (params || e.vb_m_s || e.zss_um) {
        Params p = params.value_or(ui_.session.params);
        std::string err;
        try {
            if (e.vb_m_s)
                p.zeta = units::zeta_from_vb(*e.vb_m_s, ui_.session.amplitude_um, ui_.session.frequency_khz);
            if (e.zss_um) p.rdisp = units::rdisp_from_zss(ui_.session.amplitude_um, *e.zss_um);
        } catch (const units::UnitError& x) {
            err = x.what();
        }
        if (err.empty()) err = range_error(p);
        // What the panel shows in physical units must stay finite (rdisp 5e-324 would give z_ss = inf).
        if (err.empty())
            err = units::physical_view_error(p, ui_.session.amplitude_um, ui_.session.frequency_khz);
        if (err.empty())
            ui_.session.params = p, model_changed = true;
        else
            ui_.status = err;
    }
    if (e.amplitude_um || e.frequency_khz) {
        const std::string err = set_vibration(ui_, e.amplitude_um, e.frequency_khz);
        if (err.empty())
            model_changed = data_changed = true;
        else
            ui_.status = err;
    }
    if (e.load_data) ui_.status = load_measured(ui_, *e.load_data), data_changed = true;
    if (e.clear_data && ui_.data) ui_.data.reset(), ui_.status = "data cleared", data_changed = true;
    if (e.fit_data && ui_.data && ui_.session.model == Model::dahl) {
        fit_.start(ui_);
        ui_.status = "fitting r_disp and i to " + std::to_string(ui_.data->points.size()) + " points…";
    }
    // A finished fit sets r_disp and i.
    if (const auto done = fit_.poll(ui_, wait)) {
        if (drop_fit_) {
            drop_fit_ = false;
        } else {
            ui_.status = done->status;
            if (done->params) ui_.session.params = *done->params, model_changed = true;
        }
    }
    ui_.fitting = fit_.running();
    if (e.playing) ui_.session.playing = *e.playing;
    if (e.show_help) ui_.show_help = *e.show_help;
    if (e.presentation) ui_.session.presentation = *e.presentation;
    if (e.clear_pins) ui_.session.pins.clear(), ui_.status = "pins cleared";
    bool ask_worker = false;
    if (e.panel) {
        // The map is computed only while it is shown.
        ask_worker = (*e.panel == LowerPanel::map) != (ui_.session.panel == LowerPanel::map);
        ui_.session.panel = *e.panel;
    }
    if (e.speed) ui_.session.speed = std::clamp(*e.speed, kSpeedRange.lo, kSpeedRange.hi);
    ViewState& view = ui_.session.view;
    if (e.reset_view) view = ViewState{1, {0, 0}, true, view.trail_periods, view.rewind, view.frame};
    if (e.frame) view.frame = *e.frame;
    if (e.view_aspect && std::isfinite(*e.view_aspect) && *e.view_aspect > 0) view_aspect_ = *e.view_aspect;
    if (e.zoom) view.zoom = std::clamp(*e.zoom, kZoomRange.lo, kZoomRange.hi);
    if (e.pan)
        for (int k = 0; k < 2; ++k) view.pan[k] = std::clamp((*e.pan)[k], kPanRange.lo, kPanRange.hi);
    if (e.trail_periods) {
        view.trail_periods = std::clamp(*e.trail_periods, kTrailRange.lo, kTrailRange.hi);
        sim_.set_history_periods(std::max(view.trail_periods, kHistoryPeriods));
    }
    if (model_changed) sim_.apply(ui_.session.model, ui_.session.params);
    retarget_frame(false); // a new frame only where the parameters, the trail or the area changed it
    if (model_changed || ask_worker || data_changed || start_changed) worker_.request(ratio_request());
    if (e.pin) pin_current_curve(wait); // the curve of this frame's parameters (scripts wait for it)
    if (reset) sim_.reset(ui_.session.start), step_carry_ = 0;
    // Time: any change of the model or a reset shows the live state again; scrubbing and stepping back
    // pause, so that the moment stays on screen.
    if (model_changed || reset) ui_.session.view.rewind = 0;
    if (e.rewind)
        ui_.session.view.rewind = std::clamp(*e.rewind, 0.0, max_rewind(sim_)), ui_.session.playing = false;
    if (e.step_back)
        ui_.session.view.rewind = std::min(ui_.session.view.rewind + frame_tau(), max_rewind(sim_)),
        ui_.session.playing = false;
    if (e.jump_steady) jump_to_steady();
    step_pending_ = e.step;
    refresh_units();
    Actions act{e.screenshot,         e.export_csv,      e.quit, e.save_session.value_or(""),
                e.open_export_dialog, e.export_animation};
    if (act.export_animation) {
        AnimationSpec& spec = act.export_animation->spec;
        spec.model = ui_.session.model;
        spec.params = ui_.session.params;
        spec.steady.start = ui_.session.start;
        spec.frame = ui_.session.view.frame; // the top view as on screen
        spec.vv_m_s = std::isfinite(ui_.vv_m_s) ? ui_.vv_m_s : 0;
    }
    return act;
}

ViewState AppState::view() const {
    ViewState v = ui_.session.view;
    v.box = eased_frame(frame_from_, frame_to_, frame_ease_);
    v.aspect = view_aspect_;
    return v;
}

void AppState::retarget_frame(bool snap) {
    const FrameBox to =
        steady_frame(ui_.session.model, ui_.session.params, ui_.session.view.trail_periods, view_aspect_);
    if (snap) {
        frame_from_ = frame_to_ = to, frame_ease_ = 1;
        return;
    }
    if (to == frame_to_) return;
    frame_from_ = eased_frame(frame_from_, frame_to_, frame_ease_); // from where it is now: no jump
    frame_to_ = to;
    frame_ease_ = 0;
}

double AppState::frame_tau() const {
    return ui_.session.speed * 2 * kPi / 60;
}

void AppState::advance(double dt) {
    // The frame eases in wall time, playing or not.
    if (frame_ease_ < 1) frame_ease_ = std::min(1.0, frame_ease_ + dt / kFrameEaseSeconds);
    // While rewound, playing replays the history towards the live state; then the simulation runs on.
    if (ui_.session.playing && ui_.session.view.rewind > 0) {
        ui_.session.view.rewind = std::max(0.0, ui_.session.view.rewind - dt * ui_.session.speed * 2 * kPi);
    } else if (ui_.session.playing) {
        step_carry_ += dt * ui_.session.speed * sim_.steps_per_period();
        const int n = static_cast<int>(step_carry_);
        step_carry_ -= n;
        sim_.step(n);
    }
    // One frame forward: through the history while rewound, else the simulation's steps of one frame.
    if (step_pending_) {
        if (ui_.session.view.rewind > 0)
            ui_.session.view.rewind = std::max(0.0, ui_.session.view.rewind - frame_tau());
        else
            sim_.step(std::max(1, static_cast<int>(std::lround(frame_tau() / sim_.dtau()))));
        step_pending_ = false;
    }
}

void AppState::pin_current_curve(bool wait) {
    if (ui_.session.pins.size() >= kMaxPins) {
        ui_.status = std::to_string(kMaxPins) + " curves pinned: clear the pins to pin more";
        return;
    }
    if (wait) worker_.wait_idle();
    const auto curves = worker_.latest();
    if (!curves || !(curves->request == ratio_request())) {
        ui_.status = "the curve is still being computed: pin it once it is drawn";
        return;
    }
    PinnedCurve pin = pin_of(pin_source(ui_.session.model, ui_.session.params, ui_.session.start), *curves);
    ui_.status = "pinned: " + pin.label;
    ui_.session.pins.push_back(std::move(pin));
}

void AppState::jump_to_steady() {
    ui_.session.view.rewind = 0;
    if (ui_.session.model == Model::rigid) {
        ui_.status = "the rigid model has no transient: its friction follows the velocity at once";
        return;
    }
    OdeOptions opt;
    opt.start = ui_.session.start; // the state the chosen start reaches, where two coexist
    const OdeSolution s = ode_solve(ui_.session.params, opt);
    if (!ok(s.result.status) || !std::isfinite(s.lag.x()) || !std::isfinite(s.lag.y())) {
        ui_.status =
            std::string("no verified steady state to jump to here (") + to_string(s.result.status) + ")";
        return;
    }
    // The solver's L* at a period start, then one period animated at once so that the trails, the force
    // plot and the period mean show the steady motion.
    sim_.start_steady(s.lag);
    sim_.step(sim_.steps_per_period());
    ui_.status = "on the steady state: P - T = L* at each period start (the solver's fixed point)";
}

} // namespace fv::app
