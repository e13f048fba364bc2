#include "figure_flags.hpp"

#include <algorithm>

namespace fv::cli {
namespace {

struct ParamFlags {
    const char* name;
    const char* alt; // "": none
};

ParamFlags flags_of(FigureParam p) {
    switch (p) {
    case FigureParam::zeta:
        return {"--zeta", "--vb"};
    case FigureParam::zeta_range:
        return {"--zeta", ""};
    case FigureParam::model:
        return {"--model", ""};
    case FigureParam::theta:
        return {"--theta", ""};
    case FigureParam::rdisp:
        return {"--rdisp", "--zss"};
    case FigureParam::i:
        return {"--i", ""};
    case FigureParam::data:
        return {"--data", ""};
    case FigureParam::amplitude:
        return {"--amplitude", ""};
    case FigureParam::frequency:
        return {"--frequency", ""};
    case FigureParam::start:
        return {"--start", ""};
    }
    return {"", ""};
}

// The vibration flags the unit alternative of `p` converts with: v_b = zeta 2 pi f A, z_ss = A / r_disp.
std::vector<FigureParam> unit_params(FigureParam p) {
    if (p == FigureParam::zeta) return {FigureParam::amplitude, FigureParam::frequency};
    if (p == FigureParam::rdisp) return {FigureParam::amplitude};
    return {};
}

std::string quoted(const std::string& flag, const FlagQuote& quote) {
    return quote ? quote(flag) : flag;
}

std::string joined(const std::vector<std::string>& parts) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : ", ") + p;
    return s;
}

// "needs A, B; optional C" or "takes C" of the texts of required and optional parameters.
std::string needs_text(const std::vector<std::string>& need, const std::vector<std::string>& take,
                       const char* take_word) {
    if (need.empty()) return take_word + joined(take);
    return "needs " + joined(need) + (take.empty() ? "" : "; optional " + joined(take));
}

} // namespace

std::string param_flag_text(FigureParam p, const FlagQuote& quote) {
    const ParamFlags f = flags_of(p);
    const std::string name = quoted(f.name, quote);
    return *f.alt ? name + " or " + quoted(f.alt, quote) : name;
}

std::vector<FigureParamUse> command_line_params(const FigureEntry& e) {
    std::vector<FigureParamUse> out;
    auto has = [&](FigureParam p) {
        return std::any_of(out.begin(), out.end(), [p](const FigureParamUse& u) { return u.param == p; });
    };
    for (const FigureParamUse& u : e.params)
        if (u.param != FigureParam::start) out.push_back(u);
    for (const FigureParamUse& u : e.params)
        for (FigureParam v : unit_params(u.param))
            if (!has(v)) out.push_back({v, false});
    for (const FigureParamUse& u : e.params)
        if (u.param == FigureParam::start) out.push_back(u);
    return out;
}

std::string flags_text(const FigureEntry& e, const FlagQuote& quote) {
    std::vector<std::string> need, take;
    for (const FigureParamUse& u : command_line_params(e))
        (u.required ? need : take).push_back(param_flag_text(u.param, quote));
    return needs_text(need, take, "takes ");
}

std::string flags_summary(const FigureEntry& e) {
    if (e.params.empty()) return {};
    std::vector<std::string> need, take;
    for (const FigureParamUse& u : e.params) (u.required ? need : take).push_back(flags_of(u.param).name);
    return " (" + needs_text(need, take, "") + ")";
}

std::string figures_taking(FigureParam p) {
    std::string s;
    for (const FigureEntry& e : figure_registry())
        for (const FigureParamUse& u : command_line_params(e))
            if (u.param == p) s += (s.empty() ? "" : ", ") + e.id;
    return s;
}

} // namespace fv::cli
