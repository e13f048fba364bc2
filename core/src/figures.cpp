#include "fv/figures.hpp"
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"

#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fv {

std::string params_title(const Params& p) {
    return "ζ = " + format_number("%g", p.zeta) + ", θ = " + format_number("%.4g", p.theta * 180 / kPi) +
           "°, r_{disp} = " + format_number("%g", p.rdisp) + ", i = " + format_number("%g", p.i);
}

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

std::vector<double> ratio_zeta_start(double zeta_max) {
    std::vector<double> z = {0.02};
    for (int k = 1; k <= 20; ++k) z.push_back(0.05 * k);
    for (int k = 1; 1 + 0.25 * k <= zeta_max + 1e-9; ++k) z.push_back(1 + 0.25 * k);
    return z;
}

namespace {
// The history in the title of a figure that takes --start, where it is not the paper's.
std::string start_title(Start start) {
    return start == Start::sliding ? ", vibration switched on while sliding" : "";
}
} // namespace

FigureSpec map_figure(double rdisp, double i, Start start) {
    FigureSpec f;
    f.id = "map";
    f.kind = FigureKind::map;
    f.start = start;
    f.params = {0, 0, rdisp, i};
    f.zetas = linspace(0.02, 3, 200);
    f.theta_count = 91;
    f.theta_max_deg = 90;
    f.ode_tolerance = kMapTolerance;
    f.title = "friction ratio r_{x}(ζ, θ), Dahl model, r_{disp} = " + format_number("%g", rdisp) +
              ", i = " + format_number("%g", i) + start_title(start);
    f.caption =
        "Beyond the paper: r_x of the Dahl model (r_disp = " + format_number("%g", rdisp) +
        ", i = " + format_number("%g", i) +
        ") over velocity ratio ζ and vibration angle θ, with the angle of strongest friction reduction "
        "θ*(ζ) (solid) and that of the rigid model (dashed): the question the paper's conclusion "
        "answers only for 0° and 90°. Marked cells: where the motion settles into a period of 2, 4, … "
        "vibration periods (the mean over them is shown), where a second stable steady state coexists "
        "(the other start reaches it), and where no steady state could be vouched for.";
    return f;
}

FigureSpec scene_figure(const Params& p, Start start) {
    FigureSpec f;
    f.id = "scene";
    f.kind = FigureKind::scene;
    f.start = start;
    f.params = p;
    f.title = params_title(p) + start_title(start);
    f.caption = "One parameter set, " + plain_text(params_title(p)) +
                ": top view of P and T, the friction force over one steady-state period, and r_x(ζ) with the "
                "rigid curve and the current point." +
                std::string(kForceConvention);
    f.zetas = ratio_zeta_start();
    f.zeta_budget = kRatioZetaBudget;
    f.curves = {{Model::dahl, p.theta, p.rdisp, p.i}, {Model::rigid, p.theta, 0, 0}};
    return f;
}

} // namespace fv
