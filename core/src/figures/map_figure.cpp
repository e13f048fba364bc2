// The (zeta, theta) map of r_x with the best vibration angle (beyond the paper), for any r_disp and i
// (default 2 and 1) and start; lists of r_disp, i and models draw a family of maps as small multiples
// (map_family.hpp). Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"
#include "fv/map_family.hpp"

namespace fv {
namespace {

FigureEntry map_entry() {
    FigureEntry e;
    e.id = "map";
    e.title = "r_x over (ζ, θ) with the best vibration angle θ*(ζ), beyond the paper";
    e.kind = FigureKind::map;
    // Lists: one map per combination (at most kMaxFamilyMaps). One value is written to ID.json as a number,
    // as before the map took lists; no model given is the Dahl model alone (no "model" key), so the one map
    // of before gives the same files.
    e.params = {{FigureParam::rdisp, false, true, true},
                {FigureParam::i, false, true, true},
                {FigureParam::model, false, true},
                {FigureParam::start}};
    e.defaults.rdisp = {2};
    e.defaults.i = {1};
    e.defaults.start = Start::rest;
    e.check = map_family_check;
    e.make = [](const FigureInputs& in) { return map_family_figure(map_family_of(in)); };
    e.summary =
        "Beyond the paper: r_x over (ζ, θ) for r_disp = 2, i = 1 (a 200 × 91 grid), with the best angle "
        "θ*(ζ) (solid: Dahl, dashed: rigid); marks where the motion has a longer period, where two stable "
        "states coexist (the start, from rest or sliding, decides which one is reached) and where none could "
        "be vouched for. "
        "The paper's conclusion compares only 0° "
        "and 90°; the compliant contact switches from parallel to perpendicular vibration at a lower ζ "
        "(≈ 0.76) than the rigid one (≈ 0.95–1.15), through oblique angles. Lists of r_disp, i and model "
        "draw "
        "one map per combination (at most 6) as small multiples on one colour scale.";
    return e;
}

const RegisterFigure register_map{map_entry()};

} // namespace
} // namespace fv
