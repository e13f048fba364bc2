// libFuzzer target: arbitrary bytes as an app script (app/gui/script.hpp), written to a scratch file and
// loaded; every frame it names is turned into edits. load_script must return a script or throw
// std::runtime_error with one printable line; the edits of a loaded script hold only values inside the
// shared ranges. A crash, a sanitizer report, another exception or a value out of range is a bug.
#include "gui/app_state.hpp"
#include "gui/script.hpp"

#include "fv/param_ranges.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace {

void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "broken guarantee: %s\n", what);
    std::abort();
}

const std::string& scratch() {
    static const std::string dir = [] {
        char tmpl[] = "/tmp/fv-fuzz-script-XXXXXX";
        return std::string(::mkdtemp(tmpl));
    }();
    return dir;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = scratch() + "/script.txt";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        const fv::app::Script s = fv::app::load_script(path);
        const fv::app::UiState ui;
        for (const auto& [frame, entries] : s.lines) {
            check(frame >= 0, "negative frame");
            const fv::app::UiEdits e = fv::app::script_edits(s, frame, ui);
            if (e.params) check(fv::range_error(*e.params).empty(), "parameters outside the range table");
            if (e.speed) check(fv::inside(*e.speed, fv::kSpeedRange), "speed");
            if (e.trail_periods) check(fv::inside(*e.trail_periods, fv::kTrailRange), "trail");
            if (e.amplitude_um) check(fv::inside(*e.amplitude_um, fv::kAmplitudeRange), "amplitude");
            if (e.frequency_khz) check(fv::inside(*e.frequency_khz, fv::kFrequencyRange), "frequency");
            if (e.vb_m_s) check(fv::inside(*e.vb_m_s, fv::kVbRange), "vb");
            if (e.zss_um) check(fv::inside(*e.zss_um, fv::kZssRange), "zss");
            if (e.rewind) check(std::isfinite(*e.rewind) && *e.rewind >= 0, "rewind");
        }
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        check(m.size() < 5000, "message longer than 5000 bytes"); // 1000 bytes shown, each in at most 4
        for (const char c : m)
            check(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control byte in message");
    }
    return 0;
}
