// The scene: the dashboard of any parameter set (top view, force over a period, r_x(zeta)), from the
// parameters that `ratio` takes. Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"

namespace fv {
namespace {

FigureEntry scene_entry() {
    FigureEntry e;
    e.id = "scene";
    e.title = "any parameter set: top view, force over a period, r_x(ζ)";
    e.kind = FigureKind::scene;
    e.params = {{FigureParam::zeta, true},
                {FigureParam::theta, true},
                {FigureParam::rdisp, true},
                {FigureParam::i, true},
                {FigureParam::start}};
    e.defaults.start = Start::rest;
    e.example.zeta = 0.3;
    e.example.theta_deg = {30};
    e.example.rdisp = {2};
    e.example.i = {1};
    e.make = [](const FigureInputs& in) {
        return scene_figure(
            {in.zeta.value_or(0), one(in.theta_deg, 0) * kPi / 180, one(in.rdisp, 1), one(in.i, 1)},
            in.start.value_or(Start::rest));
    };
    return e;
}

const RegisterFigure register_scene{scene_entry()};

} // namespace
} // namespace fv
