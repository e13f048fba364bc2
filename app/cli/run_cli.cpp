// frictionviz's command line (see run_cli.hpp); main.cpp only calls run_cli().
#include "run_cli.hpp"

#include "commands.hpp"
#include "errors.hpp"

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

} // namespace

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
            std::fprintf(stderr, "frictionviz: unknown command '%s'; allowed: %s (see --help)\n", argv[1],
                         names.c_str());
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
        std::fprintf(stderr, "frictionviz: %s (see --help)\n", what.c_str());
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
        std::fprintf(stderr, "frictionviz: %s\n", e.what());
        return kExitUsage;
    } catch (const NumericalFailure& e) {
        // The output is written; this line says what in it is not to be trusted.
        std::fprintf(stderr, "frictionviz: numerical failure: %s\n", e.what());
        return kExitNumerical;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frictionviz: error: %s\n", e.what());
        return kExitFailure;
    }
    return 0;
}

} // namespace fv::cli
