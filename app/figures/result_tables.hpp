// The result tables of `ratio`, `sweep`, `trace` and `render` as text, CSV and JSON: one writer for the
// command line and the library (a figure's CSV files, figure_tables.hpp; the Python module's Figure.tables).
#pragma once

#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fv::app {

enum class Format { text, csv, json };
Format parse_format(const std::string& s);

// The vibration behind the dimensionless numbers, where the command line gives it (unit_options.hpp). The
// output then also shows the physical view: v_b and v_v in m/s (amplitude and frequency known), z_ss in um
// (amplitude known; Dahl model). Left empty, the output is the dimensionless one, unchanged.
// Callers check it first (check_vibration): v_v and z_ss must be finite and > 0.
struct Vibration {
    std::optional<double> amplitude_um, frequency_khz;
};

// The status a row is reported with: the solver's, or non_finite when it vouches for an r_x or r_y that is
// not a finite number. Only SteadyStatus::converged (shown "ok") is a result; see fv::to_string.
SteadyStatus status_of(const SweepPoint& row);

// Columns of ratio and sweep output: model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,
// then vb_m_s (amplitude and frequency known) and zss_um (amplitude known; empty for the rigid model).
// status is `ok` or the reason (not_converged, integration_failed, non_finite); a failed row keeps its best
// values, r_x and r_y are empty when not finite. JSON has the same keys (null where CSV is empty).
// statuses_known = false (rows whose producer did not keep the solver's status): the status is empty/null.
std::string ratio_table(const std::vector<SweepPoint>& rows, Format f, const Vibration& v = {},
                        bool statuses_known = true);
// ratio_table in pieces, for rows that arrive block by block (sweep streams them): head(), then rows() for
// each block in order, then tail(); the pieces joined are ratio_table of all the rows (`total` of them).
class RatioTableStream {
  public:
    RatioTableStream(Format f, const Vibration& v, std::size_t total, bool statuses_known = true)
        : f_(f), v_(v), total_(total), statuses_known_(statuses_known) {}
    std::string head() const;
    std::string rows(const std::vector<SweepPoint>& rows);
    std::string tail() const;

  private:
    Format f_;
    Vibration v_;
    std::size_t total_, done_ = 0;
    bool statuses_known_;
};

// Human-readable report of one point (with amplitude, frequency, v_v, v_b, z_ss as far as `v` gives them),
// ending with "status        ok" or the reason and what it means.
std::string ratio_text(const SweepPoint& row, const Vibration& v = {});

// True when every number of every sample is finite.
bool all_finite(const std::vector<Sample>& period);

// Columns tau,Px,Py,Tx,Ty,z,Fx,Fy,status of one steady-state period (status: of the steady state, on every
// row; JSON: the ratio keys, status among them, and the columns under "trace").
std::string trace_table(const SweepPoint& row, Format f);

// What went wrong with a failed row, one line without a newline: "not_converged at zeta=0.3 theta=45 deg
// rdisp=2 i=1 (steady state not verified after 100 periods: period budget exhausted; error
// estimate 1.2e-03)".
std::string describe_failure(const SweepPoint& row);

} // namespace fv::app
