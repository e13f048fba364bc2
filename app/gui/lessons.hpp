// The guided lesson: a sequence of steps, each a setup of the app (model, parameters, start, lower panel,
// speed) with a short text in plain words, the equations behind it and a tip for the teacher. The steps are
// data, app/gui/lessons.json, compiled into the program (app/CMakeLists.txt), so the desktop app, the browser
// build and `animate --lesson` read the same file; docs/lessons.md describes its format. Each step's id is
// also a concept preset (the panel's "Concepts" buttons).
#pragma once

#include "lower_panel.hpp"

#include "fv/measurements.hpp"
#include "fv/params.hpp"
#include "fv/setup.hpp"
#include "fv/steady_state.hpp"   // Start
#include "fv/top_view_frame.hpp" // FrameChoice

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fv::app {

struct LessonSetup {
    Model model = Model::dahl;
    Params params;
    Start start = Start::rest;
    LowerPanel panel = LowerPanel::curves;
    double speed = 0.25;                   // vibration periods per second (kSpeedRange)
    FrameChoice frame = FrameChoice::body; // what stands still in the top view
    std::optional<Setup> b;                // compare mode with this setup B beside the step's; none: off
    // Example points shown on the ratio plot with the step (its "data"; the file's comment says whether they
    // are synthetic). A step without them takes away example points an earlier step showed.
    std::optional<MeasurementSet> data;
};

struct LessonStep {
    std::string id;      // "along": the concept preset's name, letters, digits and '-'
    std::string title;   // "Vibrate along the motion"
    std::string text;    // what to look at, in plain words (no equations)
    std::string details; // the equations, with the paper's numbers (shown on demand)
    std::string tip;     // for the teacher
    LessonSetup setup;
};

// what(): "lessons: step N (ID): what was wrong; allowed: ...".
struct LessonError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The steps of a lessons file's text (the format of lessons.json); every value checked against the range
// table (fv/param_ranges.hpp) and the app's speed range. Throws LessonError.
std::vector<LessonStep> parse_lessons(std::string_view json_text);

// The steps of app/gui/lessons.json, parsed once (the file is checked by tests/test_lessons.cpp, so a bad
// one cannot ship; should it all the same, the program stops with LessonError's message).
const std::vector<LessonStep>& lesson_steps();

// The step with this id (a concept preset), or nullptr.
const LessonStep* find_lesson_step(std::string_view id);

// "1-8": the step numbers a link or flag may give, for messages.
std::string lesson_range_text();

} // namespace fv::app
