// The top view's frame (its axis ranges): fixed per parameter set, so that the picture does not breathe as
// the trajectory moves, and the choice of what stands still on screen, the body or the ground. The live top
// view (fv/live_panels.hpp) draws in it; the app eases it from one parameter set's frame to the next, the
// animation export holds it over the loop.
#pragma once

#include "fv/params.hpp"

#include <optional>
#include <string>

namespace fv {

// What stands still on screen. body: the camera moves with the body's mean velocity v_b (the floor and the
// trails slide left). ground: the floor stands still, the body drifts through at v_b and wraps around the
// frame's edges, so that a stuck tip T stands still on screen too.
enum class FrameChoice { body, ground };
const char* to_string(FrameChoice f);
std::optional<FrameChoice> parse_frame(const std::string& s); // "body" or "ground"

// A rectangle in units of x_v, relative to where P would be without the vibration (the vibration centre C).
struct FrameBox {
    double x0 = -1, x1 = 1, y0 = -1, y1 = 1;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    bool operator==(const FrameBox& o) const { return x0 == o.x0 && x1 == o.x1 && y0 == o.y0 && y1 == o.y1; }
    bool operator!=(const FrameBox& o) const { return !(*this == o); }
};

// The half sizes of the body's outline drawn around P (rigid: around P's arrows; Dahl: around the z_ss
// circle).
struct BodyOutline {
    double half_w = 0, half_h = 0;
};
BodyOutline body_outline(Model model, const Params& p);

// The frame that holds everything the top view draws at any instant of the motion, with a margin: P's path
// (prescribed, Eqs. (28)-(29): P = C + sin(tau) (cos theta, sin theta)), T within z_ss of P (Dahl: |P - T| <=
// z_ss, so T's orbit lies inside the body's outline around P), the arrows at P (0.4 v, Eq. (1), and the
// friction, |F| <= F_c drawn as 0.5 x_v) and the trails' last kFrameTrailPeriods (of `trail_periods`), left
// behind at v_b; older parts of the trails may leave at the edge. It
// depends on the parameters only, not on the moment, so it holds for the transient too. Where the body's
// outline is far larger than the motion (tiny r_disp) it is left to the edges, as the paths would shrink to
// a dot. aspect > 0: widened (or heightened) about its centre to that width / height, the data area's
// (pixels), so that a painter keeping one unit equally long on both axes shows exactly this box.
FrameBox steady_frame(Model model, const Params& p, double trail_periods, double aspect = 0);

// The frame s of the way from `from` to `to` (s in [0, 1]), along a smoothstep: each edge moves
// monotonically, starting and ending at rest.
FrameBox eased_frame(const FrameBox& from, const FrameBox& to, double s);

// How much of the trails the frame holds (periods).
inline constexpr double kFrameTrailPeriods = 0.5;

// How long the app takes to move the frame to a new parameter set's (seconds of wall time).
inline constexpr double kFrameEaseSeconds = 0.3;

} // namespace fv
