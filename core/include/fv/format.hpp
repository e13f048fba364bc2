// printf-style formatting of one number into a std::string, for labels and titles.
#pragma once

#include <cstdio>
#include <string>

namespace fv {

inline std::string format_number(const char* printf_format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, printf_format, v);
    return buf;
}

} // namespace fv
