// The experiment as a picture (setup_picture.hpp). Drawn in units of a 12 x 6.3 page, equal aspect: the side
// view upper left, the magnified contact below it, the view from above on the right. Only the shake's
// direction in the view from above moves (with theta); the rest is a fixed schematic, not to scale (the shake
// is micrometres, the block centimetres).
#include "fv/setup_picture.hpp"

#include "fv/format.hpp"
#include "fv/params.hpp"

#include <cmath>

namespace fv {
namespace {

SeriesData outline(std::vector<Vec2> corners, Ink ink, float width, Dash dash = Dash::solid) {
    SeriesData s;
    corners.push_back(corners.front());
    for (const Vec2& c : corners) s.x.push_back(c.x()), s.y.push_back(c.y());
    s.ink = ink, s.width = width, s.dash = dash;
    return s;
}

SeriesData box(double x0, double y0, double x1, double y1, Ink ink, float width, Dash dash = Dash::solid) {
    return outline({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, ink, width, dash);
}

// A word or two at a place (no mark): the label is placed beside it, clear of the lines, or left out where
// it finds no room (a phone's small panel keeps the arrows' labels).
PointData words(Vec2 at, std::string text, int dx = 0, int dy = 0) {
    PointData p;
    p.at = at, p.mark = Mark::none, p.label = std::move(text), p.ink = Ink::black;
    p.label_dx = dx, p.label_dy = dy;
    p.optional = true;
    return p;
}

// A rough surface between x0 and x1 at height y: small bumps of height h (up for h > 0, down for h < 0).
SeriesData rough(double x0, double x1, double y, double h, Ink ink) {
    SeriesData s;
    const int n = 120;
    for (int k = 0; k <= n; ++k) {
        const double x = x0 + (x1 - x0) * k / n;
        // Bumps of uneven height, so that the surfaces touch at a few of them only.
        const double bump = std::pow(std::fabs(std::sin(7.0 * x)), 3) * (0.6 + 0.4 * std::sin(2.3 * x + 1));
        s.x.push_back(x), s.y.push_back(y + h * bump);
    }
    s.ink = ink, s.width = 1.6f;
    return s;
}

} // namespace

PanelData setup_panel(double theta) {
    PanelData p;
    p.title = "the experiment: a block pressed on a floor, pulled at v_{b}, shaken at θ = " +
              format_number("%.0f", theta * 180 / kPi) + "°";
    p.axes = false;
    p.equal_aspect = true;
    p.x_min = 0, p.x_max = 12, p.y_min = -0.3, p.y_max = 6.0;
    p.legend = Legend::none;

    // Seen from the side: the floor (hatched below), the block on it, pressed down and pulled along.
    p.series.push_back(box(0.3, 3.0, 5.7, 3.4, Ink::black, 1.5f));
    for (double x = 0.7; x < 5.7; x += 0.4) p.segments.push_back({{x, 3.0}, {x - 0.25, 2.75}, Ink::spring});
    p.series.push_back(box(1.8, 3.4, 3.8, 4.6, Ink::body, 2.0f));
    p.points.push_back(words({0.9, 3.2}, "floor", -1, 1));
    p.points.push_back(words({2.25, 4.0}, "block", -1, 0));
    p.arrows.push_back({{3.45, 5.6}, {3.45, 4.65}, Ink::black, "pressed down", 2.0f});
    p.arrows.push_back({{3.85, 4.0}, {5.3, 4.0}, Ink::body, "v_{b}", 2.0f});
    // The shake, both ways from the middle of the block.
    p.arrows.push_back({{2.35, 5.05}, {1.75, 5.05}, Ink::tip, "", 2.0f});
    p.arrows.push_back({{2.35, 5.05}, {2.95, 5.05}, Ink::tip, "shaken ±x_{v}", 2.0f, -1});

    // The contact under a magnifier: the surfaces touch at a few asperities; one of them is the model's
    // spring from P (on the body) to its tip T (on the floor).
    const Vec2 lens{2.8, 3.4}, zoom{2.8, 1.3};
    p.circles.push_back({lens, 0.28, Ink::black, Dash::dotted, 1.2f});
    p.segments.push_back({lens - Vec2(0, 0.28), zoom + Vec2(0, 1.3), Ink::black, Dash::dotted, 1.0f});
    p.circles.push_back({zoom, 1.3, Ink::black, Dash::dashed, 1.2f});
    p.series.push_back(rough(1.65, 3.95, 0.85, 0.22, Ink::black));
    p.series.push_back(rough(1.7, 3.9, 1.75, -0.2, Ink::body));
    const Vec2 P{3.1, 1.62}, T{2.65, 1.05};
    p.segments.push_back({P, T, Ink::spring, Dash::solid, 2.5f});
    PointData pm{P, Ink::body, Mark::circle, "P", 8};
    pm.label_dx = 1, pm.label_dy = -1;
    PointData tm{T, Ink::tip, Mark::square, "T", 8};
    tm.label_dx = -1, tm.label_dy = -1; // between the surfaces, off the floor's line
    p.points.push_back(pm);
    p.points.push_back(tm);
    p.points.push_back(words({4.2, 1.3}, "one bump (asperity) bends: the spring P–T", 1, 0));
    p.points.push_back(words({4.2, 0.2}, "magnified: the surfaces touch at tiny bumps", 1, 1));

    // Seen from above: the block, v_b along x, the shake at theta from it.
    const Vec2 c{9.0, 3.0};
    p.series.push_back(box(7.9, 1.9, 10.1, 4.1, Ink::body, 1.5f, Dash::dashed));
    p.points.push_back(words({9.0, 4.6}, "seen from above", 0, -1));
    p.arrows.push_back({{10.15, 3.0}, {11.6, 3.0}, Ink::body, "v_{b}", 2.0f});
    const Vec2 u{std::cos(theta), std::sin(theta)};
    p.arrows.push_back({c, c + 0.95 * u, Ink::tip, "±x_{v}", 2.0f});
    p.arrows.push_back({c, c - 0.95 * u, Ink::tip, "", 2.0f});
    // The angle from the direction of v_b (dotted) to the shake.
    p.segments.push_back({c, c + Vec2(1.0, 0), Ink::black, Dash::dotted, 1.0f});
    if (theta > 3 * kPi / 180) {
        SeriesData arc;
        for (int k = 0; k <= 40; ++k) {
            const double a = theta * k / 40;
            arc.x.push_back(c.x() + 0.55 * std::cos(a)), arc.y.push_back(c.y() + 0.55 * std::sin(a));
        }
        arc.ink = Ink::black, arc.width = 1.2f;
        p.series.push_back(arc);
        const double mid = theta / 2;
        p.points.push_back(words(c + 0.7 * Vec2(std::cos(mid), std::sin(mid)), "θ", 1, -1));
    }
    return p;
}

} // namespace fv
