// The spec of a family figure (figure_family.hpp): curves, zeta grid, title and caption. The curves'
// colours, dashes and legend are chosen when the figure is computed (family_style.cpp).
#include "fv/figure_family.hpp"

#include "fv/figure_registry.hpp"
#include "fv/format.hpp"
#include "fv/measurements.hpp"
#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace fv {
namespace {

std::string g(double v) {
    return format_number("%g", v);
}

// "30°, 60°"
std::string degrees_text(const std::vector<double>& deg) {
    std::string s;
    for (double d : deg) s += (s.empty() ? "" : ", ") + g(d) + "°";
    return s;
}

std::string values_text(const std::vector<double>& v) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : ", ") + g(x);
    return s;
}

bool has(const std::vector<Model>& models, Model m) {
    return std::find(models.begin(), models.end(), m) != models.end();
}

// The start grid of a span: the paper's figures' grid for the paper's span, 41 points evenly spaced in
// log zeta for a wide span, else 41 evenly spaced (from a little above 0 where the span starts there: a
// steady state needs v_b > 0), with zeta = 1 on it (the rigid curve's corner at theta = 0).
std::vector<double> start_grid(const ZetaSpan& s, bool log_zeta) {
    if (s == kPaperZetaSpan) return ratio_zeta_start(3);
    std::vector<double> z;
    if (log_zeta) {
        for (double u : linspace(std::log10(s.from), std::log10(s.to), 41)) z.push_back(std::pow(10.0, u));
        z.front() = s.from, z.back() = s.to; // exactly the span's ends
        return z;
    }
    const double lo = s.from > 0 ? s.from : std::min(0.02, s.to / 150);
    z = linspace(lo, s.to, 41);
    if (lo < 1 && s.to > 1 && std::none_of(z.begin(), z.end(), [](double v) { return v == 1; })) {
        z.push_back(1);
        std::sort(z.begin(), z.end());
    }
    return z;
}

// The title: the quantity, the models, and the parameters that are the same for every curve (those that
// vary are named in the legend).
std::string family_title(const FigureFamily& f) {
    std::string t = f.side_force ? "side force r_{y}(ζ)" : "friction ratio r_{x}(ζ)";
    const bool dahl = has(f.models, Model::dahl), rigid = has(f.models, Model::rigid);
    if (dahl) {
        std::string fixed;
        if (f.rdisp.size() == 1) fixed += "r_{disp} = " + g(f.rdisp[0]);
        if (f.i.size() == 1) fixed += (fixed.empty() ? "" : ", ") + std::string("i = ") + g(f.i[0]);
        t += ", Dahl" + (fixed.empty() ? "" : " (" + fixed + ")");
        if (rigid) t += " and rigid";
    } else {
        t += ", rigid model";
    }
    if (f.theta_deg.size() == 1) t += ", θ = " + g(f.theta_deg[0]) + "°";
    if (f.start == Start::sliding) t += ", vibration switched on while sliding";
    return t;
}

std::string family_caption(const FigureFamily& f, const MeasurementSet* data) {
    const bool dahl = has(f.models, Model::dahl), rigid = has(f.models, Model::rigid);
    const bool log_zeta = f.zeta.from > 0 && f.zeta.to / f.zeta.from >= kLogZetaRatio;
    std::string c =
        f.side_force
            ? "Beyond the paper: the mean friction across v_b, r_y = mean F_y/F_c (Eq. 31 "
              "over F_c; the friction on the body is −(r_x, r_y) F_c), "
            : "Beyond the paper: the friction ratio r_x(ζ), the period mean of F_x/F_c (Eqs. 31, 33), ";
    if (dahl)
        c += "of the Dahl model at θ = " + degrees_text(f.theta_deg) + ", r_disp = " + values_text(f.rdisp) +
             ", i = " + values_text(f.i) + (family_curves(f).size() > 1 ? ", one curve per combination" : "");
    if (rigid)
        c += std::string(dahl ? ", and " : "") + "of the rigid model (" + (f.side_force ? "Eq. 4" : "Eq. 9") +
             ") at θ = " + degrees_text(f.theta_deg);
    c += ", for ζ from " + g(f.zeta.from) + " to " + g(f.zeta.to) +
         (log_zeta ? " on a logarithmic axis" : "") + "; steady states reached " +
         (f.start == Start::sliding ? "from steady sliding (the vibration switched on while sliding)"
                                    : "from rest (the paper's start)") +
         ". The legend names what varies from curve to curve; the title what does not.";
    if (data) {
        std::size_t outside = 0;
        for (const Measurement& m : data->points) outside += m.zeta < f.zeta.from || m.zeta > f.zeta.to;
        c += " Over the curves: the " + std::to_string(data->points.size()) + " points of " + data->file +
             (data->synthetic ? " (synthetic example data, made from the model, not measurements)"
                              : " (measurements)") +
             (data->has_sigma ? " with ±σ error bars" : "") +
             (data->has_theta ? ", one marker per vibration angle" : "") + ".";
        if (outside > 0)
            c += " " + std::to_string(outside) + " of them lie outside ζ from " + g(f.zeta.from) + " to " +
                 g(f.zeta.to) + " and are not drawn.";
    }
    c += " A point the solver cannot vouch for leaves a gap in its curve, marked × at its last value.";
    return c;
}

} // namespace

FigureFamily family_of(const FigureInputs& in, bool side_force) {
    FigureFamily f;
    f.models = in.models;
    f.theta_deg = in.theta_deg;
    f.rdisp = in.rdisp;
    f.i = in.i;
    f.zeta = in.zeta_span.value_or(kPaperZetaSpan);
    f.side_force = side_force;
    f.start = in.start.value_or(Start::rest);
    return f;
}

std::string family_check(const FigureInputs& in) {
    return family_size_error(family_of(in, false));
}

FigureSpec family_figure(const std::string& id, const FigureFamily& f,
                         std::shared_ptr<const MeasurementSet> data) {
    RatioCurvesFigure c;
    c.curves = family_curves(f);
    c.side_force = f.side_force;
    c.family = true;
    c.log_zeta = f.zeta.from > 0 && f.zeta.to / f.zeta.from >= kLogZetaRatio;
    c.zetas = start_grid(f.zeta, c.log_zeta);
    c.zeta_budget = kRatioZetaBudget;
    c.axis = f.zeta;
    c.start = f.start;
    FigureSpec spec;
    spec.id = id;
    spec.title = family_title(f);
    spec.caption = family_caption(f, data.get());
    c.data = std::move(data);
    spec.content = std::move(c);
    return spec;
}

} // namespace fv
