// libFuzzer target for the share link (fv/share_link.hpp): bytes as a link, the query of a page's address or
// `gui --link`. Broken guarantees abort (and so count as crashes):
//   - parse_share_link returns or throws LinkError, nothing else; its message and every notice are one line
//     starting "column N: ";
//   - what it returns is inside the shared ranges (at most kMaxPins pins);
//   - the link written back from what it returned (share_link's keys and view_link_keys) reads back as the
//     same values, with no notice.
#include "fv/param_ranges.hpp"
#include "fv/share_link.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "broken guarantee: %s\n", what.c_str());
    std::abort();
}

void check(bool ok, const char* what) {
    if (!ok) broken(what);
}

void one_line(const std::string& m, const char* what) {
    check(m.rfind("column ", 0) == 0 && m.find_first_of("\r\n") == std::string::npos, what);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // A reader with 8 lesson steps, as the app's (the count is the app's data; any positive one will do).
    constexpr int kSteps = 8;
    fv::ShareLink l;
    try {
        l = fv::parse_share_link(text, kSteps);
    } catch (const fv::LinkError& e) {
        one_line(e.what(), "a LinkError is one line 'column N: ...'");
        return 0;
    } catch (...) {
        broken("an exception other than LinkError");
    }
    for (const std::string& n : l.notices) one_line(n, "a notice is one line 'column N: ...'");
    if (l.speed) check(fv::inside(*l.speed, fv::kSpeedRange), "speed in range");
    if (l.amplitude_um) check(fv::inside(*l.amplitude_um, fv::kAmplitudeRange), "amplitude in range");
    if (l.frequency_khz) check(fv::inside(*l.frequency_khz, fv::kFrequencyRange), "frequency in range");
    if (l.trail_periods) check(fv::inside(*l.trail_periods, fv::kTrailRange), "trail in range");
    if (l.zoom) check(fv::inside(*l.zoom, fv::kZoomRange), "zoom in range");
    if (l.pan)
        check(fv::inside((*l.pan)[0], fv::kPanRange) && fv::inside((*l.pan)[1], fv::kPanRange),
              "pan in range");
    if (l.lesson) check(*l.lesson >= 1 && *l.lesson <= kSteps, "lesson within the steps");
    if (l.pins) {
        check(!l.pins->empty() && l.pins->size() <= fv::kMaxPins, "1 to kMaxPins pins");
        for (const fv::PinSource& p : *l.pins)
            check(fv::inside(p.theta * 180 / fv::kPi, fv::kThetaRange) &&
                      fv::inside(p.rdisp, fv::kRdispRange) && fv::inside(p.i, fv::kIRange),
                  "a pin's parameters in range");
    }
    // The view written back reads back as itself.
    fv::ShareLink view;
    view.panel = l.panel;
    view.presentation = l.presentation;
    view.speed = l.speed;
    view.pins = l.pins;
    view.lesson = l.lesson;
    view.amplitude_um = l.amplitude_um;
    view.frequency_khz = l.frequency_khz;
    view.playing = l.playing;
    view.trail_periods = l.trail_periods;
    view.zoom = l.zoom;
    view.pan = l.pan;
    view.follow = l.follow;
    const fv::ShareLink again = fv::parse_share_link("?model=dahl" + fv::view_link_keys(view), kSteps);
    check(again.notices.empty(), "the view written back reads without notices");
    check(again.panel == l.panel && again.presentation == l.presentation && again.speed == l.speed,
          "panel, presentation and speed read back");
    check(again.pins.has_value() == l.pins.has_value() && (!l.pins || again.pins->size() == l.pins->size()),
          "the pins read back");
    check(again.lesson == l.lesson, "the lesson step reads back");
    check(again.amplitude_um == l.amplitude_um && again.frequency_khz == l.frequency_khz,
          "amplitude and frequency read back");
    check(again.playing == l.playing && again.trail_periods == l.trail_periods && again.zoom == l.zoom &&
              again.pan == l.pan && again.follow == l.follow,
          "play, trail, zoom, pan and follow read back");
    return 0;
}
