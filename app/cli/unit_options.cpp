#include "unit_options.hpp"

#include "errors.hpp"
#include "model_options.hpp"

#include "fv/units.hpp"

#include <cstdio>

namespace fv::cli {
namespace {

bool given(const CLI::Option* o) {
    return o && o->count() > 0;
}

// Inputs with 12 significant digits (as typed, for any sensible input), results with 6.
std::string g(double v, int digits = 12) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string vibration_text(const Vibration& v) {
    std::string s = "--amplitude " + g(*v.amplitude_um) + " um";
    if (v.frequency_khz) s += ", --frequency " + g(*v.frequency_khz) + " kHz";
    return s;
}

Vibration given_vibration(const UnitArgs& u) {
    Vibration v;
    if (given(u.amplitude_opt)) v.amplitude_um = u.amplitude;
    if (given(u.frequency_opt)) v.frequency_khz = u.frequency;
    return v;
}

// A conversion whose UnitError (a result outside the doubles) becomes a UsageError led by `what`: the flags
// and values that went in.
template <class F> double convert(const std::string& what, F&& f) {
    try {
        return f();
    } catch (const units::UnitError& e) {
        throw UsageError(what + ": " + e.what());
    }
}

void check_alternatives(const CLI::Option* plain, const CLI::Option* unit) {
    if (given(plain) && given(unit))
        throw UsageError("give " + plain->get_name() + " or " + unit->get_name() + ", not both");
}

// `label` names the flag and the value in m/s, e.g. "--vb 30 m/s".
double zeta_from_vb(double vb, const std::string& label, const UnitArgs& u) {
    if (!given(u.amplitude_opt) || !given(u.frequency_opt))
        throw UsageError("--vb needs --amplitude (um) and --frequency (kHz): zeta = v_b/(2 pi f A)");
    const std::string what = label + " at " + vibration_text(given_vibration(u));
    const double zeta = convert(what, [&] { return units::zeta_from_vb(vb, u.amplitude, u.frequency); });
    if (!inside(zeta, kZetaRange))
        throw UsageError(what + " gives zeta = " + g(zeta, 6) + "; allowed: zeta in " + describe(kZetaRange));
    return zeta;
}

double rdisp_from_zss(double zss, const UnitArgs& u) {
    if (!given(u.amplitude_opt)) throw UsageError("--zss needs --amplitude (um): r_disp = A/z_ss");
    const std::string what = "--zss " + g(zss) + " um at " + vibration_text({u.amplitude, {}});
    const double rdisp = convert(what, [&] { return units::rdisp_from_zss(u.amplitude, zss); });
    if (!inside(rdisp, kRdispRange))
        throw UsageError(what + " gives rdisp = " + g(rdisp, 6) + "; allowed: rdisp in " +
                         describe(kRdispRange));
    return rdisp;
}

[[noreturn]] void missing(const char* plain, const std::string& allowed, const char* for_what = "") {
    throw UsageError(std::string(plain) + " is required" + for_what + "; allowed: " + allowed);
}

std::string zeta_allowed() {
    return "--zeta in " + describe(kZetaRange) +
           ", or --vb in m/s with --amplitude and --frequency (zeta = v_b/(2 pi f A))";
}

std::string rdisp_allowed() {
    return "--rdisp in " + describe(kRdispRange) + ", or --zss in um with --amplitude (r_disp = A/z_ss)";
}

} // namespace

void add_vb_zss_options(CLI::App& cmd, UnitArgs& u, UnitShape shape) {
    if (shape == UnitShape::single) {
        u.vb_opt = cmd.add_option("--vb", u.vb,
                                  "sliding velocity v_b in m/s instead of --zeta: zeta = v_b/(2 pi f A) with "
                                  "--amplitude A and --frequency f")
                       ->transform(number_in(kVbRange));
        u.zss_opt = cmd.add_option("--zss", u.zss,
                                   "steady-state asperity deflection z_ss in um instead of --rdisp: r_disp = "
                                   "A/z_ss with --amplitude A (Dahl model only)")
                        ->transform(number_in(kZssRange));
    } else {
        u.vb_opt = cmd.add_option("--vb", u.vb_range,
                                  "sliding velocities v_b in m/s, FROM:TO:COUNT, instead of --zeta: zeta = "
                                  "v_b/(2 pi f A) with --amplitude A and --frequency f")
                       ->check(range_spec(kVbRange, kMaxSweepPoints));
        u.zss_opt = add_number_list(cmd, "--zss", u.zss_list, kZssRange,
                                    "steady-state asperity deflections z_ss in um, comma separated, instead "
                                    "of --rdisp: r_disp = A/z_ss with --amplitude A (Dahl model only)");
    }
}

// --frequency without --amplitude is accepted (and does nothing outside gui, which keeps it): every output it
// could feed (v_b, v_v) is left out rather than shown wrong, so nobody is misled, and fit and render fig19
// have always accepted it.
void add_vibration_options(CLI::App& cmd, UnitArgs& u, const std::string& use) {
    const std::string more = use.empty() ? "" : "; " + use;
    u.amplitude_opt =
        cmd.add_option("--amplitude", u.amplitude,
                       "vibration amplitude A = x_v in um: v_v = 2 pi f A, r_disp = A/z_ss" + more)
            ->transform(number_in(kAmplitudeRange));
    u.frequency_opt =
        cmd.add_option("--frequency", u.frequency, "vibration frequency f in kHz: v_v = 2 pi f A" + more)
            ->transform(number_in(kFrequencyRange));
}

void add_unit_options(CLI::App& cmd, UnitArgs& u, UnitShape shape, const std::string& use) {
    add_vb_zss_options(cmd, u, shape);
    add_vibration_options(cmd, u, use);
}

std::optional<double> zeta_of(const CLI::Option* zeta_opt, double zeta, const UnitArgs& u, bool required) {
    check_alternatives(zeta_opt, u.vb_opt);
    if (given(u.vb_opt)) return zeta_from_vb(u.vb, "--vb " + g(u.vb) + " m/s", u);
    if (given(zeta_opt)) return zeta;
    if (required) missing("--zeta or --vb", zeta_allowed());
    return std::nullopt;
}

std::optional<double> rdisp_of(const CLI::Option* rdisp_opt, double rdisp, const UnitArgs& u, bool required) {
    check_alternatives(rdisp_opt, u.zss_opt);
    if (given(u.zss_opt)) return rdisp_from_zss(u.zss, u);
    if (given(rdisp_opt)) return rdisp;
    if (required) missing("--rdisp or --zss", rdisp_allowed(), " for the Dahl model");
    return std::nullopt;
}

RangeSpec zeta_range_of(const CLI::Option* zeta_opt, const std::string& zeta, const UnitArgs& u) {
    check_alternatives(zeta_opt, u.vb_opt);
    if (!given(u.vb_opt)) {
        if (!given(zeta_opt)) missing("--zeta or --vb", zeta_allowed());
        return parse_range_spec(zeta);
    }
    RangeSpec r = parse_range_spec(u.vb_range);
    const std::string label = "--vb " + u.vb_range + " m/s";
    r.from = zeta_from_vb(r.from, label + " (FROM)", u);
    r.to = zeta_from_vb(r.to, label + " (TO)", u);
    if (r.count > 1 && !(r.from < r.to))
        throw UsageError(label + " at " + vibration_text(given_vibration(u)) +
                         " gives an empty zeta range; allowed: FROM < TO after the conversion");
    return r;
}

std::vector<double> rdisps_of(const CLI::Option* rdisp_opt, const std::vector<double>& rdisps,
                              const UnitArgs& u, bool required) {
    check_alternatives(rdisp_opt, u.zss_opt);
    if (!given(u.zss_opt)) {
        if (required && !given(rdisp_opt))
            missing("--rdisp or --zss", rdisp_allowed(), " for the Dahl model");
        return rdisps;
    }
    std::vector<double> out;
    for (double zss : u.zss_list) out.push_back(rdisp_from_zss(zss, u));
    return out;
}

void check_vibration(const Vibration& v, const std::vector<double>& rdisps) {
    if (!v.amplitude_um) return;
    const double a = *v.amplitude_um;
    if (v.frequency_khz)
        convert(vibration_text(v), [&] { return units::vibration_velocity(a, *v.frequency_khz); });
    for (double r : rdisps)
        convert(vibration_text({a, {}}) + " at rdisp " + g(r), [&] { return units::zss_from_rdisp(r, a); });
}

Vibration vibration_of(const UnitArgs& u, const std::vector<double>& rdisps) {
    const Vibration v = given_vibration(u);
    check_vibration(v, rdisps);
    return v;
}

} // namespace fv::cli
