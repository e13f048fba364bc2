// frictionviz's command line (see run_cli.hpp); main.cpp only calls run_cli().
#include "run_cli.hpp"

#include "fv/printable_text.hpp"

#include "commands.hpp"
#include "errors.hpp"
#include "test_hook.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#ifndef FV_VERSION
#define FV_VERSION "dev"
#endif

namespace fv::cli {

namespace {

// The footer of --help and of every SUBCOMMAND --help.
constexpr const char* kExitStatusHelp =
    "Exit status: 0 success; 1 runtime failure (e.g. a file could not be written); 2 usage error (a\n"
    "one-line message naming the flag and the allowed range; nothing is written); 3 numerical failure:\n"
    "a result the solver does not vouch for (steady state not reached, integration failed, or a value\n"
    "that is not finite). With 3 the output is still written, every result with its status (`ok` or the\n"
    "reason: not_converged, integration_failed, non_finite), and stderr names what failed.";

// One line on stderr. Messages quote what the user gave (an argument, a link, a file's text): whatever
// escaped a message's own quoting, control bytes and NUL are shown as \xNN here and the line is bounded, so
// nothing a user or a file gives can drive the terminal or cut the line short.
void say(const std::string& what) {
    std::fprintf(stderr, "frictionviz: %s\n", printable_text(what, 4000).c_str());
}

} // namespace

ResultHooks& result_hooks() {
    static ResultHooks hooks;
    return hooks;
}

int run_cli(int argc, char** argv, const RunOptions& options) {
    CLI::App app{"frictionviz - friction reduction by in-plane vibrations (Tsai & Tseng 2006)",
                 "frictionviz"};
    app.set_version_flag("--version", "frictionviz " FV_VERSION);
    app.require_subcommand(0, 1);
    app.footer(kExitStatusHelp);
    const std::vector<Command> commands{
        add_ratio_command(app), add_sweep_command(app), add_trace_command(app),  add_render_command(app),
        add_gui_command(app),   add_fit_command(app),   add_animate_command(app)};
    for (const auto& c : commands) c.app->footer(kExitStatusHelp);
    // CLI11 would report an unknown subcommand as a missing one; name it instead.
    if (argc > 1 && argv[1][0] != '-') {
        bool known = false;
        std::string names;
        for (const auto& c : commands) {
            known = known || c.app->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + c.app->get_name();
        }
        if (!known) {
            say("unknown command " + quoted_text(argv[1]) + "; allowed: " + names + " (see --help)");
            return kExitUsage;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line that names the flag and what is allowed; CLI11's own exit codes are not ours.
        std::string what = e.what();
        for (char& c : what)
            if (c == '\n') c = ' ';
        say(what + " (see --help)");
        return kExitUsage;
    }
    if (options.parse_only) return 0;
    try {
        bool ran = false;
        for (const auto& c : commands)
            if (c.app->parsed()) c.run(), ran = true;
        // No command: the interactive window (with its defaults).
        if (!ran)
            for (const auto& c : commands)
                if (c.app->get_name() == "gui") c.run();
    } catch (const UsageError& e) {
        say(e.what());
        return kExitUsage;
    } catch (const NumericalFailure& e) {
        // The output is written; this line says what in it is not to be trusted.
        say(std::string("numerical failure: ") + e.what());
        return kExitNumerical;
    } catch (const std::exception& e) {
        say(std::string("error: ") + e.what());
        return kExitFailure;
    }
    return 0;
}

} // namespace fv::cli
