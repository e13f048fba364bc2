// frictionviz animate: the periodic steady state as a seamless loop, an animated GIF or an H.264 MP4
// (anim/animation.hpp), rendered headless. Every flag is checked before anything is computed or written.
#include "commands.hpp"
#include "errors.hpp"
#include "lesson_render.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "render_output.hpp"

#include "anim/animation.hpp"

#include "fv/lower_panel.hpp"
#include "fv/units.hpp"

#include <cstdio>
#include <memory>
#include <unistd.h>

namespace fv::cli {
namespace {

// "animate  [##########..........]  60/120 frames" on one terminal line, redrawn in place.
void draw_progress(int done, int total) {
    constexpr int kWidth = 30;
    const int filled = total > 0 ? done * kWidth / total : kWidth;
    std::fprintf(stderr, "\ranimate  [%.*s%.*s]  %d/%d frames", filled, "##############################",
                 kWidth - filled, "..............................", done, total);
    if (done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
}

} // namespace

Command add_animate_command(CLI::App& root) {
    struct Args {
        ModelArgs model;
        std::string out, view = "dashboard", size = "960x600", frame = "body", panel = "curves";
        int periods = 2, lesson = 0;
        double fps = 30, speed = 0.5, scale = 1;
        // --view compare's setup B: each flag as A's; left out, compare_default's (A's, the other angle).
        double b_zeta = 0, b_theta = 0, b_rdisp = 0, b_i = 0;
        std::string b_model, b_start;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd = root.add_subcommand(
        "animate", "the steady state as a seamless looping animation: an animated GIF or an H.264 MP4");
    add_model_options(*cmd, a->model, true);
    add_unit_options(*cmd, a->model.units, UnitShape::single,
                     "A and f also put v_v on the r_x(zeta) axis (as in the app)");
    // --lesson N stands for the model flags: --theta is required only without it (checked below).
    cmd->get_option("--theta")->required(false);
    add_lesson_option(*cmd, a->lesson, "the setup of guided lesson step N");
    cmd->add_option("--out", a->out,
                    std::string("the animation: ") + anim::allowed_extensions() +
                        " (by the extension), written atomically; a symbolic link is followed and its target "
                        "replaced")
        ->required();
    cmd->add_option("--periods", a->periods,
                    "steady vibration periods in the loop (the frame after the last is the first)")
        ->check(integer_in(anim::kMinPeriods, anim::kMaxPeriods))
        ->capture_default_str();
    cmd->add_option("--fps", a->fps, "frames per second, in [1, 60] (GIF: [1, 50])")
        ->transform(number_in({anim::kMinFps, anim::kMaxFps}))
        ->capture_default_str();
    cmd->add_option("--speed", a->speed,
                    "vibration periods per second of the animation, in [0.05, 10] (slow motion; the app's "
                    "speed slider); a period takes fps/speed frames")
        ->transform(number_in({anim::kMinSpeed, anim::kMaxSpeed}))
        ->capture_default_str();
    cmd->add_option("--size", a->size, "frame size WxH in pixels (MP4: rounded up to even numbers)")
        ->check(size_spec())
        ->capture_default_str();
    cmd->add_option("--scale", a->scale,
                    "pixels per logical unit, in " + scale_range_text() +
                        ": --size 1920x1200 --scale 2 is the 960x600 picture at twice the resolution")
        ->transform(number_in({kMinScale, kMaxScale}))
        ->capture_default_str();
    cmd->add_option("--view", a->view,
                    "scene: the top view alone, full frame; dashboard: the app's picture without its control "
                    "panel (top view, force plot, r_x(zeta)); compare: the dashboard with setup B's top view "
                    "beside A's and both on the plots (the app's compare mode; --b-* set B); all under a "
                    "caption with the parameters")
        ->check(CLI::IsMember({"scene", "dashboard", "compare"}))
        ->capture_default_str();
    // Setup B of --view compare (the app's compare mode): any of these implies it.
    const std::string b_help = " of setup B (--view compare); default: A's";
    cmd->add_option("--b-zeta", a->b_zeta, "zeta" + b_help)->transform(number_in(kZetaRange));
    cmd->add_option("--b-theta", a->b_theta,
                    "angle in degrees of setup B (--view compare); default: 90, or 0 when A's is 90")
        ->transform(number_in(kThetaRange));
    cmd->add_option("--b-rdisp", a->b_rdisp, "r_disp" + b_help)->transform(number_in(kRdispRange));
    cmd->add_option("--b-i", a->b_i, "Dahl exponent i" + b_help)->transform(number_in(kIRange));
    cmd->add_option("--b-model", a->b_model, "dahl or rigid" + b_help)
        ->check(CLI::IsMember({"dahl", "rigid"}));
    cmd->add_option("--b-start", a->b_start, "rest or sliding" + b_help)
        ->check(CLI::IsMember({"rest", "sliding"}));
    cmd->add_option("--frame", a->frame,
                    "what stands still in the top view: body (the camera moves with the body, the floor "
                    "slides past) or ground (the floor stands still, a stuck tip T too; the body drifts "
                    "through and wraps round at the edges)")
        ->check(CLI::IsMember({"body", "ground"}))
        ->capture_default_str();
    cmd->add_option(
           "--panel", a->panel,
           "the dashboard's lower-right panel, as the app's: curves (r_x(zeta)), map (the (zeta, theta) "
           "map of r_x, Dahl model; a few seconds more), loop (the asperity's hysteresis) or why (the "
           "mechanism, the paper's Fig. 4) or setup (the experiment: a block pressed on a floor, pulled and "
           "shaken at theta); not with --view scene")
        ->check(CLI::IsMember(panel_name_list()))
        ->capture_default_str();
    return {
        cmd, [a, cmd] {
            const std::optional<anim::Format> format = anim::format_for_path(a->out);
            if (!format)
                throw UsageError("--out: '" + a->out +
                                 "' has no known extension; allowed: " + anim::allowed_extensions());
            anim::Spec s;
            s.format = *format;
            if (a->lesson == 0 && cmd->get_option("--theta")->count() == 0)
                throw UsageError("--theta is required (or --lesson N: a lesson step's setup)");
            s.steady = steady_options(a->model);
            // A lesson step's setup as the app shows it; each flag given replaces its part.
            const std::optional<anim::Spec> lesson =
                a->lesson > 0 ? std::optional<anim::Spec>(lesson_spec(a->lesson)) : std::nullopt;
            if (lesson) {
                s.model = lesson->model;
                s.params = lesson->params;
                s.steady.start = lesson->steady.start;
            } else {
                s.model = model_of(a->model);
                s.params = to_params(a->model);
            }
            const Vibration v =
                vibration_of(a->model.units, s.model == Model::dahl ? std::vector<double>{s.params.rdisp}
                                                                    : std::vector<double>{});
            if (v.amplitude_um && v.frequency_khz)
                s.vv_m_s = units::vibration_velocity(*v.amplitude_um, *v.frequency_khz);
            s.periods = a->periods;
            s.fps = a->fps;
            s.speed = a->speed;
            s.view = a->view == "scene"     ? anim::View::scene
                     : a->view == "compare" ? anim::View::compare
                                            : anim::View::dashboard;
            bool b_given = false;
            for (const char* f : {"--b-zeta", "--b-theta", "--b-rdisp", "--b-i", "--b-model", "--b-start"})
                b_given = b_given || cmd->get_option(f)->count() > 0;
            if (b_given && cmd->get_option("--view")->count() > 0 && s.view != anim::View::compare)
                throw UsageError("--b-zeta, --b-theta, --b-rdisp, --b-i, --b-model and --b-start are setup B "
                                 "of --view compare; allowed with --view compare (or without --view)");
            if (b_given) s.view = anim::View::compare;
            s.b = compare_default({s.model, s.params, s.steady.start});
            if (cmd->get_option("--b-zeta")->count()) s.b.params.zeta = a->b_zeta;
            if (cmd->get_option("--b-theta")->count()) s.b.params.theta = a->b_theta * kPi / 180;
            if (cmd->get_option("--b-rdisp")->count()) s.b.params.rdisp = a->b_rdisp;
            if (cmd->get_option("--b-i")->count()) s.b.params.i = a->b_i;
            if (cmd->get_option("--b-model")->count()) s.b.model = *parse_model(a->b_model);
            if (cmd->get_option("--b-start")->count()) parse_start(a->b_start, s.b.start);
            s.frame = parse_frame(a->frame).value_or(FrameChoice::body);
            if (lesson && cmd->get_option("--frame")->count() == 0) s.frame = lesson->frame; // unless asked
            s.panel = panel_from_name(a->panel).value_or(LowerPanel::curves);
            if (lesson && cmd->get_option("--panel")->count() == 0) s.panel = lesson->panel;
            // A lesson step with compare mode shows it, unless another view is asked for.
            if (lesson && lesson->view == anim::View::compare && cmd->get_option("--view")->count() == 0 &&
                !b_given)
                s.view = anim::View::compare, s.b = lesson->b;
            if (s.view == anim::View::scene && cmd->get_option("--panel")->count() > 0)
                throw UsageError(
                    "--panel " + a->panel +
                    ": not with --view scene (the top view alone); allowed with --view dashboard "
                    "or compare");
            const PixelSize sz = parse_size(a->size);
            s.width = sz.w;
            s.height = sz.h;
            s.scale = static_cast<float>(a->scale);
            anim::even_size(s);
            OutputArgs page; // the page checks of render: --size / --scale within 320x240 .. 7680x4320
            page.scale = a->scale;
            check_output_args(page, s.width, s.height);
            if (const std::string why = anim::check_spec(s); !why.empty()) throw UsageError(why);
            check_out(a->out, "--out");
            if (s.width != sz.w || s.height != sz.h)
                std::fprintf(stderr, "animate: an MP4 needs an even size: %dx%d\n", s.width, s.height);
            anim::Progress progress;
            if (::isatty(STDERR_FILENO)) progress.report = draw_progress;
            std::string err;
            try {
                err = anim::export_animation(s, a->out, progress);
            } catch (const std::runtime_error& e) {
                err = e.what();
            }
            if (!err.empty()) throw RuntimeFailure(err);
        }};
}

} // namespace fv::cli
