// The (zeta, theta) map of r_x with the best vibration angle (beyond the paper), for any r_disp and i
// (default 2 and 1) and start. Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"

namespace fv {
namespace {

FigureEntry map_entry() {
    FigureEntry e;
    e.id = "map";
    e.title = "r_x over (ζ, θ) with the best vibration angle θ*(ζ), beyond the paper";
    e.kind = FigureKind::map;
    e.params = {{FigureParam::rdisp}, {FigureParam::i}, {FigureParam::start}};
    // One map a figure: lists are refused (docs/figures.md says why and how to draw several).
    e.defaults.rdisp = {2};
    e.defaults.i = {1};
    e.defaults.start = Start::rest;
    e.make = [](const FigureInputs& in) {
        return map_figure(one(in.rdisp, 2), one(in.i, 1), in.start.value_or(Start::rest));
    };
    e.summary =
        "Beyond the paper: r_x over (ζ, θ) for r_disp = 2, i = 1 (a 200 × 91 grid), with the best angle "
        "θ*(ζ) (solid: Dahl, dashed: rigid); marks where the motion has a longer period, where two stable "
        "states coexist (the start, from rest or sliding, decides which one is reached) and where none could "
        "be vouched for. "
        "The paper's conclusion compares only 0° "
        "and 90°; the compliant contact switches from parallel to perpendicular vibration at a lower ζ "
        "(≈ 0.76) than the rigid one (≈ 0.95–1.15), through oblique angles.";
    return e;
}

const RegisterFigure register_map{map_entry()};

} // namespace
} // namespace fv
