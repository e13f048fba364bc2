// Must not compile: the animation export links figures and core, not the app (gui).
#include "gui/ratio_worker.hpp"
