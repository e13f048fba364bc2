// A decimal number parse with the contract of std::from_chars(first, last, double&) in chars_format::general,
// for every platform: emscripten's libc++ deletes the floating-point std::from_chars, and the data reader's
// error messages (measurements.cpp) depend on exactly what it consumes and when it reports a range error.
#pragma once

#include <system_error>

namespace fv {

struct ParseNumberResult {
    const char* ptr; // one past the last character consumed; `first` when nothing matched
    std::errc ec;    // {} | invalid_argument (nothing matched) | result_out_of_range
};

// Matches the longest prefix of [first, last) of the form
//   [-] ( digits [. digits] | . digits ) [(e|E) [+|-] digits]   (an exponent without digits is not consumed)
//   [-] inf | infinity | nan | nan(chars)                       (letters in any case; chars: [A-Za-z0-9_]*)
// No leading blanks, no '+' sign, no hex. The value is rounded to nearest; a finite number whose magnitude
// rounds to infinity or (from nonzero digits) to zero gives result_out_of_range and leaves `value` untouched,
// as libstdc++'s std::from_chars does; subnormal results are in range. `value` is set only on success.
ParseNumberResult parse_number(const char* first, const char* last, double& value);

} // namespace fv
