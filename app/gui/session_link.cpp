#include "session_link.hpp"

#include "lessons.hpp"

#include "fv/live_panels.hpp" // ratio_zeta_max
#include "fv/printable_text.hpp"

namespace fv::app {

std::string link_base_error(const std::string& base) {
    const bool http = base.rfind("http://", 0) == 0 || base.rfind("https://", 0) == 0;
    if (!http || base.size() > 2000 || base.find_first_of("?# ") != std::string::npos ||
        printable_text(base, 2000) != base)
        return "link base " + quoted_text(base) +
               " is not a site address; allowed: http:// or https:// and a path, no '?', '#' or spaces, e.g. "
               "https://example.org/frictionviz/";
    return "";
}

namespace {

// What a link with lesson=N sets up before its own keys (the step's setup and compare mode, lessons.json);
// the link of a state in a lesson says what differs from this.
void set_up_lesson(int step, SessionState& s) {
    const LessonSetup& u = lesson_steps()[static_cast<std::size_t>(step - 1)].setup;
    s.model = u.model, s.params = u.params, s.start = u.start;
    s.panel = u.panel, s.speed = u.speed, s.view.frame = u.frame;
    s.lesson = step;
    s.compare = u.b.has_value(); // compare mode as the step has it
    if (u.b) s.b = *u.b;
}

} // namespace

std::string session_link(const SessionState& s) {
    // What the link's reader starts from: the app's defaults, or a lesson step's setup over them.
    const SessionState defaults;
    SessionState base = defaults;
    if (s.lesson != 0) set_up_lesson(s.lesson, base);
    ShareLink view;
    // A field is written where it differs from the app's default (so a default setup's link stays the five
    // keys, and a lesson's link states its view whatever lessons.json says another day) or from what the
    // reader starts from (a lesson step's value, where the state has the default).
    const auto written = [&](const auto& get) { return get(s) != get(defaults) || get(s) != get(base); };
    const auto differs = [&](auto& slot, const auto& get) {
        if (written(get)) slot = get(s);
    };
    using S = const SessionState&;
    differs(view.amplitude_um, [](S t) { return t.amplitude_um; });
    differs(view.frequency_khz, [](S t) { return t.frequency_khz; });
    differs(view.panel, [](S t) { return t.panel; });
    differs(view.presentation, [](S t) { return t.presentation; });
    differs(view.speed, [](S t) { return t.speed; });
    differs(view.playing, [](S t) { return t.playing; });
    differs(view.trail_periods, [](S t) { return t.view.trail_periods; });
    differs(view.zoom, [](S t) { return t.view.zoom; });
    differs(view.follow, [](S t) { return t.view.follow; });
    if (written([](S t) { return std::array<double, 2>{t.view.pan.x(), t.view.pan.y()}; }))
        view.pan = std::array<double, 2>{s.view.pan.x(), s.view.pan.y()};
    std::vector<PinSource> pins;
    for (const PinnedCurve& p : s.pins)
        if (p.source) pins.push_back(*p.source);
    if (!pins.empty()) view.pins = std::move(pins);
    if (s.lesson != 0) view.lesson = s.lesson;
    // share_link writes the start and the frame only when they are not the defaults (rest, body); a lesson
    // step may have the other one, and compare mode's B starts from A's start (compare_default) or the
    // step's B: say the default where the reader would otherwise take another.
    std::string link = share_link(s.model, s.params, s.start, s.view.frame);
    if (s.start != base.start && s.start == Start::rest) link += "&start=rest";
    if (s.view.frame != base.view.frame && s.view.frame == FrameChoice::body) link += "&frame=body";
    if (s.compare) {
        link += compare_link_keys(s.b.model, s.b.params, s.b.start);
        const Start b_start = base.compare ? base.b.start : s.start;
        if (s.b.start != b_start && s.b.start == Start::rest) link += "&b.start=rest";
    } else if (base.compare) {
        link += "&compare=0"; // the step's compare mode turned off
    }
    return link + view_link_keys(view);
}

std::string share_address(const ShareAddress& where, const SessionState& s) {
    return where.base + session_link(s);
}

std::size_t pins_not_in_link(const SessionState& s) {
    std::size_t n = 0;
    for (const PinnedCurve& p : s.pins) n += p.source ? 0 : 1;
    return n;
}

ShareLink parse_link(std::string_view text) {
    return parse_share_link(text, static_cast<int>(lesson_steps().size()));
}

void apply_link(const ShareLink& link, Session& s) {
    if (link.lesson) set_up_lesson(*link.lesson, s);
    apply_share_link(link, s.model, s.params, s.start, s.view.frame);
    // compare=0: compare mode off (a lesson step's). Any of B's keys (or compare=1): compare mode, B's keys
    // over the step's B, or over A (as the link left it) at the other angle.
    if (link.compare == false) s.compare = false;
    if (link.b.any() || link.compare == true) {
        if (!s.compare) s.b = compare_default(s.a());
        s.compare = true;
        apply_share_link(link.b, s.b.model, s.b.params, s.b.start);
    }
    const auto given = [](auto& field, const auto& slot) {
        if (slot) field = *slot;
    };
    given(s.amplitude_um, link.amplitude_um);
    given(s.frequency_khz, link.frequency_khz);
    given(s.panel, link.panel);
    given(s.presentation, link.presentation);
    given(s.speed, link.speed);
    given(s.playing, link.playing);
    given(s.view.trail_periods, link.trail_periods);
    given(s.view.zoom, link.zoom);
    if (link.pan) s.view.pan = Vec2((*link.pan)[0], (*link.pan)[1]);
    given(s.view.follow, link.follow);
    if (link.pins) {
        s.pins.clear();
        for (const PinSource& p : *link.pins) s.pins.push_back(compute_pin(p, ratio_zeta_max(nullptr)));
    }
}

} // namespace fv::app
