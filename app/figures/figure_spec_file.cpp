#include "figures/figure_spec_file.hpp"

#include "fv/figure_family.hpp"
#include "fv/printable_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

namespace fv::app {
namespace {

using Json = nlohmann::ordered_json;

// The keys every spec takes besides the figure's parameters.
constexpr const char* kPictureKeys[] = {"size", "scale", "format"};

Json numbers(const std::vector<double>& v) {
    Json a = Json::array();
    for (double x : v) a.push_back(x);
    return a;
}

const char* type_name(const Json& j) {
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "true/false";
    if (j.is_number()) return "a number";
    if (j.is_array()) return "a list";
    if (j.is_object()) return "an object";
    return "null";
}

[[noreturn]] void fail(const std::string& key, const std::string& why) {
    throw SpecError(key + ": " + why);
}

[[noreturn]] void wrong_type(const std::string& key, const Json& j, const std::string& expected) {
    fail(key, "expected " + expected + ", got " + type_name(j));
}

double number(const std::string& key, const Json& j) {
    if (!j.is_number()) wrong_type(key, j, "a number");
    return j.get<double>();
}

std::string text(const std::string& key, const Json& j) {
    if (!j.is_string()) wrong_type(key, j, "a string");
    return j.get<std::string>();
}

// A number or a list of numbers (a figure that takes one value says so in input_error).
std::vector<double> number_list(const std::string& key, const Json& j) {
    if (j.is_number()) return {j.get<double>()};
    if (!j.is_array()) wrong_type(key, j, "a number or a list of numbers");
    std::vector<double> v;
    for (const Json& x : j) {
        if (!x.is_number()) wrong_type(key, x, "a list of numbers, each a number");
        v.push_back(x.get<double>());
    }
    return v;
}

// A string or a list of strings ("png,svg" as one string too).
std::vector<std::string> text_list(const std::string& key, const Json& j) {
    if (j.is_string()) return {j.get<std::string>()};
    if (!j.is_array()) wrong_type(key, j, "a string or a list of strings");
    std::vector<std::string> v;
    for (const Json& x : j) {
        if (!x.is_string()) wrong_type(key, x, "a list of strings, each a string");
        v.push_back(x.get<std::string>());
    }
    return v;
}

std::string joined(const std::vector<std::string>& v, const char* sep = ",") {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

// The value of parameter `p` at `key` into `in`.
void read_param(FigureParam p, const std::string& key, const Json& j, FigureInputs& in) {
    switch (p) {
    case FigureParam::zeta:
        in.zeta = number(key, j);
        return;
    case FigureParam::zeta_range: {
        if (j.is_string()) {
            ZetaSpan s;
            if (std::string why = read_zeta_span(key, j.get<std::string>(), s); !why.empty())
                throw SpecError(why);
            in.zeta_span = s;
            return;
        }
        const std::vector<double> v = j.is_array() ? number_list(key, j) : std::vector<double>{};
        if (v.size() != 2) wrong_type(key, j, "a range [FROM, TO]");
        in.zeta_span = ZetaSpan{v[0], v[1]};
        return;
    }
    case FigureParam::theta:
    case FigureParam::rdisp:
    case FigureParam::i: {
        // An empty list would read as "not given" (the default): refused here, where it is seen.
        const std::vector<double> v = number_list(key, j);
        if (v.empty()) throw SpecError(check_number_list(key, v, *param_range(p)));
        (p == FigureParam::theta ? in.theta_deg : p == FigureParam::rdisp ? in.rdisp : in.i) = v;
        return;
    }
    case FigureParam::model: {
        std::vector<Model> models;
        if (std::string why = read_model_list(key, joined(text_list(key, j)), models); !why.empty())
            throw SpecError(why);
        in.models = models;
        return;
    }
    case FigureParam::data:
        in.data = text(key, j);
        if (in.data.empty()) fail(key, "an empty path; allowed: a file name");
        return;
    case FigureParam::amplitude:
        in.amplitude_um = number(key, j);
        return;
    case FigureParam::frequency:
        in.frequency_khz = number(key, j);
        return;
    case FigureParam::start: {
        Start s = Start::rest;
        const std::string t = text(key, j);
        if (!parse_start(t, s)) fail(key, quoted_text(t) + " is not a start; allowed: rest, sliding");
        in.start = s;
        return;
    }
    }
}

std::string allowed_keys(const FigureEntry& e) {
    std::vector<std::string> keys{"id"};
    for (const FigureParamUse& u : e.params) keys.push_back(param_key(u.param));
    for (const char* k : kPictureKeys) keys.push_back(k);
    return joined(keys, ", ");
}

} // namespace

std::string parameters_json(const FigureEntry& e, const FigureInputs& in, int width, int height, double scale,
                            const PictureFormats& formats) {
    Json j;
    j["id"] = e.id;
    for (const FigureParamUse& u : e.params) {
        if (!given(in, u.param)) continue; // no default: not given (fig19's amplitude, frequency, theta)
        const char* key = param_key(u.param);
        switch (u.param) {
        case FigureParam::zeta:
            j[key] = *in.zeta;
            break;
        case FigureParam::zeta_range:
            j[key] = numbers({in.zeta_span->from, in.zeta_span->to});
            break;
        case FigureParam::theta:
        case FigureParam::rdisp:
        case FigureParam::i: {
            const std::vector<double>& v = u.param == FigureParam::theta   ? in.theta_deg
                                           : u.param == FigureParam::rdisp ? in.rdisp
                                                                           : in.i;
            // A list where the figure takes lists (even of one, unless one_as_number), else the number.
            if (u.list && !(u.one_as_number && v.size() == 1))
                j[key] = numbers(v);
            else
                j[key] = v.front();
            break;
        }
        case FigureParam::model: {
            Json a = Json::array();
            for (Model m : in.models) a.push_back(to_string(m));
            j[key] = a;
            break;
        }
        case FigureParam::data:
            j[key] = in.data;
            break;
        case FigureParam::amplitude:
            j[key] = *in.amplitude_um;
            break;
        case FigureParam::frequency:
            j[key] = *in.frequency_khz;
            break;
        case FigureParam::start:
            j[key] = to_string(*in.start);
            break;
        }
    }
    j["size"] = {width, height};
    j["scale"] = scale;
    j["format"] = formats.extensions();
    return j.dump();
}

FigureSpecFile parse_spec_file(const std::string& content) {
    Json doc;
    try {
        doc = Json::parse(content);
    } catch (const Json::exception& err) { // a syntax error, a number beyond double (1e400)
        throw SpecError("not JSON: " + printable_text(err.what(), 160));
    }
    if (!doc.is_object())
        throw SpecError("expected a JSON object (ID.json or its parameters), got " +
                        std::string(type_name(doc)));
    // A whole ID.json: its parameters.
    const Json& j = doc.contains("parameters") ? doc["parameters"] : doc;
    if (!j.is_object()) wrong_type("parameters", j, "an object");
    if (!j.contains("id")) throw SpecError("id is missing; allowed: " + figure_ids());
    const std::string id = text("id", j["id"]);
    FigureSpecFile spec;
    spec.entry = find_registered(id);
    if (!spec.entry) throw SpecError("id: unknown figure " + quoted_text(id) + "; allowed: " + figure_ids());
    const FigureEntry& e = *spec.entry;
    for (const auto& item : j.items()) {
        // Named copies, not a structured binding: C++17 lambdas (below) cannot capture those (clang says so).
        const std::string key = item.key();
        const Json& value = item.value();
        if (key == "id") continue;
        if (key == "size") {
            if (value.is_string()) {
                spec.size = value.get<std::string>();
                continue;
            }
            if (!value.is_array() || value.size() != 2 || !value[0].is_number_integer() ||
                !value[1].is_number_integer())
                wrong_type(key, value, "[WIDTH, HEIGHT] in whole pixels");
            spec.size =
                std::to_string(value[0].get<long long>()) + "x" + std::to_string(value[1].get<long long>());
            continue;
        }
        if (key == "scale") {
            spec.scale = number(key, value);
            continue;
        }
        if (key == "format") {
            spec.format = joined(text_list(key, value));
            continue;
        }
        const auto use = std::find_if(e.params.begin(), e.params.end(),
                                      [&](const FigureParamUse& u) { return key == param_key(u.param); });
        if (use == e.params.end())
            throw SpecError("unknown key " + quoted_text(key) + " for " + e.id +
                            "; allowed: " + allowed_keys(e));
        read_param(use->param, key, value, spec.inputs);
    }
    if (const std::optional<FigureParam> p = missing_param(e, spec.inputs))
        throw SpecError(std::string(param_key(*p)) + " is missing: " + e.id +
                        " needs it (keys: " + allowed_keys(e) + ")");
    if (std::string why =
            input_error(e, spec.inputs, [](FigureParam p) { return std::string(param_key(p)); });
        !why.empty())
        throw SpecError(why);
    return spec;
}

} // namespace fv::app
