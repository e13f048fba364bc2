// The control panel (Dear ImGui): sliders for zeta, theta, r_disp, i, the model, playback, presets, readouts.
#pragma once

#include "data_controls.hpp"
#include "ratio_worker.hpp"
#include "ui_state.hpp"

#include "fv/live_sim.hpp"
#include "fv/param_ranges.hpp"

namespace fv::app {

// What the panel's sliders span: parts of the shared range table (fv/param_ranges.hpp), which the CLI's
// validators and AppState::sync check against too.
struct SliderRanges {
    ParamRange zeta, theta_deg, rdisp, i;
};
inline constexpr SliderRanges kSliders{kZetaSlider, kThetaSlider, kRdispSlider, kISlider};

// Where the panel goes (screen_layout.hpp) and, after the frame, how far its rows scroll (0: all in view).
struct ControlsPlace {
    gfx::Rect rect;
    float scroll_max = 0; // out
};

// Draws the panel at `place` (logical pixels) and returns what the user changed. share: the address the
// share link is appended to.
UiEdits draw_controls(const UiState& ui, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                      bool busy, ControlsPlace& place, FileDialogs& dialog, const ShareAddress& share);

// Space, Right, R, S, Esc (ignored while a text field has the keyboard or a dialog is open).
UiEdits keyboard_edits(const UiState& ui);

// The paper's top-view figures as presets: fig9, fig14a, fig14b, fig17.
std::vector<const FigureSpec*> presets();

} // namespace fv::app
