#include "controls.hpp"

#include "fv/figures.hpp"
#include "fv/format.hpp"
#include "fv/param_ranges.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace fv::app {

void UiEdits::merge(const UiEdits& o) {
    if (o.model) model = o.model;
    if (o.params) params = o.params, vb_m_s.reset(), zss_um.reset();
    if (o.vb_m_s) vb_m_s = o.vb_m_s;
    if (o.zss_um) zss_um = o.zss_um;
    if (o.playing) playing = o.playing;
    if (o.show_map) show_map = o.show_map;
    if (o.speed) speed = o.speed;
    if (o.trail_periods) trail_periods = o.trail_periods;
    if (o.preset) preset = o.preset;
    if (o.amplitude_um) amplitude_um = o.amplitude_um;
    if (o.frequency_khz) frequency_khz = o.frequency_khz;
    if (o.load_data) load_data = o.load_data, clear_data = false;
    if (o.clear_data) clear_data = true, load_data.reset();
    fit_data |= o.fit_data;
    step |= o.step;
    reset |= o.reset;
    screenshot |= o.screenshot;
    export_csv |= o.export_csv;
    quit |= o.quit;
}

std::vector<const FigureSpec*> presets() {
    std::vector<const FigureSpec*> v;
    for (const auto& f : paper_figures())
        if (f.kind == FigureKind::period_view && (f.panel_i.empty() || f.only_panel >= 0))
            v.push_back(&f); // fig14's panels, not fig14 itself (two parameter sets)
    return v;
}

namespace {

bool slider_double(const char* label, double* v, double lo, double hi, const char* format, bool log = false) {
    return ImGui::SliderScalar(label, ImGuiDataType_Double, v, &lo, &hi, format,
                               log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
}
// A model parameter's slider spans a range of the shared table (fv/param_ranges.hpp).
bool slider_double(const char* label, double* v, ParamRange r, const char* format, bool log = false) {
    return slider_double(label, v, r.lo, r.hi, format, log);
}

void readout(const char* name, const char* fmt, double v) {
    ImGui::TextUnformatted(name);
    ImGui::SameLine(165);
    ImGui::Text(fmt, v);
}

} // namespace

UiEdits draw_controls(const UiState& ui, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                      bool busy, float width, float height, OpenDataDialog& dialog) {
    UiEdits e;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    ImGui::Begin("frictionviz", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_MenuBar);
    e.merge(draw_menu(ui, dialog));
    ImGui::PushItemWidth(-72);

    Params p = ui.params;
    double theta_deg = p.theta * 180 / kPi;
    bool changed = false;
    ImGui::TextUnformatted("Parameters");
    changed |= slider_double("ζ", &p.zeta, kSliders.zeta, "%.3f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("velocity ratio ζ = v_b / v_v, Eq. (6)");
    changed |= slider_double("θ [°]", &theta_deg, kSliders.theta_deg, "%.1f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("angle of the vibration to the sliding velocity, Eq. (1)");
    for (double q : {0.0, 30.0, 45.0, 60.0, 90.0}) {
        char b[16];
        std::snprintf(b, sizeof b, "%g°", q);
        if (ImGui::SmallButton(b)) theta_deg = q, changed = true;
        ImGui::SameLine();
    }
    ImGui::NewLine();
    const bool dahl = ui.model == Model::dahl;
    if (!dahl) ImGui::BeginDisabled();
    changed |= slider_double("r_disp", &p.rdisp, kSliders.rdisp, "%.3g", true);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("displacement ratio x_v / z_ss, Eq. (34): large = stiff contact");
    changed |= slider_double("i", &p.i, kSliders.i, "%.2f");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Dahl shape exponent, Eq. (12); i = 0 sticks below z_ss (Eq. 27)");
    if (ImGui::SmallButton("i = 0 (stiction)")) p.i = 0, changed = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("i = 1")) p.i = 1, changed = true;
    if (!dahl) ImGui::EndDisabled();
    int model = dahl ? 0 : 1;
    if (ImGui::RadioButton("Dahl (compliant)", &model, 0)) e.model = Model::dahl;
    ImGui::SameLine();
    if (ImGui::RadioButton("rigid", &model, 1)) e.model = Model::rigid;
    if (changed) {
        p.theta = theta_deg * kPi / 180;
        e.params = p;
    }

    ImGui::Separator();
    e.merge(draw_vibration_controls(ui));

    ImGui::Separator();
    ImGui::TextUnformatted("Paper figures");
    for (const FigureSpec* f : presets()) {
        if (ImGui::Button(f->id.c_str())) e.preset = f->id;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f->caption.c_str());
        ImGui::SameLine();
    }
    ImGui::NewLine();

    ImGui::Separator();
    ImGui::TextUnformatted("Animation");
    if (ImGui::Button(ui.playing ? "Pause [Space]" : "Play [Space]")) e.playing = !ui.playing;
    ImGui::SameLine();
    if (ImGui::Button("Step [→]")) e.step = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset [R]")) e.reset = true;
    double speed = ui.speed, trail = ui.view.trail_periods;
    if (slider_double("periods/s", &speed, 0.02, 3, "%.2f", true)) e.speed = speed;
    if (slider_double("trail", &trail, 0.25, 4, "%.2f periods")) e.trail_periods = trail;

    ImGui::Separator();
    // Readouts two to a line: the panel must leave room for the data section on an 800-pixel screen.
    ImGui::Text("Now  τ/2π %.2f   z/z_ss %.3f   %s", sim.tau() / (2 * kPi),
                sim.model() == Model::rigid ? 1.0 : sim.z() / sim.params().zss(),
                sim.model() == Model::rigid
                    ? "rigid"
                    : (sim.slipping() ? "slips" : (sim.params().i == 0 ? "sticks" : "creeps")));
    if (std::isfinite(sim.last_period_mean().x()))
        readout("F_x, last period mean", "%.4f", sim.last_period_mean().x());
    ImGui::Separator();
    if (curves) {
        ImGui::Text("Steady state%s  r_x %s   r_y %s", busy ? "…" : "",
                    format_number("%.5f", curves->current.rx).c_str(),
                    format_number("%.5f", curves->current.ry).c_str());
        // Values the solver does not vouch for get a badge beside them (on the next line if it does not fit).
        if (const SteadyStatus st = shown_status(curves->current); !ok(st)) {
            char badge[64];
            std::snprintf(badge, sizeof badge, "NOT VERIFIED: %s", to_string(st));
            ImGui::SameLine();
            if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(badge).x) ImGui::NewLine();
            ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.1f, 1.0f), "%s", badge);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("The solver does not vouch for r_x, r_y here (%s); frictionviz ratio exits "
                                  "with status 3 for these parameters.",
                                  to_string(st));
        }
        if (curves->model_failed > 0)
            ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.1f, 1.0f), "r_x(ζ): %d points failed, not drawn",
                               curves->model_failed);
        // What the search did (as `frictionviz ratio` says it), not a claim about how fast it converged.
        if (curves->request.model == Model::dahl) {
            const SteadyResult& r = curves->current;
            ImGui::Text("search: %d periods, %d Newton updates", r.periods, r.newton_steps);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("The steady state is the fixed point of the period map, found by Newton's "
                                  "method (%s); %ld stuck periods skipped in closed form.",
                                  r.on_circle ? "on the angle of the lag on the circle" : "in the plane",
                                  r.periods_skipped);
            ImGui::Text("error estimate %.1e", r.error_estimate);
        }
    } else {
        ImGui::TextUnformatted("Steady state (computing…)");
    }
    ImGui::Separator();
    bool show_map = ui.show_map;
    if (ImGui::Checkbox("(ζ, θ) map instead of r_x(ζ)", &show_map)) e.show_map = show_map;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "r_x over velocity ratio and angle for this r_disp and i, with the best angle θ*(ζ)");
    ImGui::Separator();
    e.merge(draw_data_controls(ui, dialog));
    ImGui::Separator();
    if (ImGui::Button("Export trace CSV")) e.export_csv = true;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot [S]")) e.screenshot = true;
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::PopItemWidth();
    e.merge(draw_open_dialog(dialog));
    ImGui::End();
    return e;
}

UiEdits keyboard_edits(const UiState& ui) {
    UiEdits e;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return e;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) e.playing = !ui.playing;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), true)) e.step = true;
    if (ImGui::IsKeyPressed('R', false)) e.reset = true;
    if (ImGui::IsKeyPressed('S', false)) e.screenshot = true;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) e.quit = true;
    return e;
}

} // namespace fv::app
