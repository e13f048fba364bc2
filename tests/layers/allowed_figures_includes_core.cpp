// Must compile: the control case of the layer tests. figures links core and render and sees both.
#include "figures/figure_painter.hpp"
#include "fv/params.hpp"
