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
    // Across the top: 36% of the height (on a phone the parameters' sliders and the share link in view),
    // the rest for the pictures, which need it more (three plots, two with legends); the panel scrolls to
    // the rest of its rows.
    const float panel_h = std::min(page.y, std::max(160.0f, std::round(page.y * 0.36f)));
    l.stacked = true;
    l.controls = {0, 0, page.x, panel_h};
    l.pictures = {4, panel_h + 4, page.x - 4, page.y - 4};
    l.beside = {0, panel_h, page.x, page.y};
    return l;
}

} // namespace fv::app
