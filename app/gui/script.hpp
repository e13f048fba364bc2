// Scripted input for tests and demos: "FRAME ACTION [VALUE]" per line, '#' starts a comment.
// Actions: zeta V, theta DEG, rdisp V, i V, model dahl|rigid, play, pause, step, reset, speed V, trail V,
// preset ID, map (show the (zeta, theta) map), curves (show the r_x(zeta) curves), amplitude UM,
// frequency KHZ, vb M_PER_S, zss UM (physical units, as the panel's inputs), load PATH (a data file, as
// from the menu or a drop; no spaces in PATH; relative to the script's directory), clear (the data), fit
// (r_disp and i to the data; waits for it), back (one frame back in time), rewind PERIODS (show the state
// that long ago; pauses), steady (jump onto the periodic steady state), help (show or hide the help overlay),
// loop (the hysteresis loop), why (the mechanism, Fig. 4), pin (the current r_x(zeta) curve; waits for it),
// unpin (all), save-session PATH (the state after this frame's edits, as the File menu saves it; refused
// before the run when PATH cannot be written), open-session PATH (as the File menu opens it: a bad file
// leaves the state and says why in the status line); paths relative to the script's directory. Edits of
// frame f are applied at the start of frame f, like edits from the panel.
#pragma once

#include "ui_state.hpp"

#include <map>
#include <string>

namespace fv::app {

struct Script {
    std::map<int, std::vector<std::string>> lines; // frame -> "ACTION VALUE" entries, in file order
};

// Throws std::runtime_error "FILE:LINE: reason" on a malformed line.
Script load_script(const std::string& path);

// The edits of `frame`, given the state they modify.
UiEdits script_edits(const Script& s, int frame, const UiState& ui);

// The benchmark's edit (gui --bench): zeta dragged back and forth every frame, the worst case for the UI
// thread (the simulation restarts, the r_x curves are asked for again).
Params bench_params(Params p, int frame);

} // namespace fv::app
