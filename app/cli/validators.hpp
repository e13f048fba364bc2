// CLI11 validators that turn bad numbers into one-line messages naming the allowed range.
#pragma once

#include "fv/param_ranges.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fv::cli {

// The ranges themselves (kZetaRange, ...) are core's table, fv/param_ranges.hpp.
using Range = ParamRange;
using fv::describe;
using fv::inside;

// The whole string read by the shared number reader (fv::read_decimal): true and `out` set when it is a
// decimal number that a double holds ("-1.5e3"; not hex, inf, nan, blanks or 1e-400). -0 is read as 0.
bool parse_finite(const std::string& s, double& out);

// A finite number inside `r`, read by the shared reader (fv/read_number.hpp); the message quotes the value
// and the range. Add it with ->transform(): it rewrites the text to the value read (-0 as 0).
CLI::Validator number_in(Range r);

// Comma-separated numbers, each inside `r`; an empty item ("0,,30", "0,") is an error, not skipped.
CLI::Validator number_list_in(Range r);

// The option --name: comma-separated numbers in `r` (number_list_in) into `out`.
CLI::Option* add_number_list(CLI::App& cmd, const std::string& name, std::vector<double>& out, Range r,
                             const std::string& help);

// A file name: anything but the empty string (which would otherwise read as "not given").
CLI::Validator file_name();

// An integer in [lo, hi].
CLI::Validator integer_in(long lo, long hi);

// "FROM:TO:COUNT" with FROM <= TO inside `r`, COUNT in [1, max_count], FROM < TO when COUNT > 1;
// a single number means one point.
CLI::Validator range_spec(Range r, int max_count);

struct RangeSpec {
    double from = 0, to = 0;
    int count = 1;
};
// Parse a string that range_spec() accepted.
RangeSpec parse_range_spec(const std::string& s);

} // namespace fv::cli
