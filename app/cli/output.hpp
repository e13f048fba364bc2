// Formatting results as text, CSV and JSON, and delivering them to stdout or a file (atomically).
#pragma once

#include "figures/result_tables.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace fv::cli {

// The tables themselves are the figures layer's (one writer for the command line and the library).
using app::all_finite;
using app::describe_failure;
using app::Format;
using app::parse_format;
using app::ratio_table;
using app::ratio_text;
using app::RatioTableStream;
using app::status_of;
using app::trace_table;
using app::Vibration;

// The --out FILE option of the commands that print one result (ratio, sweep, trace, fit). `out` starts as
// "-", standard output; any other path follows the output-path policy of fv/atomic_file.hpp.
CLI::Option* add_out_option(CLI::App& cmd, std::string& out);

// Standard output when out is "-", else written to `out` by the output-path policy (RuntimeFailure if that
// fails).
void deliver(const std::string& content, const std::string& out);

// Validates an --out target before any work is done (UsageError naming the flag): "-" is standard output,
// an empty path is refused, anything else must pass fv::check_writable.
void check_out(const std::string& out, const char* flag = "--out");

// Validates the output directory of `render` before any work is done (UsageError naming the flag).
void check_out_dir(const std::string& dir, const char* flag = "--out");

// The failed rows (status_of not ok) of a table, counted per reason.
struct Failures {
    long long count = 0;
    std::string by_reason; // "not_converged 3, non_finite 1"
};

// Failed rows seen block by block (a streamed sweep): counts per reason and the first few rows, for the
// same report failures_of and print_failures give for a whole table.
class FailureLog {
  public:
    void add(const std::vector<SweepPoint>& rows);
    Failures failures() const;
    void print(const std::string& prefix = "", int max_lines = 10) const;

  private:
    std::vector<SweepPoint> first_; // at most 10
    long long counts_[3] = {0, 0, 0}, total_ = 0;
};
Failures failures_of(const std::vector<SweepPoint>& rows);

// One stderr line per failed row, "frictionviz: <prefix>failed: <describe_failure>", at most max_lines of
// them and then one line saying how many more there are.
void print_failures(const std::vector<SweepPoint>& rows, const std::string& prefix = "", int max_lines = 10);

} // namespace fv::cli
