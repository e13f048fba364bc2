#include "model_options.hpp"

#include "errors.hpp"

#include "gui/lessons.hpp"

namespace fv::cli {

void add_model_options(CLI::App& cmd, ModelArgs& a, bool with_model_choice) {
    a.zeta_opt = cmd.add_option("--zeta", a.zeta, "velocity ratio zeta = v_b/v_v, Eq. (6) (or --vb)")
                     ->transform(number_in(kZetaRange));
    cmd.add_option("--theta", a.theta_deg, "vibration angle to v_b in degrees, Eq. (1)")
        ->required()
        ->transform(number_in(kThetaRange));
    a.rdisp_opt = cmd.add_option("--rdisp", a.rdisp,
                                 "displacement ratio r_disp = x_v/z_ss, Eq. (34) (or --zss; Dahl model only)")
                      ->transform(number_in(kRdispRange));
    a.i_opt =
        cmd.add_option("--i", a.i, "Dahl shape exponent i, Eq. (12); 0 = stiction, Eq. (27) (Dahl only)")
            ->transform(number_in(kIRange));
    if (with_model_choice)
        cmd.add_option("--model", a.model, "friction model")
            ->check(CLI::IsMember({"dahl", "rigid"}))
            ->capture_default_str();
    add_solver_options(cmd, a.solver);
}

Model model_of(const ModelArgs& a) {
    return a.model == "rigid" ? Model::rigid : Model::dahl;
}

Params to_params(const ModelArgs& a) {
    const bool dahl = model_of(a) == Model::dahl;
    Params p;
    p.zeta = *zeta_of(a.zeta_opt, a.zeta, a.units, true);
    // The rigid model ignores r_disp, but a given --zss is still checked like a given --rdisp.
    p.rdisp = rdisp_of(a.rdisp_opt, a.rdisp, a.units, dahl && a.rdisp_opt).value_or(a.rdisp);
    if (dahl && a.i_opt && a.i_opt->count() == 0)
        throw UsageError("--i is required for the Dahl model; allowed: a number in " + describe(kIRange));
    p.theta = a.theta_deg * kPi / 180;
    p.i = a.i;
    return p;
}

void add_solver_options(CLI::App& cmd, SolverArgs& s) {
    s.scheme_opt =
        cmd.add_option("--scheme", s.scheme,
                       "Dahl solver: ode (continuous-time limit, event location, Newton; within 1e-6 of "
                       "the dtau -> 0 limit) or paper (the paper's stepping scheme, Eqs. (17)-(27), "
                       "extrapolated to dtau -> 0 within 1e-5)")
            ->check(CLI::IsMember({"ode", "paper"}))
            ->capture_default_str();
    cmd.add_option(
           "--steps-per-period", s.steps_per_period,
           "run the paper's scheme exactly as printed with N steps per period (implies --scheme paper)")
        ->check(integer_in(kMinSteps, kMaxSteps));
    cmd.add_option("--tolerance", s.tolerance,
                   "ode scheme: the target for |r - r(dtau -> 0)| of r_x and r_y (default 1e-8; the (zeta, "
                   "theta) map uses 1e-6, so `--tolerance 1e-6` gives its cells)")
        ->transform(number_in(kToleranceRange));
    add_start_option(cmd, s.start,
                     "the history, where two steady states coexist: rest (the paper's start: sliding and "
                     "vibration begin together from an unstretched asperity) or sliding (vibration switched "
                     "on during steady sliding: the asperity fully deflected against v_b)")
        ->capture_default_str();
}

CLI::Option* add_start_option(CLI::App& cmd, std::string& start, const std::string& help) {
    return cmd.add_option("--start", start, help)->check(CLI::IsMember({"rest", "sliding"}));
}

std::optional<Start> given_start(const CLI::App& cmd, const std::string& start) {
    if (cmd.get_option("--start")->count() == 0) return std::nullopt;
    Start out = Start::rest;
    parse_start(start, out); // checked by add_start_option's IsMember
    return out;
}

SteadyOptions solver_options(const SolverArgs& s) {
    if (s.steps_per_period > 0 && s.scheme_opt && s.scheme_opt->count() > 0 && s.scheme == "ode")
        throw UsageError(
            "--steps-per-period belongs to --scheme paper; allowed: drop it, or use --scheme paper");
    SteadyOptions o;
    o.scheme = s.scheme == "paper" || s.steps_per_period > 0 ? Scheme::paper : Scheme::ode;
    o.steps_per_period = s.steps_per_period;
    parse_start(s.start, o.start);
    o.list_states = true; // every output names the stable states both starts reach
    if (s.tolerance > 0) {
        if (o.scheme == Scheme::paper)
            throw UsageError("--tolerance belongs to --scheme ode; allowed: drop it, or use --scheme ode");
        o.ode_tolerance = s.tolerance;
    }
    return o;
}

SteadyOptions steady_options(const ModelArgs& a) {
    return solver_options(a.solver);
}

CLI::Option* add_lesson_option(CLI::App& cmd, int& lesson, const std::string& what) {
    CLI::Option* o =
        cmd.add_option("--lesson", lesson,
                       what + " (" + app::lesson_range_text() +
                           ", the app's Lessons menu; docs/lessons.md): its setup replaces the model flags")
            ->check(integer_in(1, static_cast<long>(app::lesson_steps().size())));
    for (const char* flag : {"--zeta", "--theta", "--rdisp", "--i", "--model", "--start", "--vb", "--zss"})
        if (CLI::Option* f = cmd.get_option_no_throw(flag)) o->excludes(f);
    return o;
}

} // namespace fv::cli
