#include "fv/figures.hpp"
#include "fv/format.hpp"

#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fv {
namespace {

constexpr double kDeg = kPi / 180;

// Figs. 10-13: the r_disp values are not given in the paper; this family runs from compliance-dominated
// (0.5: the tip deflection at sliding is twice the vibration amplitude) to near-rigid (20).
const double kRdispFamily[] = {0.5, 1, 2, 5, 20};

FigureSpec ratio_family(const char* id, double i, double theta_deg) {
    FigureSpec f;
    f.id = id;
    f.kind = FigureKind::ratio_curves;
    f.title = std::string("Fig. ") + (id + 3) + ": friction ratio, i = " + format_number("%g", i) +
              ", θ = " + format_number("%g", theta_deg) + "°";
    f.caption = "r_x(ζ) of the Dahl model with i = " + format_number("%g", i) +
                " at θ = " + format_number("%g", theta_deg) +
                "° for r_disp = 0.5, 1, 2, 5, 20, and the rigid model (Eq. " +
                (theta_deg == 0 ? "10" : "11") + "). Larger r_disp approaches the rigid curve.";
    f.zetas = ratio_zeta_grid();
    for (double r : kRdispFamily) f.curves.push_back({Model::dahl, theta_deg * kDeg, r, i});
    f.curves.push_back({Model::rigid, theta_deg * kDeg, 0, 0});
    return f;
}

FigureSpec state_figure(const char* id, FigureKind kind, Params p, std::string title, std::string caption) {
    FigureSpec f;
    f.id = id;
    f.kind = kind;
    f.params = p;
    f.title = std::move(title);
    f.caption = std::move(caption);
    return f;
}

std::vector<FigureSpec> make_figures() {
    std::vector<FigureSpec> v;
    {
        FigureSpec f;
        f.id = "fig5";
        f.kind = FigureKind::ratio_curves;
        f.title = "Fig. 5: friction ratio of the rigid model";
        f.caption =
            "r_x(ζ) of the rigid Coulomb model, Eq. (9), for θ = 0°, 30°, 45°, 60°, 90°. Below ζ ≈ 0.95 "
            "parallel vibration (θ = 0°) reduces friction most; above ζ = 1 perpendicular vibration does.";
        f.zetas = linspace(0, 2, 201);
        for (double th : {0.0, 30.0, 45.0, 60.0, 90.0}) f.curves.push_back({Model::rigid, th * kDeg, 0, 0});
        v.push_back(f);
    }
    {
        FigureSpec f = state_figure(
            "fig8", FigureKind::step_view, {0.15, 90 * kDeg, 2, 1}, "Fig. 8: one step of the tracking scheme",
            "One step of Eqs. (17)-(22), drawn large (24 steps per period): T is pulled "
            "along the line T(t)-P(t+Δt) to T(t+Δt) at the new deflection z(t+Δt). "
            "ζ = 0.15, θ = 90°, r_disp = 2, i = 1.");
        f.steps_per_period = 24;
        v.push_back(f);
    }
    v.push_back(state_figure("fig9", FigureKind::period_view, {0.3, 60 * kDeg, 2, 1},
                             "Fig. 9: asperity over one steady-state period",
                             "Paths of the body point P and the asperity tip T over one steady-state period, "
                             "with the spring P-T at regular instants. ζ = 0.3, θ = 60°, r_disp = 2, i = 1 "
                             "(the paper does not state its parameters)."));
    v.push_back(ratio_family("fig10", 1, 90));
    v.push_back(ratio_family("fig11", 0, 90));
    v.push_back(ratio_family("fig12", 1, 0));
    v.push_back(ratio_family("fig13", 0, 0));
    v.push_back(
        state_figure("fig14a", FigureKind::period_view, {0.15, 90 * kDeg, 2, 1},
                     "Fig. 14a: r_{disp} = 2, ζ = 0.15, θ = 90°, i = 1 (no stiction)",
                     "P and T over one steady-state period at ζ = 0.15: the trajectory is squeezed in x "
                     "and the asperity relaxes in the tight turns. Dahl model without stiction, i = 1."));
    v.push_back(state_figure("fig14b", FigureKind::period_view, {0.15, 90 * kDeg, 2, 0},
                             "Fig. 14b: r_{disp} = 2, ζ = 0.15, θ = 90°, i = 0 (stiction)",
                             "As Fig. 14a with the stiction model i = 0, Eq. (27): the tip sticks until the "
                             "deflection reaches z_ss."));
    v.push_back(state_figure("fig15", FigureKind::period_force, {0.15, 90 * kDeg, 2, 1},
                             "Fig. 15: friction force over one period (Fig. 14a)",
                             "F_x, F_y and |F| over the steady-state period of Fig. 14a (i = 1): |F| drops "
                             "below F_c while the asperity relaxes."));
    v.push_back(state_figure("fig16", FigureKind::period_force, {0.15, 90 * kDeg, 2, 0},
                             "Fig. 16: friction force over one period (Fig. 14b)",
                             "F_x, F_y and |F| over the steady-state period of Fig. 14b (i = 0)."));
    {
        FigureSpec f =
            state_figure("fig17", FigureKind::period_view, {0.5, 90 * kDeg, 2, 1},
                         "Fig. 17: r_{disp} = 2, ζ = 0.5, θ = 90°",
                         "At ζ = 0.5 the trajectory is stretched in x, the asperity never relaxes and "
                         "i = 1 (solid) and i = 0 (dashed) coincide.");
        f.overlay_other_i = true;
        v.push_back(f);
    }
    v.push_back(state_figure("fig18", FigureKind::period_force, {0.5, 90 * kDeg, 2, 1},
                             "Fig. 18: friction force over one period (Fig. 17)",
                             "F_x, F_y and |F| for Fig. 17: the magnitude stays at F_c (|F| = 1)."));
    return v;
}

} // namespace

std::vector<double> ratio_zeta_grid(double zeta_max) {
    std::vector<double> z;
    for (int k = 1; k <= 25; ++k) z.push_back(0.02 * k);
    for (int k = 1; k <= 20; ++k) z.push_back(0.5 + 0.025 * k);
    for (int k = 1; k <= 20; ++k) z.push_back(1 + 0.1 * k);
    // Past 3 the curves are smooth and flat (r_x -> 1): at most 40 more points, no closer than 0.1.
    if (zeta_max > 3) {
        const int n = std::min(40, static_cast<int>(std::ceil((zeta_max - 3) / 0.1)));
        for (int k = 1; k <= n; ++k) z.push_back(3 + (zeta_max - 3) * k / n);
    }
    return z;
}

const std::vector<FigureSpec>& paper_figures() {
    static const std::vector<FigureSpec> figs = make_figures();
    return figs;
}

const FigureSpec* find_figure(const std::string& id) {
    for (const auto& f : paper_figures())
        if (f.id == id) return &f;
    return nullptr;
}

std::string figure_ids() {
    std::string s;
    for (const auto& f : paper_figures()) s += (s.empty() ? "" : ", ") + f.id;
    return s;
}

FigureSpec map_figure(double rdisp, double i) {
    FigureSpec f;
    f.id = "map";
    f.kind = FigureKind::map;
    f.params = {0, 0, rdisp, i};
    f.zetas = linspace(0.02, 3, 200);
    f.theta_count = 91;
    f.theta_max_deg = 90;
    f.title = "friction ratio r_{x}(ζ, θ), Dahl model, r_{disp} = " + format_number("%g", rdisp) +
              ", i = " + format_number("%g", i);
    f.caption =
        "r_x over velocity ratio and vibration angle, with the angle of strongest friction reduction "
        "theta*(zeta) (solid) and that of the rigid model (dashed): the question the paper's conclusion "
        "answers only for 0 vs 90 degrees.";
    return f;
}

FigureSpec scene_figure(const Params& p) {
    FigureSpec f;
    f.id = "scene";
    f.kind = FigureKind::scene;
    f.params = p;
    f.title = "ζ = " + format_number("%g", p.zeta) + ", θ = " + format_number("%.4g", p.theta / kDeg) +
              "°, r_{disp} = " + format_number("%g", p.rdisp) + ", i = " + format_number("%g", p.i);
    f.caption = "Top view, friction force over one steady-state period and r_x(ζ) for one parameter set.";
    f.zetas = ratio_zeta_grid();
    f.curves = {{Model::dahl, p.theta, p.rdisp, p.i}, {Model::rigid, p.theta, 0, 0}};
    return f;
}

} // namespace fv
