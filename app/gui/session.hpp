// Session files: the app's state as JSON, to hand a class the exact setup. Saved and opened from the File
// menu, `gui --session FILE` and the script actions save-session / open-session; written through
// write_file_atomic, read through read_input_file (the project's output and input policy).
//
//   {
//     "version": 1,
//     "model": "dahl",                         dahl | rigid
//     "zeta": 0.15, "theta": 90,               the share link's keys (theta in degrees), same ranges
//     "rdisp": 2, "i": 1,
//     "start": "rest",                         rest | sliding: the history (which steady state)
//     "amplitude_um": 0.7, "frequency_khz": 60, the vibration behind the physical units
//     "speed": 0.25, "playing": true,          animation: vibration periods per second, running or paused
//     "panel": "curves",                       lower right: curves | map | loop | why (mechanism)
//     "lesson": 3,                             the guided lesson's step on screen (written only during a
//                                              lesson; 0 or missing: none; lessons.hpp)
//     "view": {"zoom": 1, "pan": [0, 0], "follow": true, "trail_periods": 1.5, "presentation": false},
//     "compare": {"model": "dahl", "zeta": 0.15, "theta": 0, "rdisp": 2, "i": 1, "start": "rest"},
//                                              compare mode's setup B (written only when on; null or left
//                                              out: off; a key left out: A's, theta at the other angle)
//     "pins": [{"label": "..", "zeta": [..], "r_x": [..], "link": "dahl:60:2:1"}],   pinned r_x(zeta)
//                                              curves (at most 6; null: a gap; link: optional, what the
//                                              curve was computed at, as a share link's pins= has it)
//     "data": null                             a measurements CSV (absolute when saved; a relative path
//   }                                          is taken from the session file's directory), or null
//
// Reading is strict: "version" is required and must be 1; every other key is optional (a missing one takes
// the app's default, so a hand-written session may name only what it changes); an unknown or repeated key,
// a value of the wrong type or outside the shared range table (fv/param_ranges.hpp and the app's ranges)
// and a data file that does not load are errors "FILE:LINE:COL: message" pointing at the offending key or
// value. Opening a session restarts the simulation from its state (tau = 0): the simulation's history is
// not part of it, so a session opened twice shows the same frames.
#pragma once

#include "ui_state.hpp"

#include "fv/measurements.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fv::app {

inline constexpr int kSessionVersion = 1;

// A session: the app's setup and the measured data file it shows.
struct Session : SessionState {
    std::string data_file; // empty: no data
};

// One line "FILE:LINE:COL: message".
struct SessionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The state of the app as a session (the data file's path made absolute).
Session session_of(const UiState& ui);

// The session as JSON text (2-space indent, keys in the order above, numbers that read back bit for bit).
std::string session_json(const Session& s);

// Parses and checks the text of the session file `file` (named in messages; a relative data path is taken
// from its directory). Throws SessionError.
Session parse_session(const std::string& text, const std::string& file);

// A session read from `path` with its data file loaded (with the session's A and f), ready to show.
struct LoadedSession {
    Session session;
    std::optional<MeasurementSet> data;
};
// Throws SessionError: unreadable file ("FILE: reason"), a parse or range error, or a data file that does not
// load ("FILE:LINE:COL: data: DATAFILE:LINE:COL: message").
LoadedSession load_session(const std::string& path);

// Writes `s` to `path` atomically; returns "" or a one-line reason.
std::string write_session(const std::string& path, const Session& s);

} // namespace fv::app
