// The paper's figures of one steady-state period: the step of the tracking scheme (Fig. 8), top views of P
// and T (Figs. 9, 14a, 14b, 17) and the friction force (Figs. 15, 16, 18). Each registers itself
// (figure_registry.hpp); the title of each names its parameters.
#include "fv/figure_registry.hpp"

namespace fv {
namespace {

constexpr double kDeg = kPi / 180;

FigureEntry period_figure(const char* id, const char* list_title, FigureKind kind, Params p,
                          std::string title, std::string caption, int steps_per_period = 0,
                          bool overlay_other_i = false) {
    FigureSpec f;
    f.id = id;
    f.kind = kind;
    f.params = p;
    f.title = std::move(title);
    f.caption = std::move(caption);
    f.steps_per_period = steps_per_period;
    f.overlay_other_i = overlay_other_i;
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

const RegisterFigure register_fig14a{period_figure(
    "fig14a", "top view, ζ = 0.15, θ = 90°, r_disp = 2, i = 1", FigureKind::period_view, kFig14a,
    "Fig. 14a: " + params_title(kFig14a) + " (no stiction)",
    "r_disp = 2, ζ = 0.15, θ = 90°, i = 1: the path of P is squeezed in x and the asperity relaxes in the "
    "tight turns.")};

const RegisterFigure register_fig14b{period_figure(
    "fig14b", "top view, ζ = 0.15, θ = 90°, r_disp = 2, i = 0", FigureKind::period_view, kFig14b,
    "Fig. 14b: " + params_title(kFig14b) + " (stiction)",
    "r_disp = 2, ζ = 0.15, θ = 90°, i = 0 (stiction, Eq. 27): the tip sticks until the deflection reaches "
    "z_ss.")};

const RegisterFigure register_fig15{period_figure(
    "fig15", "friction force over one period, ζ = 0.15, i = 1", FigureKind::period_force, kFig14a,
    "Fig. 15: friction force over one period, " + params_title(kFig14a),
    "F_x, F_y and |F| over the steady period of Fig. 14a (ζ = 0.15, θ = 90°, r_disp = 2, i = 1): |F| drops "
    "well below F_c while the asperity relaxes.")};

const RegisterFigure register_fig16{period_figure(
    "fig16", "friction force over one period, ζ = 0.15, i = 0", FigureKind::period_force, kFig14b,
    "Fig. 16: friction force over one period, " + params_title(kFig14b),
    "F_x, F_y and |F| over the steady period of Fig. 14b (ζ = 0.15, θ = 90°, r_disp = 2, i = 0).")};

const RegisterFigure register_fig17{period_figure(
    "fig17", "top view, ζ = 0.5, θ = 90°, r_disp = 2, i = 1 and 0", FigureKind::period_view, kFig17,
    "Fig. 17: ζ = 0.5, θ = 90°, r_{disp} = 2, i = 1 (solid) and i = 0 (dashed)",
    "ζ = 0.5, θ = 90°, r_disp = 2: the asperity never relaxes; i = 1 (solid) and i = 0 (dashed) coincide.", 0,
    true)};

const RegisterFigure register_fig18{period_figure(
    "fig18", "friction force over one period, ζ = 0.5, i = 1", FigureKind::period_force, kFig17,
    "Fig. 18: friction force over one period, " + params_title(kFig17),
    "F_x, F_y and |F| over the steady period of Fig. 17 (ζ = 0.5, θ = 90°, r_disp = 2, i = 1): |F| = F_c "
    "throughout.")};

} // namespace
} // namespace fv
