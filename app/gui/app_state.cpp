#include "app_state.hpp"

#include "fv/figures.hpp"
#include "fv/format.hpp"
#include "fv/units.hpp"

#include <algorithm>
#include <cmath>

namespace fv::app {

AppState::AppState(Model model, const Params& params, double amplitude_um, double frequency_khz,
                   std::optional<MeasurementSet> data)
    : sim_(model, params) {
    ui_.model = model;
    ui_.params = params;
    ui_.amplitude_um = amplitude_um;
    ui_.frequency_khz = frequency_khz;
    if (data) ui_.status = show_measured(ui_, std::move(*data));
    sim_.set_history_periods(std::max(ui_.view.trail_periods, 2.0));
    refresh_units();
    worker_.request(ratio_request());
}

RatioRequest AppState::ratio_request() const {
    return RatioRequest{ui_.model, ui_.params, ui_.show_map, ratio_zeta_max(ui_.data ? &*ui_.data : nullptr)};
}

void AppState::refresh_units() {
    try {
        ui_.vv_m_s = units::vibration_velocity(ui_.amplitude_um, ui_.frequency_khz);
        ui_.vb_m_s = vb_of(ui_);
        ui_.zss_um = zss_of(ui_);
    } catch (const units::UnitError&) {
        ui_.vv_m_s = ui_.vb_m_s = ui_.zss_um = std::nan(""); // A and f are checked on every edit
    }
}

AppState::Actions AppState::sync(const UiEdits& e, bool wait) {
    ++syncs_;
    std::optional<Params> params = e.params;
    std::optional<Model> model = e.model;
    bool reset = e.reset;
    if (e.preset) {
        if (const FigureSpec* f = find_figure(*e.preset)) {
            params = f->params;
            model = Model::dahl;
            reset = true;
        }
    }
    bool model_changed = false, data_changed = false;
    if (model && *model != ui_.model) ui_.model = *model, model_changed = true;
    // Parameters and their physical inputs: one candidate, checked once against the range table.
    if (params || e.vb_m_s || e.zss_um) {
        Params p = params.value_or(ui_.params);
        std::string err;
        try {
            if (e.vb_m_s) p.zeta = units::zeta_from_vb(*e.vb_m_s, ui_.amplitude_um, ui_.frequency_khz);
            if (e.zss_um) p.rdisp = units::rdisp_from_zss(ui_.amplitude_um, *e.zss_um);
        } catch (const units::UnitError& x) {
            err = x.what();
        }
        if (err.empty()) err = range_error(p);
        if (err.empty())
            ui_.params = p, model_changed = true;
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
    if (e.fit_data && ui_.data && ui_.model == Model::dahl) {
        fit_.start(ui_);
        ui_.status = "fitting r_disp and i to " + std::to_string(ui_.data->points.size()) + " points…";
    }
    // A finished fit sets r_disp and i.
    if (const auto done = fit_.poll(ui_, wait)) {
        ui_.status = done->status;
        if (done->params) ui_.params = *done->params, model_changed = true;
    }
    ui_.fitting = fit_.running();
    if (e.playing) ui_.playing = *e.playing;
    bool ask_worker = false;
    if (e.show_map && *e.show_map != ui_.show_map) ui_.show_map = *e.show_map, ask_worker = true;
    if (e.speed) ui_.speed = std::clamp(*e.speed, kSpeedRange.lo, kSpeedRange.hi);
    if (e.trail_periods) {
        ui_.view.trail_periods = std::clamp(*e.trail_periods, kTrailRange.lo, kTrailRange.hi);
        sim_.set_history_periods(std::max(ui_.view.trail_periods, 2.0));
    }
    if (model_changed) sim_.apply(ui_.model, ui_.params);
    if (model_changed || ask_worker || data_changed) worker_.request(ratio_request());
    if (reset) sim_.reset(), step_carry_ = 0;
    step_pending_ = e.step;
    refresh_units();
    return {e.screenshot, e.export_csv, e.quit};
}

void AppState::advance(double dt) {
    if (ui_.playing) {
        step_carry_ += dt * ui_.speed * sim_.steps_per_period();
        const int n = static_cast<int>(step_carry_);
        step_carry_ -= n;
        sim_.step(n);
    }
    if (step_pending_) sim_.step(1), step_pending_ = false;
}

} // namespace fv::app
