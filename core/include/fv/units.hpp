// Physical units <-> the model's dimensionless numbers (paper Eqs. (6), (34); docs/model.md).
//   v_v   = omega x_v = 2 pi f A        vibration velocity amplitude
//   zeta  = v_b / v_v                   Eq. (6)
//   rdisp = x_v / z_ss = A / z_ss       Eq. (34)
// Units are those in which measurements are usually reported: v_b in m/s, amplitude A and z_ss in
// micrometres, frequency f in kHz. Example (Littmann et al., paper Sec. 4): A = 0.7 um at 60 kHz gives
// v_v = 2 pi * 60e3 * 0.7e-6 m/s = 0.2639 m/s.
#pragma once

#include "fv/params.hpp"

#include <stdexcept>
#include <string>

namespace fv::units {

// The experiment of the paper's Fig. 19 (Littmann et al., Sec. 4): 0.7 um at 60 kHz.
inline constexpr double kLittmannAmplitudeUm = 0.7, kLittmannFrequencyKhz = 60;

// Thrown for an argument that is not finite or out of its range; what() names it and the allowed range.
struct UnitError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// v_v in m/s; amplitude_um > 0, frequency_khz > 0.
double vibration_velocity(double amplitude_um, double frequency_khz);

// zeta = v_b / v_v; vb_m_s >= 0.
double zeta_from_vb(double vb_m_s, double amplitude_um, double frequency_khz);
// v_b = zeta v_v in m/s; zeta >= 0.
double vb_from_zeta(double zeta, double amplitude_um, double frequency_khz);

// rdisp = A / z_ss; zss_um > 0.
double rdisp_from_zss(double amplitude_um, double zss_um);
// z_ss = A / rdisp in um; rdisp > 0.
double zss_from_rdisp(double rdisp, double amplitude_um);

// The physical view of a state, checked as one: v_v = 2 pi f A, v_b = zeta v_v and z_ss = A / rdisp must
// each be a finite number inside its range of param_ranges.hpp (kVbRange, kZssRange), so that no door
// (a session, a link with the app's default A, an edit) can leave the app showing NaN or infinity. "" or one
// line naming the values, e.g. "rdisp = 5e-324 with amplitude 0.7 um gives z_ss = A / rdisp = inf um;
// allowed: z_ss in (0, 1e+06] um, so rdisp >= 7e-07 at this amplitude".
std::string physical_view_error(const Params& p, double amplitude_um, double frequency_khz);

} // namespace fv::units
