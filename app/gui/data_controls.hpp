// The control panel's physical-units and measured-data sections, the File menu and its open dialog.
#pragma once

#include "ui_state.hpp"

#include <string>

namespace fv::app {

// State of the "Open data file" dialog between frames (the path being typed).
struct OpenDataDialog {
    std::string path;
    bool open_requested = false;
};

// Amplitude and frequency inputs; v_b and z_ss as inputs that set zeta and r_disp (Eqs. (6), (34)).
UiEdits draw_vibration_controls(const UiState& ui);

// The data file shown, its points, and buttons to open, fit and clear.
UiEdits draw_data_controls(const UiState& ui, OpenDataDialog& dialog);

// The panel's menu bar: File (open data, clear data, export, screenshot, quit). Call right after Begin()
// of a window with ImGuiWindowFlags_MenuBar.
UiEdits draw_menu(const UiState& ui, OpenDataDialog& dialog);

// The modal open dialog (a path field and the CSV files next to it); call once per frame, at window level.
UiEdits draw_open_dialog(OpenDataDialog& dialog);

} // namespace fv::app
