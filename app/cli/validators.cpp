#include "validators.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fv::cli {

namespace {

// Whether `s` is spelled as a decimal number: optional sign, digits with at most one point, optional
// exponent. strtod alone would also take hex floats (0x10, 0x1p3), "inf", "nan" and leading blanks.
bool decimal_syntax(const std::string& s) {
    std::size_t k = 0;
    const auto digits = [&] {
        const std::size_t from = k;
        while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
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

} // namespace

Parsed parse_decimal(const std::string& s, double& out) {
    if (!decimal_syntax(s)) return Parsed::not_decimal;
    errno = 0;
    const double v = std::strtod(s.c_str(), nullptr);
    // ERANGE: overflow to +-HUGE_VAL, or underflow. A subnormal result (5e-324) is still the number asked
    // for; one that rounds to zero (1e-400) is not.
    if (errno == ERANGE && (std::isinf(v) || v == 0)) return Parsed::unrepresentable;
    out = v + 0.0; // -0 is read as 0: it is the same angle, ratio or exponent, and should print as one
    return Parsed::ok;
}

bool parse_finite(const std::string& s, double& out) {
    return parse_decimal(s, out) == Parsed::ok;
}

namespace {

std::string number_error(const std::string& s, Range r) {
    double v = 0;
    switch (parse_decimal(s, v)) {
    case Parsed::not_decimal:
        return "'" + s + "' is not a decimal number; allowed: a number in " + describe(r);
    case Parsed::unrepresentable:
        return "'" + s + "' is out of range (beyond double precision); allowed: a number in " + describe(r);
    case Parsed::ok:
        break;
    }
    if (!inside(v, r)) return "'" + s + "' is out of range; allowed: a number in " + describe(r);
    return {};
}

// "a,b,c" split at every comma, empty items kept (so that "0,,30" can be refused rather than read as 0,30).
std::vector<std::string> split_list(const std::string& s) {
    std::vector<std::string> items;
    std::size_t from = 0;
    for (;;) {
        const std::size_t comma = s.find(',', from);
        items.push_back(s.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
        if (comma == std::string::npos) return items;
        from = comma + 1;
    }
}

} // namespace

CLI::Validator number_in(Range r) {
    return CLI::Validator([r](std::string& s) { return number_error(s, r); }, "NUMBER in " + describe(r));
}

CLI::Validator number_list_in(Range r) {
    return CLI::Validator(
        [r](std::string& s) -> std::string {
            const std::vector<std::string> items = split_list(s);
            for (std::size_t k = 0; k < items.size(); ++k) {
                if (items[k].empty())
                    return "'" + s + "' has an empty item (number " + std::to_string(k + 1) +
                           "); allowed: comma-separated numbers in " + describe(r);
                if (auto e = number_error(items[k], r); !e.empty()) return e;
            }
            return {};
        },
        "NUMBER[,NUMBER...] in " + describe(r));
}

CLI::Option* add_number_list(CLI::App& cmd, const std::string& name, std::vector<double>& out, Range r,
                             const std::string& help) {
    // No CLI11 delimiter: it drops empty items silently. The validator sees each argument whole, and the
    // callback splits it (repeated flags append).
    return cmd
        .add_option_function<std::vector<std::string>>(
            name,
            [&out](const std::vector<std::string>& args) {
                out.clear();
                for (const std::string& a : args)
                    for (const std::string& item : split_list(a)) {
                        double v = 0;
                        parse_finite(item, v);
                        out.push_back(v);
                    }
            },
            help)
        ->check(number_list_in(r));
}

CLI::Validator file_name() {
    return CLI::Validator(
        [](std::string& s) -> std::string { return s.empty() ? "empty path; give a file name" : ""; },
        "FILE");
}

CLI::Validator integer_in(long lo, long hi) {
    return CLI::Validator(
        [lo, hi](std::string& s) -> std::string {
            errno = 0;
            char* end = nullptr;
            const long v = s.empty() ? 0 : std::strtol(s.c_str(), &end, 10);
            std::ostringstream os;
            os << "an integer in [" << lo << ", " << hi << "]";
            if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
                return "'" + s + "' is not an integer; allowed: " + os.str();
            if (v < lo || v > hi) return "'" + s + "' is out of range; allowed: " + os.str();
            return {};
        },
        "INT");
}

RangeSpec parse_range_spec(const std::string& s) {
    RangeSpec rs;
    const auto a = s.find(':');
    if (a == std::string::npos) {
        parse_finite(s, rs.from);
        rs.to = rs.from;
        return rs;
    }
    const auto b = s.find(':', a + 1);
    parse_finite(s.substr(0, a), rs.from);
    parse_finite(s.substr(a + 1, b - a - 1), rs.to);
    rs.count = std::atoi(s.substr(b + 1).c_str());
    return rs;
}

CLI::Validator range_spec(Range r, int max_count) {
    return CLI::Validator(
        [r, max_count](std::string& s) -> std::string {
            std::ostringstream allowed;
            allowed << "allowed: FROM:TO:COUNT with FROM <= TO in " << describe(r) << " and COUNT in [1, "
                    << max_count << "], or a single number";
            const auto a = s.find(':');
            if (a == std::string::npos) {
                const auto e = number_error(s, r);
                return e.empty() ? e : "'" + s + "' is not a valid range; " + allowed.str();
            }
            const auto b = s.find(':', a + 1);
            if (b == std::string::npos || s.find(':', b + 1) != std::string::npos)
                return "'" + s + "' is not FROM:TO:COUNT; " + allowed.str();
            double from = 0, to = 0;
            if (!parse_finite(s.substr(0, a), from) || !parse_finite(s.substr(a + 1, b - a - 1), to))
                return "'" + s + "' has a FROM or TO that is not a finite number; " + allowed.str();
            const std::string c = s.substr(b + 1);
            char* end = nullptr;
            errno = 0;
            const long count = c.empty() ? -1 : std::strtol(c.c_str(), &end, 10);
            if (c.empty() || end != c.c_str() + c.size() || errno == ERANGE)
                return "'" + s + "' has a COUNT that is not an integer; " + allowed.str();
            if (count < 1 || count > max_count) return "'" + s + "' has COUNT out of range; " + allowed.str();
            if (!inside(from, r) || !inside(to, r))
                return "'" + s + "' leaves the allowed range; " + allowed.str();
            if (from > to) return "'" + s + "' is reversed (FROM > TO); " + allowed.str();
            if (from == to && count > 1)
                return "'" + s + "' is empty (FROM == TO with COUNT > 1); " + allowed.str();
            return {};
        },
        "FROM:TO:COUNT");
}

} // namespace fv::cli
