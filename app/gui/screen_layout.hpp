// Where the control panel and the pictures go on the page, for any window: a desktop window, a Chromebook's
// small screen, a phone held upright. A wide page has the panel down the left edge and the pictures beside it
// (the layout the app always had: 1280 x 800 is unchanged); a page too narrow for both side by side has the
// panel across the top, scrolling, and the pictures below it (stacked one above the other where the space
// left is upright, figures/dashboard_painter.cpp). The panel scrolls wherever its rows do not fit, so every
// control stays reachable.
#pragma once

#include "fv/gfx/types.hpp"

namespace fv::app {

// The panel's width in logical pixels (presentation mode's is wider: its type is larger).
inline constexpr float kPanelWidth = 340, kPresentationPanelWidth = 450;
// Presentation mode: the pictures' type, lines and markers this much larger (the panel's font 22 px instead
// of 15).
inline constexpr float kPresentationScale = 1.4f;
// The pictures need at least this much width beside the panel; less and the panel goes on top.
inline constexpr float kMinPicturesWidth = 380;

struct ScreenLayout {
    gfx::Rect controls;   // the ImGui panel
    gfx::Rect pictures;   // the area paint_dashboard fills
    gfx::Rect beside;     // the page outside the panel (the help overlay's area)
    bool stacked = false; // the panel across the top
};

// The layout of a page of `page` logical pixels.
ScreenLayout screen_layout(gfx::Vec2 page, bool presentation);

} // namespace fv::app
