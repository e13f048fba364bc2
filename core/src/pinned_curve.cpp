#include "fv/pinned_curve.hpp"

#include "fv/format.hpp"
#include "fv/ratio_curves.hpp"

namespace fv {

PinSource pin_source(Model model, const Params& p, Start start) {
    return PinSource{model, p.theta, p.rdisp, p.i, start};
}

std::string pin_label(const PinSource& s) {
    const bool rigid = s.model == Model::rigid;
    return std::string(rigid ? "rigid" : "Dahl") + ", θ = " + format_number("%.3g", s.theta * 180 / kPi) +
           "°" +
           (rigid ? ""
                  : ", r_{disp} = " + format_number("%.3g", s.rdisp) + ", i = " + format_number("%g", s.i)) +
           (rigid || s.start == Start::rest ? "" : ", from sliding");
}

PinnedCurve pin_of(const PinSource& s, const RatioCurves& curves) {
    PinnedCurve pin;
    pin.label = pin_label(s);
    pin.zeta = curves.zetas;
    pin.rx = s.model == Model::rigid ? curves.rigid_rx : curves.model_rx;
    pin.source = s;
    return pin;
}

PinnedCurve compute_pin(const PinSource& s, double zeta_max) {
    RatioRequest req;
    req.model = s.model;
    req.params = Params{0.5, s.theta, s.rdisp, s.i}; // zeta only places the current point, not the curve
    req.zeta_max = zeta_max;
    req.start = s.start;
    return pin_of(s, compute_ratio_curves(req));
}

} // namespace fv
