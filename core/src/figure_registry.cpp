#include "fv/figure_registry.hpp"

#include "fv/adaptive_sampling.hpp"
#include "fv/figure_family.hpp"
#include "fv/format.hpp"
#include "fv/read_number.hpp"
#include "fv/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>
#include <variant>

namespace fv {
namespace {

// Filled by the registrars before main; read only after (figure_registry() sorts it on first use).
std::vector<FigureEntry>& registrations() {
    static std::vector<FigureEntry> v;
    return v;
}

// The paper's figures by number (fig14a, fig14b after fig14), then the others by id.
std::tuple<int, long, std::string> order_key(const std::string& id) {
    if (id.rfind("fig", 0) == 0 && id.size() > 3 && std::isdigit(static_cast<unsigned char>(id[3]))) {
        std::size_t end = 3;
        while (end < id.size() && std::isdigit(static_cast<unsigned char>(id[end]))) ++end;
        return {0, std::stol(id.substr(3, end - 3)), id.substr(end)};
    }
    return {1, 0, id};
}

std::string number(double v) {
    return format_number("%g", v);
}

// 1e-08 -> 1e-8
std::string tolerance(double v) {
    std::string s = format_number("%.0e", v);
    const std::size_t e = s.find('e');
    const std::size_t digits = s.find_first_not_of("+-0", e + 1);
    if (e != std::string::npos && digits != std::string::npos)
        s = s.substr(0, e + 1) + (s[e + 1] == '-' ? "-" : "") + s.substr(digits);
    return s;
}
std::string degrees(double rad) {
    return format_number("%.4g", rad * 180 / kPi) + "°";
}

std::string params_text(const Params& p) {
    return "ζ = " + number(p.zeta) + ", θ = " + degrees(p.theta) + ", r_disp = " + number(p.rdisp) +
           ", i = " + number(p.i);
}

// "0.5, 1, 2" of the distinct values, in order of appearance.
template <class F> std::string distinct(const std::vector<Curve>& curves, Model m, F value) {
    std::vector<std::string> seen;
    for (const Curve& c : curves)
        if (c.model == m) {
            const std::string v = value(c);
            if (std::find(seen.begin(), seen.end(), v) == seen.end()) seen.push_back(v);
        }
    std::string s;
    for (const std::string& v : seen) s += (s.empty() ? "" : ", ") + v;
    return s;
}

std::string ode_solver(double tol = 0) {
    return "the continuous-time steady-state solver (Radau IIA, Newton on the period map), tolerance " +
           tolerance(tol > 0 ? tol : SteadyOptions{}.ode_tolerance) + " on r_x and r_y";
}
// The history behind a figure's steady states (scene, map).
std::string start_text(Start start) {
    return start == Start::sliding
               ? "from steady sliding (the vibration switched on while sliding, the asperity fully deflected "
                 "against v_b)"
               : "from rest (sliding and vibration begin together, T = P: the paper's start)";
}

const char* kQuadrature = "adaptive Gauss–Kronrod quadrature of Eq. (9), tolerance 1e-13";

std::string paper_scheme(int steps) {
    return "the paper's tracking scheme (Eqs. 17–27) at " + std::to_string(steps) +
           " steps per period, run to its periodic steady state (tolerance " +
           tolerance(SteadyOptions{}.tolerance) + " in units of F_c)";
}

// The steady period behind a top view or force plot.
std::string period_source(int steps) {
    return steps > 0 ? "one steady-state period of " + paper_scheme(steps)
                     : "one steady-state period from " + ode_solver() + ", sampled at 1024 instants";
}

std::string zeta_sampling(const std::vector<double>& z, std::size_t budget = 0) {
    if (z.empty()) return "no ζ values";
    if (budget > 0)
        return "ζ from " + number(z.front()) + " to " + number(z.back()) +
               " sampled adaptively: a start grid of " + std::to_string(z.size()) +
               " points, then halving the intervals next to every sample further than " +
               number(AdaptiveSampling{}.tolerance * 100) +
               "% of the plot from the chord of its neighbours (kinks, ζ = 1 of the rigid model), at most " +
               std::to_string(budget) + " samples a curve";
    const std::string n = std::to_string(z.size()), range = number(z.front()) + " to " + number(z.back());
    if (z == ratio_zeta_grid())
        return "ζ at " + n + " points from " + range + " (0.02 apart up to 0.5, 0.025 up to 1, 0.1 up to 3)";
    bool even = z.size() > 2;
    for (std::size_t k = 2; even && k < z.size(); ++k)
        even = std::abs((z[k] - z[k - 1]) - (z[1] - z[0])) <= 1e-9 * std::max(1.0, std::abs(z.back()));
    return "ζ at " + n + (even ? " evenly spaced" : "") + " points from " + range;
}

std::string ratio_models(const RatioCurvesFigure& spec) {
    const std::string dahl_theta =
        distinct(spec.curves, Model::dahl, [](const Curve& c) { return degrees(c.theta); });
    const std::string rigid_theta =
        distinct(spec.curves, Model::rigid, [](const Curve& c) { return degrees(c.theta); });
    std::string s;
    if (!dahl_theta.empty())
        s += "Dahl model at θ = " + dahl_theta + ", r_disp = " +
             distinct(spec.curves, Model::dahl, [](const Curve& c) { return number(c.rdisp); }) +
             ", i = " + distinct(spec.curves, Model::dahl, [](const Curve& c) { return number(c.i); });
    if (!rigid_theta.empty())
        s += std::string(s.empty() ? "" : "; ") + "rigid model" +
             (s.empty() ? " (no asperity: r_disp → ∞, i does not apply)" : "") + " at θ = " + rigid_theta;
    return s;
}

// How the r_x of the curves were computed.
std::string ratio_solvers(const RatioCurvesFigure& spec) {
    bool dahl = false, rigid = false;
    for (const Curve& c : spec.curves) (c.model == Model::rigid ? rigid : dahl) = true;
    const std::string r = spec.side_force ? "r_y" : "r_x";
    std::string s;
    if (dahl) s += "Dahl " + r + " from " + ode_solver();
    if (rigid)
        s += std::string(s.empty() ? "" : "; ") + "rigid " + r + " by " +
             (spec.side_force ? "adaptive Gauss–Kronrod quadrature of the mean of Eq. (4), tolerance 1e-13"
                              : kQuadrature);
    return s;
}

// The sentence naming the parameters of each kind of figure (figure_parameters), without "Parameters: ".
std::string parameters_of(const RatioCurvesFigure& c) {
    return ratio_models(c) + "; " + zeta_sampling(c.zetas, c.zeta_budget) + "; " + ratio_solvers(c);
}

std::string parameters_of(const MechanismFigure& c) {
    return "rigid model (no asperity: r_disp → ∞, i does not apply), ζ = " + number(c.zeta) +
           ", θ = " + degrees(c.theta) +
           "; velocity and friction from Eqs. (1)–(4) at 1024 evenly spaced instants of one period, arrows "
           "at "
           "τ = kπ/4; r_x (and r_y) by " +
           kQuadrature;
}

std::string parameters_of(const DahlCurvesFigure& c) {
    std::string is;
    for (double i : c.exponents) is += (is.empty() ? "" : ", ") + number(i);
    return "Dahl model's law alone, Eq. (12), i = " + is +
           ", in one dimension (ζ, θ and r_disp do not apply: lengths in units of z_ss, forces in F_c); "
           "each curve is the model's update (Eqs. 17–27) stepped along x in steps of 1e-4 z_ss, drawn "
           "every 0.01 z_ss; no solver tolerance: the first-order steps stay within 2e-4 F_c of the law's "
           "closed form (docs/model.md, tested)";
}

std::string parameters_of(const StepViewFigure& c) {
    return "Dahl model, " + params_text(c.params) + "; " + paper_scheme(c.steps_per_period) +
           "; the step drawn is the one of that period where the spring turns most";
}

// One steady period of the Dahl model at p (and at the other i, overlaid).
std::string period_text(const Params& p, int steps_per_period, bool overlay_other_i = false) {
    return "Dahl model, " + params_text(p) +
           (overlay_other_i ? " (and i = " + number(p.i == 0 ? 1 : 0) + ", overlaid)" : "") + "; " +
           period_source(steps_per_period);
}

std::string parameters_of(const PeriodViewFigure& c) {
    if (c.panel_i.empty() || c.only_panel >= 0)
        return period_text(c.params, c.steps_per_period, c.overlay_other_i);
    std::string is, tags;
    for (std::size_t k = 0; k < c.panel_i.size(); ++k) {
        is += (k ? ", " : "") + number(c.panel_i[k]);
        tags += (k ? ", " : "") + std::string(1, static_cast<char>('a' + k));
    }
    const Params& p = c.params;
    return "Dahl model, ζ = " + number(p.zeta) + ", θ = " + degrees(p.theta) +
           ", r_disp = " + number(p.rdisp) + ", i = " + is + " (panels " + tags + ", on shared axes); " +
           period_source(c.steps_per_period);
}

std::string parameters_of(const PeriodForceFigure& c) {
    return period_text(c.params, c.steps_per_period);
}

std::string parameters_of(const SceneFigure& c) {
    return "Dahl model, " + params_text(c.params) + ", steady states reached " + start_text(c.start) +
           "; top view and force over " + period_source(0) +
           "; r_x(ζ) of the Dahl model and the rigid model, " +
           zeta_sampling(c.ratio.zetas, c.ratio.zeta_budget) + ", rigid r_x by " + kQuadrature;
}

// The map's grid of cells: "ζ at 200 evenly spaced points from 0.02 to 3 × θ at 91 evenly spaced angles
// from 0° to 90°".
std::string map_grid(const MapFigure& c) {
    return zeta_sampling(c.zetas) + " × θ at " + std::to_string(c.theta_count) +
           " evenly spaced angles from 0° to " + number(c.theta_max_deg) + "°";
}

// One Dahl map (c.family empty), or a family's (map_family.hpp) Dahl maps and rigid map.
std::string parameters_of(const MapFigure& c) {
    std::string maps, dahl = "Dahl model, r_disp = " + number(c.rdisp) + ", i = " + number(c.i), rigid;
    if (!c.family.empty()) {
        std::vector<double> rdisp, i;
        for (const MapPanelSpec& p : c.family) {
            if (p.model == Model::rigid) {
                rigid = "rigid model (no asperity: r_disp and i do not apply), r_x by " +
                        std::string(kQuadrature);
                continue;
            }
            if (std::find(rdisp.begin(), rdisp.end(), p.rdisp) == rdisp.end()) rdisp.push_back(p.rdisp);
            if (std::find(i.begin(), i.end(), p.i) == i.end()) i.push_back(p.i);
        }
        dahl = rdisp.empty() ? ""
                             : "Dahl model, r_disp = " + list_text(rdisp) + ", i = " + list_text(i) +
                                   (rdisp.size() * i.size() > 1 ? " (one map per combination)" : "");
        const std::size_t cols = static_cast<std::size_t>(c.columns), n = c.family.size();
        if (n > 1)
            maps = std::to_string(n) + " maps in " + std::to_string((n + cols - 1) / cols) + " × " +
                   std::to_string(cols) + " panels on one colour scale: ";
    }
    const std::string best = "θ*(ζ) is the grid's smallest r_x refined by a parabola through its neighbours";
    if (dahl.empty()) return maps + rigid + ", on a grid of " + map_grid(c) + "; " + best;
    return maps + dahl + ", steady states reached " + start_text(c.start) +
           ", each cell also started from the other history; r_x from " + ode_solver(c.ode_tolerance) +
           " on a grid of " + map_grid(c) + "; " + best + ", for the rigid model by " + kQuadrature +
           (rigid.empty() ? "" : "; the " + rigid);
}

std::string parameters_of(const MeasurementsFigure& c) {
    return c.parameters;
}

} // namespace

RegisterFigure::RegisterFigure(FigureEntry entry) {
    for (const FigureEntry& e : registrations())
        if (e.id == entry.id) {
            std::fprintf(stderr, "frictionviz: figure '%s' is registered twice\n", entry.id.c_str());
            std::abort();
        }
    // Every caller (the command line, a spec file, tests, the Python module) gets the figure of the resolved
    // inputs: make sees every default it has, given or not.
    entry.make = [make = std::move(entry.make), defaults = entry.defaults,
                  params = entry.params](const FigureInputs& in) {
        FigureEntry e;
        e.defaults = defaults;
        e.params = params;
        return make(with_defaults(e, in));
    };
    registrations().push_back(std::move(entry));
}

const std::vector<FigureEntry>& figure_registry() {
    static const std::vector<FigureEntry> sorted = [] {
        std::vector<FigureEntry> v = registrations();
        std::sort(v.begin(), v.end(), [](const FigureEntry& a, const FigureEntry& b) {
            return order_key(a.id) < order_key(b.id);
        });
        return v;
    }();
    return sorted;
}

const FigureEntry* find_registered(const std::string& id) {
    for (const FigureEntry& e : figure_registry())
        if (e.id == id) return &e;
    return nullptr;
}

std::string figure_ids() {
    std::string s;
    for (const FigureEntry& e : figure_registry()) s += (s.empty() ? "" : ", ") + e.id;
    return s;
}

const char* param_key(FigureParam p) {
    switch (p) {
    case FigureParam::zeta:
    case FigureParam::zeta_range:
        return "zeta";
    case FigureParam::theta:
        return "theta";
    case FigureParam::rdisp:
        return "rdisp";
    case FigureParam::i:
        return "i";
    case FigureParam::model:
        return "model";
    case FigureParam::data:
        return "data";
    case FigureParam::amplitude:
        return "amplitude";
    case FigureParam::frequency:
        return "frequency";
    case FigureParam::start:
        return "start";
    }
    return "";
}

const ParamRange* param_range(FigureParam p) {
    switch (p) {
    case FigureParam::zeta:
        return &kZetaRange;
    case FigureParam::theta:
        return &kThetaRange;
    case FigureParam::rdisp:
        return &kRdispRange;
    case FigureParam::i:
        return &kIRange;
    case FigureParam::amplitude:
        return &kAmplitudeRange;
    case FigureParam::frequency:
        return &kFrequencyRange;
    default:
        return nullptr;
    }
}

bool given(const FigureInputs& in, FigureParam p) {
    switch (p) {
    case FigureParam::zeta:
        return in.zeta.has_value();
    case FigureParam::zeta_range:
        return in.zeta_span.has_value();
    case FigureParam::theta:
        return !in.theta_deg.empty();
    case FigureParam::rdisp:
        return !in.rdisp.empty();
    case FigureParam::i:
        return !in.i.empty();
    case FigureParam::model:
        return !in.models.empty();
    case FigureParam::data:
        return !in.data.empty();
    case FigureParam::amplitude:
        return in.amplitude_um.has_value();
    case FigureParam::frequency:
        return in.frequency_khz.has_value();
    case FigureParam::start:
        return in.start.has_value();
    }
    return false;
}

FigureInputs over(FigureInputs base, const FigureInputs& top) {
    for (auto [to, from] : {std::pair{&base.zeta, &top.zeta},
                            {&base.amplitude_um, &top.amplitude_um},
                            {&base.frequency_khz, &top.frequency_khz}})
        if (*from) *to = *from;
    for (auto [to, from] :
         {std::pair{&base.theta_deg, &top.theta_deg}, {&base.rdisp, &top.rdisp}, {&base.i, &top.i}})
        if (!from->empty()) *to = *from;
    if (top.zeta_span) base.zeta_span = top.zeta_span;
    if (!top.models.empty()) base.models = top.models;
    if (!top.data.empty()) base.data = top.data;
    if (top.start) base.start = top.start;
    return base;
}

std::optional<FigureParam> missing_param(const FigureEntry& e, const FigureInputs& in) {
    for (const FigureParamUse& u : e.params)
        if (u.required && !given(in, u.param)) return u.param;
    return std::nullopt;
}

FigureInputs with_defaults(const FigureEntry& e, const FigureInputs& given_inputs) {
    const FigureInputs all = over(e.defaults, given_inputs);
    FigureInputs out; // only what `e` takes
    for (const FigureParamUse& u : e.params) switch (u.param) {
        case FigureParam::zeta:
            out.zeta = all.zeta;
            break;
        case FigureParam::zeta_range:
            out.zeta_span = all.zeta_span;
            break;
        case FigureParam::theta:
            out.theta_deg = all.theta_deg;
            break;
        case FigureParam::rdisp:
            out.rdisp = all.rdisp;
            break;
        case FigureParam::i:
            out.i = all.i;
            break;
        case FigureParam::model:
            out.models = all.models;
            break;
        case FigureParam::data:
            out.data = all.data;
            break;
        case FigureParam::amplitude:
            out.amplitude_um = all.amplitude_um;
            break;
        case FigureParam::frequency:
            out.frequency_khz = all.frequency_khz;
            break;
        case FigureParam::start:
            out.start = all.start;
            break;
        }
    return out;
}

FigureInputs fitting(const FigureEntry& e, FigureInputs in) {
    auto use = [&](FigureParam p) -> const FigureParamUse* {
        for (const FigureParamUse& u : e.params)
            if (u.param == p) return &u;
        return nullptr;
    };
    for (auto [p, list] : {std::pair{FigureParam::theta, &in.theta_deg},
                           {FigureParam::rdisp, &in.rdisp},
                           {FigureParam::i, &in.i}})
        if (list->size() > 1 && !(use(p) && use(p)->list)) list->clear();
    if (in.models.size() > 1 && !(use(FigureParam::model) && use(FigureParam::model)->list))
        in.models.clear();
    if (!use(FigureParam::zeta_range)) in.zeta_span.reset();
    if (!use(FigureParam::zeta)) in.zeta.reset();
    if (!(use(FigureParam::data) && use(FigureParam::data)->required)) {
        in.data.clear();
        in.amplitude_um.reset();
        in.frequency_khz.reset();
    }
    return in;
}

std::string figures_taking_lists(FigureParam p) {
    std::string s;
    for (const FigureEntry& e : figure_registry())
        for (const FigureParamUse& u : e.params)
            if (u.param == p && u.list) s += (s.empty() ? "" : ", ") + e.id;
    return s;
}

namespace {

const std::vector<double>* list_of(const FigureInputs& in, FigureParam p) {
    if (p == FigureParam::theta) return &in.theta_deg;
    if (p == FigureParam::rdisp) return &in.rdisp;
    if (p == FigureParam::i) return &in.i;
    return nullptr;
}

} // namespace

std::string input_error(const FigureEntry& e, const FigureInputs& in,
                        const std::function<std::string(FigureParam)>& name) {
    // zeta as one number where the figure takes a range, and the other way round.
    auto takes = [&](FigureParam p) {
        return std::any_of(e.params.begin(), e.params.end(),
                           [p](const FigureParamUse& u) { return u.param == p; });
    };
    if (takes(FigureParam::zeta_range) && in.zeta && !in.zeta_span)
        return name(FigureParam::zeta_range) + " has one value; " + e.id +
               " takes a range FROM:TO (e.g. 0.01:10; default 0:3)";
    if (takes(FigureParam::zeta) && in.zeta_span && !in.zeta)
        return name(FigureParam::zeta) + " is a range; " + e.id + " takes one value";
    for (const FigureParamUse& u : e.params) {
        if (!given(in, u.param)) continue;
        const std::string n = name(u.param);
        const std::vector<double>* list = list_of(in, u.param);
        const std::size_t count = list ? list->size() : u.param == FigureParam::model ? in.models.size() : 1;
        if (count > 1 && !u.list) {
            const std::string lists = figures_taking_lists(u.param);
            return n + " has " + std::to_string(count) + " values; " + e.id + " takes one" +
                   (lists.empty() ? "" : " (lists: " + lists + ")");
        }
        if (list) {
            if (std::string why = check_number_list(n, *list, *param_range(u.param)); !why.empty())
                return why;
        } else if (u.param == FigureParam::model) {
            if (std::string why = check_model_list(n, in.models); !why.empty()) return why;
        } else if (u.param == FigureParam::zeta_range) {
            if (std::string why = check_zeta_span(n, *in.zeta_span); !why.empty()) return why;
        } else if (const ParamRange* r = param_range(u.param)) {
            const double v = u.param == FigureParam::zeta        ? *in.zeta
                             : u.param == FigureParam::amplitude ? *in.amplitude_um
                                                                 : *in.frequency_khz;
            if (std::string why = range_message(n, v, *r); !why.empty()) return why;
        }
    }
    return e.check ? e.check(with_defaults(e, in)) : std::string();
}

const std::vector<FigureSpec>& paper_figures() {
    static const std::vector<FigureSpec> figs = [] {
        std::vector<FigureSpec> v;
        for (const FigureEntry& e : figure_registry())
            if (e.params.empty()) v.push_back(e.make(e.example));
        return v;
    }();
    return figs;
}

const FigureSpec* find_figure(const std::string& id) {
    for (const auto& f : paper_figures())
        if (f.id == id) return &f;
    return nullptr;
}

std::string figure_parameters(const FigureSpec& spec) {
    return "Parameters: " +
           std::visit([](const auto& content) { return parameters_of(content); }, spec.content) + ".";
}

std::string plain_text(const std::string& markup) {
    std::string s;
    for (std::size_t k = 0; k < markup.size(); ++k) {
        const char c = markup[k];
        if ((c == '_' || c == '^') && k + 1 < markup.size() && markup[k + 1] == '{') {
            const std::size_t close = markup.find('}', k + 2);
            if (close != std::string::npos) {
                s += c;
                s += markup.substr(k + 2, close - k - 2);
                k = close;
                continue;
            }
        }
        s += c;
    }
    return s;
}

} // namespace fv
