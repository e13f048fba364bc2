// The experiment the model stands for, as a picture for a class (the lower panel "setup"): a block pressed
// onto a rough floor and pulled at a steady speed v_b while it is shaken by ±x_v (seen from the side), the
// contact magnified (the surfaces touch at asperities; one of them, P on the body, T its tip on the floor, is
// the model's spring), and the same block seen from above with the shake at the angle theta to v_b (the
// paper's Fig. 2). Plain words; drawn as a panel without axes.
#pragma once

#include "fv/figure_data.hpp"

namespace fv {

// The picture with the shake at `theta` (radians, from v_b, as Params::theta).
PanelData setup_panel(double theta);

} // namespace fv
