// The app's live panels as figure data: the top view of the running simulation (P, T, spring, z_ss circle,
// arrows, fading trails), the force over the last periods, the r_x(zeta) curves with the current point, the
// (zeta, theta) map, the hysteresis loop and the mechanism. Built from the same pieces as the static scene
// figure (scene_parts.hpp), painted by the figures layer (app/figures/dashboard_painter.hpp) in the window,
// the headless app and the animation export alike.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/live_sim.hpp"
#include "fv/lower_panel.hpp"
#include "fv/measurements.hpp"
#include "fv/pinned_curve.hpp"
#include "fv/ratio_curves.hpp"
#include "fv/top_view_frame.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace fv {

// How the top view is framed and which moment the panels show (the app's mouse, time slider and view
// controls set it; the animation export sets its own).
struct ViewState {
    double zoom = 1;    // the frame's size times this (< 1 shows less, larger)
    Vec2 pan{0, 0};     // data units, added to the followed centre (ground frame: to the window's place)
    bool follow = true; // body frame: keep the body in view (false: the camera stays where it was put)
    double trail_periods = 1.5;
    double rewind = 0; // dimensionless time behind the live simulation that is shown (0: live)
    FrameChoice frame = FrameChoice::body; // what stands still on screen: the body or the ground
    // Not saved, set each frame by whoever draws: the frame shown (the app eases it from one parameter set's
    // to the next; unset: steady_frame of the parameters), and the top view's data area width / height in
    // pixels (0: not known yet), which the ground frame's wrap-around needs.
    std::optional<FrameBox> box;
    double aspect = 0;
};

// Every x coordinate of the panel moved by dx (a camera that moves with the body, the ground frame's wrap).
void shift_panel_x(PanelData& p, double dx);

// The state shown at `rewind` behind the live simulation (from its history; the live state at 0).
struct SimMoment {
    double tau = 0;
    Vec2 P{0, 0}, T{0, 0}, F{0, 0}, velocity{0, 0};
    Vec2 centre{0, 0}; // where P would be without the vibration
    double z = 0;
    bool slip = false;
};
SimMoment moment_at(const LiveSim& sim, double rewind);
// How far back the history reaches (dimensionless time).
double max_rewind(const LiveSim& sim);

// setup: compare mode's name of the setup shown ("A", "B"; null: the one setup), which then heads the title
// with its angle ("A: θ = 90°") and leaves the legend out (two views share the room of one).
PanelData top_view_panel(const LiveSim& sim, const ViewState& view, const char* setup = nullptr);

// Compare mode's setup B on the plots that show both setups: its simulation (on A's time base: the same tau)
// and its r_x(zeta) curves (null: none yet). sim null: no compare.
struct CompareOverlay {
    const LiveSim* sim = nullptr;
    const RatioCurves* curves = nullptr;
    bool busy = false; // B's curves are being computed
};

// With b: both setups' F_x and period means, A's in blue and B's in orange (the components and the slip bands
// of the one setup would double the lines).
PanelData force_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, double rewind = 0,
                           const CompareOverlay& b = {});
// What the ratio plot shows besides the model: measured points and the physical scale of zeta.
struct RatioOverlay {
    const MeasurementSet* data = nullptr; // measured r_x(zeta), or none
    double vv_m_s = 0;                    // v_v = 2 pi f A; > 0 adds the v_b scale to the axis title
    const std::vector<PinnedCurve>* pins = nullptr; // curves kept to compare with
    CompareOverlay b;                               // compare mode: B's curve and r_x point beside A's
};

// The zeta range the ratio plot spans: [0, 3], wider when measured points lie further out.
double ratio_zeta_max(const MeasurementSet* data);

PanelData ratio_panel_live(const std::optional<RatioCurves>& curves, bool busy,
                           const RatioOverlay& overlay = {});

// The map panel with the current (zeta, theta) marked.
PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy);

// The asperity's hysteresis over the period before the shown moment: the friction force along the vibration
// against the vibration displacement u = sin tau, and the work of the body against friction over that period
// (F_c x_v units): W = sum of F . dP, and the loop's area, the sum of F_par du (the vibration's share).
struct LoopData {
    std::vector<double> u, f;
    std::vector<bool> slip; // per sample: the tip slips (LiveSample::slip)
    double work = 0, vibration_work = 0;
    bool complete = false; // a whole period was recorded
};
LoopData hysteresis_loop(const LiveSim& sim, double rewind = 0);
PanelData loop_panel_live(const LiveSim& sim, double rewind = 0);

// The mechanism panel's base: the left panel of fig4 (the paper's Fig. 4: the rigid model's velocity and
// friction at tau = k pi/4, their loci, the mean friction) for the current zeta and theta, faded. Computing
// it is a figure's sweep, so it is kept (in AppState) while zeta and theta stay.
class MechanismBase {
  public:
    const PanelData& for_params(const Params& p);

  private:
    std::optional<std::pair<Vec2, PanelData>> cached_; // (zeta, theta) and the panel
};
// The mechanism (the paper's Fig. 4) live: the velocity and the friction on the body at the shown instant
// over the base.
PanelData mechanism_panel_live(const LiveSim& sim, MechanismBase& base, double rewind = 0);

// The lower-right panel `which` at the view's moment: the one switch behind the app's dashboard and the
// animation export (`animate`, `render --lesson`), so that both show a lesson step's panel alike. With
// overlay.b (compare mode) the curves show B's curve and point beside A's; the map, loop and why panels are
// A's and say so ("A: ..." in their title).
PanelData lower_panel_live(LowerPanel which, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                           bool busy, const RatioOverlay& overlay, MechanismBase& mechanism,
                           double rewind = 0);

} // namespace fv
