// What an animation shows and how it is encoded: the one description that the command line's `animate`, the
// app's File > Export animation and the encoder (app/anim/) share. Data only; anim/animation.hpp checks it
// (ranges, frame count) and renders it.
#pragma once

#include "fv/lower_panel.hpp"
#include "fv/measurements.hpp"
#include "fv/params.hpp"
#include "fv/setup.hpp"
#include "fv/steady_state.hpp"
#include "fv/top_view_frame.hpp"

#include <optional>
#include <string>

namespace fv {

enum class AnimationFormat { gif, mp4 };
// The format a file name asks for by its extension (.gif, .mp4, any case), if any.
std::optional<AnimationFormat> animation_format(const std::string& path);

// scene: the top view alone over the whole frame. dashboard: the app's picture without its control panel
// (top view, force plot, r_x(zeta)); both under a one-line caption naming the parameters and r_x. compare:
// the app's compare mode, the dashboard with setup B's top view beside A's and both on the plots.
enum class AnimationView { scene, dashboard, compare };

struct AnimationSpec {
    Model model = Model::dahl;
    Params params{0.15, kPi / 2, 2, 1};
    int periods = 2;    // steady periods in the loop
    double fps = 30;    // frames per second
    double speed = 0.5; // vibration periods per second of the animation (slow motion: 2 s per period)
    int width = 960, height = 600; // pixels (MP4: even)
    float scale = 1;               // pixels per logical unit
    AnimationView view = AnimationView::dashboard;
    FrameChoice frame = FrameChoice::body; // what stands still in the top view: the body or the ground
    LowerPanel panel = LowerPanel::curves; // the dashboard's lower-right panel (the app's, a lesson step's)
    AnimationFormat format = AnimationFormat::gif;
    SteadyOptions steady; // the solver behind the caption's r_x and the loop's starting point (its start: the
                          // history that picks between coexisting steady states)
    double vv_m_s = 0;    // > 0: the r_x(zeta) axis also names v_v (as the app does with A and f)
    Setup b =
        compare_default(Setup{}); // the compare view's setup B (its solver options: steady's, B's start)
    std::string title;            // a line above the caption (a lesson step's title); none when empty
    std::optional<MeasurementSet> data; // points on the r_x(zeta) panel (a lesson step's example points)
};

} // namespace fv
