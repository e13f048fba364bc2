#include "controls.hpp"

#include "app_state.hpp"
#include "help_overlay.hpp"
#include "lesson_card.hpp"
#include "lessons.hpp"

#include "figures/figure_painter.hpp"

#include "fv/figures.hpp"
#include "fv/format.hpp"
#include "fv/param_ranges.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace fv::app {

void UiEdits::merge(const UiEdits& o) {
    if (o.model) model = o.model;
    if (o.start) start = o.start;
    if (o.params) params = o.params, vb_m_s.reset(), zss_um.reset();
    if (o.vb_m_s) vb_m_s = o.vb_m_s;
    if (o.zss_um) zss_um = o.zss_um;
    if (o.playing) playing = o.playing;
    if (o.panel) panel = o.panel;
    if (o.show_help) show_help = o.show_help;
    if (o.presentation) presentation = o.presentation;
    pin |= o.pin;
    if (o.clear_pins) clear_pins = true, pin = false;
    if (o.speed) speed = o.speed;
    if (o.trail_periods) trail_periods = o.trail_periods;
    if (o.preset) preset = o.preset;
    if (o.lesson) lesson = o.lesson;
    if (o.compare) compare = o.compare;
    if (o.b_setup) b_setup = o.b_setup, b = SetupEdits{};
    b.merge(o.b);
    if (o.editing_b) editing_b = o.editing_b;
    if (o.zoom) zoom = o.zoom;
    if (o.pan) pan = o.pan;
    if (o.frame) frame = o.frame;
    if (o.view_aspect) view_aspect = o.view_aspect;
    reset_view |= o.reset_view;
    if (o.status) status = o.status;
    if (o.amplitude_um) amplitude_um = o.amplitude_um;
    if (o.frequency_khz) frequency_khz = o.frequency_khz;
    if (o.load_data) load_data = o.load_data, clear_data = false;
    if (o.clear_data) clear_data = true, load_data.reset();
    if (o.example_data) example_data = o.example_data, drop_example_data = false;
    if (o.drop_example_data) drop_example_data = true, example_data.reset();
    if (o.open_session) open_session = o.open_session;
    if (o.save_session) save_session = o.save_session;
    fit_data |= o.fit_data;
    step |= o.step;
    if (o.rewind) rewind = o.rewind;
    step_back |= o.step_back;
    jump_steady |= o.jump_steady;
    reset |= o.reset;
    screenshot |= o.screenshot;
    export_csv |= o.export_csv;
    open_export_dialog |= o.open_export_dialog;
    if (o.export_animation) export_animation = o.export_animation;
    quit |= o.quit;
}

std::vector<const FigureSpec*> presets() {
    std::vector<const FigureSpec*> v;
    for (const auto& f : paper_figures()) {
        const auto* view = std::get_if<PeriodViewFigure>(&f.content);
        if (view && (view->panel_i.empty() || view->only_panel >= 0))
            v.push_back(&f); // fig14's panels, not fig14 itself (two parameter sets)
    }
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

// A parameter's tooltip: its meaning, the slider's span and what can be typed (Ctrl+click) — the range
// table's.
void range_tooltip(const char* meaning, ParamRange slider, ParamRange allowed) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::SetTooltip("%s\nslider %s; Ctrl+click to type any value in %s", meaning, describe(slider).c_str(),
                      describe(allowed).c_str());
}

// Where more than one stable steady state coexists (below the start control, which picks between them):
// each r_x with the start that reaches it, and which one the animation is in (its last period's mean F_x
// nearest a state's r_x), or that it is still settling.
void draw_coexisting_states(const std::optional<RatioCurves>& curves, const LiveSim& sim) {
    if (!curves) return;
    const std::vector<SteadyState>& states = coexisting_states(*curves);
    if (states.empty()) return;
    const Params& q = curves->request.params;
    const Params& p = sim.params();
    // The animation is only compared with the states of its own parameters (not a result still computing).
    const bool current = curves->request.model == sim.model() && q.zeta == p.zeta && q.theta == p.theta &&
                         q.rdisp == p.rdisp && q.i == p.i;
    const int in = current ? state_of_motion(states, sim.last_period_mean().x(), kMotionStateTolerance) : -1;
    ImGui::TextColored(ImVec4(0.0f, 0.35f, 0.7f, 1.0f), "%zu stable steady states here:", states.size());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%zu periodic motions are stable at these parameters; where the motion starts "
                          "decides which one it ends in. The readouts and the r_x(ζ) curve are the one "
                          "reached from %s. The animation is in the state whose r_x its last period's mean "
                          "F_x is nearest (within %.2g).",
                          states.size(), curves->request.start == Start::sliding ? "sliding" : "rest",
                          kMotionStateTolerance);
    // Wrapped, never clipped: the panel's width in characters is smaller in presentation mode.
    ImGui::Indent();
    for (std::size_t k = 0; k < states.size(); ++k)
        ImGui::TextWrapped("r_x %s  %s%s", format_number("%.4f", states[k].rx).c_str(),
                           reached_from(states[k]), static_cast<int>(k) == in ? "  ← animation" : "");
    if (in < 0 && current) ImGui::TextWrapped("the animation is still settling");
    ImGui::Unindent();
}

// The colours of setups A and B (the plots' blue and orange, ink_color), for the panel's text and buttons.
ImVec4 setup_colour(bool b) {
    const gfx::Color c = ink_color(b ? Ink::setup_b : Ink::body, 0);
    return ImVec4(c.r, c.g, c.b, 1);
}

// Compare mode (turned on from the View menu or with C): its switch, and which setup the controls below
// edit, in the setups' colours. Only while it is on: the panel keeps its rows otherwise.
UiEdits draw_compare_controls(const UiState& ui) {
    UiEdits e;
    if (!ui.session.compare) return e;
    bool compare = ui.session.compare;
    if (ImGui::Checkbox("Compare A | B [C]", &compare)) e.compare = compare;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Two setups side by side on one time base: A (blue) and B (orange), two top views, "
                          "both force traces and both r_x points. Turned on, B is A at the other angle "
                          "(θ = 90°, or 0° when A is at 90°).");
    ImGui::SameLine();
    ImGui::TextUnformatted("edit:");
    for (const bool b : {false, true}) {
        ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Text, setup_colour(b));
        if (ImGui::RadioButton(b ? "B##edit" : "A##edit", ui.editing_b == b)) e.editing_b = b;
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the sliders, the model and the start below set up %s (B key: switch)",
                              b ? "B" : "A");
    }
    return e;
}

// The model's parameters, the model and the start (with the coexisting states where there are several) of
// setup A, or of B when compare mode edits B: the same controls, their edits sent to the one shown.
UiEdits draw_parameter_controls(const UiState& ui, const LiveSim& sim,
                                const std::optional<RatioCurves>& curves, const ShareAddress& share) {
    UiEdits e;
    const bool edit_b = ui.session.compare && ui.editing_b;
    const Setup& shown = edit_b ? ui.session.b : ui.session.a();
    Params p = shown.params;
    double theta_deg = p.theta * 180 / kPi;
    bool changed = false;
    if (edit_b)
        ImGui::TextColored(setup_colour(true), "Parameters of B");
    else if (ui.session.compare)
        ImGui::TextColored(setup_colour(false), "Parameters of A");
    else
        ImGui::TextUnformatted("Parameters");
    ImGui::SameLine();
    e.merge(draw_share_link(ui, share)); // the share link of this state, on the header's row
    e.merge(draw_compare_controls(ui));
    SetupEdits edits; // the setup's own, sent to A's or B's below
    if (edit_b) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.9f, 0.62f, 0.0f, 0.25f));
    changed |= slider_double("ζ", &p.zeta, kSliders.zeta, "%.3f");
    range_tooltip("velocity ratio ζ = v_b / v_v, Eq. (6)", kSliders.zeta, kZetaRange);
    changed |= slider_double("θ [°]", &theta_deg, kSliders.theta_deg, "%.1f");
    range_tooltip("angle θ of the vibration to the sliding velocity in degrees, Eq. (1)", kSliders.theta_deg,
                  kThetaRange);
    for (double q : {0.0, 30.0, 45.0, 60.0, 90.0}) {
        char b[16];
        std::snprintf(b, sizeof b, "%g°", q);
        if (ImGui::SmallButton(b)) theta_deg = q, changed = true;
        ImGui::SameLine();
    }
    ImGui::NewLine();
    const bool dahl = shown.model == Model::dahl;
    if (!dahl) ImGui::BeginDisabled();
    changed |= slider_double("r_disp", &p.rdisp, kSliders.rdisp, "%.3g", true);
    range_tooltip("displacement ratio x_v / z_ss, Eq. (34): large = stiff contact", kSliders.rdisp,
                  kRdispRange);
    changed |= slider_double("i", &p.i, kSliders.i, "%.2f");
    range_tooltip("Dahl shape exponent, Eq. (12); i = 0 sticks below z_ss (Eq. 27)", kSliders.i, kIRange);
    if (ImGui::SmallButton("i = 0 (stiction)")) p.i = 0, changed = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "%s",
            "i = 0: the asperity sticks until it is stretched to z_ss, then slips (Coulomb with a spring)");
    ImGui::SameLine();
    if (ImGui::SmallButton("i = 1")) p.i = 1, changed = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", "i = 1: the classic Dahl law, the force rises smoothly to F_c");
    if (!dahl) ImGui::EndDisabled();
    int model = dahl ? 0 : 1;
    if (ImGui::RadioButton("Dahl (compliant)", &model, 0)) edits.model = Model::dahl;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s",
                          "the asperity bends (Dahl law, Eq. 12): friction builds up over a stretch z_ss");
    ImGui::SameLine();
    if (ImGui::RadioButton("rigid", &model, 1)) edits.model = Model::rigid;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "%s", "Coulomb friction, F_c against the velocity at every instant (Eq. 2; r_disp -> infinity)");
    // The history (docs/model.md, "Which steady state"): it decides which steady state the motion reaches
    // where two coexist. The rigid model has no deflection to start from, so no choice there.
    if (!dahl) ImGui::BeginDisabled();
    const char* starts[] = {"from rest (paper)", "switched on while sliding"};
    int start = shown.start == Start::sliding ? 1 : 0;
    if (ImGui::Combo("start", &start, starts, 2)) edits.start = start == 1 ? Start::sliding : Start::rest;
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(
            "%s",
            "Where the motion starts. Where two stable steady states coexist, this history decides which "
            "one the motion ends in (a hysteresis).\n"
            "from rest (the paper's start): sliding and vibration begin together, the asperity unstretched "
            "(T = P, no force).\n"
            "switched on while sliding: the body already slides steadily, the asperity fully deflected "
            "against v_b (P - T = z_ss along v_b, the force F_c); then the vibration is switched on.\n"
            "Choosing one starts the motion again from it; r_x and the r_x(ζ) curve are that start's.");
    if (!dahl) ImGui::EndDisabled();
    if (dahl && !edit_b) draw_coexisting_states(curves, sim);
    if (edit_b) ImGui::PopStyleColor();
    if (changed) {
        p.theta = theta_deg * kPi / 180;
        edits.params = p;
    }
    if (edit_b) {
        e.b.merge(edits);
    } else {
        if (edits.model) e.model = edits.model;
        if (edits.start) e.start = edits.start;
        if (edits.params) e.params = edits.params;
    }
    return e;
}

// The next item, `width` wide, beside the last one where it fits within the panel's width, else on a new
// line.
void same_line_if_fits(float width) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
}

// A row of buttons that wraps to the panel's width (large type in presentation mode, narrow windows):
// each button beside the one before while it fits, else on a new line. Returns the label clicked, or null.
// Labels and tips point into the lessons and the registry, which outlive the frame.
using LabelAndTip = std::pair<const std::string*, const std::string*>;
const std::string* button_row(const std::vector<LabelAndTip>& labels_and_tips) {
    const std::string* clicked = nullptr;
    for (std::size_t k = 0; k < labels_and_tips.size(); ++k) {
        const auto [label, tip] = labels_and_tips[k];
        if (k > 0)
            same_line_if_fits(ImGui::CalcTextSize(label->c_str()).x + 2 * ImGui::GetStyle().FramePadding.x);
        if (ImGui::Button(label->c_str())) clicked = label;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip->c_str());
    }
    return clicked;
}

// The presets: the lesson's steps by concept (lessons.json), then the registered figures the app can open.
UiEdits draw_presets() {
    UiEdits e;
    std::vector<LabelAndTip> concepts, figures;
    for (const LessonStep& s : lesson_steps()) concepts.emplace_back(&s.id, &s.title);
    for (const FigureSpec* f : presets()) figures.emplace_back(&f->id, &f->caption);
    ImGui::TextUnformatted("Concepts");
    if (const std::string* id = button_row(concepts)) e.preset = *id;
    ImGui::TextUnformatted("Paper figures");
    if (const std::string* id = button_row(figures)) e.preset = *id;
    return e;
}

// Play, reset, the steady-state jump, stepping and the time slider, speed and trail.
UiEdits draw_animation_controls(const UiState& ui, const LiveSim& sim) {
    UiEdits e;
    ImGui::Separator();
    ImGui::TextUnformatted("Animation");
    const bool rewound = ui.session.view.rewind > 0;
    if (ImGui::Button(ui.session.playing ? (rewound ? "Pause replay" : "Pause [Space]")
                                         : (rewound ? "Replay [Space]" : "Play [Space]")))
        e.playing = !ui.session.playing;
    ImGui::SameLine();
    if (ImGui::Button("Reset [R]")) e.reset = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s",
                          "start again at time 0 from the start chosen above (from rest: an unstretched "
                          "asperity; while sliding: fully deflected against v_b)");
    ImGui::SameLine();
    if (ImGui::Button("Steady state [J]")) e.jump_steady = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Skip the transient: put the tip on the periodic steady state that r_x is the mean "
                          "of (the solver's fixed point), and animate one period of it.");
    // Time: one frame back or forward, and a scrub slider over the history kept (kHistoryPeriods periods).
    if (ImGui::Button("←")) e.step_back = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("one frame back [←] (pauses)");
    ImGui::SameLine();
    if (ImGui::Button("→")) e.step = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("one frame forward [→]");
    ImGui::SameLine();
    const double reach = max_rewind(sim) / (2 * kPi);
    double ago = ui.session.view.rewind / (2 * kPi);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 64);
    // Reversed (the past on the left, now on the right), the value never hidden: "live" or "N periods ago".
    if (slider_double("##time", &ago, std::max(reach, 1e-3), 0, rewound ? "%.2f periods ago" : "live"))
        e.rewind = ago * 2 * kPi;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Drag back to rewind through the last %.1f periods (pauses); Play replays from "
                          "there to the live state.",
                          reach);
    ImGui::SameLine();
    ImGui::TextUnformatted("time");
    double speed = ui.session.speed, trail = ui.session.view.trail_periods;
    if (slider_double("periods/s", &speed, kSpeedRange.lo, kSpeedRange.hi, "%.2f", true)) e.speed = speed;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("animation speed: vibration periods per second of wall time, %s",
                          describe(kSpeedRange).c_str());
    if (slider_double("trail", &trail, 0.25, 4, "%.2f periods")) e.trail_periods = trail;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("how much of P's and T's past path the top view draws, fading (periods)");
    // The top view's camera: riding on the body, or standing on the floor (a stuck tip then stands still).
    const FrameChoice frame = ui.session.view.frame;
    if (ImGui::RadioButton("body", frame == FrameChoice::body)) e.frame = FrameChoice::body;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The camera rides on the body: the body stays put and the floor slides past "
                          "underneath, so a tip stuck to the floor moves backwards on screen.");
    ImGui::SameLine();
    if (ImGui::RadioButton("ground", frame == FrameChoice::ground)) e.frame = FrameChoice::ground;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The camera stands on the floor: a tip stuck to the floor stands still, and the "
                          "body drifts across and comes back in at the other edge.");
    ImGui::SameLine();
    ImGui::TextUnformatted("frame of the top view");

    return e;
}

// What the motion does now and the steady state it tends to: read only.
void draw_readouts(const UiState& ui, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                   bool busy) {
    ImGui::Separator();
    // Readouts two to a line: the panel must leave room for the data section on an 800-pixel screen.
    const SimMoment now = moment_at(sim, ui.session.view.rewind);
    // In compare mode these are A's (B's r_x is in the ratio plot's title).
    if (ui.session.compare) {
        ImGui::TextColored(setup_colour(false), "A:");
        ImGui::SameLine();
    }
    if (sim.model() == Model::rigid)
        ImGui::Text("Now  τ/2π %.2f   rigid: F = F_c against v", now.tau / (2 * kPi));
    else
        ImGui::Text("Now  τ/2π %.2f   z/z_ss %.3f   %s", now.tau / (2 * kPi), now.z / sim.params().zss(),
                    now.slip ? "slips" : (sim.params().i == 0 ? "sticks" : "creeps"));
    // The live mean and the steady r_x: equal once the transient is over (up to the animation's step).
    const double mean = sim.last_period_mean().x();
    if (std::isfinite(mean)) {
        const bool settled = curves && std::abs(mean - curves->current.rx) < 2e-3;
        // Where two states coexist the motion may settle in the one the start does not reach (a parameter
        // moved during the run): that is steady too, not a transient.
        const int in = curves ? state_of_motion(coexisting_states(*curves), mean, kMotionStateTolerance) : -1;
        const bool other = in >= 0 && std::abs(coexisting_states(*curves)[static_cast<std::size_t>(in)].rx -
                                               curves->current.rx) > 1e-6;
        ImGui::Text("period mean F_x %s%s", format_number("%.4f", mean).c_str(),
                    curves ? (settled ? " = r_x: steady"
                              : other ? ": another stable state"
                                      : " ≠ r_x: transient")
                           : "");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The mean of F_x over the last animated period (Eq. 30) approaches the steady r_x "
                "as the motion settles from its start (the start control). Until then "
                "they differ; 'Steady state [J]' skips the transient. A few 1e-3 remain from "
                "the animation's %d steps per period.",
                sim.steps_per_period());
    }
    ImGui::Separator();
    if (curves) {
        // format_number: a value that rounds to zero reads "0.00000", never "-0.00000".
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
        if (curves->request.model == Model::dahl && !ui.session.presentation) {
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
}

// The lower-right panel: the r_x(zeta) curves (with pins), the (zeta, theta) map, the loop or the mechanism.
UiEdits draw_panel_choice(const UiState& ui) {
    UiEdits e;
    ImGui::Separator();
    // The radio buttons in LowerPanel's order, each beside the one before while it fits (the panel is narrow
    // on a phone and in presentation mode).
    static constexpr std::pair<const char*, const char*> kRadios[] = {
        {"r_x(ζ)", "r_x over the velocity ratio for this θ, r_disp, i, and the rigid model"},
        {"map", "r_x over velocity ratio and angle for this r_disp and i, with the best angle θ*(ζ)"},
        {"loop", "the asperity's force along the vibration against the vibration displacement over the last "
                 "period: its area is the energy the vibration loses to friction"},
        {"why",
         "the mechanism (the paper's Fig. 4): the body's velocity turns with the vibration, the friction "
         "turns with it, and its mean against v_b is less than F_c"},
        {"setup", "the experiment the model stands for: a block pressed on a rough floor, pulled at v_b and "
                  "shaken at the angle θ; the contact magnified"},
    };
    static_assert(std::size(kRadios) == std::size(kLowerPanels));
    int panel = static_cast<int>(ui.session.panel);
    const int before = panel;
    for (int k = 0; k < static_cast<int>(std::size(kRadios)); ++k) {
        const auto [label, tip] = kRadios[k];
        if (k > 0)
            same_line_if_fits(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                              ImGui::CalcTextSize(label).x);
        ImGui::RadioButton(label, &panel, k);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    }
    if (panel != before) e.panel = kLowerPanels[panel];
    if (ImGui::Button("Pin curve")) e.pin = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("keep this r_x(ζ) curve on the plot to compare with others (up to %zu)", kMaxPins);
    ImGui::SameLine();
    if (ImGui::Button("Clear pins")) e.clear_pins = true;
    ImGui::SameLine();
    ImGui::Text("%zu pinned", ui.session.pins.size());
    return e;
}

} // namespace

UiEdits draw_controls(const UiState& ui, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                      bool busy, ControlsPlace& place, FileDialogs& dialog, const ShareAddress& share) {
    UiEdits e;
    ImGui::SetNextWindowPos(ImVec2(place.rect.x0, place.rect.y0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(place.rect.width(), place.rect.height()), ImGuiCond_Always);
    ImGui::Begin("frictionviz", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_MenuBar);
    e.merge(draw_menu(ui, dialog));
    e.merge(draw_lesson_card(ui));
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 4.8f); // room for the labels at any font size
    e.merge(draw_parameter_controls(ui, sim, curves, share));
    // Presentation mode folds the physical units, the search details and the data away; the presets stay
    // (a lecture jumps between them).
    if (!ui.session.presentation) {
        ImGui::Separator();
        e.merge(draw_vibration_controls(ui));
    }
    ImGui::Separator();
    e.merge(draw_presets());
    e.merge(draw_animation_controls(ui, sim));
    draw_readouts(ui, sim, curves, busy);
    e.merge(draw_panel_choice(ui));
    if (!ui.session.presentation) {
        ImGui::Separator();
        e.merge(draw_data_controls(ui, dialog));
    }
    // Export trace CSV and Screenshot [S] are in the File menu: the panel keeps its rows for the teaching.
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::PopItemWidth();
    e.merge(draw_file_dialogs(dialog));
    place.scroll_max = ImGui::GetScrollMaxY();
    ImGui::End();
    return e;
}

UiEdits keyboard_edits(const UiState& ui) {
    UiEdits e;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return e;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) e.playing = !ui.session.playing;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), true)) e.step = true;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow), true)) e.step_back = true;
    if (ImGui::IsKeyPressed('J', false)) e.jump_steady = true;
    if (help_key_pressed()) e.show_help = !ui.show_help;
    if (ImGui::IsKeyPressed('P', false)) e.presentation = !ui.session.presentation;
    if (ImGui::IsKeyPressed('R', false)) e.reset = true;
    if (ImGui::IsKeyPressed('C', false)) e.compare = !ui.session.compare;
    if (ImGui::IsKeyPressed('B', false) && ui.session.compare) e.editing_b = !ui.editing_b;
    if (ImGui::IsKeyPressed('S', false)) e.screenshot = true;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) e.quit = true;
    e.merge(lesson_keys(ui));
    return e;
}

} // namespace fv::app
