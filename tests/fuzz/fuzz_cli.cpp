// libFuzzer target: arbitrary bytes as a frictionviz command line. The bytes are split on NUL and space into
// at most kMaxArgs arguments (empty ones kept, as a shell can pass them) and handed to fv::cli::run_cli with
// parse_only: CLI11 parsing, every flag's validator and the unknown-command check run, no subcommand does
// (nothing is computed, rendered or written). A crash, a sanitizer report, an escaping exception or an exit
// code other than 0 (would run) or 2 (usage error) is a bug.
#include "cli/errors.hpp"
#include "cli/run_cli.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {
constexpr std::size_t kMaxArgs = 24;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"frictionviz"};
    std::string cur;
    bool pending = false;
    for (std::size_t k = 0; k < size && args.size() < kMaxArgs + 1; ++k) {
        const char c = static_cast<char>(data[k]);
        if (c == '\0' || c == ' ') {
            args.push_back(cur);
            cur.clear();
            pending = false;
        } else {
            cur += c;
            pending = true;
        }
    }
    if (pending && args.size() < kMaxArgs + 1) args.push_back(cur);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    fv::cli::RunOptions options;
    options.parse_only = true;
    const int rc = fv::cli::run_cli(static_cast<int>(args.size()), argv.data(), options);
    if (rc != 0 && rc != fv::cli::kExitUsage) {
        std::fprintf(stderr, "fuzz_cli: exit code %d from parsing alone\n", rc);
        std::abort();
    }
    return 0;
}
