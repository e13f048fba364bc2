// Hit tests of display-list commands against rectangles: what a plot's legend and a figure's labels are
// placed against (every drawn sample, segment, marker, arrow and text).
#include "fv/gfx/display_list.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <type_traits>

namespace fv::gfx {

bool clip_segment(double& ax, double& ay, double& bx, double& by, double x0, double y0, double x1,
                  double y1) {
    double t0 = 0, t1 = 1;
    const double dx = bx - ax, dy = by - ay;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    const double nax = ax + t0 * dx, nay = ay + t0 * dy;
    bx = ax + t1 * dx, by = ay + t1 * dy;
    ax = nax, ay = nay;
    return true;
}

namespace {

Rect grow(const Rect& r, float d) {
    return {r.x0 - d, r.y0 - d, r.x1 + d, r.y1 + d};
}

bool segment_meets(Vec2 a, Vec2 b, const Rect& r) {
    double ax = a.x, ay = a.y, bx = b.x, by = b.y;
    return std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by) &&
           clip_segment(ax, ay, bx, by, r.x0, r.y0, r.x1, r.y1);
}

// Nearest and farthest distance from a point to a rectangle.
float nearest(Vec2 c, const Rect& r) {
    const float dx = std::max({r.x0 - c.x, 0.0f, c.x - r.x1}), dy = std::max({r.y0 - c.y, 0.0f, c.y - r.y1});
    return std::hypot(dx, dy);
}
float farthest(Vec2 c, const Rect& r) {
    return std::hypot(std::max(std::fabs(c.x - r.x0), std::fabs(c.x - r.x1)),
                      std::max(std::fabs(c.y - r.y0), std::fabs(c.y - r.y1)));
}

bool ring_meets(Vec2 c, float radius, float half_width, const Rect& r) {
    return nearest(c, r) <= radius + half_width && farthest(c, r) >= radius - half_width;
}

constexpr Rect kNoBox{1, 1, 0, 0}; // empty: overlaps nothing

// The box around the finite points [first, last), grown by d; non-finite points are skipped, as segment_meets
// skips their segments.
Rect points_box(const Vec2* first, const Vec2* last, float d) {
    Rect r = kNoBox;
    bool any = false;
    for (const Vec2* p = first; p != last; ++p) {
        if (!std::isfinite(p->x) || !std::isfinite(p->y)) continue;
        r = any ? Rect{std::min(r.x0, p->x), std::min(r.y0, p->y), std::max(r.x1, p->x), std::max(r.y1, p->y)}
                : Rect{p->x, p->y, p->x, p->y};
        any = true;
    }
    return any ? grow(r, d) : kNoBox;
}
// A shape's few points without a vector (the label placer asks for every command's box each frame).
Rect points_box(std::initializer_list<Vec2> ps, float d) {
    return points_box(ps.begin(), ps.end(), d);
}

} // namespace

bool command_touches(const dl::Command& cmd, const Rect& r0, const FontSet& fonts, float pad) {
    return std::visit(
        [&](const auto& c) -> bool {
            using T = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<T, dl::Polyline>) {
                const Rect r = grow(r0, pad + 0.5f * c.stroke.width);
                const std::size_t n = c.points.size();
                if (n == 1) return r.contains(c.points[0]);
                for (std::size_t k = 1; k < n; ++k)
                    if (segment_meets(c.points[k - 1], c.points[k], r)) return true;
                return c.closed && n > 2 && segment_meets(c.points[n - 1], c.points[0], r);
            } else if constexpr (std::is_same_v<T, dl::Marker>) {
                const float h = 0.5f * c.style.size + c.style.edge_width;
                return grow(r0, pad).overlaps(
                    {c.center.x - h, c.center.y - h, c.center.x + h, c.center.y + h});
            } else if constexpr (std::is_same_v<T, dl::Circle>) {
                return ring_meets(c.center, c.radius, pad + 0.5f * c.stroke.width, r0);
            } else if constexpr (std::is_same_v<T, dl::FillCircle>) {
                return nearest(c.center, r0) <= c.radius + pad;
            } else if constexpr (std::is_same_v<T, dl::Arrow>) {
                const Rect r = grow(r0, pad + 0.5f * std::max(c.style.shaft.width, c.style.head_width));
                return segment_meets(c.from, c.to, r);
            } else if constexpr (std::is_same_v<T, dl::FillTriangle>) {
                const Rect b{std::min({c.a.x, c.b.x, c.c.x}), std::min({c.a.y, c.b.y, c.c.y}),
                             std::max({c.a.x, c.b.x, c.c.x}), std::max({c.a.y, c.b.y, c.c.y})};
                return grow(r0, pad).overlaps(b);
            } else if constexpr (std::is_same_v<T, dl::Text>) {
                return grow(r0, pad).overlaps(text_bounds(c, fonts));
            } else if constexpr (std::is_same_v<T, dl::StrokeRect>) {
                const Rect r = grow(r0, pad + 0.5f * c.stroke.width);
                const Vec2 a{c.rect.x0, c.rect.y0}, b{c.rect.x1, c.rect.y0}, d{c.rect.x1, c.rect.y1},
                    e{c.rect.x0, c.rect.y1};
                return segment_meets(a, b, r) || segment_meets(b, d, r) || segment_meets(d, e, r) ||
                       segment_meets(e, a, r);
            } else {
                return false; // fills (backgrounds), images, clips
            }
        },
        cmd);
}

Rect command_bounds(const dl::Command& cmd, const FontSet& fonts) {
    return std::visit(
        [&](const auto& c) -> Rect {
            using T = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<T, dl::Polyline>) {
                return points_box(c.points.data(), c.points.data() + c.points.size(), 0.5f * c.stroke.width);
            } else if constexpr (std::is_same_v<T, dl::Marker>) {
                return points_box({c.center}, 0.5f * c.style.size + c.style.edge_width);
            } else if constexpr (std::is_same_v<T, dl::Circle>) {
                return points_box({c.center}, c.radius + 0.5f * c.stroke.width);
            } else if constexpr (std::is_same_v<T, dl::FillCircle>) {
                return points_box({c.center}, c.radius);
            } else if constexpr (std::is_same_v<T, dl::Arrow>) {
                return points_box({c.from, c.to}, 0.5f * std::max(c.style.shaft.width, c.style.head_width));
            } else if constexpr (std::is_same_v<T, dl::FillTriangle>) {
                return points_box({c.a, c.b, c.c}, 0);
            } else if constexpr (std::is_same_v<T, dl::Text>) {
                return text_bounds(c, fonts);
            } else if constexpr (std::is_same_v<T, dl::StrokeRect>) {
                return grow(c.rect, 0.5f * c.stroke.width);
            } else {
                return kNoBox;
            }
        },
        cmd);
}

} // namespace fv::gfx
