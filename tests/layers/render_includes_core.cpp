// Must not compile: the render layer draws shapes and text; it knows nothing of the model.
#include "fv/params.hpp"
