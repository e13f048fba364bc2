#include "fv/figures.hpp"
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"

#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

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

// A spec's kind is the index of its content.
static_assert(std::variant_size_v<FigureContent> == static_cast<std::size_t>(FigureKind::measurements) + 1);
static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(FigureKind::map), FigureContent>,
                   MapFigure>);

FigureSpec map_figure(double rdisp, double i, Start start) {
    MapFigure m;
    m.rdisp = rdisp;
    m.i = i;
    m.start = start;
    m.zetas = linspace(0.02, 3, 200);
    m.theta_count = 91;
    m.theta_max_deg = 90;
    m.ode_tolerance = kMapTolerance;
    FigureSpec f;
    f.id = "map";
    f.content = std::move(m);
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
    SceneFigure s;
    s.params = p;
    s.start = start;
    s.ratio.zetas = ratio_zeta_start();
    s.ratio.zeta_budget = kRatioZetaBudget;
    s.ratio.curves = {{Model::dahl, p.theta, p.rdisp, p.i}, {Model::rigid, p.theta, 0, 0}};
    FigureSpec f;
    f.id = "scene";
    f.content = std::move(s);
    f.title = params_title(p) + start_title(start);
    f.caption = "One parameter set, " + plain_text(params_title(p)) +
                ": top view of P and T, the friction force over one steady-state period, and r_x(ζ) with the "
                "rigid curve and the current point." +
                std::string(kForceConvention);
    return f;
}

} // namespace fv
