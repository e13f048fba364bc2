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
    // Compare mode as the step has it: on with its B, or off.
    e.compare = u.b.has_value();
    e.b = SetupEdits{};
    if (u.b)
        e.b_setup = *u.b;
    else
        e.b_setup.reset();
    if (u.data)
        e.example_data = *u.data, e.drop_example_data = false;
    else
        e.drop_example_data = true, e.example_data.reset();
}

// "" when the parameters may be shown: inside the range table and with a finite physical view (what the
// panel shows in physical units must stay finite: rdisp 5e-324 would give z_ss = inf). A's and B's alike.
std::string params_error(const Params& p, const SessionState& s) {
    std::string err = range_error(p);
    if (err.empty()) err = units::physical_view_error(p, s.amplitude_um, s.frequency_khz);
    return err;
}

// The status line after a session has been opened.
std::string opened(const std::string& file, const std::string& loaded) {
    return "opened session " + file + (loaded.empty() ? "" : "; " + loaded);
}

} // namespace

AppState::AppState(const Session& start, std::optional<MeasurementSet> data, const std::string& session_file)
    : a_(start.a()), b_(start.b) {
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
    std::string loaded;
    if (data) {
        loaded = show_measured(ui_, std::move(*data));
    } else if (s.lesson >= 1 && s.lesson <= static_cast<int>(lesson_steps().size())) {
        // A session or link during a lesson step with example points: the step's points, as Next showed them
        // (a session saves no file for them).
        const LessonSetup& u = lesson_steps()[static_cast<std::size_t>(s.lesson - 1)].setup;
        if (u.data) loaded = show_measured(ui_, *u.data), ui_.data_is_example = true;
    }
    for (SetupRun* run : {&a_, &b_})
        run->set_history_periods(std::max(ui_.session.view.trail_periods, kHistoryPeriods));
    a_.apply(ui_.session.a());
    b_.apply(ui_.session.b);
    reset_sims();
    step_pending_ = false;
    refresh_units();
    retarget_frames(true);
    request_curves(true, true);
    return loaded;
}

RatioRequest AppState::ratio_request(const Setup& s, bool map) const {
    return RatioRequest{s.model, s.params, map, ratio_zeta_max(ui_.data ? &*ui_.data : nullptr), s.start};
}

void AppState::request_curves(bool a, bool b) {
    if (a) a_.worker().request(ratio_request(ui_.session.a(), ui_.session.panel == LowerPanel::map));
    // B's curve only while it is shown (never its map: the lower panel's map is A's).
    if (b && ui_.session.compare) b_.worker().request(ratio_request(ui_.session.b, false));
}

void AppState::reset_sims() {
    a_.reset(ui_.session.start);
    b_.reset(ui_.session.b.start);
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
        if (err.empty()) err = params_error(p, ui_.session);
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
    if (e.drop_example_data && ui_.data && ui_.data_is_example) ui_.data.reset(), data_changed = true;
    // Data the user opened stay over a step's example points: a teacher who loaded the class's measurements
    // and goes Back and Next again finds them still there.
    if (e.example_data && (!ui_.data || ui_.data_is_example)) {
        ui_.status = show_measured(ui_, *e.example_data);
        ui_.data_is_example = true, data_changed = true;
    }
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
        for (SetupRun* run : {&a_, &b_})
            run->set_history_periods(std::max(view.trail_periods, kHistoryPeriods));
    }
    if (model_changed) a_.apply(ui_.session.a());
    bool restart = false;
    const bool b_changed = sync_compare(e, restart);
    if (b_changed) b_.apply(ui_.session.b);
    reset = reset || restart;
    retarget_frames(false); // a new frame only where the parameters, the trail or the area changed it
    request_curves(model_changed || ask_worker || data_changed || start_changed, b_changed || data_changed);
    if (e.pin) pin_current_curve(wait); // the curve of this frame's parameters (scripts wait for it)
    if (reset) reset_sims();
    // Time: any change of the model or a reset shows the live state again; scrubbing and stepping back
    // pause, so that the moment stays on screen.
    if (model_changed || b_changed || reset) ui_.session.view.rewind = 0;
    if (e.rewind)
        ui_.session.view.rewind = std::clamp(*e.rewind, 0.0, max_rewind(a_.sim())),
        ui_.session.playing = false;
    if (e.step_back)
        ui_.session.view.rewind = std::min(ui_.session.view.rewind + frame_tau(), max_rewind(a_.sim())),
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
        spec.panel = ui_.session.panel;      // and the lower panel (curves, map, loop, why, setup)
        spec.vv_m_s = std::isfinite(ui_.vv_m_s) ? ui_.vv_m_s : 0;
        // In compare mode the dashboard shows both setups, as on screen.
        if (ui_.session.compare && spec.view == AnimationView::dashboard) {
            spec.view = AnimationView::compare;
            spec.b = ui_.session.b;
        }
    }
    return act;
}

bool AppState::sync_compare(const UiEdits& e, bool& restart) {
    SessionState& s = ui_.session;
    bool changed = false, turned_on = false;
    if (e.compare && *e.compare != s.compare) {
        s.compare = *e.compare;
        if (s.compare) {
            // B starts beside A (after this frame's edits of A) at the other angle, both from tau = 0.
            s.b = compare_default(s.a());
            changed = restart = turned_on = true;
            ui_.status = "compare: setup B beside A";
        } else {
            ui_.editing_b = false;
            ui_.status = "compare off";
        }
    }
    if (e.b_setup) {
        if (const std::string err = params_error(e.b_setup->params, s); err.empty())
            s.b = *e.b_setup, changed = restart = true;
        else
            ui_.status = "setup B: " + err;
    }
    if (e.b.model && *e.b.model != s.b.model) s.b.model = *e.b.model, changed = true;
    if (e.b.start && *e.b.start != s.b.start) s.b.start = *e.b.start, changed = restart = true;
    if (e.b.params) {
        if (const std::string err = params_error(*e.b.params, s); err.empty())
            s.b.params = *e.b.params, changed = true;
        else
            ui_.status = "setup B: " + err;
    }
    if (e.editing_b) ui_.editing_b = *e.editing_b && s.compare;
    // B's view appears in its own frame at once (easing is for a frame on screen that changes).
    if (turned_on) b_.retarget_frame(s.b, s.view.trail_periods, view_aspect_, true);
    return changed && s.compare;
}

ViewState AppState::view_of(const SetupRun& run) const {
    ViewState v = ui_.session.view;
    v.box = run.frame();
    v.aspect = view_aspect_;
    return v;
}

void AppState::retarget_frames(bool snap) {
    const double trail = ui_.session.view.trail_periods;
    a_.retarget_frame(ui_.session.a(), trail, view_aspect_, snap);
    // B's while it is shown; turned on, it eases from wherever it was left (or snaps with A).
    if (ui_.session.compare || snap) b_.retarget_frame(ui_.session.b, trail, view_aspect_, snap);
}

double AppState::frame_tau() const {
    return ui_.session.speed * 2 * kPi / 60;
}

void AppState::advance(double dt) {
    // The frames ease in wall time, playing or not. Both setups run on one time base: the same periods of
    // simulation time each frame (B's steps are its own, as fine as its parameters need).
    const bool compare = ui_.session.compare;
    a_.ease(dt);
    if (compare) b_.ease(dt);
    // While rewound, playing replays the history towards the live state; then the simulations run on.
    if (ui_.session.playing && ui_.session.view.rewind > 0) {
        ui_.session.view.rewind = std::max(0.0, ui_.session.view.rewind - dt * ui_.session.speed * 2 * kPi);
    } else if (ui_.session.playing) {
        a_.run(dt * ui_.session.speed);
        if (compare) b_.run(dt * ui_.session.speed);
    }
    // One frame forward: through the history while rewound, else the simulations' steps of one frame.
    if (step_pending_) {
        if (ui_.session.view.rewind > 0) {
            ui_.session.view.rewind = std::max(0.0, ui_.session.view.rewind - frame_tau());
        } else {
            a_.step_frame(frame_tau());
            if (compare) b_.step_frame(frame_tau());
        }
        step_pending_ = false;
    }
}

void AppState::pin_current_curve(bool wait) {
    if (ui_.session.pins.size() >= kMaxPins) {
        ui_.status = std::to_string(kMaxPins) + " curves pinned: clear the pins to pin more";
        return;
    }
    if (wait) a_.worker().wait_idle();
    const auto curves = a_.worker().latest();
    if (!curves ||
        !(curves->request == ratio_request(ui_.session.a(), ui_.session.panel == LowerPanel::map))) {
        ui_.status = "the curve is still being computed: pin it once it is drawn";
        return;
    }
    PinnedCurve pin = pin_of(pin_source(ui_.session.model, ui_.session.params, ui_.session.start), *curves);
    ui_.status = "pinned: " + pin.label;
    ui_.session.pins.push_back(std::move(pin));
}

void AppState::jump_to_steady() {
    ui_.session.view.rewind = 0;
    std::string why = a_.jump_to_steady(ui_.session.a());
    // B onto its own steady state too (a rigid B has none to skip to and is steady already).
    if (ui_.session.compare && ui_.session.b.model == Model::dahl) {
        const std::string b_why = b_.jump_to_steady(ui_.session.b);
        if (!b_why.empty()) why = "setup B: " + b_why;
    }
    ui_.status =
        why.empty() ? "on the steady state: P - T = L* at each period start (the solver's fixed point)" : why;
}

} // namespace fv::app
