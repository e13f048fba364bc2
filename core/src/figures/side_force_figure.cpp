// r_y(zeta), the mean friction across v_b that the model computes and the paper defines (Eq. 31) but never
// shows: for theta = 30, 45, 60 deg, the Dahl model (any r_disp and i, default 2 and 1) and the rigid one.
// Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"

namespace fv {
namespace {

FigureSpec ry_figure(double rdisp, double i) {
    FigureSpec f;
    f.id = "ry";
    const std::string r = format_number("%g", rdisp), is = format_number("%g", i);
    f.title = "side force r_{y}(ζ), Dahl (r_{disp} = " + r + ", i = " + is + ") and rigid, θ = 30°, 45°, 60°";
    f.caption =
        "Beyond the paper: the mean friction across v_b, r_y = mean F_y/F_c (Eq. 31 over F_c; the sign "
        "convention of r_x, the friction on the body being −(r_x, r_y) F_c), of the Dahl model (r_disp = " +
        r + ", i = " + is +
        ", solid) and the rigid model (Eq. 4, dashed) at θ = 30°, 45°, 60°. r_y < 0 for 0° < θ < 90°: the "
        "mean friction pushes the body towards +y, up to about a quarter of F_c; it vanishes at θ = 0° and "
        "90° and changes sign under θ → 180° − θ (docs/model.md); for large ζ the rigid r_y tends to "
        "−sin 2θ/(4ζ²).";
    RatioCurvesFigure c;
    c.side_force = true;
    c.zetas = ratio_zeta_start();
    c.zeta_budget = kRatioZetaBudget;
    for (double th : {30.0, 45.0, 60.0}) c.curves.push_back({Model::dahl, th * kPi / 180, rdisp, i});
    for (double th : {30.0, 45.0, 60.0}) c.curves.push_back({Model::rigid, th * kPi / 180, 0, 0});
    f.content = std::move(c);
    return f;
}

FigureEntry ry_entry() {
    FigureEntry e;
    e.id = "ry";
    e.title = "side force r_y(ζ) for θ = 30°, 45°, 60°, Dahl and rigid, beyond the paper";
    e.kind = FigureKind::ratio_curves;
    e.params = {{FigureParam::rdisp}, {FigureParam::i}};
    e.make = [](const FigureInputs& in) { return ry_figure(in.rdisp.value_or(2), in.i.value_or(1)); };
    return e;
}

const RegisterFigure register_ry{ry_entry()};

} // namespace
} // namespace fv
