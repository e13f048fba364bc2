// render --lesson N: a guided lesson step's picture for a slide or a handout, a frame
// (anim::Frames::still_frame) of what `animate --lesson N` plays (top view, force plot and the step's lower
// panel, at the step's setup, frame and compare mode) under the step's title and a caption naming the
// parameters, as lesson-N.png/.svg/.pdf (--format) with lesson-N.json beside it (the step's title, its
// plain-words text and the share link that opens the step). --page lays the SVG and PDF out on a printed page
// (as render --figure does), --caption puts the step's title and text under the picture.
#pragma once

#include "render_output.hpp"

#include "anim/animation.hpp"
#include "figures/figure_renderer.hpp" // PaperPage

#include <string>

namespace fv::cli {

// Lesson step N (1-based, checked by the caller) as the app shows it: its model, parameters, start, what
// stands still in the top view, its lower panel and, where it has a setup B, compare mode; all from the
// lessons file (app/gui/lessons.json) the app reads. `animate --lesson N` and `render --lesson N` start from
// it; the size, title and encoding are the caller's.
anim::Spec lesson_spec(int lesson);

// Checks the output (size, scale, formats, the files in `dir`), then draws and writes; UsageError or
// RuntimeFailure with one line.
void render_lesson(int lesson, const std::string& dir, const PixelSize& size, OutputArgs& output,
                   app::PaperPage paper = app::PaperPage::none, bool caption = false);

} // namespace fv::cli
