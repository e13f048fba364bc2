#include "output.hpp"

#include "errors.hpp"

#include "fv/atomic_file.hpp"

#include <cstdio>
#include <iostream>

namespace fv::cli {

CLI::Option* add_out_option(CLI::App& cmd, std::string& out) {
    out = "-";
    return cmd.add_option("--out", out,
                          "write to FILE instead of standard output (-), atomically; a symbolic link is "
                          "followed and its target replaced, a device or FIFO is written directly");
}

void check_out(const std::string& out, const char* flag) {
    if (out == "-") return;
    if (out.empty())
        throw UsageError(std::string(flag) + ": empty path; give a file name, or - for standard output");
    if (auto why = check_writable(out); !why.empty()) throw UsageError(std::string(flag) + ": " + why);
}

void check_out_dir(const std::string& dir, const char* flag) {
    if (auto why = check_output_dir(dir); !why.empty()) throw UsageError(std::string(flag) + ": " + why);
}

void deliver(const std::string& content, const std::string& out) {
    if (out == "-") {
        std::cout << content << std::flush;
        if (!std::cout) throw RuntimeFailure("cannot write to standard output");
        return;
    }
    if (auto why = write_file_atomic(out, content); !why.empty()) throw RuntimeFailure(why);
}

namespace {
constexpr SteadyStatus kFailureKinds[] = {SteadyStatus::not_converged, SteadyStatus::integration_failed,
                                          SteadyStatus::non_finite};
} // namespace

void FailureLog::add(const std::vector<SweepPoint>& rows) {
    for (const auto& r : rows) {
        const SteadyStatus st = status_of(r);
        if (ok(st)) continue;
        for (int k = 0; k < 3; ++k) counts_[k] += kFailureKinds[k] == st;
        ++total_;
        if (first_.size() < 10) first_.push_back(r);
    }
}

Failures FailureLog::failures() const {
    Failures f;
    for (int k = 0; k < 3; ++k) {
        if (counts_[k] == 0) continue;
        f.count += counts_[k];
        f.by_reason += (f.by_reason.empty() ? "" : ", ") + std::string(to_string(kFailureKinds[k])) + " " +
                       std::to_string(counts_[k]);
    }
    return f;
}

void FailureLog::print(const std::string& prefix, int max_lines) const {
    int shown = 0;
    for (const auto& r : first_)
        if (shown < max_lines) {
            std::fprintf(stderr, "frictionviz: %sfailed: %s\n", prefix.c_str(), describe_failure(r).c_str());
            ++shown;
        }
    if (total_ > shown)
        std::fprintf(stderr, "frictionviz: %s... and %lld more failed\n", prefix.c_str(), total_ - shown);
}

Failures failures_of(const std::vector<SweepPoint>& rows) {
    FailureLog log;
    log.add(rows);
    return log.failures();
}

void print_failures(const std::vector<SweepPoint>& rows, const std::string& prefix, int max_lines) {
    FailureLog log;
    log.add(rows);
    log.print(prefix, max_lines);
}

} // namespace fv::cli
