// Scripted input for tests and demos: "FRAME ACTION [VALUE]" per line, '#' starts a comment. Edits of frame f
// are applied at the start of frame f, like edits from the panel. The actions are one table (script.cpp's
// kActions: name, argument, range, help, effect) that drives the parser, its messages and the edits; numbers
// are read by the shared reader (fv/read_number.hpp) inside the shared ranges, so a script refuses at load
// what the command line refuses (1e-400, 0x10, zeta 200), with the same message. Paths are relative to the
// script's directory; files a script writes (save-session, animate) are checked before the run, like
// --screenshot. script_actions() lists them for gui --help.
#pragma once

#include "ui_state.hpp"

#include <map>
#include <string>
#include <vector>

namespace fv::app {

struct ScriptAction;

// One line of a script, checked: its action and its value (a number read, or the text of a path or word).
struct ScriptEntry {
    const ScriptAction* action = nullptr;
    std::string text; // the value as written (a path made absolute)
    double number = 0;
};

struct Script {
    std::map<int, std::vector<ScriptEntry>> lines; // frame -> entries, in file order
};

// The largest frame number a script may name.
inline constexpr long long kMaxScriptFrame = 100000000;

// Throws std::runtime_error "FILE:LINE: reason" on a malformed line.
Script load_script(const std::string& path);

// The edits of `frame`, given the state they modify.
UiEdits script_edits(const Script& s, int frame, const UiState& ui);

// Every action with its argument: "zeta NUMBER, theta NUMBER, …, animate PATH" (gui --help).
std::string script_actions();

// The benchmark's edit (gui --bench): zeta dragged back and forth every frame, the worst case for the UI
// thread (the simulation restarts, the r_x curves are asked for again).
Params bench_params(Params p, int frame);

} // namespace fv::app
