#include "validators.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fv::cli {

bool parse_finite(const std::string& s, double& out) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return false;
    out = v;
    return true;
}

std::string describe(Range r) {
    std::ostringstream os;
    os << (r.lo_open ? "(" : "[") << r.lo << ", " << r.hi << "]";
    return os.str();
}

bool inside(double v, Range r) {
    return (r.lo_open ? v > r.lo : v >= r.lo) && v <= r.hi;
}

namespace {

std::string number_error(const std::string& s, Range r) {
    double v = 0;
    if (!parse_finite(s, v)) return "'" + s + "' is not a finite number; allowed: a number in " + describe(r);
    if (!inside(v, r)) return "'" + s + "' is out of range; allowed: a number in " + describe(r);
    return {};
}

} // namespace

CLI::Validator number_in(Range r) {
    return CLI::Validator([r](std::string& s) { return number_error(s, r); }, "NUMBER in " + describe(r));
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
