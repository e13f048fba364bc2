#include "render_flags.hpp"

#include "errors.hpp"
#include "figure_flags.hpp"
#include "model_options.hpp"

#include "fv/figure_family.hpp"
#include "fv/figure_registry.hpp"
#include "fv/read_number.hpp"

namespace fv::cli {
namespace {

// A list of numbers in `r` (core's reader: each item, empty items, repeats).
CLI::Validator list_in(ParamRange r) {
    return CLI::Validator(
        [r](std::string& s) {
            std::vector<double> unused;
            return read_number_list("", s, r, unused);
        },
        "NUMBER[,NUMBER...] in " + describe(r));
}

std::vector<double> list_of(const std::string& text, ParamRange r) {
    std::vector<double> v;
    read_number_list("", text, r, v); // checked by list_in
    return v;
}

// --zeta: one number (fig4, scene) or FROM:TO (rx, ry).
CLI::Validator zeta_text() {
    return CLI::Validator(
        [](std::string& s) {
            if (s.find(':') != std::string::npos) {
                ZetaSpan unused;
                return read_zeta_span("", s, unused);
            }
            double v = 0;
            return read_number("", s, kZetaRange, v);
        },
        "NUMBER or FROM:TO in " + describe(kZetaRange));
}

// "; a comma-separated list for rx, ry (one curve per combination), map (one map per combination)".
std::string lists_note(FigureParam p) {
    std::string curves, maps;
    for (const FigureEntry& e : figure_registry())
        for (const FigureParamUse& u : e.params)
            if (u.param == p && u.list) {
                std::string& to = e.kind == FigureKind::map ? maps : curves;
                to += (to.empty() ? "" : ", ") + e.id;
            }
    std::string s;
    if (!curves.empty()) s += curves + " (one curve per combination)";
    if (!maps.empty()) s += (s.empty() ? "" : ", ") + maps + " (one map per combination)";
    return "; a comma-separated list for " + s;
}

} // namespace

std::string flag_name(FigureParam p) {
    const std::string s = param_flag_text(p);
    return s.substr(0, s.find(' ')); // "--zeta or --vb" -> "--zeta"
}

void add_render_flags(CLI::App& cmd, RenderFlags& f) {
    f.data_opt = cmd.add_option("--data", f.data,
                                figures_taking(FigureParam::data) +
                                    ": CSV of measured r_x (columns zeta,r_x or vb,r_x; optional theta_deg, "
                                    "sigma); rx draws it over the curves, fig19 fits the models to it")
                     ->check(file_name());
    add_vibration_options(cmd, f.units,
                          figures_taking(FigureParam::amplitude) +
                              ": for --vb, --zss (and fig19, rx: a vb column; fig19: z_ss)");
    f.zeta_opt = cmd.add_option("--zeta", f.zeta,
                                figures_taking(FigureParam::zeta) + ": velocity ratio; " +
                                    figures_taking(FigureParam::zeta_range) +
                                    ": the range FROM:TO of the curves (default 0:3, the paper's; "
                                    "logarithmic axis from TO/FROM >= 100 on)")
                     ->check(zeta_text());
    f.theta_opt = cmd.add_option("--theta", f.theta,
                                 figures_taking(FigureParam::theta) +
                                     ": vibration angle in degrees (fig19: of points without theta_deg)" +
                                     lists_note(FigureParam::theta))
                      ->check(list_in(kThetaRange));
    f.rdisp_opt = cmd.add_option("--rdisp", f.rdisp,
                                 figures_taking(FigureParam::rdisp) +
                                     ": displacement ratio (map: default 2)" + lists_note(FigureParam::rdisp))
                      ->check(list_in(kRdispRange));
    f.i_opt = cmd.add_option("--i", f.i,
                             figures_taking(FigureParam::i) + ": Dahl exponent (map: default 1)" +
                                 lists_note(FigureParam::i))
                  ->check(list_in(kIRange));
    f.model_opt = cmd.add_option("--model", f.model,
                                 figures_taking(FigureParam::model) +
                                     ": the models, comma separated: dahl, rigid (the rigid model ignores "
                                     "--rdisp and --i: one rigid curve per angle, one rigid map)")
                      ->check(CLI::Validator(
                          [](std::string& s) {
                              std::vector<Model> unused;
                              return read_model_list("", s, unused);
                          },
                          "dahl,rigid"));
    add_vb_zss_options(cmd, f.units, UnitShape::single);
    f.start_opt = add_start_option(cmd, f.start,
                                   figures_taking(FigureParam::start) +
                                       ": the history where two steady states coexist, rest (the paper's) or "
                                       "sliding (vibration switched on while sliding)");
}

FigureInputs inputs_of(const RenderFlags& f) {
    const UnitArgs& u = f.units;
    FigureInputs in;
    const bool span = f.zeta_opt->count() > 0 && f.zeta.find(':') != std::string::npos;
    if (span) {
        if (u.vb_opt && u.vb_opt->count() > 0)
            throw UsageError("--zeta " + f.zeta +
                             " and --vb: give one of them; allowed: --zeta FROM:TO (rx, ry) "
                             "or --vb (scene)");
        ZetaSpan s;
        read_zeta_span("", f.zeta, s);
        in.zeta_span = s;
    } else {
        double z = 0;
        if (f.zeta_opt->count() > 0) read_number("", f.zeta, kZetaRange, z);
        in.zeta = zeta_of(f.zeta_opt, z, u, false);
    }
    if (f.theta_opt->count() > 0) in.theta_deg = list_of(f.theta, kThetaRange);
    // --zss stands in for one --rdisp (scene, map); both given is an error of rdisp_of.
    const std::vector<double> rdisps =
        f.rdisp_opt->count() > 0 ? list_of(f.rdisp, kRdispRange) : std::vector<double>{};
    if (rdisps.size() > 1 && u.zss_opt && u.zss_opt->count() > 0)
        throw UsageError("--rdisp and --zss: give one of them; allowed: --rdisp (a list for " +
                         figures_taking_lists(FigureParam::rdisp) + ") or --zss (one value)");
    if (rdisps.size() > 1)
        in.rdisp = rdisps;
    else if (const std::optional<double> r = rdisp_of(f.rdisp_opt, rdisps.empty() ? 0 : rdisps[0], u, false))
        in.rdisp = {*r};
    if (f.i_opt->count() > 0) in.i = list_of(f.i, kIRange);
    if (f.model_opt->count() > 0) read_model_list("", f.model, in.models);
    in.data = f.data;
    if (u.amplitude_opt->count() > 0) in.amplitude_um = u.amplitude;
    if (u.frequency_opt->count() > 0) in.frequency_khz = u.frequency;
    if (f.start_opt->count() > 0) {
        Start s = Start::rest;
        parse_start(f.start, s);
        in.start = s;
    }
    return in;
}

std::string first_given(const RenderFlags& f) {
    for (const CLI::Option* o :
         {f.zeta_opt, f.theta_opt, f.rdisp_opt, f.i_opt, f.model_opt, f.data_opt, f.start_opt, f.units.vb_opt,
          f.units.zss_opt, f.units.amplitude_opt, f.units.frequency_opt})
        if (o && o->count() > 0) return o->get_name();
    return {};
}

} // namespace fv::cli
