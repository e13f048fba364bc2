#include "screen_layout.hpp"

#include <algorithm>
#include <cmath>

namespace fv::app {

ScreenLayout screen_layout(gfx::Vec2 page, bool presentation) {
    const float panel_w = presentation ? kPresentationPanelWidth : kPanelWidth;
    ScreenLayout l;
    if (page.x >= panel_w + kMinPicturesWidth) {
        l.controls = {0, 0, panel_w, page.y};
        l.pictures = {panel_w + 6, 4, page.x - 4, page.y - 4};
        l.beside = {panel_w, 0, page.x, page.y};
        return l;
    }
    // Across the top: 42% of the height (the parameters' sliders and the share link in view on a phone),
    // the rest for the pictures; the panel scrolls to the rest of its rows.
    const float panel_h = std::min(page.y, std::max(160.0f, std::round(page.y * 0.42f)));
    l.stacked = true;
    l.controls = {0, 0, page.x, panel_h};
    l.pictures = {4, panel_h + 4, page.x - 4, page.y - 4};
    l.beside = {0, panel_h, page.x, page.y};
    return l;
}

} // namespace fv::app
