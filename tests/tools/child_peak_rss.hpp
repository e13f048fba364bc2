// Runs a program as a child process and reports its own peak resident set size (wait4's rusage, which
// counts that child alone, unlike getrusage(RUSAGE_CHILDREN), the largest of all children waited for) and
// its wall time. Used by the render memory test (tests/reliability) and benchmark (bench/render_memory.cpp).
#pragma once

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <string>
#include <vector>

namespace fv::testing {

struct ChildRun {
    int exit_code = -1;     ///< -1 when the child could not start or did not exit normally
    long peak_rss_kb = 0;   ///< ru_maxrss of the child, KiB
    double seconds = 0;     ///< wall time
    double cpu_seconds = 0; ///< user + system time of the child (its threads summed)
};

/// argv[0] is the program's path. The child's stdout goes to /dev/null; its stderr stays.
inline ChildRun run_child(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& s : argv) args.push_back(const_cast<char*>(s.c_str()));
    args.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) return {};
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, STDOUT_FILENO);
        execv(args[0], args.data());
        _exit(127);
    }
    int status = 0;
    rusage ru{};
    while (wait4(pid, &status, 0, &ru) < 0)
        if (errno != EINTR) return {};
    ChildRun r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.peak_rss_kb = ru.ru_maxrss;
    r.cpu_seconds = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                    1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// "ID,ID,...": the same figure id `count` times, for `render --figure`.
inline std::string repeated_figure(const std::string& id, int count) {
    std::string s;
    for (int k = 0; k < count; ++k) s += (k ? "," : "") + id;
    return s;
}

} // namespace fv::testing
