// Formatting results as text, CSV and JSON, and delivering them to stdout or a file (atomically).
#pragma once

#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fv::cli {

enum class Format { text, csv, json };
Format parse_format(const std::string& s);

// The vibration behind the dimensionless numbers, where the command line gives it (unit_options.hpp). The
// output then also shows the physical view: v_b and v_v in m/s (amplitude and frequency known), z_ss in um
// (amplitude known; Dahl model). Left empty, the output is the dimensionless one, unchanged.
// Callers check it first (check_vibration): v_v and z_ss must be finite and > 0.
struct Vibration {
    std::optional<double> amplitude_um, frequency_khz;
};

// Columns of ratio and sweep output: model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate, then
// vb_m_s (amplitude and frequency known) and zss_um (amplitude known; empty for the rigid model). JSON has
// the same keys (zss_um null for the rigid model).
std::string ratio_table(const std::vector<SweepPoint>& rows, Format f, const Vibration& v = {});
// Human-readable report of one point (with amplitude, frequency, v_v, v_b, z_ss as far as `v` gives them).
std::string ratio_text(const SweepPoint& row, const Vibration& v = {});

// Columns tau,Px,Py,Tx,Ty,z,Fx,Fy of one steady-state period.
std::string trace_table(const SweepPoint& row, Format f);

// stdout when out is empty, else written atomically to `out` (RuntimeFailure if that fails).
void deliver(const std::string& content, const std::string& out);

// Validates an --out target before any work is done (UsageError naming the flag).
void check_out(const std::string& out, const char* flag = "--out");

// One line on stderr when a steady state was not reached, so it is never silently passed off.
void warn_if_unsteady(const SweepPoint& row);

} // namespace fv::cli
