#include "fv/params.hpp"

#include <cmath>
#include <sstream>

namespace fv {

const char* to_string(Model m) {
    return m == Model::rigid ? "rigid" : "dahl";
}

std::optional<Model> parse_model(const std::string& s) {
    if (s == "rigid") return Model::rigid;
    if (s == "dahl") return Model::dahl;
    return std::nullopt;
}

std::string validate(const Params& p) {
    auto bad = [](const char* name, double v, const char* allowed) {
        std::ostringstream os;
        os << name << " = " << v << " is not allowed: " << allowed;
        return os.str();
    };
    if (!std::isfinite(p.zeta) || p.zeta < 0) return bad("zeta", p.zeta, "need a finite number >= 0");
    if (!std::isfinite(p.theta)) return bad("theta", p.theta, "need a finite angle");
    if (!std::isfinite(p.rdisp) || p.rdisp <= 0) return bad("rdisp", p.rdisp, "need a finite number > 0");
    if (!std::isfinite(p.i) || p.i < 0) return bad("i", p.i, "need a finite number >= 0");
    return {};
}

} // namespace fv
