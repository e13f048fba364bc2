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
    e.example = {0.3, 30, 2, 1};
    e.make = [](const FigureInputs& in) {
        return scene_figure({in.zeta.value_or(0), in.theta_deg.value_or(0) * kPi / 180, in.rdisp.value_or(1),
                             in.i.value_or(1)},
                            in.start.value_or(Start::rest));
    };
    return e;
}

const RegisterFigure register_scene{scene_entry()};

} // namespace
} // namespace fv
