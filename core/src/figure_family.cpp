#include "fv/figure_family.hpp"

#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include <algorithm>

namespace fv {
namespace {

constexpr double kDeg = kPi / 180;

// "a,b,c" split at every comma, empty items kept (so that "0,,30" is refused, not read as 0,30).
std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> items;
    for (std::size_t from = 0;;) {
        const std::size_t at = s.find(sep, from);
        items.push_back(s.substr(from, at == std::string_view::npos ? std::string_view::npos : at - from));
        if (at == std::string_view::npos) return items;
        from = at + 1;
    }
}

// "NAME = TEXT", or TEXT alone where the caller names the parameter itself (a command-line flag: CLI11 puts
// the flag before the message).
std::string subject(std::string_view name, const std::string& text) {
    return name.empty() ? text : std::string(name) + " = " + text;
}

std::string empty_item(std::string_view name, std::string_view text, std::size_t k, const std::string& what) {
    return subject(name, quoted_text(text)) + " has an empty item (number " + std::to_string(k + 1) +
           "); allowed: " + what;
}

std::string number_list_allowed(ParamRange r) {
    return "comma-separated numbers in " + describe(r) + ", each once";
}

template <class T, class Text>
std::string twice(std::string_view name, const std::vector<T>& values, Text text,
                  const std::string& allowed) {
    for (std::size_t k = 0; k < values.size(); ++k)
        for (std::size_t j = 0; j < k; ++j)
            if (values[j] == values[k])
                return (name.empty() ? "the list" : std::string(name)) + " has " + text(values[k]) +
                       " twice (items " + std::to_string(j + 1) + " and " + std::to_string(k + 1) +
                       "); allowed: " + allowed;
    return {};
}

const char* model_name(Model m) {
    return m == Model::rigid ? "rigid" : "dahl";
}

} // namespace

std::vector<Curve> family_curves(const FigureFamily& f) {
    std::vector<Curve> out;
    for (Model m : f.models)
        for (double th : f.theta_deg) {
            if (m == Model::rigid) {
                out.push_back({Model::rigid, th * kDeg, 0, 0});
                continue;
            }
            for (double r : f.rdisp)
                for (double i : f.i) out.push_back({Model::dahl, th * kDeg, r, i});
        }
    return out;
}

std::string family_size_error(const FigureFamily& f) {
    const std::size_t n = family_curves(f).size();
    if (n <= kMaxFamilyCurves) return {};
    const bool dahl = std::find(f.models.begin(), f.models.end(), Model::dahl) != f.models.end();
    const bool rigid = std::find(f.models.begin(), f.models.end(), Model::rigid) != f.models.end();
    std::string s;
    if (dahl)
        s += "theta " + std::to_string(f.theta_deg.size()) + " × r_disp " + std::to_string(f.rdisp.size()) +
             " × i " + std::to_string(f.i.size()) + " = " +
             std::to_string(f.theta_deg.size() * f.rdisp.size() * f.i.size()) + " Dahl curves";
    if (rigid) s += std::string(dahl ? " + " : "") + std::to_string(f.theta_deg.size()) + " rigid";
    return s + " = " + std::to_string(n) + " curves; allowed: at most " + std::to_string(kMaxFamilyCurves) +
           " curves in one figure (split the family into several figures)";
}

std::string read_number_list(std::string_view name, std::string_view text, ParamRange r,
                             std::vector<double>& out) {
    const std::vector<std::string_view> items = split(text, ',');
    std::vector<double> values;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (items[k].empty()) return empty_item(name, text, k, number_list_allowed(r));
        double v = 0;
        if (std::string why = read_number(name, items[k], r, v); !why.empty()) return why;
        values.push_back(v);
    }
    if (std::string why = check_number_list(name, values, r); !why.empty()) return why;
    out = std::move(values);
    return {};
}

std::string check_number_list(std::string_view name, const std::vector<double>& values, ParamRange r) {
    if (values.empty())
        return (name.empty() ? "an empty list" : std::string(name) + " is an empty list") +
               "; allowed: " + number_list_allowed(r);
    for (double v : values)
        if (std::string why = range_message(name, v, r); !why.empty()) return why;
    return twice(name, values, shortest_decimal, number_list_allowed(r));
}

std::string read_model_list(std::string_view name, std::string_view text, std::vector<Model>& out) {
    const std::vector<std::string_view> items = split(text, ',');
    std::vector<Model> models;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (items[k].empty()) return empty_item(name, text, k, "dahl, rigid (comma separated, each once)");
        const std::optional<Model> m = parse_model(std::string(items[k]));
        if (!m)
            return subject(name, quoted_text(items[k])) +
                   " is not a model; allowed: dahl, rigid (comma separated, each once)";
        models.push_back(*m);
    }
    if (std::string why = check_model_list(name, models); !why.empty()) return why;
    out = std::move(models);
    return {};
}

std::string check_model_list(std::string_view name, const std::vector<Model>& models) {
    if (models.empty())
        return (name.empty() ? "an empty list" : std::string(name) + " is an empty list") +
               "; allowed: dahl, rigid (comma separated, each once)";
    return twice(name, models, model_name, "dahl, rigid (comma separated, each once)");
}

std::string read_zeta_span(std::string_view name, std::string_view text, ZetaSpan& out) {
    const std::string allowed = "FROM:TO with FROM < TO in " + describe(kZetaRange);
    const std::vector<std::string_view> parts = split(text, ':');
    if (parts.size() != 2) return subject(name, quoted_text(text)) + " is not a range; allowed: " + allowed;
    ZetaSpan s;
    const std::string from_name = name.empty() ? "FROM" : std::string(name) + " FROM",
                      to_name = name.empty() ? "TO" : std::string(name) + " TO";
    if (std::string why = read_number(from_name, parts[0], kZetaRange, s.from); !why.empty()) return why;
    if (std::string why = read_number(to_name, parts[1], kZetaRange, s.to); !why.empty()) return why;
    if (std::string why = check_zeta_span(name, s); !why.empty()) return why;
    out = s;
    return {};
}

std::string check_zeta_span(std::string_view name, const ZetaSpan& s) {
    const std::string allowed = "FROM:TO with FROM < TO in " + describe(kZetaRange);
    const std::string what = subject(name, shortest_decimal(s.from) + ":" + shortest_decimal(s.to));
    for (double v : {s.from, s.to})
        if (!inside(v, kZetaRange)) return what + " leaves the allowed range; allowed: " + allowed;
    if (s.from > s.to) return what + " is reversed (FROM > TO); allowed: " + allowed;
    if (s.from == s.to) return what + " is empty (FROM == TO); allowed: " + allowed;
    return {};
}

std::string list_text(const std::vector<double>& values) {
    std::string s;
    for (double v : values) s += (s.empty() ? "" : ", ") + shortest_decimal(v);
    return s;
}

} // namespace fv
