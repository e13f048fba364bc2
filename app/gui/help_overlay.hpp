// The help overlay (F1 or ?): every symbol on screen, what it means and where it comes from in the paper.
#pragma once

#include "fv/gfx/types.hpp"

namespace fv::app {

// Draws the overlay over `area` (logical units) when `open`; returns false when the user closed it.
bool draw_help_overlay(bool open, const gfx::Rect& area);

// '?' typed (not while a text field has the keyboard). F1 comes from the platform (PlatformEvents::help_key):
// Dear ImGui 1.86 has no key code for it.
bool help_key_pressed();

} // namespace fv::app
