#include "fv/params.hpp"
#include "fv/setup.hpp"

#include "fv/format.hpp"
#include "fv/param_ranges.hpp"

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

std::string describe(ParamRange r) {
    std::ostringstream os;
    os << (r.lo_open ? "(" : "[") << r.lo << ", " << r.hi << "]";
    return os.str();
}

bool inside(double v, ParamRange r) {
    return (r.lo_open ? v > r.lo : v >= r.lo) && v <= r.hi;
}

std::string range_error(const Params& p) {
    if (std::string why = validate(p); !why.empty()) return why;
    auto outside = [](const char* name, double v, ParamRange r) {
        return std::string(name) + " = " + format_number("%.4g", v) + "; allowed: " + name + " in " +
               describe(r);
    };
    if (!inside(p.zeta, kZetaRange)) return outside("zeta", p.zeta, kZetaRange);
    // Radians to degrees and back are not exact: 180 degrees may come back as 180 + 3e-14.
    const double theta_deg = p.theta * 180 / kPi;
    if (!(theta_deg >= kThetaRange.lo - 1e-9 && theta_deg <= kThetaRange.hi + 1e-9))
        return outside("theta", theta_deg, kThetaRange) + " degrees";
    if (!inside(p.rdisp, kRdispRange)) return outside("r_disp", p.rdisp, kRdispRange);
    if (!inside(p.i, kIRange)) return outside("i", p.i, kIRange);
    return {};
}

} // namespace fv

namespace fv {

Setup compare_default(const Setup& a) {
    Setup b = a;
    // 90 degrees as any door writes it (90 * pi / 180 from a link or a flag, pi / 2 here) is "across"
    // already.
    b.params.theta = std::abs(a.params.theta - kPi / 2) < 1e-9 ? 0 : kPi / 2;
    return b;
}

} // namespace fv
