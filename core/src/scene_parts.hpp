// The pieces that the scene figures (one steady period: figure_data.cpp) and the app's live panels (the
// running simulation: live_panels.cpp) both draw. One builder per piece, so that the same quantity has the
// same name, colour and line in a figure and in the app.
#pragma once

#include "fv/figure_data.hpp"

#include <vector>

namespace fv::scene {

// The top view's axes: positions in units of x_v, one unit as long on both axes.
PanelData top_view_axes();

// The paths of the body point P and of the asperity tip T (empty; the caller adds the points).
SeriesData body_path(float width);
SeriesData tip_path(float width);
// The marks of P (circle) and T (square, in `ink`: the tip's state where the app shows it).
PointData body_mark(const Vec2& P, float size);
PointData tip_mark(const Vec2& T, Ink ink, float size);

// A force panel's axes: time (x_title) against F / F_c (the force convention), F in [-1.15, 1.15].
PanelData force_axes(const std::string& x_title);

// |F|, F_x and F_y over time, filled by add() and handed over in drawing order (|F| below the components).
class ForceCurves {
  public:
    ForceCurves();
    void add(double tau, const Vec2& F);
    std::vector<SeriesData> take();

  private:
    SeriesData magnitude_, x_, y_;
};

// The r_x(zeta) panel's axes: zeta from 0 to zeta_max, r_x in [0, 1.05].
PanelData ratio_axes(double zeta_max);
// The rigid model's r_x(zeta), dashed, as the scene figure and the app draw it beside the Dahl curve.
SeriesData rigid_curve(std::vector<double> zetas, std::vector<double> rx);

} // namespace fv::scene
