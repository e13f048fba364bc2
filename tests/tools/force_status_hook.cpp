// frictionviz with the test hooks of app/cli/test_hook.hpp installed: FV_TEST_FORCE_STATUS=REASON[@ZETA]
// marks results as failed after they were computed. REASON is not_converged, integration_failed or non_finite
// (the last also sets r_x and r_y to NaN, as a real non-finite result would show). Unset or empty: nothing
// happens. Any other value is a usage error, so that a typo in a test cannot pass silently. Built with the
// tests only (tests/CMakeLists.txt: frictionviz_forced); tests/test_cli.cpp and the reliability tests run it.
#include "cli/errors.hpp"
#include "cli/run_cli.hpp"
#include "cli/test_hook.hpp"

#include "fv/atomic_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

namespace fv::cli {
namespace {

struct Forced {
    SteadyStatus status = SteadyStatus::converged;
    std::optional<double> zeta;
};

// Read on every call: cheap next to any steady state, and no state to go stale.
std::optional<Forced> forced() {
    const char* env = std::getenv("FV_TEST_FORCE_STATUS");
    if (!env || !*env) return std::nullopt;
    const std::string v = env;
    const std::size_t at = v.find('@');
    const std::string reason = v.substr(0, at);
    Forced f;
    if (reason == "not_converged")
        f.status = SteadyStatus::not_converged;
    else if (reason == "integration_failed")
        f.status = SteadyStatus::integration_failed;
    else if (reason == "non_finite")
        f.status = SteadyStatus::non_finite;
    else
        throw UsageError("FV_TEST_FORCE_STATUS: unknown reason '" + reason +
                         "'; allowed: not_converged, integration_failed, non_finite");
    if (at != std::string::npos) {
        const std::string z = v.substr(at + 1);
        char* end = nullptr;
        const double zeta = std::strtod(z.c_str(), &end);
        if (z.empty() || *end || !std::isfinite(zeta))
            throw UsageError("FV_TEST_FORCE_STATUS: '" + z + "' after '@' is not a number (zeta)");
        f.zeta = zeta;
    }
    return f;
}

void apply(const Forced& f, SweepPoint& row) {
    if (f.zeta && !(std::abs(row.params.zeta - *f.zeta) <= 1e-9)) return;
    row.result.status = f.status;
    if (f.status == SteadyStatus::non_finite)
        row.result.rx = row.result.ry = std::numeric_limits<double>::quiet_NaN();
}

void force_row(SweepPoint& row) {
    if (const auto f = forced()) apply(*f, row);
}

void force_table(TableData& table) {
    const auto f = forced();
    if (!f) return;
    for (SweepPoint& r : table.ratios) apply(*f, r);
    if (!table.trace.empty() && !f->zeta) table.status = f->status;
}

void force_fit(FitResult& fit) {
    if (!forced()) return;
    for (FitCandidate& c : fit.candidates) c.unsteady = c.evaluations;
    fit.best.unsteady = fit.best.evaluations;
}

} // namespace
} // namespace fv::cli

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // as app/main.cpp
    fv::install_interrupt_cleanup();
    fv::cli::result_hooks() = {fv::cli::force_row, fv::cli::force_table, fv::cli::force_fit};
    return fv::cli::run_cli(argc, argv);
}
