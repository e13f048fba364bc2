// The dashboard's lower-right panel (curves, map, loop, why, setup): defined in core (fv/lower_panel.hpp),
// where the share link's parser checks its names; the app's code names it fv::app::LowerPanel as before.
#pragma once

#include "fv/lower_panel.hpp"

namespace fv::app {

using fv::kLowerPanels;
using fv::LowerPanel;
using fv::panel_from_name;
using fv::panel_name;

} // namespace fv::app
