// r_y(zeta), the mean friction across v_b that the model computes and the paper defines (Eq. 31) but never
// shows: by default for theta = 30, 45, 60 deg, the Dahl model (r_disp 2, i 1) and the rigid one; any lists
// of theta, r_disp, i and models make a family (figure_family.hpp), as rx does for r_x. Registers itself
// (figure_registry.hpp).
#include "fv/figure_family.hpp"
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"

namespace fv {
namespace {

// "30°, 45°, 60°"
std::string angles_text(const std::vector<double>& theta_deg) {
    std::string s;
    for (double t : theta_deg) s += (s.empty() ? "" : ", ") + format_number("%g", t) + "°";
    return s;
}

// The figure as it was before families: both models, one r_disp and i, the paper's zeta range, from rest.
FigureSpec ry_figure(const std::vector<double>& theta_deg, double rdisp, double i) {
    FigureSpec f;
    f.id = "ry";
    const std::string r = format_number("%g", rdisp), is = format_number("%g", i),
                      th = angles_text(theta_deg);
    f.title = "side force r_{y}(ζ), Dahl (r_{disp} = " + r + ", i = " + is + ") and rigid, θ = " + th;
    f.caption =
        "Beyond the paper: the mean friction across v_b, r_y = mean F_y/F_c (Eq. 31 over F_c; the sign "
        "convention of r_x, the friction on the body being −(r_x, r_y) F_c), of the Dahl model (r_disp = " +
        r + ", i = " + is + ", solid) and the rigid model (Eq. 4, dashed) at θ = " + th +
        ". r_y < 0 for 0° < θ < 90°: the "
        "mean friction pushes the body towards +y, up to about a quarter of F_c; it vanishes at θ = 0° and "
        "90° and changes sign under θ → 180° − θ (docs/model.md); for large ζ the rigid r_y tends to "
        "−sin 2θ/(4ζ²).";
    RatioCurvesFigure c;
    c.side_force = true;
    c.zetas = ratio_zeta_start();
    c.zeta_budget = kRatioZetaBudget;
    for (double t : theta_deg) c.curves.push_back({Model::dahl, t * kPi / 180, rdisp, i});
    for (double t : theta_deg) c.curves.push_back({Model::rigid, t * kPi / 180, 0, 0});
    f.content = std::move(c);
    return f;
}

FigureEntry ry_entry() {
    FigureEntry e;
    e.id = "ry";
    e.title = "side force r_y(ζ) for θ = 30°, 45°, 60°, Dahl and rigid (or any family), beyond the paper";
    e.kind = FigureKind::ratio_curves;
    e.params = {{FigureParam::theta, false, true}, {FigureParam::rdisp, false, true},
                {FigureParam::i, false, true},     {FigureParam::model, false, true},
                {FigureParam::zeta_range},         {FigureParam::start}};
    e.defaults.theta_deg = {30, 45, 60};
    e.defaults.rdisp = {2};
    e.defaults.i = {1};
    e.defaults.models = {Model::dahl, Model::rigid};
    e.defaults.zeta_span = kPaperZetaSpan;
    e.defaults.start = Start::rest;
    e.check = family_check;
    e.make = [](const FigureInputs& in) {
        const FigureFamily f = family_of(in, true);
        if (f.rdisp.size() == 1 && f.i.size() == 1 &&
            f.models == std::vector<Model>{Model::dahl, Model::rigid} && f.zeta == kPaperZetaSpan &&
            f.start == Start::rest)
            return ry_figure(f.theta_deg, f.rdisp.front(), f.i.front());
        return family_figure("ry", f);
    };
    return e;
}

const RegisterFigure register_ry{ry_entry()};

} // namespace
} // namespace fv
