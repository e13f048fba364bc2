// The help overlay (F1 or ?): every symbol on screen, what it means and where it comes from in the paper.
#pragma once

#include "fv/gfx/types.hpp"

namespace fv::app {

// Where the overlay put things, in logical units (for the layout test at every font size).
struct HelpLayout {
    float term_right = 0;      // the right edge of the widest term ("P", "spring, green", ...)
    float meaning_left = 1e9f; // the left edge of the meanings' column (every row)
    gfx::Rect window;          // the overlay's window
    float scroll_max = 0;      // > 0: taller than the area, the rest reached by scrolling
};

// Draws the overlay over `area` (logical units) when `open`, laid out for the current font (its columns from
// the widest term, its width and height within the area, scrolling when the rows do not fit); returns false
// when the user closed it. `layout`: where things went.
bool draw_help_overlay(bool open, const gfx::Rect& area, HelpLayout* layout = nullptr);

// '?' typed (not while a text field has the keyboard). F1 comes from the platform (PlatformEvents::help_key):
// Dear ImGui 1.86 has no key code for it.
bool help_key_pressed();

} // namespace fv::app
