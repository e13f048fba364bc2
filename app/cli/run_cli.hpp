// The whole command line: parse, validate, run the subcommand, map failures to exit codes. main() is one call
// to run_cli(); the CLI fuzz target (tests/fuzz/fuzz_cli.cpp) calls it with parse_only.
#pragma once

namespace fv::cli {

struct RunOptions {
    // Stop after parsing and validating the arguments (CLI11 parse with every flag's validator, the check
    // for unknown subcommands): no subcommand runs, nothing is computed or written. Help and version texts
    // are still printed. Returns 0 for arguments that would run.
    bool parse_only = false;
};

// Returns the process exit code: 0 success, kExitUsage (2) usage error, kExitFailure (1) runtime failure.
int run_cli(int argc, char** argv, const RunOptions& options = {});

} // namespace fv::cli
