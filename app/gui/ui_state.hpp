// What the controls edit and when the edits take effect: the UI writes into UiEdits during a frame, the
// loop applies them all at one point at the start of the next frame (MuJoCo `simulate` style).
#pragma once

#include "dashboard.hpp"

#include "fv/params.hpp"

#include <optional>
#include <string>

namespace fv::app {

struct UiState {
    Model model = Model::dahl;
    Params params{0.15, kPi / 2, 2, 1};
    bool playing = true;
    bool show_map = false; // lower-right panel: r_x(zeta) curves, or the (zeta, theta) map
    double speed = 0.25;   // vibration periods per second of wall time
    ViewState view;
    std::string status; // last message (file written, ...)
};

struct UiEdits {
    std::optional<Model> model;
    std::optional<Params> params;
    std::optional<bool> playing, show_map;
    std::optional<double> speed, trail_periods;
    bool step = false, reset = false, screenshot = false, export_csv = false, quit = false;
    std::optional<std::string> preset;

    // Later edits of the same field win; actions accumulate.
    void merge(const UiEdits& o);
};

} // namespace fv::app
