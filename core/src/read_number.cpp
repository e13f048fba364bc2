#include "fv/read_number.hpp"

#include "fv/parse_number.hpp"
#include "fv/printable_text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace fv {
namespace {

bool digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Whether `s` is spelled as a decimal number: optional sign, digits with at most one point (digits on at
// least one side), optional exponent with digits. parse_number alone would also take inf and nan, and stops
// early rather than refusing trailing text.
bool decimal_syntax(std::string_view s) {
    std::size_t k = 0;
    const auto digits = [&] {
        const std::size_t from = k;
        while (k < s.size() && digit(s[k])) ++k;
        return k - from;
    };
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    std::size_t mantissa = digits();
    if (k < s.size() && s[k] == '.') {
        ++k;
        mantissa += digits();
    }
    if (mantissa == 0) return false;
    if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
        ++k;
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        if (digits() == 0) return false;
    }
    return k == s.size();
}

std::string allowed(std::string_view name, const std::string& range) {
    return name.empty() ? "; allowed: a number in " + range
                        : "; allowed: " + std::string(name) + " in " + range;
}

std::string subject(std::string_view name, const std::string& shown) {
    return name.empty() ? shown : std::string(name) + " = " + shown;
}

} // namespace

NumberVerdict read_decimal(std::string_view text, double& value) {
    if (!decimal_syntax(text)) return NumberVerdict::not_decimal;
    // parse_number (std::from_chars' contract) takes no '+'.
    if (text[0] == '+') text.remove_prefix(1);
    double v = 0;
    const ParseNumberResult r = parse_number(text.data(), text.data() + text.size(), v);
    // Out of range: a finite text that rounds to infinity (1e400) or, from nonzero digits, to zero (1e-400).
    // A subnormal (5e-324) is in range: it is the number asked for.
    if (r.ec == std::errc::result_out_of_range) return NumberVerdict::beyond_double;
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v))
        return NumberVerdict::not_decimal;
    value = v + 0.0; // -0 reads as 0: the same angle, ratio or exponent, and it should print as one
    return NumberVerdict::ok;
}

std::string read_number(std::string_view name, std::string_view text, ParamRange r, double& value) {
    double v = 0;
    if (text.empty())
        return (name.empty() ? "an empty text" : std::string(name) + " is empty") +
               allowed(name, describe(r));
    switch (read_decimal(text, v)) {
    case NumberVerdict::not_decimal:
        return subject(name, quoted_text(text)) + " is not a decimal number" + allowed(name, describe(r));
    case NumberVerdict::beyond_double:
        return subject(name, printable_text(text)) + " is out of range (beyond double precision)" +
               allowed(name, describe(r));
    case NumberVerdict::ok:
        break;
    }
    if (!inside(v, r))
        return subject(name, printable_text(text)) + " is out of range" + allowed(name, describe(r));
    value = v;
    return {};
}

std::string range_message(std::string_view name, double v, ParamRange r) {
    if (inside(v, r)) return {};
    return subject(name, shortest_decimal(v)) + " is out of range" + allowed(name, describe(r));
}

std::string read_integer(std::string_view name, std::string_view text, long long lo, long long hi,
                         long long& value) {
    const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    std::size_t k = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
    const bool negative = k == 1 && text[0] == '-';
    if (k == text.size())
        return subject(name, quoted_text(text)) + " is not an integer" + allowed(name, range);
    // Accumulated with an overflow check: sscanf("%d") and atoi wrap 4294967616 to 320.
    unsigned long long magnitude = 0;
    bool overflow = false;
    for (; k < text.size(); ++k) {
        if (!digit(text[k]))
            return subject(name, quoted_text(text)) + " is not an integer" + allowed(name, range);
        const unsigned d = static_cast<unsigned>(text[k] - '0');
        if (magnitude > (std::numeric_limits<unsigned long long>::max() - d) / 10)
            overflow = true;
        else
            magnitude = magnitude * 10 + d;
    }
    const auto within = [&](long long v) { return v >= lo && v <= hi; };
    constexpr auto kMax = static_cast<unsigned long long>(std::numeric_limits<long long>::max());
    if (overflow || magnitude > kMax + (negative ? 1 : 0))
        return subject(name, printable_text(text)) + " is out of range" + allowed(name, range);
    const long long v = negative ? (magnitude == kMax + 1 ? std::numeric_limits<long long>::min()
                                                          : -static_cast<long long>(magnitude))
                                 : static_cast<long long>(magnitude);
    if (!within(v)) return subject(name, printable_text(text)) + " is out of range" + allowed(name, range);
    value = v;
    return {};
}

std::string shortest_decimal(double v) {
    if (v == 0) v = 0; // -0
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[48];
    int digits = 1;
    for (; digits < 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    // Those significant digits without an exponent where that is short (60, not 6e+01; 0.0001), else
    // with one (1e-07, 1e20).
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v);
    const int exponent = std::atoi(std::strchr(buf, 'e') + 1);
    if (exponent >= -5 && exponent < 17)
        std::snprintf(buf, sizeof buf, "%.*f", std::max(0, digits - 1 - exponent), v);
    else
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    std::string s = buf;
    if (const auto plus = s.find("e+"); plus != std::string::npos) s.erase(plus + 1, 1);
    return s;
}

} // namespace fv
