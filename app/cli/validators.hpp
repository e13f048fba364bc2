// CLI11 validators that turn bad numbers into one-line messages naming the allowed range.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace fv::cli {

struct Range {
    double lo, hi;
    bool lo_open = false; // lo itself excluded
};

// Parses a whole string as a finite double; false on junk, trailing characters, NaN or infinity.
bool parse_finite(const std::string& s, double& out);

// A finite number inside `r`; the message quotes the value and the range.
CLI::Validator number_in(Range r);

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

std::string describe(Range r);

// v lies in r.
bool inside(double v, Range r);

} // namespace fv::cli
