// The lesson on screen: the Lessons menu, the card above the controls (the step's title and plain-words
// text, the equations and the teacher's tip on demand, Back and Next) and the keys a presenter's remote
// sends (Page Down / Page Up). The steps themselves are data: lessons.hpp.
#pragma once

#include "ui_state.hpp"

namespace fv::app {

// The Lessons menu of the menu bar (call between BeginMenuBar and EndMenuBar): every step, and Close.
UiEdits draw_lessons_menu(const UiState& ui);

// The card of step ui.lesson (nothing when no lesson is on), at the top of the control panel.
UiEdits draw_lesson_card(const UiState& ui);

// Page Down: the next step, Page Up: the one before (while a lesson is on). Part of keyboard_edits, which
// leaves the keys alone while a text field has the keyboard or a dialog is open.
UiEdits lesson_keys(const UiState& ui);

} // namespace fv::app
