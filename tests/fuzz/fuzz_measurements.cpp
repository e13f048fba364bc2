// libFuzzer target: arbitrary bytes as the contents of a measurements CSV file, read with several
// ReadOptions. fv::DataError is the reader's only way to reject a file; any other exception, a sanitizer
// report, or a result that breaks the documented guarantees (measurements.hpp) is a bug.
#include "fv/measurements.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz_measurements: broken guarantee: %s\n", what);
        std::abort();
    }
}

void read_with(std::string_view text, const fv::ReadOptions& opt) {
    try {
        const fv::MeasurementSet set = fv::parse_measurements(text, "fuzz.csv", opt);
        check(!set.points.empty(), "a set without rows was accepted");
        check(set.points.size() <= opt.max_rows, "more rows than max_rows");
        for (const fv::Measurement& m : set.points) {
            check(std::isfinite(m.zeta) && m.zeta >= 0 && m.zeta <= fv::kMaxZeta, "zeta outside [0, 100]");
            check(std::isfinite(m.rx) && m.rx >= fv::kMinRx && m.rx <= fv::kMaxRx, "r_x outside [-0.5, 1.5]");
            check(m.theta_deg.has_value() == set.has_theta, "theta_deg on some rows only");
            check(m.sigma.has_value() == set.has_sigma, "sigma on some rows only");
            if (m.theta_deg) check(*m.theta_deg >= 0 && *m.theta_deg <= 180, "theta_deg outside [0, 180]");
            if (m.sigma) check(std::isfinite(*m.sigma) && *m.sigma > 0, "sigma not finite and > 0");
            check(m.label.find(',') == std::string::npos, "label with a comma");
            check(m.line >= 1, "row without a line number");
        }
    } catch (const fv::DataError& e) {
        check(e.file == "fuzz.csv", "DataError names another file");
        check(e.line >= 1 && e.column >= 1, "DataError without a 1-based line and column");
        check(!e.message.empty(), "DataError without a message");
        const std::string what = e.what();
        check(what.find('\n') == std::string::npos && what.find('\r') == std::string::npos,
              "DataError message is not one line");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fv::ReadOptions defaults;
    read_with(text, defaults);

    fv::ReadOptions vb; // a vb column converts to zeta
    vb.amplitude_um = 2.0;
    vb.frequency_khz = 40.0;
    read_with(text, vb);

    fv::ReadOptions tiny_velocity; // v_v tiny: most vb values overflow the zeta range
    tiny_velocity.amplitude_um = 1e-300;
    tiny_velocity.frequency_khz = 1e-300;
    read_with(text, tiny_velocity);

    fv::ReadOptions small; // every limit within reach of short inputs
    small.amplitude_um = 1.0;
    small.frequency_khz = 1.0;
    small.max_rows = 2;
    small.max_line_bytes = 24;
    small.max_file_bytes = 64;
    read_with(text, small);

    fv::ReadOptions zero; // degenerate limits
    zero.max_rows = 0;
    zero.max_line_bytes = 0;
    zero.max_file_bytes = 0;
    read_with(text, zero);
    return 0;
}
