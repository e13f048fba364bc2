// The app's picture: top view (P, T, spring, z_ss circle, arrows, fading trails), live force plot and the
// r_x(zeta) plot. Built as figure panels and painted by the figure painter, so the window, the headless
// render and the screenshots share one drawing path.
#pragma once

#include "lower_panel.hpp"
#include "pinned_curve.hpp"
#include "ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/gfx/canvas.hpp"
#include "fv/gfx/plot.hpp"
#include "fv/live_sim.hpp"
#include "fv/measurements.hpp"
#include "fv/param_ranges.hpp"

#include <optional>

namespace fv::app {

struct ViewState {
    double zoom = 1;    // > 1 shows less
    Vec2 pan{0, 0};     // data units, added to the followed centre
    bool follow = true; // keep P's drift in view
    double trail_periods = 1.5;
    double rewind = 0; // dimensionless time behind the live simulation that is shown (0: live)
};
// What the mouse can set (and a session file may hold): zoom factor, each pan coordinate.
inline constexpr ParamRange kZoomRange{0.05, 20};
inline constexpr ParamRange kPanRange{-1e6, 1e6};

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

struct DashboardLayout {
    gfx::Rect top_view, force, ratio;
};

DashboardLayout layout_dashboard(const gfx::Rect& area);

PanelData top_view_panel(const LiveSim& sim, const ViewState& view);
PanelData force_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, double rewind = 0);
// What the ratio plot shows besides the model: measured points and the physical scale of zeta.
struct RatioOverlay {
    const MeasurementSet* data = nullptr; // measured r_x(zeta), or none
    double vv_m_s = 0;                    // v_v = 2 pi f A; > 0 adds the v_b scale to the axis title
    const std::vector<PinnedCurve>* pins = nullptr; // curves kept to compare with
};

// The zeta range the ratio plot spans: [0, 3], wider when measured points lie further out.
double ratio_zeta_max(const MeasurementSet* data);

PanelData ratio_panel_live(const std::optional<RatioCurves>& curves, bool busy,
                           const RatioOverlay& overlay = {});

struct DashboardTransforms {
    gfx::PlotTransform top_view, force, ratio;
};

// The map panel with the current (zeta, theta) marked.
PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy);

// The asperity's hysteresis over the period before the shown moment: the friction force along the vibration
// against the vibration displacement u = sin tau, and the work of the body against friction over that period
// (F_c x_v units): W = sum of F . dP, and the loop's area, the sum of F_par du (the vibration's share).
struct LoopData {
    std::vector<double> u, f;
    double work = 0, vibration_work = 0;
    bool complete = false; // a whole period was recorded
};
LoopData hysteresis_loop(const LiveSim& sim, double rewind = 0);
PanelData loop_panel_live(const LiveSim& sim, double rewind = 0);

// The mechanism panel's base: the registered fig4 (the paper's Fig. 4: the rigid model's velocity and
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
// mechanism: the base kept between frames (nullptr: computed for this call).
DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const LiveSim& sim,
                                    const ViewState& view, const std::optional<RatioCurves>& curves,
                                    bool busy, LowerPanel lower = LowerPanel::curves,
                                    const RatioOverlay& overlay = {}, float style = 1,
                                    MechanismBase* mechanism = nullptr);
// The panel with its text, lines and markers k times larger (presentation mode).
PanelData enlarged(PanelData panel, float k);

} // namespace fv::app
