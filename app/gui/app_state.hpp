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
#include "setup_run.hpp"
#include "ui_state.hpp"

#include "fv/live_sim.hpp"

#include <optional>

namespace fv::app {

// The app's own ranges (not model parameters), animation speed and trail length in periods, are in the
// shared table (fv/param_ranges.hpp: kSpeedRange, kTrailRange) since share links carry them. The panel's
// sliders span a part of them.
// How much of the past the app keeps to rewind through, in vibration periods (at least the trail).
inline constexpr double kHistoryPeriods = 6;

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
    ViewState view() const { return view_of(a_); }
    const LiveSim& sim() const { return a_.sim(); }
    RatioWorker& worker() { return a_.worker(); }
    // Compare mode's setup B (running while ui().session.compare): as sim(), worker() and view() for A.
    ViewState view_b() const { return view_of(b_); }
    const LiveSim& sim_b() const { return b_.sim(); }
    RatioWorker& worker_b() { return b_.worker(); }
    MechanismBase& mechanism() { return mechanism_; } // the mechanism panel's base, kept between frames
    int syncs() const { return syncs_; }              // how many frames' edits were applied

  private:
    ViewState view_of(const SetupRun& run) const;
    RatioRequest ratio_request(const Setup& s, bool map) const;
    void request_curves(bool a, bool b);
    void jump_to_steady();
    void pin_current_curve(bool wait);
    double frame_tau() const; // dimensionless time of one displayed frame at the current speed (1/60 s)
    void refresh_units();
    // The frames for the parameters, trail and area in effect (B's while compare mode is on): eased to
    // from the frames shown now, or (`snap`) shown at once.
    void retarget_frames(bool snap);
    // Both setups back to tau = 0, each from its start (one time base).
    void reset_sims();
    // Compare mode's edits: on or off, B's setup and its edits (checked as A's). Returns whether B's
    // simulation must take new parameters, and sets `restart` when both must start again (compare turned on,
    // B's start changed).
    bool sync_compare(const UiEdits& e, bool& restart);
    // The whole state from `s` and `data`; the simulation restarts at tau = 0. Returns the data's status
    // line ("loaded FILE: N points"), or "" without data.
    std::string show_session(const Session& s, std::optional<MeasurementSet> data);

    UiState ui_;
    SetupRun a_, b_; // A always; B in compare mode
    MechanismBase mechanism_;
    DataFit fit_;
    bool step_pending_ = false;
    bool drop_fit_ = false; // a session was opened while a fit ran: its result is for another state
    int syncs_ = 0;
    double view_aspect_ = 0; // the top view's data area, width / height (A's; B's is the same size)
};

} // namespace fv::app
