#include "layout_checks.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>
#include <vector>

namespace fv::test {

using gfx::DisplayList;
using gfx::Rect;
using gfx::Vec2;

namespace {

std::string point(Vec2 p) {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

// Whether a closed axis-aligned rectangle (5 points, the last the first) is what the polyline draws.
bool rectangle(const gfx::dl::Polyline& pl) {
    const auto& q = pl.points;
    if (q.size() != 5 || std::hypot(q[0].x - q[4].x, q[0].y - q[4].y) > 0.01f) return false;
    for (std::size_t k = 0; k < 4; ++k)
        if (std::fabs(q[k].x - q[k + 1].x) > 0.01f && std::fabs(q[k].y - q[k + 1].y) > 0.01f) return false;
    return true;
}

// Whether the marker covers the point p: a circle its disc, any other shape its square, with its edge.
bool covers(const gfx::dl::Marker& m, Vec2 p) {
    const float h = 0.5f * m.style.size + 0.5f * m.style.edge_width;
    if (m.style.shape == gfx::MarkerShape::Circle) return std::hypot(p.x - m.center.x, p.y - m.center.y) <= h;
    return std::fabs(p.x - m.center.x) <= h && std::fabs(p.y - m.center.y) <= h;
}

} // namespace

std::string overlapping_texts(const DisplayList& list, const gfx::FontSet& fonts, float slack) {
    std::vector<std::pair<Rect, const gfx::dl::Text*>> boxes;
    for (const auto& c : list.commands)
        if (const auto* t = std::get_if<gfx::dl::Text>(&c)) boxes.push_back({gfx::text_bounds(*t, fonts), t});
    for (std::size_t a = 0; a < boxes.size(); ++a)
        for (std::size_t b = a + 1; b < boxes.size(); ++b) {
            const Rect &p = boxes[a].first, &q = boxes[b].first;
            if (std::min(p.x1, q.x1) - std::max(p.x0, q.x0) > slack &&
                std::min(p.y1, q.y1) - std::max(p.y0, q.y0) > slack)
                return "\"" + boxes[a].second->text + "\" and \"" + boxes[b].second->text + "\"";
        }
    return "";
}

std::string label_on_shape(const DisplayList& list, const gfx::FontSet& fonts, bool outlines) {
    for (const gfx::Region& data : list.regions) {
        if (data.role != "data") continue;
        for (std::size_t k = data.first; k < data.last; ++k) {
            const auto* t = std::get_if<gfx::dl::Text>(&list.commands[k]);
            if (!t) continue;
            // The glyphs' box: the text's line box less 2 units each side (its leading, the gaps in glyphs);
            // a label beside its marker may touch the marker's halo.
            const Rect l = gfx::text_bounds(*t, fonts);
            const Rect b{l.x0 + 2, l.y0 + 2, l.x1 - 2, l.y1 - 2};
            for (std::size_t j = data.first; j < data.last; ++j) {
                const auto& c = list.commands[j];
                const bool solid =
                    std::holds_alternative<gfx::dl::Arrow>(c) || std::holds_alternative<gfx::dl::Marker>(c);
                if (solid && gfx::command_touches(c, b, fonts, 0.0f))
                    return "\"" + t->text + "\" on " +
                           (std::holds_alternative<gfx::dl::Arrow>(c) ? "an arrow" : "a marker");
                const auto* pl = std::get_if<gfx::dl::Polyline>(&c);
                if (outlines && pl && rectangle(*pl) && gfx::command_touches(c, b, fonts, 0.0f))
                    return "\"" + t->text + "\" on the outline " + point(pl->points[0]) + " - " +
                           point(pl->points[2]);
            }
        }
    }
    return "";
}

std::string arrow_on_arrow(const DisplayList& list) {
    // Each arrow with the data region it is drawn (and clipped) in: arrows of two panels never meet on
    // screen, though the ground frame's copies run on beyond their axes in the list.
    std::vector<const gfx::dl::Arrow*> arrows;
    std::vector<std::size_t> region;
    for (std::size_t k = 0; k < list.commands.size(); ++k)
        if (const auto* a = std::get_if<gfx::dl::Arrow>(&list.commands[k])) {
            arrows.push_back(a);
            region.push_back(list.regions.size());
            for (std::size_t r = 0; r < list.regions.size(); ++r)
                if (list.regions[r].role == "data" && list.regions[r].first <= k && k < list.regions[r].last)
                    region.back() = r;
        }
    auto distance = [](Vec2 p, Vec2 a, Vec2 b) {
        const float dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
        const float t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.f, 1.f) : 0.f;
        return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
    };
    for (std::size_t i = 0; i < arrows.size(); ++i)
        for (std::size_t j = 0; j < arrows.size(); ++j) {
            const auto *a = arrows[i], *b = arrows[j];
            if (i == j || region[i] != region[j]) continue;
            const float reach = 0.5f * (a->style.shaft.width + b->style.shaft.width) + 1;
            int near = 0;
            constexpr int kN = 24;
            for (int k = 0; k <= kN; ++k) {
                const float t = static_cast<float>(k) / kN;
                const Vec2 p{a->from.x + t * (a->to.x - a->from.x), a->from.y + t * (a->to.y - a->from.y)};
                near += distance(p, b->from, b->to) <= reach;
            }
            if (near * 3 > kN + 1)
                return "arrow (" + std::to_string(a->from.x) + ", " + std::to_string(a->from.y) + ") -> (" +
                       std::to_string(a->to.x) + ", " + std::to_string(a->to.y) + ") along the arrow (" +
                       std::to_string(b->from.x) + ", " + std::to_string(b->from.y) + ") -> (" +
                       std::to_string(b->to.x) + ", " + std::to_string(b->to.y) + ")";
        }
    return "";
}
std::string hidden_arrow(const DisplayList& list, float min_visible) {
    for (std::size_t k = 0; k < list.commands.size(); ++k) {
        const auto* a = std::get_if<gfx::dl::Arrow>(&list.commands[k]);
        if (!a) continue;
        // The markers drawn after it in its panel's data region (another panel's cover only what its clip
        // left out: the ground frame's copies run on beyond their axes).
        std::size_t last = list.commands.size();
        for (const gfx::Region& r : list.regions)
            if (r.role == "data" && r.first <= k && k < r.last) last = r.last;
        std::vector<const gfx::dl::Marker*> above;
        for (std::size_t j = k + 1; j < last; ++j)
            if (const auto* m = std::get_if<gfx::dl::Marker>(&list.commands[j])) above.push_back(m);
        auto hidden = [&](Vec2 p) {
            return std::any_of(above.begin(), above.end(), [&](const auto* m) { return covers(*m, p); });
        };
        // Walked in steps of a quarter unit: the length outside every marker drawn later.
        const float len = std::hypot(a->to.x - a->from.x, a->to.y - a->from.y);
        const int n = 1 + static_cast<int>(len * 4);
        float seen = 0;
        for (int i = 0; i < n; ++i) {
            const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
            seen += hidden({a->from.x + t * (a->to.x - a->from.x), a->from.y + t * (a->to.y - a->from.y)})
                        ? 0
                        : len / static_cast<float>(n);
        }
        if (seen < min_visible || hidden(a->to))
            return "arrow " + point(a->from) + " -> " + point(a->to) + ": " + std::to_string(seen) +
                   " units seen" + (hidden(a->to) ? ", its tip under a marker" : "");
    }
    return "";
}

std::string text_outside(const DisplayList& list, const gfx::FontSet& fonts, std::size_t first,
                         std::size_t last, const Rect& bounds) {
    for (std::size_t k = first; k < last && k < list.commands.size(); ++k)
        if (const auto* t = std::get_if<gfx::dl::Text>(&list.commands[k])) {
            const Rect b = gfx::text_bounds(*t, fonts);
            if (b.x0 < bounds.x0 - 1 || b.x1 > bounds.x1 + 1 || b.y0 < bounds.y0 - 1 || b.y1 > bounds.y1 + 1)
                return "\"" + t->text + "\" at " + point({b.x0, b.y0}) + " - " + point({b.x1, b.y1}) +
                       " outside " + point({bounds.x0, bounds.y0}) + " - " + point({bounds.x1, bounds.y1});
        }
    return "";
}

} // namespace fv::test
