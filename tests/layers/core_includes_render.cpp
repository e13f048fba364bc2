// Must not compile: the model (core) knows nothing of drawing.
#include "fv/gfx/canvas.hpp"
