#include "scene_parts.hpp"

#include "fv/axis_titles.hpp"

#include <utility>

namespace fv::scene {

PanelData top_view_axes() {
    PanelData panel;
    panel.equal_aspect = true;
    panel.x_title = titles::kTopViewX;
    panel.y_title = titles::kTopViewY;
    return panel;
}

SeriesData body_path(float width) {
    return {"body point P", {}, {}, Ink::body, Dash::solid, Mark::none, width};
}

SeriesData tip_path(float width) {
    return {"asperity tip T", {}, {}, Ink::tip, Dash::solid, Mark::none, width};
}

PointData body_mark(const Vec2& P, float size) {
    return {P, Ink::body, Mark::circle, "P", size};
}

PointData tip_mark(const Vec2& T, Ink ink, float size) {
    return {T, ink, Mark::square, "T", size};
}

PanelData force_axes(const std::string& x_title) {
    PanelData panel;
    panel.x_title = x_title;
    panel.y_title = titles::kForce;
    panel.y_min = -1.15;
    panel.y_max = 1.15;
    return panel;
}

ForceCurves::ForceCurves()
    : magnitude_{"|F|", {}, {}, Ink::magnitude, Dash::solid, Mark::none, 2.5f},
      x_{"F_{x}", {}, {}, Ink::force, Dash::solid, Mark::none, 2}, y_{"F_{y}",      {},         {}, Ink::pull,
                                                                      Dash::dashed, Mark::none, 2} {}

void ForceCurves::add(double tau, const Vec2& F) {
    magnitude_.x.push_back(tau), magnitude_.y.push_back(F.norm());
    x_.x.push_back(tau), x_.y.push_back(F.x());
    y_.x.push_back(tau), y_.y.push_back(F.y());
}

std::vector<SeriesData> ForceCurves::take() {
    return {std::move(magnitude_), std::move(x_), std::move(y_)};
}

PanelData ratio_axes(double zeta_max) {
    PanelData panel;
    panel.x_title = titles::kZeta;
    panel.y_title = titles::kRx;
    panel.x_min = 0;
    panel.x_max = zeta_max;
    panel.y_min = 0;
    panel.y_max = 1.05;
    return panel;
}

SeriesData rigid_curve(std::vector<double> zetas, std::vector<double> rx) {
    return {"rigid", std::move(zetas), std::move(rx), Ink::rigid, Dash::dashed, Mark::none, 2};
}

} // namespace fv::scene
