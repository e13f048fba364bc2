#include "validators.hpp"

#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace fv::cli {

bool parse_finite(const std::string& s, double& out) {
    return read_decimal(s, out) == NumberVerdict::ok;
}

namespace {

// The shared reader's verdict and message (fv/read_number.hpp), as for links, sessions, scripts and data.
std::string number_error(const std::string& s, Range r) {
    double v = 0;
    return read_number("", s, r, v);
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
    // A transform: the text CLI11 converts is the shortest decimal of the value the shared reader took, so
    // the option holds exactly that value ("-0" becomes 0, "+1" 1, as at every other door).
    return CLI::Validator(
        [r](std::string& s) {
            double v = 0;
            std::string why = read_number("", s, r, v);
            if (why.empty()) s = shortest_decimal(v);
            return why;
        },
        "NUMBER in " + describe(r));
}

CLI::Validator number_list_in(Range r) {
    return CLI::Validator(
        [r](std::string& s) -> std::string {
            const std::vector<std::string> items = split_list(s);
            for (std::size_t k = 0; k < items.size(); ++k) {
                if (items[k].empty())
                    return quoted_text(s) + " has an empty item (number " + std::to_string(k + 1) +
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
            long long v = 0;
            return read_integer("", s, lo, hi, v);
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
    long long count = 1;
    read_integer("", s.substr(b + 1), 1, std::numeric_limits<int>::max(), count);
    rs.count = static_cast<int>(count);
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
                return e.empty() ? e : quoted_text(s) + " is not a valid range; " + allowed.str();
            }
            const auto b = s.find(':', a + 1);
            if (b == std::string::npos || s.find(':', b + 1) != std::string::npos)
                return quoted_text(s) + " is not FROM:TO:COUNT; " + allowed.str();
            double from = 0, to = 0;
            if (!parse_finite(s.substr(0, a), from) || !parse_finite(s.substr(a + 1, b - a - 1), to))
                return quoted_text(s) + " has a FROM or TO that is not a finite number; " + allowed.str();
            long long count = 0;
            if (const std::string why = read_integer("", s.substr(b + 1), 1, max_count, count); !why.empty())
                return quoted_text(s) +
                       (why.find("not an integer") != std::string::npos
                            ? " has a COUNT that is not an integer; "
                            : " has COUNT out of range; ") +
                       allowed.str();
            if (!inside(from, r) || !inside(to, r))
                return quoted_text(s) + " leaves the allowed range; " + allowed.str();
            if (from > to) return quoted_text(s) + " is reversed (FROM > TO); " + allowed.str();
            if (from == to && count > 1)
                return quoted_text(s) + " is empty (FROM == TO with COUNT > 1); " + allowed.str();
            return {};
        },
        "FROM:TO:COUNT");
}

} // namespace fv::cli
