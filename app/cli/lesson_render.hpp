// render --lesson N: a guided lesson step's picture for a slide or a handout, a frame
// (anim::Frames::still_frame) of what `animate --lesson N` plays (top view, force plot, r_x(zeta) at the
// step's setup and frame) under the step's title and a caption naming the parameters, as
// lesson-N.png/.svg/.pdf (--format) with lesson-N.json beside it (the step's title, its plain-words text and
// the share link that opens the step).
#pragma once

#include "render_output.hpp"

#include <string>

namespace fv::cli {

// Checks the output (size, scale, formats, the files in `dir`), then draws and writes; UsageError or
// RuntimeFailure with one line.
void render_lesson(int lesson, const std::string& dir, const PixelSize& size, OutputArgs& output);

} // namespace fv::cli
