// Runs the real executable through the shell for the command-line tests: its exit code and its stderr, stdout
// discarded, stdin empty; a scratch directory per test program.
#pragma once

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fv::test {

struct Run {
    int code;
    std::string err;
};

// A directory made once per process, /tmp/PREFIX-XXXXXX (the prefix of the first call).
inline const std::string& scratch_dir(const char* prefix) {
    static const std::string r = [prefix] {
        std::string tmpl = std::string("/tmp/") + prefix + "-XXXXXX";
        return std::string(::mkdtemp(tmpl.data()));
    }();
    return r;
}

// `command_line` (program and arguments, shell syntax) with stderr captured in DIR/stderr.
inline Run run_command(const std::string& command_line, const std::string& dir) {
    const std::string e = dir + "/stderr";
    const int status = std::system((command_line + " >/dev/null 2>" + e + " </dev/null").c_str());
    std::ifstream f(e);
    std::stringstream ss;
    ss << f.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

} // namespace fv::test
