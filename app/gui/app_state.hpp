// The app's state and the one point per frame where edits take effect (MuJoCo `simulate` style): the panel,
// the keys, the mouse, a drop, the script and the benchmark all queue UiEdits during a frame; sync() applies
// them at the start of the next one: checked against the shared range table (fv/param_ranges.hpp), physical
// units converted once, the simulation and the background curves told once. No window or GL here: tests
// drive it directly.
#pragma once

#include "dashboard.hpp"
#include "measured_data.hpp"
#include "ratio_worker.hpp"
#include "session.hpp"
#include "ui_state.hpp"

#include "fv/live_sim.hpp"

#include <optional>

namespace fv::app {

// App-only ranges (not model parameters): animation speed in vibration periods per second (in the shared
// table, fv/param_ranges.hpp, since share links carry it), trail length in periods. The panel's sliders span
// a part of them.
using fv::kSpeedRange;
// How much of the past the app keeps to rewind through, in vibration periods (at least the trail).
inline constexpr double kHistoryPeriods = 6;
inline constexpr ParamRange kTrailRange{0.1, 10};

class AppState {
  public:
    // Starts from a session's state (from flags, a link or a file; checked by whoever made it), with its
    // measured data already read. session_file: the file it came from (the status line names it, as when
    // the session is opened from the menu), or "".
    explicit AppState(const Session& start, std::optional<MeasurementSet> data = std::nullopt,
                      const std::string& session_file = "");
    AppState(Model model, const Params& params, double amplitude_um, double frequency_khz,
             std::optional<MeasurementSet> data = std::nullopt);

    // What a frame's edits ask of the loop rather than of the state (files, exit).
    struct Actions {
        bool screenshot = false, export_csv = false, quit = false;
        std::string save_session; // a path, or empty
        bool open_export_dialog = false;
        std::optional<AnimationRequest> export_animation; // with the model and parameters in effect
    };
    // Applies one frame's edits, in a fixed order: session, preset, model, parameters, v_b/z_ss, A/f, data,
    // fit, playback, view. An edit outside the ranges changes nothing and says why in ui().status; so does a
    // session that does not load (session.hpp), the state before it kept. wait: block for a running fit
    // (scripted runs, for reproducible pictures).
    Actions sync(const UiEdits& edits, bool wait = false);
    // Advances the simulation by dt seconds of wall time at ui().session.speed while playing, then the single
    // step asked for by the last sync.
    void advance(double dt_seconds);

    const UiState& ui() const { return ui_; }
    // The view to draw: the session's, with the top view's frame as it is now (eased over kFrameEaseSeconds
    // of wall time from the last parameter set's to this one's, by advance()).
    ViewState view() const;
    const LiveSim& sim() const { return sim_; }
    RatioWorker& worker() { return worker_; }
    MechanismBase& mechanism() { return mechanism_; } // the mechanism panel's base, kept between frames
    int syncs() const { return syncs_; }              // how many frames' edits were applied

  private:
    RatioRequest ratio_request() const;
    void jump_to_steady();
    void pin_current_curve(bool wait);
    double frame_tau() const; // dimensionless time of one displayed frame at the current speed (1/60 s)
    void refresh_units();
    // The frame for the parameters, trail and area in effect: eased to from the frame shown now, or
    // (`snap`) shown at once.
    void retarget_frame(bool snap);
    // The whole state from `s` and `data`; the simulation restarts at tau = 0. Returns the data's status
    // line ("loaded FILE: N points"), or "" without data.
    std::string show_session(const Session& s, std::optional<MeasurementSet> data);

    UiState ui_;
    LiveSim sim_;
    RatioWorker worker_;
    MechanismBase mechanism_;
    DataFit fit_;
    double step_carry_ = 0;
    bool step_pending_ = false;
    bool drop_fit_ = false; // a session was opened while a fit ran: its result is for another state
    int syncs_ = 0;
    // The top view's frame: eased from `from` to `to`, `ease` of the way (0..1, in kFrameEaseSeconds).
    FrameBox frame_from_, frame_to_;
    double frame_ease_ = 1, view_aspect_ = 0;
};

} // namespace fv::app
