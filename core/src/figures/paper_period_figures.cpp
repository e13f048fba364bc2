// The paper's figures of one steady-state period: the step of the tracking scheme (Fig. 8), top views of P
// and T (Figs. 9, 14 with its panels 14a and 14b, 17) and the friction force (Figs. 15, 16, 18). Each
// registers itself (figure_registry.hpp); the title of each names its parameters.
#include "fv/figure_registry.hpp"

namespace fv {
namespace {

constexpr double kDeg = kPi / 180;

// What a figure of one steady period of `kind` draws (overlay_other_i: a top view's only).
FigureContent period_content(FigureKind kind, const Params& p, int steps_per_period, bool overlay_other_i) {
    if (kind == FigureKind::step_view) return StepViewFigure{p, steps_per_period};
    if (kind == FigureKind::period_force) return PeriodForceFigure{p, steps_per_period};
    return PeriodViewFigure{p, steps_per_period, overlay_other_i};
}

FigureEntry period_figure(const char* id, const std::string& list_title, FigureKind kind, Params p,
                          std::string title, std::string caption, int steps_per_period = 0,
                          bool overlay_other_i = false) {
    FigureSpec f;
    f.id = id;
    f.title = std::move(title);
    f.caption = std::move(caption);
    f.content = period_content(kind, p, steps_per_period, overlay_other_i);
    FigureEntry e;
    e.id = id;
    e.title = list_title;
    e.kind = kind;
    e.make = [f](const FigureInputs&) { return f; };
    return e;
}

const Params kFig14a{0.15, 90 * kDeg, 2, 1}, kFig14b{0.15, 90 * kDeg, 2, 0}, kFig17{0.5, 90 * kDeg, 2, 1};

const RegisterFigure register_fig8{period_figure(
    "fig8", "one step of the tracking scheme, Eqs. (17)-(22)", FigureKind::step_view, kFig14a,
    "Fig. 8: one tracking step (24 per period), " + params_title(kFig14a),
    "One step of the tracking scheme (Eqs. 17–22), 24 steps per period so that it is visible: T(t) is pulled "
    "along the line T(t)–P(t+Δt) to T(t+Δt), at the new deflection z(t+Δt). ζ = 0.15, θ = 90°, r_disp = 2, "
    "i = 1.",
    24)};

const RegisterFigure register_fig9{period_figure(
    "fig9", "asperity over one steady-state period", FigureKind::period_view, {0.3, 60 * kDeg, 2, 1},
    "Fig. 9: one steady-state period, " + params_title({0.3, 60 * kDeg, 2, 1}),
    "P and T over one steady-state period, the spring P–T drawn at 24 instants. ζ = 0.3, θ = 60°, r_disp = "
    "2, "
    "i = 1 (parameters not in the paper).")};

// Fig. 14 as in the paper: (a) i = 1 and (b) i = 0 side by side on shared axes. fig14a and fig14b are its
// panels alone, on the same axes (the app's presets load their parameters).
const char* const kFig14What[] = {
    "i = 1: the path of P is squeezed in x and the asperity relaxes in the tight turns",
    "i = 0 (stiction, Eq. 27): the tip sticks until the deflection reaches z_ss"};

FigureEntry with_panels(FigureEntry e, int only_panel) {
    e.make = [make = e.make, only_panel](const FigureInputs& in) {
        FigureSpec f = make(in);
        auto& view = std::get<PeriodViewFigure>(f.content);
        view.panel_i = {1, 0};
        view.only_panel = only_panel;
        return f;
    };
    return e;
}

FigureEntry fig14_panel(int k) {
    const std::string tag(1, "ab"[k]);
    const Params& p = k == 0 ? kFig14a : kFig14b;
    return with_panels(
        period_figure(("fig14" + tag).c_str(),
                      "panel (" + tag + ") of fig14 alone, i = " + (k == 0 ? "1" : "0") +
                          " (the app's preset)",
                      FigureKind::period_view, p,
                      "Fig. 14" + tag + ": " + params_title(p) + (k == 0 ? " (no stiction)" : " (stiction)"),
                      "Panel (" + tag + ") of Fig. 14 alone, on its axes: r_disp = 2, ζ = 0.15, θ = 90°, " +
                          kFig14What[k] + "."),
        k);
}

const RegisterFigure register_fig14{with_panels(
    period_figure(
        "fig14", "top views, ζ = 0.15, θ = 90°, r_disp = 2: (a) i = 1, (b) i = 0, shared axes",
        FigureKind::period_view, kFig14a, "Fig. 14: ζ = 0.15, θ = 90°, r_{disp} = 2; (a) i = 1, (b) i = 0",
        std::string("P and T over one steady-state period, r_disp = 2, ζ = 0.15, θ = 90°, on shared "
                    "axes: (a) ") +
            kFig14What[0] + "; (b) " + kFig14What[1] + "."),
    -1)};
const RegisterFigure register_fig14a{fig14_panel(0)};
const RegisterFigure register_fig14b{fig14_panel(1)};

const RegisterFigure register_fig15{period_figure(
    "fig15", "friction force over one period, ζ = 0.15, i = 1", FigureKind::period_force, kFig14a,
    "Fig. 15: friction force over one period, " + params_title(kFig14a),
    "F_x, F_y and |F| over the steady period of Fig. 14a (ζ = 0.15, θ = 90°, r_disp = 2, i = 1): |F| drops "
    "well below F_c while the asperity relaxes." +
        std::string(kForceConvention))};

const RegisterFigure register_fig16{period_figure(
    "fig16", "friction force over one period, ζ = 0.15, i = 0", FigureKind::period_force, kFig14b,
    "Fig. 16: friction force over one period, " + params_title(kFig14b),
    "F_x, F_y and |F| over the steady period of Fig. 14b (ζ = 0.15, θ = 90°, r_disp = 2, i = 0)." +
        std::string(kForceConvention))};

const RegisterFigure register_fig17{period_figure(
    "fig17", "top view, ζ = 0.5, θ = 90°, r_disp = 2, i = 1 and 0", FigureKind::period_view, kFig17,
    "Fig. 17: ζ = 0.5, θ = 90°, r_{disp} = 2, i = 1 (solid) and i = 0 (dashed)",
    "ζ = 0.5, θ = 90°, r_disp = 2: the asperity never relaxes; i = 1 (solid) and i = 0 (dashed) coincide.", 0,
    true)};

const RegisterFigure register_fig18{period_figure(
    "fig18", "friction force over one period, ζ = 0.5, i = 1", FigureKind::period_force, kFig17,
    "Fig. 18: friction force over one period, " + params_title(kFig17),
    "F_x, F_y and |F| over the steady period of Fig. 17 (ζ = 0.5, θ = 90°, r_disp = 2, i = 1): |F| = F_c "
    "throughout." +
        std::string(kForceConvention))};

} // namespace
} // namespace fv
