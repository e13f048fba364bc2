// libFuzzer target: arbitrary bytes as a session file (app/gui/session.hpp). parse_session must return a
// session whose every value lies in the shared ranges, or throw SessionError with one printable line of
// bounded length ("FILE:LINE:COL: message"). A crash, a sanitizer report (deep nesting once overflowed the
// stack in a message), another exception, an out-of-range value or a raw control byte in a message is a bug.
#include "gui/app_state.hpp"
#include "gui/session.hpp"

#include "fv/printable_text.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "broken guarantee: %s\n", what);
    std::abort();
}

bool in(double v, fv::ParamRange r) {
    return fv::inside(v, r);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const fv::app::Session s = fv::app::parse_session(text, "s.json");
        check(fv::range_error(s.params).empty(), "parameters outside the range table");
        check(in(s.amplitude_um, fv::kAmplitudeRange) && in(s.frequency_khz, fv::kFrequencyRange), "A or f");
        check(in(s.speed, fv::kSpeedRange), "speed");
        check(in(s.view.zoom, fv::kZoomRange) && in(s.view.trail_periods, fv::kTrailRange), "view");
        check(std::isfinite(s.view.pan.x()) && std::isfinite(s.view.pan.y()), "pan");
        check(s.pins.size() <= fv::kMaxPins, "pins");
        for (const fv::PinnedCurve& p : s.pins) {
            check(fv::text_error(p.label, fv::kMaxLabelBytes).empty(), "label");
            check(p.zeta.size() == p.rx.size(), "pin lengths");
            for (double z : p.zeta) check(in(z, fv::kZetaRange), "pin zeta");
            for (double r : p.rx) check(std::isnan(r) || in(r, fv::kRxDataRange), "pin r_x");
        }
    } catch (const fv::app::SessionError& e) {
        const std::string m = e.what();
        check(m.rfind("s.json", 0) == 0, "message without the file");
        check(m.size() < 5000, "message longer than 5000 bytes"); // 1000 bytes shown, each in at most 4
        for (const char c : m)
            check(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control byte in message");
    }
    return 0;
}
