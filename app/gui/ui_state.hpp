// What the controls edit and when the edits take effect: the UI writes into UiEdits during a frame, the
// loop applies them all at one point at the start of the next frame (MuJoCo `simulate` style).
#pragma once

#include "animation_export.hpp"
#include "dashboard.hpp"
#include "lower_panel.hpp"

#include "fv/measurements.hpp"
#include "fv/params.hpp"
#include "fv/setup.hpp"
#include "fv/steady_state.hpp" // Start

#include <optional>
#include <string>
#include <vector>

namespace fv::app {

// What a session file holds (session.hpp) apart from its data file: the setup a teacher hands a class. The
// app keeps it as one value (UiState::session): saving writes it, opening a session replaces it.
// Its Setup (fv/setup.hpp: model, params, start) is setup A, the one the app always shows. start, the history
// (docs/model.md, "Which steady state"): where the animation starts (reset, a new start) and which of
// coexisting steady states the readouts and the r_x(zeta) curve report.
struct SessionState : Setup {
    // The physical view of zeta and r_disp: v_b = zeta 2 pi f A, z_ss = A / r_disp (units.hpp). Default:
    // the experiment of the paper's Fig. 19 (Littmann et al., Sec. 4: 0.7 um at 60 kHz).
    double amplitude_um = 0.7, frequency_khz = 60;
    double speed = 0.25; // vibration periods per second of wall time
    bool playing = true;
    LowerPanel panel = LowerPanel::curves;
    bool presentation = false; // larger type, thicker lines, the advanced panels folded away (View menu, P)
    ViewState view;            // its rewind is not saved: an opened session restarts the simulation
    std::vector<PinnedCurve> pins;
    // Compare mode: setup B beside A, on A's time base, speed, view and vibration (A and f).
    bool compare = false;
    Setup b = compare_default(Setup{});
    const Setup& a() const { return *this; }
    int lesson = 0; // the lesson step shown above the controls (1-based, lessons.hpp); 0: none
};

struct UiState {
    SessionState session;
    bool show_help = false; // the overlay that explains every symbol (F1, ?)
    bool editing_b = false; // compare mode: the panel's parameter controls edit setup B (else A)
    std::string status;     // last message (file written, ...)

    // The physical view of session.params under A and f, converted once per frame (AppState::sync): v_v = 2
    // pi f A and v_b in m/s, z_ss in um. What the panel shows; its inputs send UiEdits::vb_m_s and zss_um.
    double vv_m_s = 0, vb_m_s = 0, zss_um = 0;

    // Measured r_x(zeta) shown on the ratio plot (menu, drag-and-drop, --data, script `load`). A file that
    // gives v_b keeps it per point (Measurement::vb): A or f changes convert again, never re-read the file.
    std::optional<MeasurementSet> data;
    bool data_is_example = false; // `data` are a lesson step's example points, from no file (none to save)
    bool fitting = false;         // a fit of r_disp and i to the data is running
};

// Edits of one setup's model, start and parameters.
struct SetupEdits {
    std::optional<Model> model;
    std::optional<Start> start; // another start restarts the animation from it
    std::optional<Params> params;
    bool any() const { return model || start || params; }
    void merge(const SetupEdits& o) {
        if (o.model) model = o.model;
        if (o.start) start = o.start;
        if (o.params) params = o.params;
    }
};

struct UiEdits {
    std::optional<Model> model;
    std::optional<Start> start; // another start restarts the animation from it
    std::optional<Params> params;
    std::optional<LowerPanel> panel;
    std::optional<bool> playing, show_help, presentation;
    std::optional<double> speed, trail_periods;
    // A or f: v_b and z_ss stay, zeta and r_disp follow (as when an experimenter turns up the amplitude).
    std::optional<double> amplitude_um, frequency_khz;
    // v_b (m/s) or z_ss (um) typed in the panel: set zeta or r_disp, converted with the A and f in effect
    // before this frame's A or f edits (as the panel shows them).
    std::optional<double> vb_m_s, zss_um;
    std::optional<std::string> load_data; // a CSV path to read (replaces the data shown)
    // A session file to open (replaces the whole state, applied before the frame's other edits) or to save
    // (the state after this frame's edits).
    std::optional<std::string> open_session, save_session;
    bool clear_data = false, fit_data = false;
    // A lesson step's example points (shown unless the user opened data); or, for a step without them, take
    // away example points an earlier step showed (data the user opened stay).
    std::optional<MeasurementSet> example_data;
    bool drop_example_data = false;
    bool step = false, reset = false, screenshot = false, export_csv = false, quit = false;
    // Time: scrub to this far behind the live simulation (pauses), one frame back, onto the steady state.
    std::optional<double> rewind;
    bool step_back = false, jump_steady = false;
    // File > Export animation…: open its dialog; the dialog's request (AppState::sync adds the parameters).
    bool open_export_dialog = false;
    std::optional<AnimationRequest> export_animation;
    bool pin = false, clear_pins = false; // pin the current r_x(zeta) curve; remove all pins
    // The mouse over the top view: zoom, pan (data units, added to the followed centre); reset_view: zoom 1,
    // no pan, following P, live (double-click). Clamped to kZoomRange and kPanRange.
    std::optional<double> zoom;
    std::optional<Vec2> pan;
    bool reset_view = false;
    std::optional<FrameChoice> frame; // the top view's frame: body or ground (zoom and pan stay)
    // The top view's data area width / height in pixels as last drawn (the loop measures it): the frame is
    // fitted to it (top_view_frame.hpp).
    std::optional<double> view_aspect;
    // A message for the status line from outside the state (a file the loop wrote or could not write, the
    // animation export's progress): shown unless this frame's own edits say something newer.
    std::optional<std::string> status;
    // A registered figure's id (a paper preset) or a lesson step's id (a concept preset): its setup.
    std::optional<std::string> preset;
    // The lesson step to show and set up (1-based); 0 closes the lesson, the setup staying as it is.
    std::optional<int> lesson;
    // Compare mode on (setup B set to compare_default of A after this frame's edits, unless `b` or
    // `b_setup` says otherwise) or off; B's whole setup (a lesson, a link); edits of B (the panel, a script,
    // applied after b_setup); which setup the panel edits.
    std::optional<bool> compare;
    std::optional<Setup> b_setup;
    SetupEdits b;
    std::optional<bool> editing_b;

    // Later edits of the same field win; actions accumulate.
    void merge(const UiEdits& o);
    // Whether these edits may change the model or its parameters, and so the r_x(zeta) curves.
    bool moves_curves() const {
        return model || start || params || amplitude_um || frequency_khz || vb_m_s || zss_um ||
               open_session || preset || lesson || compare || b_setup || b.any();
    }
};

} // namespace fv::app
