// printf-style formatting of one number into a std::string, for labels and titles.
#pragma once

#include <cstdio>
#include <string>

namespace fv {

// True when a formatted number reads as zero: no digit 1-9 before any exponent ("-0", "-0.0000", "-0e+00").
inline bool reads_as_zero(const std::string& s) {
    for (char c : s) {
        if (c == 'e' || c == 'E') break;
        if (c >= '1' && c <= '9') return false;
    }
    return s.find('0') != std::string::npos;
}

// A value that rounds to zero in the format prints without its sign: never "-0" or "-0.0000".
inline std::string format_number(const char* printf_format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, printf_format, v);
    std::string s = buf;
    const std::size_t minus = s.find_first_not_of(' '); // the sign of the mantissa, not of an exponent
    if (minus != std::string::npos && s[minus] == '-' && reads_as_zero(s.substr(minus + 1)))
        s.erase(minus, 1);
    return s;
}

} // namespace fv
