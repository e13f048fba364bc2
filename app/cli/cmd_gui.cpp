// frictionviz gui (also: no subcommand): the interactive app on a platform chosen by name (--platform
// window|headless|auto; --headless is --platform headless): the window, or the same app into an OSMesa buffer
// (scripted tests, screenshots, benchmarks).
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "render_output.hpp"

#include "anim/animation.hpp"
#include "gui/gui_app.hpp"
#include "gui/platform.hpp"
#include "gui/script.hpp"
#include "gui/session_link.hpp"

#include "fv/atomic_file.hpp"
#include "fv/measurements.hpp"
#include "fv/share_link.hpp"
#include "fv/units.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <tuple>

namespace fv::cli {
namespace {

std::string no_window_message(const std::string& why) {
    return "cannot open a window: " + why +
           "; run the app without a window with `frictionviz gui --headless --frames N --screenshot FILE`, "
           "render the figures with `frictionviz render --figure all --out DIR`, or run under `xvfb-run -a "
           "frictionviz gui`";
}

// File > Export animation… in the app: the request the app made (the format by the file's extension), checked
// as `animate` checks its flags and exported by the same code.
app::AnimationExporter animation_exporter() {
    return [](const app::AnimationRequest& r, const std::function<void(int, int)>& progress,
              const std::atomic<bool>& cancel) -> std::string {
        const std::optional<anim::Format> format = anim::format_for_path(r.path);
        if (!format) return "'" + r.path + "': allowed: " + anim::allowed_extensions();
        anim::Spec s = r.spec;
        s.format = *format;
        anim::even_size(s);
        if (std::string why = anim::check_spec(s); !why.empty()) return why;
        if (std::string why = check_writable(r.path); !why.empty()) return why;
        return anim::export_animation(s, r.path, {progress, &cancel});
    };
}

// The starting state from the model, unit and data flags (or a --link), the rest from Fig. 14a's parameters.
template <class Args> void start_from_flags(const Args& a, CLI::App& cmd, app::GuiOptions& o) {
    app::Session& s = o.start;
    const UnitArgs& u = a.model.units;
    if (auto zeta = zeta_of(a.model.zeta_opt, a.model.zeta, u, false)) s.params.zeta = *zeta;
    if (cmd.get_option("--theta")->count()) s.params.theta = a.model.theta_deg * kPi / 180;
    // r_disp from --zss whatever the model: the window can switch to the Dahl model.
    if (auto rdisp = rdisp_of(a.model.rdisp_opt, a.model.rdisp, u, false)) s.params.rdisp = *rdisp;
    if (cmd.get_option("--i")->count()) s.params.i = a.model.i;
    if (cmd.get_option("--model")->count()) s.model = model_of(a.model);
    if (const auto start = given_start(cmd, a.model.solver.start)) s.start = *start;
    // The amplitude and frequency each from a flag or from the link (its amplitude= and frequency=), not
    // both: the two would contradict each other.
    std::string given; // the vibration as given, for a message about the physical view
    if (cmd.get_option("--link")->count() > 0) {
        try {
            const ShareLink link = app::parse_link(a.link);
            for (const auto& [flag, key, value] :
                 {std::tuple{u.amplitude_opt, "amplitude", link.amplitude_um},
                  std::tuple{u.frequency_opt, "frequency", link.frequency_khz}})
                if (value) {
                    if (*flag)
                        throw UsageError(std::string("--") + key + " and --link's " + key +
                                         "= both set the " + key + "; give one of them");
                    given += (given.empty() ? "--link " : " ") + (key + ("=" + shortest_decimal(*value)));
                }
            app::apply_link(link, s);
            // A view value that did not read is ignored (share_link.hpp): said on stderr and in the app.
            for (const std::string& n : link.notices) {
                std::fprintf(stderr, "frictionviz: --link: %s\n", n.c_str());
                o.start_notice += (o.start_notice.empty() ? "--link: " : "; ") + n;
            }
        } catch (const LinkError& e) {
            throw UsageError("--link: " + std::string(e.what()));
        }
    }
    if (*u.amplitude_opt) s.amplitude_um = u.amplitude;
    if (*u.frequency_opt) s.frequency_khz = u.frequency;
    // The window combines a given amplitude or frequency with the default of the other one; the message
    // names the values as they are (a default the user never typed is not blamed on a flag).
    if (const std::string why = units::physical_view_error(s.params, s.amplitude_um, s.frequency_khz);
        !why.empty()) {
        if (*u.amplitude_opt)
            given += (given.empty() ? "" : " ") + ("--amplitude " + shortest_decimal(u.amplitude));
        if (*u.frequency_opt)
            given += (given.empty() ? "" : " ") + ("--frequency " + shortest_decimal(u.frequency));
        const bool default_amplitude = !*u.amplitude_opt && given.find("amplitude=") == std::string::npos;
        throw UsageError((given.empty() ? "" : given + ": ") + why +
                         (default_amplitude ? " (the app's default amplitude; --amplitude sets it)" : ""));
    }
    // Compare mode's B (a link's b.* keys) likewise.
    if (s.compare)
        if (const std::string why = units::physical_view_error(s.b.params, s.amplitude_um, s.frequency_khz);
            !why.empty())
            throw UsageError("--link: setup B: " + why);
    // A malformed data file is a usage error before any window opens.
    if (!a.data.empty()) {
        ReadOptions ro;
        ro.amplitude_um = s.amplitude_um;
        ro.frequency_khz = s.frequency_khz;
        try {
            o.data = read_measurements(a.data, ro);
        } catch (const DataError& e) {
            throw UsageError(e.what()); // FILE:LINE:COL: message
        }
        if (o.data->points.empty()) throw UsageError("--data: " + a.data + " has no data rows");
    }
}

} // namespace

Command add_gui_command(CLI::App& root) {
    struct Args {
        ModelArgs model;
        bool headless = false;
        std::string platform = "auto", size;
        double scale = 0;
        int frames = 0, bench = 0;
        std::string script, screenshot, data, session, link, link_base;
        int lesson = 0;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd = root.add_subcommand("gui", "interactive window (the default when no command is given)");
    a->model.zeta_opt = cmd->add_option("--zeta", a->model.zeta, "initial velocity ratio (or --vb)")
                            ->transform(number_in(kZetaRange));
    cmd->add_option("--theta", a->model.theta_deg, "initial vibration angle in degrees")
        ->transform(number_in(kThetaRange));
    a->model.rdisp_opt = cmd->add_option("--rdisp", a->model.rdisp, "initial displacement ratio (or --zss)")
                             ->transform(number_in(kRdispRange));
    cmd->add_option("--i", a->model.i, "initial Dahl exponent")->transform(number_in(kIRange));
    cmd->add_option("--model", a->model.model, "friction model")->check(CLI::IsMember({"dahl", "rigid"}));
    add_start_option(*cmd, a->model.solver.start,
                     "initial history: rest (the paper's start) or sliding (vibration switched on while "
                     "sliding); it decides the state where two coexist");
    add_unit_options(*cmd, a->model.units, UnitShape::single,
                     "shown in the window (default 0.7 um at 60 kHz, the paper's Sec. 4)");
    cmd->add_option("--data", a->data,
                    "measured r_x to show on the ratio plot: CSV zeta,r_x or vb,r_x [,theta_deg,sigma,label] "
                    "(vb converted with the window's amplitude and frequency)")
        ->check(file_name());
    CLI::Option* session =
        cmd->add_option(
               "--session", a->session,
               "start from a session file (JSON: parameters, model, units, animation, view, data; see "
               "docs/app.md), instead of the model, unit and --data flags")
            ->check(file_name());
    CLI::Option* link =
        cmd->add_option("--link", a->link,
                        "start from a share link, ?zeta=Z&theta=DEG&rdisp=R&i=I&model=dahl|rigid "
                        "(any of the keys; or a URL with that query), instead of the model flags");
    cmd->add_option("--link-base", a->link_base,
                    std::string("the address of the browser version's site, which Copy link puts before the "
                                "share link so that a student can click it (default: the environment's "
                                "FRICTIONVIZ_LINK_BASE, else ") +
                        app::kDefaultLinkBase + ", scripts/serve-web.sh on this machine; docs/web.md)");
    // A session holds the whole state, a link the model and its parameters: flags for the same things
    // would contradict them.
    for (const char* flag : {"--zeta", "--theta", "--rdisp", "--i", "--model", "--start", "--vb", "--zss"}) {
        session->excludes(flag);
        link->excludes(flag);
    }
    for (const char* flag : {"--amplitude", "--frequency", "--data"}) session->excludes(flag);
    session->excludes(link);
    CLI::Option* lesson = add_lesson_option(*cmd, a->lesson, "open the guided lesson at step N");
    lesson->excludes(session);
    lesson->excludes(link);
    cmd->add_option(
           "--platform", a->platform,
           "where the app runs: window, headless (an OSMesa buffer, the same pixels; needs --frames or "
           "--bench) or auto (a window when DISPLAY or WAYLAND_DISPLAY is set, else headless)")
        ->check(CLI::IsMember(app::platform_names()))
        ->capture_default_str();
    cmd->add_flag("--headless", a->headless, "the same as --platform headless");
    cmd->add_option("--size", a->size,
                    "framebuffer size WxH in pixels (default: 1280x800 logical units at the scale)")
        ->check(size_spec());
    cmd->add_option("--scale", a->scale,
                    "UI and drawing scale, pixels per logical unit, in " + scale_range_text() +
                        " (default: the monitor's content scale; 1 headless); --size 2560x1600 --scale 2 is "
                        "the 1280x800 screen at twice the resolution")
        ->transform(number_in({kMinScale, kMaxScale}));
    cmd->add_option("--frames", a->frames, "stop after N frames (fixed 1/60 s per frame)")
        ->check(integer_in(1, 1000000));
    cmd->add_option("--script", a->script,
                    "scripted edits: lines 'FRAME ACTION [VALUE]', ACTION one of: " + app::script_actions() +
                        " (docs/app.md)")
        ->check(file_name());
    cmd->add_option("--screenshot", a->screenshot, "write the last frame to this PNG (with --frames)")
        ->check(file_name());
    cmd->add_option("--bench", a->bench,
                    "benchmark: N frames with a slider changing every frame; prints frame times")
        ->check(integer_in(10, 100000));
    return {
        cmd, [a, cmd] {
            app::GuiOptions o;
            if (a->headless) {
                if (cmd->get_option("--platform")->count() > 0 && a->platform != "headless")
                    throw UsageError("--headless contradicts --platform " + a->platform);
                a->platform = "headless";
            }
            o.platform = a->platform;
            if (!a->size.empty()) {
                const PixelSize sz = parse_size(a->size);
                o.width = sz.w;
                o.height = sz.h;
            }
            o.scale = static_cast<float>(a->scale);
            // The app needs room for its panel and plots (a narrow page has the panel on top, a phone's
            // 390 x 844 included): a logical page of at least 320 x 320.
            if (o.width > 0) {
                const double s = a->scale > 0 ? a->scale : 1;
                if (o.width / s < 320 || o.height / s < 320)
                    throw UsageError("--size " + a->size +
                                     " leaves a page smaller than 320x320 logical "
                                     "units at the scale; allowed: --size at least 320x320 times --scale");
            }
            // Where Copy link points: the flag, the environment, the default (session_link.hpp).
            const char* env_base = std::getenv("FRICTIONVIZ_LINK_BASE");
            o.share.base = !a->link_base.empty()        ? a->link_base
                           : env_base && *env_base != 0 ? std::string(env_base)
                                                        : std::string(app::kDefaultLinkBase);
            if (const std::string why = app::link_base_error(o.share.base); !why.empty())
                throw UsageError((a->link_base.empty() ? "FRICTIONVIZ_LINK_BASE: " : "--link-base: ") + why);
            o.frames = a->frames;
            o.lesson = a->lesson;
            o.bench_frames = a->bench;
            o.script = a->script;
            o.screenshot = a->screenshot;
            if (cmd->get_option("--screenshot")->count() > 0) {
                if (o.frames == 0) throw UsageError("--screenshot needs --frames N (the frame to capture)");
                // A PNG is a file, not terminal output: "-" is not standard output here.
                if (o.screenshot == "-")
                    throw UsageError("--screenshot: give a file name (standard output is not allowed for "
                                     "a PNG; /dev/stdout is, for a pipe)");
                check_out(o.screenshot, "--screenshot");
            }
            // Headless has no one to close it: it needs a number of frames (checked before any context).
            if (app::resolve_platform_name(o.platform) == "headless" && o.frames == 0 && a->bench == 0) {
                if (o.platform == "auto") // no display, and nothing to run headless
                    throw RuntimeFailure(no_window_message("no display (neither DISPLAY nor "
                                                           "WAYLAND_DISPLAY is set)"));
                throw UsageError("--platform headless needs --frames N or --bench N (a headless app has no "
                                 "window to close)");
            }
            if (!a->session.empty()) {
                // Everything from the file (its data read with its A and f): a bad one is a usage error.
                try {
                    app::LoadedSession l = app::load_session(a->session);
                    o.start = l.session;
                    o.data = std::move(l.data);
                    o.session_file = a->session;
                } catch (const app::SessionError& e) {
                    throw UsageError(std::string("--session: ") + e.what());
                }
            } else {
                start_from_flags(*a, *cmd, o);
            }
            o.animation_exporter = animation_exporter();
            try {
                const int rc = app::run_gui(o);
                if (rc != 0) throw RuntimeFailure("the window closed with an error");
            } catch (const UsageError&) {
                throw;
            } catch (const std::exception& e) {
                const std::string what = e.what();
                if (what.find("display") != std::string::npos) throw RuntimeFailure(no_window_message(what));
                if (what.find(a->script) == 0 && !a->script.empty()) throw UsageError("--script: " + what);
                throw RuntimeFailure(what);
            }
        }};
}

} // namespace fv::cli
