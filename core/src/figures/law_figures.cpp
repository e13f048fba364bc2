// The paper's figures of the two friction laws on their own: the mechanism of friction reduction in the
// rigid model (Fig. 4: at any zeta and theta, default 0.5 and 90 deg) and the friction-displacement curves of
// the Dahl law for several i (Fig. 6). Each registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"
#include "fv/rigid.hpp"

namespace fv {
namespace {

constexpr double kDeg = kPi / 180;

FigureSpec fig4(double zeta, double theta_deg) {
    FigureSpec f;
    f.id = "fig4";
    f.content = MechanismFigure{zeta, theta_deg * kDeg};
    const std::string z = format_number("%g", zeta), th = format_number("%g", theta_deg);
    const Ratio r = rigid_ratio(zeta, theta_deg * kDeg);
    f.title = "Fig. 4: mechanism of friction reduction, rigid model, ζ = " + z + ", θ = " + th + "°";
    f.caption =
        "Rigid model (Eqs. 1–4) at ζ = " + z + ", θ = " + th +
        "°: the body's velocity v = v_b + v_v cos τ (cos θ, sin θ) turns (and may reverse) with the "
        "vibration, "
        "the Coulomb friction on the body, F = −F_c v/|v| (Eq. 2), turns with it at constant magnitude F_c, "
        "so its component against v_b, −F_x (Eq. 3), averages to r_x F_c = " +
        format_number("%.4f", r.rx) +
        " F_c < F_c (Eq. 9); the mean friction is −(r_x, r_y) F_c with r_y = " + format_number("%.4f", r.ry) +
        ". " +
        (mechanism_parallel(theta_deg * kDeg)
             ? std::string(
                   "Left (θ within 10° of the sliding line, where every arrow would lie on one line): "
                   "the components along v_b of v/v_v (blue, above each row) and F/F_c (vermillion, "
                   "below it) at τ = kπ/4, k = 0…8, one row per instant up a time axis, with their "
                   "loci over the period, the instants where v_x = 0 (dotted) and the mean friction "
                   "(black)")
             : std::string("Left: v/v_v (blue) and F/F_c (vermillion) at τ = kπ/4, k = 0…4 (τ and 2π − τ "
                           "have the same velocity), the loci over the whole period and the mean friction "
                           "(black)")) +
        "; right: −F_x/F_c over the period with its mean r_x, the dots at τ = kπ/4.";
    return f;
}

FigureEntry fig4_entry() {
    FigureEntry e;
    e.id = "fig4";
    e.title = "mechanism: velocity and Coulomb friction turning over a period, rigid model";
    e.kind = FigureKind::mechanism;
    e.params = {{FigureParam::zeta}, {FigureParam::theta}};
    e.defaults.zeta = 0.5;
    e.defaults.theta_deg = {90};
    e.make = [](const FigureInputs& in) { return fig4(in.zeta.value_or(0.5), one(in.theta_deg, 90)); };
    return e;
}

const RegisterFigure register_fig4{fig4_entry()};

FigureEntry fig6_entry() {
    FigureEntry e;
    e.id = "fig6";
    e.title = "friction–displacement curves of the Dahl law, Eq. (12), i = 0, 0.5, 1, 2";
    e.kind = FigureKind::dahl_curves;
    e.make = [](const FigureInputs&) {
        FigureSpec f;
        f.id = "fig6";
        f.content = DahlCurvesFigure{{0, 0.5, 1, 2}};
        f.title = "Fig. 6: friction–displacement curves of the Dahl law, Eq. (12), i = 0, 0.5, 1, 2";
        f.caption =
            "The Dahl law, Eq. (12), dF/dx = σ₀ (1 − sgn(v) F/F_c)^i, for i = 0, 0.5, 1, 2 (F/F_c against "
            "x/z_ss, z_ss = F_c/σ₀, Eq. 15): every curve starts with the slope σ₀ and tends to F_c; i = 0 is "
            "the elastic–perfectly plastic law of Eq. (25) (sticks, then slips at F_c from x = z_ss on), "
            "0 < i < 1 reaches F_c at a finite displacement (x = z_ss/(1 − i)), i ≥ 1 only approaches it "
            "(i = 1: 1 − e^(−x/z_ss); i = 2: x/(x + z_ss)). (a) loading from rest with v > 0, the paper's "
            "Fig. 6; (b) loading to 3 z_ss, unloading and reversal to −3 z_ss, reloading to 3 z_ss (the "
            "hysteresis loop): a reversal at F = ±F_c starts with the slope 2^i σ₀ (Eq. 12 with sgn(v) "
            "reversed), steeper than the first loading for i > 0.";
        return f;
    };
    return e;
}

const RegisterFigure register_fig6{fig6_entry()};

} // namespace
} // namespace fv
