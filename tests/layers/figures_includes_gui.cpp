// Must not compile: the figures layer does not link the app (gui), so it cannot see its headers.
#include "gui/app_state.hpp"
