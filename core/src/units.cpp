#include "fv/units.hpp"

#include "fv/param_ranges.hpp"
#include "fv/params.hpp"
#include "fv/read_number.hpp"

#include <cmath>
#include <sstream>

namespace fv::units {

namespace {

// 1 kHz * 1 um = 1e3 /s * 1e-6 m = 1e-3 m/s.
constexpr double kKhzUmToMps = 1e-3;

void require(const char* name, double v, bool zero_allowed) {
    if (std::isfinite(v) && (zero_allowed ? v >= 0 : v > 0)) return;
    std::ostringstream os;
    os << name << " = " << v << " is not allowed: need a finite number " << (zero_allowed ? ">= 0" : "> 0");
    throw UnitError(os.str());
}

// Valid arguments can still give a result outside the doubles (1e-300 um at 1e-300 kHz underflows to 0; a
// division by that gives NaN or infinity): reject it rather than pass it on.
double checked(const char* name, double v, bool zero_allowed) {
    if (std::isfinite(v) && (zero_allowed ? v >= 0 : v > 0)) return v;
    std::ostringstream os;
    os << name << " = " << v << " is outside the range of doubles; allowed: arguments that give a finite "
       << (zero_allowed ? "result >= 0" : "result > 0");
    throw UnitError(os.str());
}

} // namespace

double vibration_velocity(double amplitude_um, double frequency_khz) {
    require("amplitude (um)", amplitude_um, false);
    require("frequency (kHz)", frequency_khz, false);
    return checked("v_v (m/s)", 2 * kPi * frequency_khz * amplitude_um * kKhzUmToMps, false);
}

double zeta_from_vb(double vb_m_s, double amplitude_um, double frequency_khz) {
    require("v_b (m/s)", vb_m_s, true);
    return checked("zeta", vb_m_s / vibration_velocity(amplitude_um, frequency_khz), true);
}

double vb_from_zeta(double zeta, double amplitude_um, double frequency_khz) {
    require("zeta", zeta, true);
    return checked("v_b (m/s)", zeta * vibration_velocity(amplitude_um, frequency_khz), true);
}

double rdisp_from_zss(double amplitude_um, double zss_um) {
    require("amplitude (um)", amplitude_um, false);
    require("z_ss (um)", zss_um, false);
    return checked("rdisp", amplitude_um / zss_um, false);
}

double zss_from_rdisp(double rdisp, double amplitude_um) {
    require("rdisp", rdisp, false);
    require("amplitude (um)", amplitude_um, false);
    return checked("z_ss (um)", amplitude_um / rdisp, false);
}

std::string physical_view_error(const Params& p, double amplitude_um, double frequency_khz) {
    const auto num = [](double v) { return shortest_decimal(v); };
    if (std::string why = range_message("amplitude_um", amplitude_um, kAmplitudeRange); !why.empty())
        return why;
    if (std::string why = range_message("frequency_khz", frequency_khz, kFrequencyRange); !why.empty())
        return why;
    const double vv = 2 * kPi * frequency_khz * amplitude_um * kKhzUmToMps;
    const std::string at = " with amplitude " + num(amplitude_um) + " um";
    if (!(std::isfinite(vv) && vv > 0))
        return "amplitude " + num(amplitude_um) + " um at " + num(frequency_khz) +
               " kHz gives v_v = 2 pi f A = " + num(vv) + " m/s; allowed: a finite v_v > 0";
    const double vb = p.zeta * vv;
    if (!inside(vb, kVbRange))
        return "zeta = " + num(p.zeta) + at + " at " + num(frequency_khz) +
               " kHz gives v_b = zeta v_v = " + num(vb) + " m/s; allowed: v_b in " + describe(kVbRange) +
               " m/s";
    const double zss = amplitude_um / p.rdisp;
    if (!inside(zss, kZssRange))
        return "rdisp = " + num(p.rdisp) + at + " gives z_ss = A / rdisp = " + num(zss) +
               " um; allowed: z_ss in " + describe(kZssRange) +
               " um, so rdisp >= " + num(amplitude_um / kZssRange.hi) + " at this amplitude";
    return {};
}

} // namespace fv::units
