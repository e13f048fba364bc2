// Each subcommand declares its own flags and its own action; main.cpp only lists them.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace fv::cli {

struct Command {
    CLI::App* app = nullptr;   // the parsed subcommand
    std::function<void()> run; // throws UsageError / RuntimeFailure
};

Command add_ratio_command(CLI::App& root);
Command add_sweep_command(CLI::App& root);
Command add_trace_command(CLI::App& root);
Command add_render_command(CLI::App& root);
Command add_gui_command(CLI::App& root);
Command add_fit_command(CLI::App& root);
Command add_animate_command(CLI::App& root);

} // namespace fv::cli
