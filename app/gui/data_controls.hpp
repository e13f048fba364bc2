// The control panel's physical-units, measured-data and share-link sections, the File menu and its dialogs.
#pragma once

#include "session_link.hpp"
#include "ui_state.hpp"

#include <functional>
#include <string>

namespace fv::app {

// A path dialog's state between frames: the path being typed, and a request to show the dialog.
struct PathDialog {
    std::string path;
    bool open_requested = false;
};
// The File menu's dialogs: open a data file, open a session, save a session.
struct FileDialogs {
    PathDialog data, open_session, save_session;
    // The platform's own chooser for files to open, given the extension they take (the browser's file
    // input; the file arrives as a drop, routed by its extension): true when it opened instead of the path
    // dialog. May be empty.
    std::function<bool(const std::string& accept)> choose;
};

// Amplitude and frequency inputs; v_b and z_ss as inputs that set zeta and r_disp (Eqs. (6), (34)).
UiEdits draw_vibration_controls(const UiState& ui);

// The data file shown, its points, and buttons to open, fit and clear.
UiEdits draw_data_controls(const UiState& ui, FileDialogs& dialog);

// The share link of the state shown (session_link.hpp) in a read-only field, with a button that copies the
// whole address (the site's address and the link) to the clipboard (in the browser the system's, web
// platform); one line of text high (for the Parameters header's row).
UiEdits draw_share_link(const UiState& ui, const ShareAddress& where);

// The panel's menu bar: File (open data, clear data, open and save a session, export, screenshot, quit).
// Call right after Begin() of a window with ImGuiWindowFlags_MenuBar.
UiEdits draw_menu(const UiState& ui, FileDialogs& dialog);

// The modal dialogs (a path field and the CSV or JSON files next to it); call once per frame, at window
// level.
UiEdits draw_file_dialogs(FileDialogs& dialog);

} // namespace fv::app
