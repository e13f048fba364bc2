// Formatting results as text, CSV and JSON, and delivering them to stdout or a file (atomically).
#pragma once

#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <string>
#include <vector>

namespace fv::cli {

enum class Format { text, csv, json };
Format parse_format(const std::string& s);

// Columns of ratio and sweep output: model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate
std::string ratio_table(const std::vector<SweepPoint>& rows, Format f);
// Human-readable report of one point.
std::string ratio_text(const SweepPoint& row);

// Columns tau,Px,Py,Tx,Ty,z,Fx,Fy of one steady-state period.
std::string trace_table(const SweepPoint& row, Format f);

// stdout when out is empty, else written atomically to `out` (RuntimeFailure if that fails).
void deliver(const std::string& content, const std::string& out);

// Validates an --out target before any work is done (UsageError naming the flag).
void check_out(const std::string& out, const char* flag = "--out");

// One line on stderr when a steady state was not reached, so it is never silently passed off.
void warn_if_unsteady(const SweepPoint& row);

} // namespace fv::cli
