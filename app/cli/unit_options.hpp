// Physical units on the command line, as alternatives to the dimensionless numbers (fv/units.hpp):
//   --vb V (m/s) with --amplitude A (um) and --frequency f (kHz):  zeta   = V/(2 pi f A), Eq. (6)
//   --zss Z (um) with --amplitude A (um):                          r_disp = A/Z,          Eq. (34)
// Used by ratio, sweep, trace, render (scene, map) and gui; fit and render fig19 share --amplitude and
// --frequency. The resolution functions throw UsageError with one line naming the flags: both alternatives
// given, a unit flag without what it needs, a converted value outside the model's range, or a conversion
// that fails (fv::units::UnitError). --amplitude and --frequency with plain --zeta/--rdisp are allowed: they
// add the physical view to the output (output.hpp, Vibration).
#pragma once

#include "output.hpp"
#include "validators.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace fv::cli {

// kVbRange (m/s), kAmplitudeRange (um), kFrequencyRange (kHz), kZssRange (um): fv/param_ranges.hpp.

struct UnitArgs {
    double vb = 0, amplitude = 0, frequency = 0, zss = 0;
    std::string vb_range;         // sweep: FROM:TO:COUNT in m/s
    std::vector<double> zss_list; // sweep: comma separated, um
    // nullptr: the flag is not registered in this command (counts as not given).
    CLI::Option *vb_opt = nullptr, *amplitude_opt = nullptr, *frequency_opt = nullptr, *zss_opt = nullptr;
};

// One value each (ratio, trace, render, gui) or, for sweep, --vb FROM:TO:COUNT and a --zss list.
enum class UnitShape { single, sweep };

// --vb and --zss.
void add_vb_zss_options(CLI::App& cmd, UnitArgs& u, UnitShape shape);
// --amplitude and --frequency; `use` (may be empty) says in the help what else they do in this command.
void add_vibration_options(CLI::App& cmd, UnitArgs& u, const std::string& use);
// All four: --vb --zss --amplitude --frequency.
void add_unit_options(CLI::App& cmd, UnitArgs& u, UnitShape shape, const std::string& use);

// zeta from --zeta (zeta_opt, zeta) or --vb; nullopt when neither is given and !required.
std::optional<double> zeta_of(const CLI::Option* zeta_opt, double zeta, const UnitArgs& u, bool required);
// r_disp from --rdisp (rdisp_opt, rdisp) or --zss; nullopt when neither is given and !required (the message
// of a missing one says that the Dahl model needs it).
std::optional<double> rdisp_of(const CLI::Option* rdisp_opt, double rdisp, const UnitArgs& u, bool required);

// sweep: the zeta range of --zeta FROM:TO:COUNT or --vb FROM:TO:COUNT (one of them is required).
RangeSpec zeta_range_of(const CLI::Option* zeta_opt, const std::string& zeta, const UnitArgs& u);
// sweep: the r_disp list of --rdisp or --zss (empty when neither is given and !required).
std::vector<double> rdisps_of(const CLI::Option* rdisp_opt, const std::vector<double>& rdisps,
                              const UnitArgs& u, bool required);

// --amplitude and --frequency as given, checked (check_vibration) against the r_disp values the output will
// show z_ss for.
Vibration vibration_of(const UnitArgs& u, const std::vector<double>& rdisps);
// Throws UsageError unless v_v = 2 pi f A (amplitude and frequency known) and z_ss = A/r_disp for each of
// `rdisps` (amplitude known) are finite and > 0, so that the output's conversions cannot fail.
void check_vibration(const Vibration& v, const std::vector<double>& rdisps);

} // namespace fv::cli
