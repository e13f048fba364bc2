// The one number reader of every door: command-line flags, share links and the web page's address,
// session files, scripts, measured-data files and --size. The same text gets the same verdict and the same
// message wherever it is typed (tests/reliability/test_number_doors.cpp feeds one list of hostile numbers
// through every door).
//
//   accepted   [+|-] digits [. digits] [(e|E) [+|-] digits]   (or a point with digits on one side only)
//              -0 reads as 0; a subnormal (5e-324) is the number it names
//   refused    blanks around it, hex (0x10, 0x1p3), inf, nan, an empty text      "is not a decimal number"
//              a value that overflows (1e400) or underflows to 0 (1e-400)       "beyond double precision"
//              a number outside the door's range (param_ranges.hpp)             "is out of range"
#pragma once

#include "fv/param_ranges.hpp"

#include <string>
#include <string_view>

namespace fv {

enum class NumberVerdict { ok, not_decimal, beyond_double };

// Reads the whole of `text` as a decimal number; `value` is set only when the verdict is ok.
NumberVerdict read_decimal(std::string_view text, double& value);

// Reads `text` as a number inside `r`. Returns "" (and sets `value`) or one line:
//   NAME = 'TEXT' is not a decimal number; allowed: NAME in RANGE
//   NAME = TEXT is out of range (beyond double precision); allowed: NAME in RANGE
//   NAME = TEXT is out of range; allowed: NAME in RANGE
// With an empty `name` the line starts with the text and ends "allowed: a number in RANGE". TEXT is shown
// printable and bounded (printable_text).
std::string read_number(std::string_view name, std::string_view text, ParamRange r, double& value);

// The message read_number gives for a value already read (sessions' numbers from a JSON parser, the app's
// edits): "" when v is inside r, else "NAME = V is out of range; allowed: NAME in RANGE".
std::string range_message(std::string_view name, double v, ParamRange r);

// Reads the whole of `text` as a decimal integer in [lo, hi] (optional sign, digits only). Returns "" (and
// sets `value`) or "NAME = 'TEXT' is not an integer; allowed: NAME in [LO, HI]" / "... is out of range; ...".
std::string read_integer(std::string_view name, std::string_view text, long long lo, long long hi,
                         long long& value);

// The shortest decimal text that strtod reads back as v (up to 17 significant digits; exponent without '+';
// -0 as "0").
std::string shortest_decimal(double v);

} // namespace fv
